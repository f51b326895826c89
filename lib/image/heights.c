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
 * of 1, 2 and 4-bit samples, row by row unless interlaced.  Netpbm,
 * JPEG and TGA files go through the codecs (pnm.c, jpeg.c, tga.c),
 * which keep the stored codes.
 *
 * The samples are kept as codes in their smallest faithful form, in the
 * caller's arena (charged to its budget): one byte for height k / 255
 * (8-bit grey, palette indices, GIF), two bytes for k / 65535 (16-bit
 * grey, the red/green rule, POT, and 1, 2 and 4-bit grey, whose maxval
 * divides 65535).  A Netpbm grey file of another maxval is rounded to
 * the nearest 16-bit code (an error below 1 / 131070 of the height).
 * An 11000 x 11000 grey PNG thus costs 121 MB, not 484 as floats.
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

#include "core/arena.h"
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
  zr_status reported; /* a message already given with this status */
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

/* The 16-bit code of a colour pixel: 256 r + g. */
static unsigned colour_code(unsigned r, unsigned g) {
  return (r & 255u) << 8 | (g & 255u);
}

/* Stores code k of the row-major sample array. */
static void put_code(zr_height_codes *c, size_t k, unsigned code) {
  if (c->bits == 8)
    ((uint8_t *)c->codes)[k] = (uint8_t)code;
  else
    ((uint16_t *)c->codes)[k] = (uint16_t)code;
}

/* The code array of a w x h field of 8 or 16 bits, in arena; false (and
   the message given) when the budget or the memory refuses it. */
static bool codes_new(zr_context *ctx, zr_arena *arena, const char *name,
                      int w, int h, int bits, zr_height_codes *out) {
  size_t bytes = (size_t)w * (size_t)h * (size_t)(bits / 8);
  arena->over_budget = 0;
  out->codes = zr__arena_alloc(arena, bytes);
  out->bits = bits;
  out->width = w;
  out->height = h;
  if (out->codes)
    return true;
  if (arena->over_budget) {
    char what[200];
    snprintf(what, sizeof what, "the %dx%d height field '%.120s'", w, h,
             name);
    zr__context_over_budget(ctx, bytes, NULL, what);
  } else {
    zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "%s: %s", name,
             zr_status_str(ZR_ENOMEM));
  }
  return false;
}

/* The code of pixel x of a decoded row. */
static unsigned png_code(const png_byte *r, int x, int channels, int depth,
                         int type) {
  unsigned s[2] = {0, 0};
  for (int c = 0; c < channels && c < 2; c++)
    s[c] = depth == 16 ? (unsigned)r[2 * (x * channels + c)] << 8 |
                             r[2 * (x * channels + c) + 1]
                       : r[x * channels + c];
  if (type == PNG_COLOR_TYPE_PALETTE)
    return s[0];
  if (!(type & PNG_COLOR_MASK_COLOR))
    /* 1, 2 and 4-bit grey: maxval 1, 3 or 15 divides 65535. */
    return depth >= 8 ? s[0] : s[0] * (65535u / ((1u << depth) - 1));
  return depth == 16 ? colour_code(s[0] >> 8, s[1] >> 8)
                     : colour_code(s[0], s[1]);
}

/* Decodes the rows into codes; the png structs are the caller's.  A
   non-interlaced file is read one row at a time. */
