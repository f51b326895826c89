/*
 * image.h - the private side of zr_image: its layout, the transfer
 * functions shared by every codec and the codec entry points.
 *
 * A zr_image made by zr_image_new (a render's picture) holds linear
 * floats, three per pixel, rows top to bottom.  A decoded file keeps its
 * samples in the smallest faithful form instead (issue 10: an 8-bit grey
 * PNG costs one byte a pixel, not 28): its stored codes, one or three a
 * pixel of one or two bytes, or palette indices, with a table giving the
 * linear value of each code; samplers convert per lookup
 * (zr__image_linear, lib/scene/bitmap.c).  zr_image_read adds the floats
 * for the public API (zr_image_pixels).
 *
 * Codecs decode from a byte array (so files served by the MPI reader work
 * the same as local ones) and encode to an open stdio stream that
 * image.c has created beside the final file.
 */
#ifndef ZR_IMAGE_IMAGE_H
#define ZR_IMAGE_IMAGE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "zrcube.h"

/* How a decoded image keeps its samples. */
typedef enum zr_image_layout {
  ZR_LAYOUT_FLOAT = 0, /* pixels only: three linear floats a pixel */
  ZR_LAYOUT_GREY,      /* codes: one a pixel, grey */
  ZR_LAYOUT_RGB,       /* codes: red, green, blue a pixel */
  ZR_LAYOUT_INDEX      /* indices: a palette entry a pixel */
} zr_image_layout;

struct zr_image {
  int width;
  int height;
  /* width * height * 3 linear floats: images made by zr_image_new, float
     files (PFM) and images zr_image_read returns; else NULL. */
  float *pixels;
  /* zr_image_new's pixels: their size, which zr_image_free gives
     zr__map_free; 0 when pixels is malloc's. */
  size_t pixels_bytes;
  /* NULL, or width * height straight alpha values in [0, 1] (1
     opaque), made by zr_image_add_alpha: for the writers that store it,
     and by the PNG, TGA, BMP and TIFF readers for a file that has it. */
  float *alpha;
  zr_image_layout layout;
  /* GREY and RGB: the stored samples, rows top to bottom, unsigned char
     when maxval <= 255, else unsigned short; alpha is in alpha. */
  void *codes;
  unsigned maxval;
  /* maxval + 1 floats: the linear value of each code (non-FLOAT). */
  float *table;
  /* The codes are the file's own samples (PNG, GIF, TGA), which
     image_map's "gamma G" may decode again; JPEG and Netpbm codes are
     kept too, but that option is refused for them. */
  bool stored_codes;
  /* The file states how its codes map to light (a PNG sRGB or gAMA
     chunk); false when the transfer is only presumed. */
  bool transfer_stated;
  /* Netpbm (PPM, PGM) codes, which POV-Ray presumes to be in the scene's
     working space ("Gamma in Input Images"), not sRGB as zr_image_read
     decodes them. */
  bool codes_working;
  /* The file's alpha is associated (TIFF, "Using the Alpha Channel"):
     the decoder divided its colours by alpha, which an image_map's
     "premultiplied off" undoes. */
  bool alpha_associated;
  /* Palette files (PNG colour type 3, GIF, colour-mapped TGA) only, else
     NULL and 0: the palette entry of each pixel, which image_map's
     "filter INDEX, AMOUNT" and "transmit INDEX, AMOUNT" refer to, and
     (INDEX layout) the codes of every byte value's entry, 3 * 256, black
     past the palette. */
  unsigned char *indices;
  int palette_size;
  unsigned short *palette;
  /* A decoded file's memory, charged to the budget of the context that
     read it (NULL: none) until the image is freed. */
  struct zr_budget *budget;
  size_t charged;
  /* NULL, or the writers' wait for rows still being made
     (zr_image_set_rows_wait). */
  zr_image_rows_fn rows_wait;
  void *rows_user;
};

/* Waits, where the image has a rows_wait, until rows 0 .. rows - 1 are
   final; ZR_OK, or ZR_ECANCELLED when the maker gave up. */
