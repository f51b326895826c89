/*
 * heights.c - an image file read as a height field's samples (POV-Ray
 * 3.7 reference, "Height Field"), not as colours: the stored numbers
 * themselves, scaled to [0, 1], with no transfer function, as POV-Ray
 * "will normally interpret the height field input file as a container
 * of linear data".
 *
 *   - a palette image gives its palette index (0 .. 255) / 255, whatever
 *     the colours are;
 *   - a grey image gives its grey value / maxval (8 or 16 bits, so 16
 *     bit PNG and PGM files are as smooth as they are stored);
 *   - a colour image holds a 16-bit number in its red (high byte) and
 *     green (low byte) samples, the TGA and PPM convention the manual
 *     gives, which PNG colour images follow too: (256 r + g) / 65535.
 *     A grey picture stored as colour (r = g = b = v) gives v / 255.
 *     Samples of more than 8 bits are taken by their high byte here.
 *   - a GIF file is a palette image: index / 255; so is a colour-mapped
 *     TGA file, and TGA colour files follow the red/green rule above;
 *     so do BMP files (palette or colour) and TIFF files (read as
 *     8-bit colour; a grey TIFF has r = g = b, so v / 255);
 *   - a POT file (Fractint's "continuous potential", which the manual
 *     calls "essentially a GIF file with a 16 bit palette") is a GIF
 *     twice as wide as the field: the left half holds the high bytes of
 *     16-bit heights, the right half the low bytes, so a pixel of the
 *     field is (256 left + right) / 65535.  The layout was checked on
 *     the stock mtmand.pot, whose halves join without a seam.
 *
 * PNG files are decoded by libpng with no conversion but the unpacking
 * of 1, 2 and 4-bit samples.  Netpbm, JPEG and TGA files go through the
 * codecs (pnm.c, jpeg.c, tga.c), which keep the stored codes.
 */
#include "config.h"

#include <math.h>
#include <png.h>
#include <setjmp.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/budget.h"
#include "core/context.h"
#include "image/image.h"

typedef struct png_source {
  const unsigned char *bytes;
  size_t size, pos;
} png_source;

static void read_memory(png_structp png, png_bytep data, size_t length) {
  png_source *src = png_get_io_ptr(png);
  if (length > src->size - src->pos)
    png_error(png, "truncated");
  memcpy(data, src->bytes + src->pos, length);
  src->pos += length;
}

/* What libpng's error handler leaves for the message. */
typedef struct png_failure {
  char text[200];
  size_t over_budget; /* bytes the memory budget refused, else 0 */
} png_failure;

static void on_error(png_structp png, png_const_charp msg) {
  png_failure *f = png_get_error_ptr(png);
  snprintf(f->text, sizeof f->text, "%s", msg);
  png_longjmp(png, 1);
}

static void on_warning(png_structp png, png_const_charp msg) {
  (void)png;
  (void)msg;
}

static float colour_height(unsigned r, unsigned g) {
  return (float)((256.0 * r + g) / 65535.0);
}