static bool png_heights(zr_context *ctx, png_structp png, png_infop info,
                        png_source *src, const char *name, zr_arena *arena,
                        zr_height_codes *out) {
  png_bytep rows = NULL;
  png_bytepp row_ptrs = NULL;
  /* volatile: changed between setjmp and a longjmp back to it. */
  png_bytep volatile rows_v = NULL;
  png_bytepp volatile ptrs_v = NULL;
  volatile size_t charged_v = 0;
  png_failure *failure = png_get_error_ptr(png);
  if (setjmp(png_jmpbuf(png))) {
    if (ctx)
      zr__budget_release(ctx->budget, charged_v);
    free(rows_v);
    free(ptrs_v);
    return false;
  }
  png_set_read_fn(png, src, read_memory);
  png_set_user_limits(png, ZR_IMAGE_MAX_SIDE, ZR_IMAGE_MAX_SIDE);
  png_read_info(png, info);
  int type = png_get_color_type(png, info);
  int depth = png_get_bit_depth(png, info);
  if (depth < 8)
    png_set_packing(png); /* one byte per sample, values kept */
  int passes = png_set_interlace_handling(png);
  png_read_update_info(png, info);
  int width = (int)png_get_image_width(png, info);
  int height = (int)png_get_image_height(png, info);
  int channels = png_get_channels(png, info);
  size_t rowbytes = png_get_rowbytes(png, info);
  if ((size_t)width * (size_t)height > ZR_IMAGE_MAX_PIXELS)
    png_error(png, "image too large");
  bool narrow = type == PNG_COLOR_TYPE_PALETTE ||
                (!(type & PNG_COLOR_MASK_COLOR) && depth == 8);
  /* The codes first (they are what is kept), then the decoded rows,
     charged to the memory budget while they are made: a header of a
     few bytes may declare 2^27 pixels (found by tests/fuzz/fuzz_image). */
  if (!codes_new(ctx, arena, name, width, height, narrow ? 8 : 16, out)) {
    failure->reported = arena->over_budget ? ZR_ELIMIT : ZR_ENOMEM;
    png_error(png, "no memory for the samples");
  }
  size_t n_rows = passes > 1 ? (size_t)height : 1;
  size_t need = rowbytes * n_rows + n_rows * sizeof *row_ptrs;
  if (ctx && !zr__budget_charge(ctx->budget, need)) {
    failure->over_budget = need;
    png_error(png, "over the memory budget");
  }
  charged_v = need;
  rows = malloc(rowbytes * n_rows);
  rows_v = rows;
  row_ptrs = malloc(n_rows * sizeof *row_ptrs);
  ptrs_v = row_ptrs;
  if (!rows || !row_ptrs)
    png_error(png, "out of memory");
  for (size_t y = 0; y < n_rows; y++)
    row_ptrs[y] = rows + y * rowbytes;
  if (passes > 1)
    png_read_image(png, row_ptrs);
  for (int y = 0; y < height; y++) {
    const png_byte *r = row_ptrs[passes > 1 ? y : 0];
    if (passes <= 1)
      png_read_row(png, row_ptrs[0], NULL);
    size_t k = (size_t)y * (size_t)width;
    for (int x = 0; x < width; x++)
      put_code(out, k + (size_t)x, png_code(r, x, channels, depth, type));
  }
  free(rows);
  free(row_ptrs);
  if (ctx)
    zr__budget_release(ctx->budget, need);
  return true;
}

static zr_status read_png(zr_context *ctx, const char *name,
                          const unsigned char *bytes, size_t size,
                          zr_arena *arena, zr_height_codes *out) {
  png_failure failure = {"cannot decode", 0, ZR_OK};
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &failure,
                                           on_error, on_warning);
  png_infop info = png ? png_create_info_struct(png) : NULL;
  if (!info) {
    png_destroy_read_struct(&png, NULL, NULL);
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "%s: %s", name,
                    zr_status_str(ZR_ENOMEM));
  }
  png_source src = {bytes, size, 0};
  bool ok = png_heights(ctx, png, info, &src, name, arena, out);
  png_destroy_read_struct(&png, &info, NULL);
  if (!ok && failure.reported != ZR_OK)
    return failure.reported;
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

