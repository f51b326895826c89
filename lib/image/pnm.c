/*
 * pnm.c - Netpbm grey and colour maps (PGM/PPM: P2, P3, P5, P6) and the
 * Portable Float Map (PFM), read from memory and written to a stream.
 *
 * PPM/PGM follow the Netpbm format pages: a header of whitespace-separated
 * ASCII fields with '#' comments, then exactly one whitespace character
 * and the raster; maxval may be 1 to 65535, and above 255 a binary sample
 * is two bytes, most significant first.  Integer samples are decoded as
 * sRGB (the Netpbm page names BT.709, but sRGB is what every program that
 * writes PPM means in practice, POV-Ray included).  Only one image of a
 * multi-image file is read.  Bitmaps (P1, P4) and PAM (P7) are refused.
 *
 * PFM is the format of Debevec's HDRShop: "PF" (RGB) or "Pf" (grey), the
 * size, then a scale whose sign gives the byte order (negative: little
 * endian) and whose magnitude we ignore, as most programs do; then
 * IEEE-754 floats, rows bottom to top.  We write little endian, "-1.0".
 * PFM values are linear and pass untouched both ways, so a round trip is
 * exact.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/context.h"
#include "image/image.h"

/* A read position in a memory file. */
typedef struct cursor {
  const unsigned char *p;
  const unsigned char *end;
} cursor;

static int is_space(int c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' ||
         c == '\f';
}

/* Skips whitespace and comments; returns 0 at the end of the data. */
static int skip_blanks(cursor *c) {
  while (c->p < c->end) {
    if (is_space(*c->p)) {
      c->p++;
    } else if (*c->p == '#') {
      while (c->p < c->end && *c->p != '\n' && *c->p != '\r')
        c->p++;
    } else {
      return 1;
    }
  }
  return 0;
}

/*
 * Reads an unsigned decimal field.  Returns 1 on success, 0 at the end of
 * the data (truncated) and -1 for anything else (malformed).
 */
static int read_uint(cursor *c, unsigned long limit, unsigned long *out) {
  if (!skip_blanks(c))
    return 0;
  if (*c->p < '0' || *c->p > '9')
    return -1;
  unsigned long v = 0;
  while (c->p < c->end && *c->p >= '0' && *c->p <= '9') {
    v = v * 10 + (unsigned long)(*c->p - '0');
    if (v > limit)
      return -1;
    c->p++;
  }
  if (c->p < c->end && !is_space(*c->p) && *c->p != '#')
    return -1;
  *out = v;
  return 1;
}

static zr_status truncated(zr_context *ctx, const char *name,
                           const char *kind) {
  return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL,
                  "%s: truncated %s file", name, kind);
}

static zr_status malformed(zr_context *ctx, const char *name,
                           const char *kind, const char *what) {
  return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL,
                  "%s: invalid %s file: %s", name, kind, what);
}

/* Reads one header field, with the message for each way it can fail. */
static zr_status header_field(zr_context *ctx, const char *name,
                              const char *kind, cursor *c,
                              unsigned long limit, const char *what,
                              unsigned long *out) {
  int r = read_uint(c, limit, out);
  if (r == 0)
    return truncated(ctx, name, kind);
  if (r < 0 || *out == 0)
    return malformed(ctx, name, kind, what);
  return ZR_OK;
}

/* Reads the i-th sample of a binary raster (1 or 2 bytes big endian). */
static unsigned binary_sample(const unsigned char *raster, size_t i,
                              int wide) {
  if (wide)
    return ((unsigned)raster[2 * i] << 8) | raster[2 * i + 1];
  return raster[i];
}