/* Decodes rows into heights[w * h]; the png structs are the caller's. */
static bool png_heights(zr_context *ctx, png_structp png, png_infop info,
                        png_source *src, float **out, int *w, int *h) {
  png_bytep rows = NULL;
  png_bytepp row_ptrs = NULL;
  float *heights = NULL;
  /* volatile: changed between setjmp and a longjmp back to it. */
  png_bytep volatile rows_v = NULL;
  png_bytepp volatile ptrs_v = NULL;
  float *volatile heights_v = NULL;
  volatile size_t charged_v = 0;
  if (setjmp(png_jmpbuf(png))) {
    if (ctx)
      zr__budget_release(ctx->budget, charged_v);
    free(rows_v);
    free(ptrs_v);
    free(heights_v);
    return false;
  }
  png_set_read_fn(png, src, read_memory);
  png_set_user_limits(png, ZR_IMAGE_MAX_SIDE, ZR_IMAGE_MAX_SIDE);
  png_read_info(png, info);
  int type = png_get_color_type(png, info);
  int depth = png_get_bit_depth(png, info);
  if (depth < 8)
    png_set_packing(png); /* one byte per sample, values kept */
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  int width = (int)png_get_image_width(png, info);
  int height = (int)png_get_image_height(png, info);
  int channels = png_get_channels(png, info);
  size_t rowbytes = png_get_rowbytes(png, info);
  if ((size_t)width * (size_t)height > ZR_IMAGE_MAX_PIXELS)
    png_error(png, "image too large");
  /* The decoded rows and the samples are charged to the memory budget
     while they are made: a header of a few bytes may declare 2^27
     pixels (found by tests/fuzz/fuzz_image); the caller owns the
     samples after. */
  size_t need = rowbytes * (size_t)height +
                (size_t)height * sizeof *row_ptrs +
                (size_t)width * (size_t)height * sizeof *heights;
  if (ctx && !zr__budget_charge(ctx->budget, need)) {
    ((png_failure *)png_get_error_ptr(png))->over_budget = need;
    png_error(png, "over the memory budget");
  }
  charged_v = need;
  rows = malloc(rowbytes * (size_t)height);
  rows_v = rows;
  row_ptrs = malloc((size_t)height * sizeof *row_ptrs);
  ptrs_v = row_ptrs;
  heights = malloc((size_t)width * (size_t)height * sizeof *heights);
  heights_v = heights;
  if (!rows || !row_ptrs || !heights)
    png_error(png, "out of memory");
  for (int y = 0; y < height; y++)
    row_ptrs[y] = rows + (size_t)y * rowbytes;
  png_read_image(png, row_ptrs);
  double maxval = depth == 16 ? 65535.0 : (double)((1u << depth) - 1);
  for (int y = 0; y < height; y++) {
    const png_byte *r = row_ptrs[y];
    float *dst = heights + (size_t)y * width;
    for (int x = 0; x < width; x++) {
      unsigned s[4] = {0, 0, 0, 0};
      for (int c = 0; c < channels && c < 4; c++)
        s[c] = depth == 16 ? (unsigned)r[2 * (x * channels + c)] << 8 |
                                 r[2 * (x * channels + c) + 1]
                           : r[x * channels + c];
      if (type == PNG_COLOR_TYPE_PALETTE)
        dst[x] = (float)(s[0] / 255.0);
      else if (!(type & PNG_COLOR_MASK_COLOR))
        dst[x] = (float)(s[0] / maxval);
      else if (depth == 16)
        dst[x] = colour_height(s[0] >> 8, s[1] >> 8);
      else
        dst[x] = colour_height(s[0], s[1]);
    }
  }
  free(rows);
  free(row_ptrs);
  if (ctx)
    zr__budget_release(ctx->budget, need);
  *out = heights;
  *w = width;
  *h = height;
  return true;
}

static zr_status read_png(zr_context *ctx, const char *name,
                          const unsigned char *bytes, size_t size,
                          float **out, int *w, int *h) {
  png_failure failure = {"cannot decode", 0};
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &failure,
                                           on_error, on_warning);
  png_infop info = png ? png_create_info_struct(png) : NULL;
  if (!info) {
    png_destroy_read_struct(&png, NULL, NULL);
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "%s: %s", name,
                    zr_status_str(ZR_ENOMEM));
  }
  png_source src = {bytes, size, 0};
  bool ok = png_heights(ctx, png, info, &src, out, w, h);
  png_destroy_read_struct(&png, &info, NULL);
  if (!ok && failure.over_budget) {
    char what[200];
    snprintf(what, sizeof what, "the height field '%.120s'", name);
    return zr__context_over_budget(ctx, failure.over_budget, NULL, what);
  }
  if (!ok)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL, "%s: %s", name,
                    failure.text);
  return ZR_OK;
}

/* The magic number and maxval of a Netpbm header ("P5 640 480 255"). */
static bool pnm_header(const unsigned char *b, size_t n, char *magic,
                       unsigned long *maxval) {
  if (n < 2 || b[0] != 'P')
    return false;
  *magic = (char)b[1];
  size_t i = 2;
  unsigned long field[3] = {0, 0, 0};
  for (int k = 0; k < 3; k++) {
    for (;;) {
      while (i < n && (b[i] == ' ' || b[i] == '\t' || b[i] == '\n' ||
                       b[i] == '\r'))
        i++;
      if (i < n && b[i] == '#') {
        while (i < n && b[i] != '\n')
          i++;
        continue;
      }
      break;
    }
    if (i >= n || b[i] < '0' || b[i] > '9')
      return false;
    while (i < n && b[i] >= '0' && b[i] <= '9' && field[k] < 1000000)
      field[k] = field[k] * 10 + (unsigned long)(b[i++] - '0');
  }
  *maxval = field[2];
  return *maxval >= 1 && *maxval <= 65535;
}

/* An array for a decoded image's heights, charged to the memory budget
   while the caller fills it (heights_done gives the charge back: the
   caller owns the heights after, as for PNG and GIF files); on failure
   the image is freed and the message given. */