zr_status zr__image_wait_rows(const zr_image *image, int rows);

/* ZR_IMAGE_MAX_SIDE and ZR_IMAGE_MAX_PIXELS (zrcube.h) keep a hostile
   header from asking for gigabytes. */

/* How stored integer samples map to linear light. */
typedef enum zr_transfer {
  ZR_TRANSFER_SRGB,  /* IEC 61966-2-1 piecewise curve */
  ZR_TRANSFER_POWER  /* linear = stored ^ exponent */
} zr_transfer;

/* The sRGB curve, both directions, on [0, 1]. */
double zr__srgb_encode(double linear);
double zr__srgb_decode(double encoded);

/*
 * Fills table[0 .. maxval] with the linear value of each stored code.
 * exponent is used only by ZR_TRANSFER_POWER.  Returns NULL when out of
 * memory; the caller frees the table.
 */
float *zr__decode_table(unsigned maxval, zr_transfer transfer,
                        double exponent);

/*
 * The stored code of a working-space value: clamped to [0, 1], raised to
 * assumed_gamma to reach linear light, sRGB-encoded and rounded to
 * 0 .. maxval.
 */
unsigned zr__encode_sample(float value, double assumed_gamma,
                           unsigned maxval);

/*
 * The same with any file gamma (File_Gamma, zr_image_encoding's
 * file_gamma): 0 is the sRGB transfer, as zr__encode_sample; G > 0
 * pre-corrects linear light for a display of gamma G (power 1/G), so a
 * working value is raised to assumed_gamma / G - none at all when the
 * two are equal, which is how POV-Ray writes a legacy scene's colours
 * ("Gamma in Legacy Scenes": gamma correction turned off).
 */
unsigned zr__encode_code(float value, double assumed_gamma,
                         double file_gamma, unsigned maxval);

/*
 * zr__encode_sample for 8-bit codes without a pow() per sample, giving
 * the same code for every float: first[k] is the smallest float in
 * (0, 1) whose code is at least k, found once by bisection over the
 * floats' bits with zr__encode_sample itself, and a sample is placed
 * between two of them from the code at the start of its run of 2^16
 * floats (the top bits of the float index a table; a run spans a few
 * codes at most), then a short walk.  The rounded computation can only
 * disagree with the exact, increasing function for floats whose
 * pre-rounding value is within ~1e-13 of a half code, far below one
 * float step, so a sample within two floats of a boundary is simply
 * encoded the slow way (issue 13: the per-sample pow() was most of a
 * PNG write).
 */
typedef struct zr_encoder8 {
  double assumed_gamma;
  double file_gamma;        /* as zr__encode_code's */
  unsigned zero, one;       /* the codes of 0 and 1 */
  uint32_t first[257];      /* bits of first[k]; first[256]: of 1.0f */
  /* start[b >> 16]: the code of the float with bits b & ~0xffff. */
  uint8_t start[(0x3f800000 >> 16) + 1];
} zr_encoder8;
void zr__encoder8_init(zr_encoder8 *e, double assumed_gamma,
                       double file_gamma);
unsigned zr__encoder8_code(const zr_encoder8 *e, float value);

/* Codecs.  name is the file name that messages quote. */
zr_status zr__png_decode(zr_context *ctx, const char *name,
                         const unsigned char *bytes, size_t size,
                         zr_image **out);
zr_status zr__png_encode(zr_context *ctx, const char *name,
                         const zr_image *image, int bits, bool alpha,
                         double assumed_gamma, double file_gamma,
                         FILE *stream);
zr_status zr__jpeg_decode(zr_context *ctx, const char *name,
                          const unsigned char *bytes, size_t size,
                          zr_image **out);
zr_status zr__pnm_decode(zr_context *ctx, const char *name,
                         const unsigned char *bytes, size_t size,
                         zr_image **out);
zr_status zr__pfm_decode(zr_context *ctx, const char *name,
                         const unsigned char *bytes, size_t size,
                         zr_image **out);
