/*
 * ttf.h - reading TrueType fonts for the text object (lib/scene/ttf.c):
 * character map, glyph outlines, advance widths and kerning.
 */
#ifndef ZR_SCENE_TTF_H
#define ZR_SCENE_TTF_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* An opened font: offsets into the caller's bytes, which must outlive
   it.  Every offset was checked against the size when it was opened. */
typedef struct zr_ttf {
  const uint8_t *data;
  size_t size;
  unsigned units_per_em;
  int loca_long; /* head.indexToLocFormat */
  unsigned n_glyphs;
  unsigned n_hmetrics;
  size_t glyf, glyf_len, loca, loca_len, hmtx, hmtx_len;
  size_t cmap4, cmap4_len; /* the format 4 subtable */
  bool symbol;             /* a (3, 0) symbol map: codes live at 0xF0xx */
  size_t kern, kern_len;   /* the first horizontal pairs table, or 0 */
} zr_ttf;

/* Opens a font (the first of a collection).  NULL on success, otherwise
   a static message saying what is wrong with the file. */
const char *zr__ttf_open(zr_ttf *font, const uint8_t *data, size_t size);

/* The glyph of a character code (0: the font's missing glyph). */
unsigned zr__ttf_glyph(const zr_ttf *font, uint32_t code);

/* Advance width and the kerning of the pair (left, right), font units. */
int zr__ttf_advance(const zr_ttf *font, unsigned glyph);
int zr__ttf_kerning(const zr_ttf *font, unsigned left, unsigned right);

/* Receives the outline: the quadratic curve p0 c p1, or the line p0 p1
   (c unused) when line is set, in font units.  Returns false to stop
   (out of memory). */
typedef bool (*zr_ttf_segment_fn)(void *user, const double p0[2],
                                  const double c[2], const double p1[2],
                                  bool line);

/* Walks a glyph's contours (composite glyphs included).  NULL on
   success, or a static message when the glyph's data is broken; stopped
   (out of memory) gives "out of memory". */
const char *zr__ttf_outline(const zr_ttf *font, unsigned glyph,
                            zr_ttf_segment_fn segment, void *user);

#endif /* ZR_SCENE_TTF_H */