/* Netpbm and JPEG: the codes the codecs keep (image.h). */
static zr_status read_coded(zr_context *ctx, const char *name,
                            const unsigned char *bytes, size_t size,
                            bool jpeg, zr_arena *arena,
                            zr_height_codes *out) {
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
  bool grey = magic == '2' || magic == '5';
  int bits = grey && maxval == 255 ? 8 : 16;
  if (!codes_new(ctx, arena, name, image->width, image->height, bits,
                 out)) {
    zr_image_free(image);
    return arena->over_budget ? ZR_ELIMIT : ZR_ENOMEM;
  }
  size_t n = (size_t)image->width * (size_t)image->height;
  for (size_t i = 0; i < n; i++) {
    unsigned r = zr__image_stored(image, 3 * i);
    if (grey) {
      /* v / maxval as a 16-bit code, exact when maxval divides 65535. */
      put_code(out, i, bits == 8 ? r
                                 : (unsigned)((r * 65535ul + maxval / 2) /
                                              maxval));
      continue;
    }
    unsigned g = zr__image_stored(image, 3 * i + 1);
    if (maxval > 255) {
      r >>= 8;
      g >>= 8;
    }
    put_code(out, i, colour_code(r, g));
  }
  zr_image_free(image);
  return ZR_OK;
}

/* TGA files: decoded, then read by their stored codes. */
static zr_status read_tga(zr_context *ctx, const char *name,
                          const unsigned char *bytes, size_t size,
                          zr_arena *arena, zr_height_codes *out) {
  zr_image *image = NULL;
  zr_status s = zr__tga_decode(ctx, name, bytes, size, &image);
  if (s != ZR_OK)
    return s;
  bool grey = (bytes[2] & 7) == 3;
  bool narrow = image->indices || grey;
  if (!codes_new(ctx, arena, name, image->width, image->height,
                 narrow ? 8 : 16, out)) {
    zr_image_free(image);
    return arena->over_budget ? ZR_ELIMIT : ZR_ENOMEM;
  }
  size_t n = (size_t)image->width * (size_t)image->height;
  for (size_t i = 0; i < n; i++) {
    if (image->indices)
      put_code(out, i, image->indices[i]);
    else if (grey)
      put_code(out, i, zr__image_stored(image, 3 * i));
    else
      put_code(out, i, colour_code(zr__image_stored(image, 3 * i),
                                   zr__image_stored(image, 3 * i + 1)));
  }
  zr_image_free(image);
  return ZR_OK;
}

/* BMP and TIFF files: decoded, then read by their stored codes, a
   palette image by its indices. */
static zr_status read_decoded(zr_context *ctx, const char *name,
                              const unsigned char *bytes, size_t size,
                              bool tiff, zr_arena *arena,
                              zr_height_codes *out) {
  zr_image *image = NULL;
  zr_status s = tiff ? zr__tiff_decode(ctx, name, bytes, size, &image)
                     : zr__bmp_decode(ctx, name, bytes, size, &image);
  if (s != ZR_OK)
    return s;
  if (!codes_new(ctx, arena, name, image->width, image->height,
                 image->indices ? 8 : 16, out)) {
    zr_image_free(image);
    return arena->over_budget ? ZR_ELIMIT : ZR_ENOMEM;
  }
  size_t n = (size_t)image->width * (size_t)image->height;
  const unsigned char *codes = image->codes;
  for (size_t i = 0; i < n; i++)
    put_code(out, i, image->indices
                         ? image->indices[i]
                         : colour_code(codes[3 * i], codes[3 * i + 1]));
  zr_image_free(image);
  return ZR_OK;
}

/* GIF and POT files (see the top of the file). */
static zr_status read_gif(zr_context *ctx, const char *name,
                          const unsigned char *bytes, size_t size, bool pot,
                          zr_arena *arena, zr_height_codes *out) {
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
  /* The codes must fit in what is left of the memory budget beside the
     indices (a GIF header may declare 2^27 pixels in a few bytes; found
     by tests/fuzz/fuzz_image). */
  if (!codes_new(ctx, arena, name, width, g.height, pot ? 16 : 8, out)) {
    free(g.indices);
    return arena->over_budget ? ZR_ELIMIT : ZR_ENOMEM;
  }
  for (int y = 0; y < g.height; y++) {
    const unsigned char *row = g.indices + (size_t)y * (size_t)g.width;
    size_t k = (size_t)y * (size_t)width;
    for (int x = 0; x < width; x++)
      put_code(out, k + (size_t)x,
               pot ? colour_code(row[x], row[x + width]) : row[x]);
  }
  free(g.indices);
  return ZR_OK;
}