static zr_status read_samples(zr_context *ctx, const char *name,
                              cursor *c, int binary, unsigned maxval,
                              size_t count, zr_image *image) {
  if (binary) {
    int wide = maxval > 255;
    size_t need = count * (wide ? 2 : 1);
    if ((size_t)(c->end - c->p) < need)
      return truncated(ctx, name, "PPM");
    for (size_t i = 0; i < count; i++) {
      unsigned v = binary_sample(c->p, i, wide);
      if (v > maxval)
        return malformed(ctx, name, "PPM", "sample larger than maxval");
      zr__image_set_code(image, i, v);
    }
    c->p += need;
  } else {
    for (size_t i = 0; i < count; i++) {
      unsigned long v;
      int r = read_uint(c, 65535, &v);
      if (r == 0)
        return truncated(ctx, name, "PPM");
      if (r < 0)
        return malformed(ctx, name, "PPM", "bad sample");
      if (v > maxval)
        return malformed(ctx, name, "PPM", "sample larger than maxval");
      zr__image_set_code(image, i, (unsigned)v);
    }
  }
  return ZR_OK;
}

zr_status zr__pnm_decode(zr_context *ctx, const char *name,
                         const unsigned char *bytes, size_t size,
                         zr_image **out) {
  char type = (char)bytes[1];
  if (type == '1' || type == '4' || type == '7')
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EUNSUPPORTED, NULL,
                    "%s: Netpbm type P%c is not supported (use P2, P3, P5 "
                    "or P6)",
                    name, type);
  int channels = (type == '3' || type == '6') ? 3 : 1;
  int binary = type == '5' || type == '6';
  cursor c = {bytes + 2, bytes + size};
  unsigned long w, h, maxval;
  zr_status s;
  if ((s = header_field(ctx, name, "PPM", &c, ZR_IMAGE_MAX_SIDE * 2ul,
                        "bad width", &w)) != ZR_OK ||
      (s = header_field(ctx, name, "PPM", &c, ZR_IMAGE_MAX_SIDE * 2ul,
                        "bad height", &h)) != ZR_OK ||
      (s = header_field(ctx, name, "PPM", &c, 65535, "bad maxval",
                        &maxval)) != ZR_OK)
    return s;
  /* Exactly one whitespace character separates the header and raster. */
  if (c.p >= c.end)
    return truncated(ctx, name, "PPM");
  c.p++;
  zr_image *image;
  if ((s = zr__image_new_coded(
           ctx, name, (int)w, (int)h,
           channels == 3 ? ZR_LAYOUT_RGB : ZR_LAYOUT_GREY, (unsigned)maxval,
           ZR_TRANSFER_SRGB, 0.0, 0, &image)) != ZR_OK)
    return s;
  size_t count = (size_t)w * h * (size_t)channels;
  s = read_samples(ctx, name, &c, binary, (unsigned)maxval, count, image);
  image->codes_working = true;
  if (s == ZR_OK)
    *out = image;
  else
    zr_image_free(image);
  return s;
}

/* ---- PFM ---- */

