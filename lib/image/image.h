/*
 * image.h - the private side of zr_image: its layout, the transfer
 * functions shared by every codec and the codec entry points.
 *
 * A zr_image holds linear floats, three per pixel, rows top to bottom.
 * Codecs decode from a byte array (so files served by the MPI reader work
 * the same as local ones) and encode to an open stdio stream that
 * image.c has created beside the final file.
 */
#ifndef ZR_IMAGE_IMAGE_H
#define ZR_IMAGE_IMAGE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#include "zrcube.h"

struct zr_image {
  int width;
  int height;
  float *pixels; /* width * height * 3 linear floats */
  /* NULL, or width * height alpha values in [0, 1] (1 opaque), made by
     zr_image_add_alpha for the writers that store it. */
  float *alpha;
  /* Palette files (PNG colour type 3) only, else NULL and 0: the palette
     entry of each pixel, which image_map's "filter INDEX, AMOUNT" and
     "transmit INDEX, AMOUNT" refer to. */
  unsigned char *indices;
  int palette_size;
  /* PNG files only, else NULL: the stored code of each sample (three per
     pixel, 0 .. maxval) before decoding, so that image_map's "gamma G"
     can decode them again with the transfer it names. */
  unsigned short *codes;
  unsigned maxval;
  /* A decoded file's memory, charged to the budget of the context that
     read it (NULL: none) until the image is freed. */
  struct zr_budget *budget;
  size_t charged;
};

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

/* Codecs.  name is the file name that messages quote. */
zr_status zr__png_decode(zr_context *ctx, const char *name,
                         const unsigned char *bytes, size_t size,
                         zr_image **out);
zr_status zr__png_encode(zr_context *ctx, const char *name,
                         const zr_image *image, int bits, bool alpha,
                         double assumed_gamma, FILE *stream);
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
                         FILE *stream);
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

/* zr_image_read from a file's bytes already read (name for messages). */
zr_status zr__image_decode(zr_context *ctx, const char *name,
                           const char *bytes, size_t size, zr_image **out);

/* zr_image_new with a message through ctx on failure. */
zr_status zr__image_new_named(zr_context *ctx, const char *name, int width,
                              int height, zr_image **out);

#endif /* ZR_IMAGE_IMAGE_H */