zr_status zr__image_decode_height_codes(zr_context *ctx, const char *path,
                                        bool pot, const char *bytes,
                                        size_t size, zr_arena *arena,
                                        zr_height_codes *out) {
  zr_status s;
  memset(out, 0, sizeof *out);
  static const unsigned char png_sig[8] = {0x89, 'P', 'N', 'G',
                                           '\r', '\n', 0x1a, '\n'};
  const unsigned char *b = (const unsigned char *)bytes;
  bool gif = size >= 6 && (!memcmp(b, "GIF87a", 6) ||
                           !memcmp(b, "GIF89a", 6));
  if (pot && !gif)
    s = zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL,
                 "%s: not a POT file (a POT file is a GIF file)", path);
  else if (gif)
    s = read_gif(ctx, path, b, size, pot, arena, out);
  else if (size >= 8 && !memcmp(b, png_sig, 8))
    s = read_png(ctx, path, b, size, arena, out);
  else if (size >= 3 && b[0] == 0xff && b[1] == 0xd8 && b[2] == 0xff)
    s = read_coded(ctx, path, b, size, true, arena, out);
  else if (size >= 2 && b[0] == 'B' && b[1] == 'M')
    s = read_decoded(ctx, path, b, size, false, arena, out);
  else if (size >= 4 && (!memcmp(b, "II*\0", 4) || !memcmp(b, "MM\0*", 4)))
    s = read_decoded(ctx, path, b, size, true, arena, out);
  else if (!(size >= 2 && b[0] == 'P') && zr__tga_looks_like(b, size))
    s = read_tga(ctx, path, b, size, arena, out);
  else
    s = read_coded(ctx, path, b, size, false, arena, out);
  if (s != ZR_OK)
    memset(out, 0, sizeof *out);
  return s;
}

double zr__height_code_value(const zr_height_codes *c, size_t k) {
  return c->bits == 8 ? ((const uint8_t *)c->codes)[k] / 255.0
                      : ((const uint16_t *)c->codes)[k] / 65535.0;
}

zr_status zr__image_decode_heights(zr_context *ctx, const char *path,
                                   bool pot, const char *bytes, size_t size,
                                   float **heights, int *width,
                                   int *height) {
  *heights = NULL;
  zr_arena arena;
  zr__arena_init(&arena);
  arena.budget = ctx ? ctx->budget : NULL;
  zr_height_codes c;
  zr_status s = zr__image_decode_height_codes(ctx, path, pot, bytes, size,
                                              &arena, &c);
  if (s == ZR_OK) {
    size_t n = (size_t)c.width * (size_t)c.height;
    *heights = malloc(n * sizeof **heights);
    if (!*heights) {
      s = zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "%s: %s", path,
                   zr_status_str(ZR_ENOMEM));
    } else {
      for (size_t k = 0; k < n; k++)
        (*heights)[k] = (float)zr__height_code_value(&c, k);
      *width = c.width;
      *height = c.height;
    }
  }
  zr__arena_free(&arena);
  return s;
}

zr_status zr__image_read_heights(zr_context *ctx, const char *path, bool pot,
                                 float **heights, int *width,
                                 int *height) {
  *heights = NULL;
  char *bytes = NULL;
  size_t size = 0;
  zr_status s = zr__image_read_bytes(ctx, path, &bytes, &size);
  if (s != ZR_OK)
    return s;
  s = zr__image_decode_heights(ctx, path, pot, bytes, size, heights, width,
                               height);
  free(bytes);
  return s;
}