static float float_from_bytes(const unsigned char *b, int little) {
  uint32_t u = little ? (uint32_t)b[0] | (uint32_t)b[1] << 8 |
                            (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24
                      : (uint32_t)b[3] | (uint32_t)b[2] << 8 |
                            (uint32_t)b[1] << 16 | (uint32_t)b[0] << 24;
  float f;
  memcpy(&f, &u, sizeof f);
  return f;
}

/* Reads the scale field: a decimal number ending in whitespace. */
static int read_scale(cursor *c, double *out) {
  if (!skip_blanks(c))
    return 0;
  char text[64];
  size_t n = 0;
  while (c->p < c->end && !is_space(*c->p) && n + 1 < sizeof text)
    text[n++] = (char)*c->p++;
  if (c->p >= c->end)
    return 0;
  text[n] = '\0';
  char *end;
  *out = strtod(text, &end);
  return *end == '\0' && n > 0 && isfinite(*out) ? 1 : -1;
}

zr_status zr__pfm_decode(zr_context *ctx, const char *name,
                         const unsigned char *bytes, size_t size,
                         zr_image **out) {
  int channels = bytes[1] == 'F' ? 3 : 1;
  cursor c = {bytes + 2, bytes + size};
  if (c.p < c.end && !is_space(*c.p))
    return malformed(ctx, name, "PFM", "bad magic number");
  unsigned long w, h;
  zr_status s;
  if ((s = header_field(ctx, name, "PFM", &c, ZR_IMAGE_MAX_SIDE * 2ul,
                        "bad width", &w)) != ZR_OK ||
      (s = header_field(ctx, name, "PFM", &c, ZR_IMAGE_MAX_SIDE * 2ul,
                        "bad height", &h)) != ZR_OK)
    return s;
  double scale;
  int r = read_scale(&c, &scale);
  if (r == 0)
    return truncated(ctx, name, "PFM");
  if (r < 0 || scale == 0.0)
    return malformed(ctx, name, "PFM", "bad scale");
  c.p++; /* the one whitespace character before the raster */
  zr_image *image;
  if ((s = zr__image_new_named(ctx, name, (int)w, (int)h, &image)) != ZR_OK)
    return s;
  size_t row_bytes = (size_t)w * (size_t)channels * 4;
  if ((size_t)(c.end - c.p) < row_bytes * h) {
    zr_image_free(image);
    return truncated(ctx, name, "PFM");
  }
  int little = scale < 0.0;
  for (size_t y = 0; y < h; y++) {
    /* The file's first row is the bottom of the picture. */
    const unsigned char *src = c.p + (h - 1 - y) * row_bytes;
    float *dst = image->pixels + y * w * 3;
    for (size_t x = 0; x < w; x++)
      for (int k = 0; k < 3; k++)
        dst[3 * x + k] = float_from_bytes(
            src + 4 * (x * (size_t)channels + (channels == 3 ? k : 0)),
            little);
  }
  *out = image;
  return ZR_OK;
}

/* ---- writing ---- */

static zr_status write_failed(zr_context *ctx, const char *name) {
  return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EIO, NULL, "%s: write failed",
                  name);
}

zr_status zr__ppm_encode(zr_context *ctx, const char *name,
                         const zr_image *image, double assumed_gamma,
                         double file_gamma, FILE *stream) {
  size_t row_len = (size_t)image->width * 3;
  unsigned char *row = malloc(row_len);
  if (!row)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "%s: %s", name,
                    zr_status_str(ZR_ENOMEM));
  zr_encoder8 enc;
  zr__encoder8_init(&enc, assumed_gamma, file_gamma);
  int ok = fprintf(stream, "P6\n%d %d\n255\n", image->width,
                   image->height) > 0;
  for (int y = 0; ok && y < image->height; y++) {
    const float *src = image->pixels + (size_t)y * row_len;
    for (size_t i = 0; i < row_len; i++)
      row[i] = (unsigned char)zr__encoder8_code(&enc, src[i]);
    ok = fwrite(row, 1, row_len, stream) == row_len;
  }
  free(row);
  return ok ? ZR_OK : write_failed(ctx, name);
}

zr_status zr__pfm_encode(zr_context *ctx, const char *name,
                         const zr_image *image, FILE *stream) {
  size_t row_len = (size_t)image->width * 3;
  unsigned char *row = malloc(row_len * 4);
  if (!row)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "%s: %s", name,
                    zr_status_str(ZR_ENOMEM));
  int ok = fprintf(stream, "PF\n%d %d\n-1.0\n", image->width,
                   image->height) > 0;
  for (int y = image->height - 1; ok && y >= 0; y--) {
    const float *src = image->pixels + (size_t)y * row_len;
    for (size_t i = 0; i < row_len; i++) {
      uint32_t u;
      memcpy(&u, &src[i], sizeof u);
      for (int b = 0; b < 4; b++)
        row[4 * i + (size_t)b] = (unsigned char)(u >> (8 * b));
    }
    ok = fwrite(row, 1, row_len * 4, stream) == row_len * 4;
  }
  free(row);
  return ok ? ZR_OK : write_failed(ctx, name);
}