static float *heights_for(zr_context *ctx, const char *name,
                          zr_image *image) {
  size_t n = (size_t)image->width * (size_t)image->height;
  if (ctx && !zr__budget_charge(ctx->budget, n * sizeof(float))) {
    char what[200];
    snprintf(what, sizeof what, "the %dx%d height field '%.120s'",
             image->width, image->height, name);
    zr_image_free(image);
    zr__context_over_budget(ctx, n * sizeof(float), NULL, what);
    return NULL;
  }
  float *heights = malloc(n * sizeof *heights);
  if (!heights) {
    if (ctx)
      zr__budget_release(ctx->budget, n * sizeof(float));
    zr_image_free(image);
    zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "%s: %s", name,
             zr_status_str(ZR_ENOMEM));
  }
  return heights;
}

static void heights_done(zr_context *ctx, zr_image *image) {
  if (ctx)
    zr__budget_release(ctx->budget, (size_t)image->width *
                                        (size_t)image->height *
                                        sizeof(float));
  zr_image_free(image);
}

/* Netpbm and JPEG: the codes the codecs keep (image.h). */
static zr_status read_coded(zr_context *ctx, const char *name,
                            const unsigned char *bytes, size_t size,
                            bool jpeg, float **out, int *w, int *h) {
  char magic = '6';
  unsigned long maxval = 255;
  if (!jpeg && !pnm_header(bytes, size, &magic, &maxval))
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL,
                    "%s: not a PNG, GIF, TGA, PGM, PPM or JPEG file", name);
  zr_image *image = NULL;
  zr_status s = jpeg ? zr__jpeg_decode(ctx, name, bytes, size, &image)
                     : zr__pnm_decode(ctx, name, bytes, size, &image);
  if (s != ZR_OK) {
    zr_image_free(image);
    return s;
  }
  size_t n = (size_t)image->width * (size_t)image->height;
  float *heights = heights_for(ctx, name, image);
  if (!heights)
    return ZR_ENOMEM;
  bool grey = magic == '2' || magic == '5';
  for (size_t i = 0; i < n; i++) {
    unsigned r = zr__image_stored(image, 3 * i);
    if (grey) {
      heights[i] = (float)(r / (double)maxval);
      continue;
    }
    unsigned g = zr__image_stored(image, 3 * i + 1);
    if (maxval > 255) {
      r >>= 8;
      g >>= 8;
    }
    heights[i] = colour_height(r, g);
  }
  *w = image->width;
  *h = image->height;
  *out = heights;
  heights_done(ctx, image);
  return ZR_OK;
}

/* TGA files: decoded, then read by their stored codes. */
static zr_status read_tga(zr_context *ctx, const char *name,
                          const unsigned char *bytes, size_t size,
                          float **out, int *w, int *h) {
  zr_image *image = NULL;
  zr_status s = zr__tga_decode(ctx, name, bytes, size, &image);
  if (s != ZR_OK)
    return s;
  size_t n = (size_t)image->width * (size_t)image->height;
  float *heights = heights_for(ctx, name, image);
  if (!heights)
    return ZR_ENOMEM;
  bool grey = (bytes[2] & 7) == 3;
  for (size_t i = 0; i < n; i++) {
    if (image->indices)
      heights[i] = (float)(image->indices[i] / 255.0);
    else if (grey)
      heights[i] = (float)(zr__image_stored(image, 3 * i) / 255.0);
    else
      heights[i] = colour_height(zr__image_stored(image, 3 * i),
                                 zr__image_stored(image, 3 * i + 1));
  }
  *w = image->width;
  *h = image->height;
  *out = heights;
  heights_done(ctx, image);
  return ZR_OK;
}

/* BMP and TIFF files: decoded, then read by their stored codes, a
   palette image by its indices. */
static zr_status read_decoded(zr_context *ctx, const char *name,
                              const unsigned char *bytes, size_t size,
                              bool tiff, float **out, int *w, int *h) {
  zr_image *image = NULL;
  zr_status s = tiff ? zr__tiff_decode(ctx, name, bytes, size, &image)
                     : zr__bmp_decode(ctx, name, bytes, size, &image);
  if (s != ZR_OK)
    return s;
  size_t n = (size_t)image->width * (size_t)image->height;
  float *heights = heights_for(ctx, name, image);
  if (!heights)
    return ZR_ENOMEM;
  for (size_t i = 0; i < n; i++)
    heights[i] = image->indices
                     ? (float)(image->indices[i] / 255.0)
                     : colour_height(
                           ((const unsigned char *)image->codes)[3 * i],
                           ((const unsigned char *)image->codes)[3 * i + 1]);
  *w = image->width;
  *h = image->height;
  *out = heights;
  zr_image_free(image);
  return ZR_OK;
}