/* A GIF file's first image as palette indices (gif.c), for image maps
   (zr__gif_decode) and height fields, which read the indices alone. */
typedef struct zr_gif_indices {
  int width, height;
  unsigned char *indices; /* width * height, rows top to bottom; malloc'ed */
  int palette_size;
  unsigned char palette[768]; /* red, green, blue of each entry */
} zr_gif_indices;
zr_status zr__gif_decode_indices(zr_context *ctx, const char *name,
                                 const unsigned char *bytes, size_t size,
                                 zr_gif_indices *out);
zr_status zr__gif_decode(zr_context *ctx, const char *name,
                         const unsigned char *bytes, size_t size,
                         zr_image **out);
/* TGA (tga.c): whether a header could be one of the TGA files read
   (TGA has no signature), and the decoder. */
bool zr__tga_looks_like(const unsigned char *bytes, size_t size);
zr_status zr__tga_decode(zr_context *ctx, const char *name,
                         const unsigned char *bytes, size_t size,
                         zr_image **out);
zr_status zr__ppm_encode(zr_context *ctx, const char *name,
                         const zr_image *image, double assumed_gamma,
                         double file_gamma, FILE *stream);
zr_status zr__pfm_encode(zr_context *ctx, const char *name,
                         const zr_image *image, FILE *stream);

/* Writers added for issue 12, one file each.  e is the caller's
   encoding (format already resolved, never AUTO). */
zr_status zr__jpeg_encode(zr_context *ctx, const char *name,
                          const zr_image *image, const zr_image_encoding *e,
                          FILE *stream);
zr_status zr__tga_encode(zr_context *ctx, const char *name,
                         const zr_image *image, const zr_image_encoding *e,
                         FILE *stream);
zr_status zr__hdr_encode(zr_context *ctx, const char *name,
                         const zr_image *image, const zr_image_encoding *e,
                         FILE *stream);
zr_status zr__exr_encode(zr_context *ctx, const char *name,
                         const zr_image *image, const zr_image_encoding *e,
                         FILE *stream);
zr_status zr__bmp_encode(zr_context *ctx, const char *name,
                         const zr_image *image, const zr_image_encoding *e,
                         FILE *stream);
/* Readers added for issue 12 (hdr.c, exr.c, bmp.c, tiff.c). */
bool zr__hdr_looks_like(const unsigned char *bytes, size_t size);
zr_status zr__hdr_decode(zr_context *ctx, const char *name,
                         const unsigned char *bytes, size_t size,
                         zr_image **out);
bool zr__exr_looks_like(const unsigned char *bytes, size_t size);
zr_status zr__exr_decode(zr_context *ctx, const char *name,
                         const unsigned char *bytes, size_t size,
                         zr_image **out);
/* Whether this build reads and writes OpenEXR (configure's check). */
bool zr__exr_available(void);
zr_status zr__bmp_decode(zr_context *ctx, const char *name,
                         const unsigned char *bytes, size_t size,
                         zr_image **out);
zr_status zr__tiff_decode(zr_context *ctx, const char *name,
                          const unsigned char *bytes, size_t size,
                          zr_image **out);
/* A coverage (alpha) value stored linearly: clamped to [0, 1], NaN 0,
   rounded to 0 .. maxval. */
unsigned zr__encode_linear(float value, unsigned maxval);
/* The value stored for linear light by the float formats (HDR, EXR):
   the working value raised to assumed_gamma, negatives and NaN 0. */
float zr__linear_sample(float value, double assumed_gamma);

/* An image file's bytes (the caller frees them); a missing or unreadable
   file gets its message here. */
zr_status zr__image_read_bytes(zr_context *ctx, const char *path,
                               char **bytes, size_t *size);

/*
 * A height field's samples (lib/image/heights.c): the stored values of
 * a PNG, GIF, PGM, PPM or JPEG file scaled to [0, 1], one per pixel,
 * rows top to bottom, in a malloc'ed array the caller frees.  pot: the
 * file is a POT file (a double-width GIF holding 16-bit heights).
 */