/* GIF and POT files (see the top of the file). */
static zr_status read_gif(zr_context *ctx, const char *name,
                          const unsigned char *bytes, size_t size, bool pot,
                          float **out, int *w, int *h) {
  zr_gif_indices g;
  zr_status s = zr__gif_decode_indices(ctx, name, bytes, size, &g);
  if (s != ZR_OK)
    return s;
  if (pot && g.width % 2 != 0) {
    free(g.indices);
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL,
                    "%s: a POT file is twice as wide as its height field, "
                    "but this one is %d pixels wide", name, g.width);
  }
  int width = pot ? g.width / 2 : g.width;
  /* The samples beside the indices must fit in what is left of the
     memory budget (a GIF header may declare 2^27 pixels in a few bytes;
     found by tests/fuzz/fuzz_image); the caller owns them after. */
  size_t need = (size_t)width * (size_t)g.height * sizeof(float) +
                (size_t)g.width * (size_t)g.height;
  if (ctx && !zr__budget_charge(ctx->budget, need)) {
    free(g.indices);
    char what[200];
    snprintf(what, sizeof what, "the %dx%d height field '%.120s'", width,
             g.height, name);
    return zr__context_over_budget(ctx, need, NULL, what);
  }
  float *heights = malloc((size_t)width * (size_t)g.height * sizeof *heights);
  if (ctx)
    zr__budget_release(ctx->budget, need);
  if (!heights) {
    free(g.indices);
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "%s: %s", name,
                    zr_status_str(ZR_ENOMEM));
  }
  for (int y = 0; y < g.height; y++) {
    const unsigned char *row = g.indices + (size_t)y * (size_t)g.width;
    float *dst = heights + (size_t)y * (size_t)width;
    for (int x = 0; x < width; x++)
      dst[x] = pot ? colour_height(row[x], row[x + width])
                   : (float)(row[x] / 255.0);
  }
  free(g.indices);
  *out = heights;
  *w = width;
  *h = g.height;
  return ZR_OK;
}

zr_status zr__image_read_heights(zr_context *ctx, const char *path, bool pot,
                                 float **heights, int *width,
                                 int *height) {
  *heights = NULL;
  char *bytes = NULL;
  size_t size = 0;
  zr_status s = zr__context_read(ctx, path, &bytes, &size);
  if (s == ZR_ENOTFOUND)
    return zr__diag(ctx, ZR_DIAG_ERROR, s, NULL, "%s: file not found",
                    path);
  if (s == ZR_EACCESS)
    return s; /* zr__context_read said why */
  if (s != ZR_OK) {
    char why[160];
    return zr__diag(ctx, ZR_DIAG_ERROR, s, NULL, "%s: cannot read: %s",
                    path, zr__context_read_error(ctx, s, why, sizeof why));
  }
  s = zr__image_decode_heights(ctx, path, pot, bytes, size, heights, width,
                               height);
  free(bytes);
  return s;
}

zr_status zr__image_decode_heights(zr_context *ctx, const char *path,
                                   bool pot, const char *bytes, size_t size,
                                   float **heights, int *width,
                                   int *height) {
  zr_status s;
  *heights = NULL;
  static const unsigned char png_sig[8] = {0x89, 'P', 'N', 'G',
                                           '\r', '\n', 0x1a, '\n'};
  const unsigned char *b = (const unsigned char *)bytes;
  bool gif = size >= 6 && (!memcmp(b, "GIF87a", 6) ||
                           !memcmp(b, "GIF89a", 6));
  if (pot && !gif)
    s = zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL,
                 "%s: not a POT file (a POT file is a GIF file)", path);
  else if (gif)
    s = read_gif(ctx, path, b, size, pot, heights, width, height);
  else if (size >= 8 && !memcmp(b, png_sig, 8))
    s = read_png(ctx, path, b, size, heights, width, height);
  else if (size >= 3 && b[0] == 0xff && b[1] == 0xd8 && b[2] == 0xff)
    s = read_coded(ctx, path, b, size, true, heights, width, height);
  else if (size >= 2 && b[0] == 'B' && b[1] == 'M')
    s = read_decoded(ctx, path, b, size, false, heights, width, height);
  else if (size >= 4 && (!memcmp(b, "II*\0", 4) || !memcmp(b, "MM\0*", 4)))
    s = read_decoded(ctx, path, b, size, true, heights, width, height);
  else if (!(size >= 2 && b[0] == 'P') && zr__tga_looks_like(b, size))
    s = read_tga(ctx, path, b, size, heights, width, height);
  else
    s = read_coded(ctx, path, b, size, false, heights, width, height);
  return s;
}