zr_status zr__image_read_heights(zr_context *ctx, const char *path, bool pot,
                                 float **heights, int *width, int *height);

/* The same from a file's bytes already read (name for messages). */
zr_status zr__image_decode_heights(zr_context *ctx, const char *name,
                                   bool pot, const char *bytes, size_t size,
                                   float **heights, int *width,
                                   int *height);

/* A height field's samples as the file stores them: w x h codes, rows
   top to bottom, of 8 bits (height code / 255) or 16 bits (code /
   65535), in an arena. */
typedef struct zr_height_codes {
  void *codes;
  int bits;
  int width, height;
} zr_height_codes;

struct zr_arena;
/* Decodes a height field's file into codes allocated in arena (charged
   to the arena's budget); the message is given on failure. */
zr_status zr__image_decode_height_codes(zr_context *ctx, const char *name,
                                        bool pot, const char *bytes,
                                        size_t size, struct zr_arena *arena,
                                        zr_height_codes *out);
/* Code k of c as a height in [0, 1]. */
double zr__height_code_value(const zr_height_codes *c, size_t k);

/* zr_image_read from a file's bytes already read (name for messages). */
zr_status zr__image_decode(zr_context *ctx, const char *name,
                           const char *bytes, size_t size, zr_image **out);

/* zr_image_new with a message through ctx on failure, charged to ctx's
   budget: a float image for decoders of float files. */
zr_status zr__image_new_named(zr_context *ctx, const char *name, int width,
                              int height, zr_image **out);

/*
 * An image of stored codes (GREY, RGB) or palette indices (INDEX, maxval
 * of the palette's codes), without floats, charged to ctx's budget with
 * the bytes it holds plus extra bytes the decoder needs while it runs
 * (released by zr__image_release_extra).  The table is filled with
 * transfer (exponent for ZR_TRANSFER_POWER); the INDEX palette is black.
 */
zr_status zr__image_new_coded(zr_context *ctx, const char *name, int width,
                              int height, zr_image_layout layout,
                              unsigned maxval, zr_transfer transfer,
                              double exponent, size_t extra,
                              zr_image **out);
void zr__image_release_extra(zr_image *image, size_t extra);

/* Channels a pixel of the layout holds in codes (1 or 3; INDEX 1). */
int zr__image_channels(const zr_image *image);

/* Code k of a GREY or RGB image's codes array. */
static inline unsigned zr__image_code_at(const zr_image *im, size_t k) {
  return im->maxval > 255 ? ((const unsigned short *)im->codes)[k]
                          : ((const unsigned char *)im->codes)[k];
}
static inline void zr__image_set_code(zr_image *im, size_t k, unsigned v) {
  if (im->maxval > 255)
    ((unsigned short *)im->codes)[k] = (unsigned short)v;
  else
    ((unsigned char *)im->codes)[k] = (unsigned char)v;
}

/* The stored code of sample k = 3 * pixel + channel, seen as RGB
   (non-FLOAT layouts). */
static inline unsigned zr__image_stored(const zr_image *im, size_t k) {
  switch (im->layout) {
  case ZR_LAYOUT_GREY:
    return zr__image_code_at(im, k / 3);
  case ZR_LAYOUT_INDEX:
    return im->palette[3 * (size_t)im->indices[k / 3] + k % 3];
  default:
    return zr__image_code_at(im, k);
  }
}

/* The linear value of sample k = 3 * pixel + channel. */
static inline float zr__image_linear(const zr_image *im, size_t k) {
  if (im->pixels)
    return im->pixels[k];
  return im->table[zr__image_stored(im, k)];
}

/* Adds the floats (pixels) to a coded image. */
zr_status zr__image_add_floats(zr_context *ctx, const char *name,
                               zr_image *image);

/* The bytes an image's samples take (codes, indices, palette, table,
   floats): what the budget is charged for it. */
size_t zr__image_bytes(const zr_image *image);

#endif /* ZR_IMAGE_IMAGE_H */
