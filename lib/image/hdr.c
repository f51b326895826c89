/*
 * hdr.c - Radiance HDR (RGBE) files, read and written: POV-Ray's +FH
 * and the "hdr" image type (POV-Ray 3.7 reference, "Output File Type"
 * and "Image Maps").
 *
 * The format is Greg Ward's, from "Real Pixels" (Graphics Gems II, 1991)
 * and the Radiance reference manual's file formats chapter:
 *   - a header of text lines, the first "#?RADIANCE" (or "#?" and any
 *     program name), variables such as FORMAT=32-bit_rle_rgbe, ended by
 *     an empty line;
 *   - a resolution line, "-Y height +X width" for the usual top-down,
 *     left-to-right order ("+Y" is bottom-up; other orders are refused);
 *   - the scanlines, four bytes a pixel: red, green and blue mantissas
 *     and a shared exponent; the value is (m + 0.5) * 2^(e - 136), and
 *     e = 0 is black.  A scanline of 8 to 32767 pixels may be run-length
 *     encoded by component: it starts 2, 2, width high, width low, then
 *     each of the four components is packets of a count byte, above 128
 *     a run of count - 128 copies of the next byte, else count literal
 *     bytes.  Older files repeat the previous pixel by 1, 1, 1, n (n
 *     shifted by 8 more bits for each repeat code in a row).
 * XYZE files are refused by name; EXPOSURE is not applied (the values
 * are taken as stored, as most readers do).
 *
 * Writing stores linear light (image.c) with the component run-length
 * encoding when the width allows it: runs of 4 or more bytes, literal
 * packets between them.
 */
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "core/context.h"
#include "image/image.h"

/* The header may not run on for ever in a damaged file. */
enum { MAX_HEADER = 1 << 16, MIN_RUN = 4 };

bool zr__hdr_looks_like(const unsigned char *b, size_t n) {
  return n >= 2 && b[0] == '#' && b[1] == '?';
}

static zr_status bad(zr_context *ctx, const char *name, const char *why) {
  return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL, "%s: %s", name, why);
}

static void rgbe_to_float(const unsigned char *p, float *rgb) {
  if (p[3] == 0) {
    rgb[0] = rgb[1] = rgb[2] = 0.0f;
    return;
  }
  double f = ldexp(1.0, (int)p[3] - (128 + 8));
  for (int c = 0; c < 3; c++)
    rgb[c] = (float)((p[c] + 0.5) * f);
}

/* Reads one line of the header into line (NUL-terminated, no newline);
   false at the end of the bytes. */
static bool header_line(const unsigned char *b, size_t n, size_t *pos,
                        char *line, size_t cap) {
  size_t k = 0;
  while (*pos < n && b[*pos] != '\n') {
    if (k + 1 < cap)
      line[k++] = (char)b[*pos];
    (*pos)++;
  }
  line[k] = '\0';
  if (*pos >= n)
    return false;
  (*pos)++; /* the newline */
  return true;
}

/* One scanline of width pixels into rgbe (4 bytes a pixel). */
static bool read_scanline(const unsigned char *b, size_t n, size_t *pos,
                          int width, unsigned char *rgbe) {
  if (width >= 8 && width < 32768 && n - *pos >= 4 && b[*pos] == 2 &&
      b[*pos + 1] == 2 && !(b[*pos + 2] & 0x80)) {
    if (((int)b[*pos + 2] << 8 | b[*pos + 3]) != width)
      return false;
    *pos += 4;
    for (int c = 0; c < 4; c++) {
      int x = 0;
      while (x < width) {
        if (*pos >= n)
          return false;
        unsigned count = b[(*pos)++];
        if (count > 128) {
          count -= 128;
          if (*pos >= n || count > (unsigned)(width - x))
            return false;
          unsigned char v = b[(*pos)++];
          for (unsigned i = 0; i < count; i++)
            rgbe[4 * (size_t)x++ + c] = v;
        } else {
          if (count == 0 || count > (unsigned)(width - x) ||
              count > n - *pos)
            return false;
          for (unsigned i = 0; i < count; i++)
            rgbe[4 * (size_t)x++ + c] = b[(*pos)++];
        }
      }
    }
    return true;
  }
  /* Flat pixels, with the old repeat codes. */
  int x = 0, shift = 0;
  while (x < width) {
    if (n - *pos < 4)
      return false;
    const unsigned char *p = b + *pos;
    *pos += 4;
    if (p[0] == 1 && p[1] == 1 && p[2] == 1) {
      if (x == 0 || shift > 16)
        return false;
      size_t repeat = (size_t)p[3] << shift;
      if (repeat > (size_t)(width - x))
        return false;
      for (size_t i = 0; i < repeat; i++, x++)
        memcpy(rgbe + 4 * (size_t)x, rgbe + 4 * (size_t)(x - 1), 4);
      shift += 8;
    } else {
      memcpy(rgbe + 4 * (size_t)x++, p, 4);
      shift = 0;
    }
  }
  return true;
}

zr_status zr__hdr_decode(zr_context *ctx, const char *name,
                         const unsigned char *b, size_t n, zr_image **out) {
  *out = NULL;
  size_t pos = 0;
  char line[256];
  if (!zr__hdr_looks_like(b, n))
    return bad(ctx, name, "not a Radiance HDR file");
  for (;;) {
    if (pos > MAX_HEADER || !header_line(b, n, &pos, line, sizeof line))
      return bad(ctx, name, "truncated Radiance HDR file (header)");
    if (!line[0])
      break;
    if (!strncmp(line, "FORMAT=", 7) &&
        strcmp(line + 7, "32-bit_rle_rgbe") != 0)
      return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EUNSUPPORTED, NULL,
                      "%s: Radiance files of FORMAT=%.40s are not "
                      "supported (32-bit_rle_rgbe is)", name, line + 7);
  }
  if (!header_line(b, n, &pos, line, sizeof line))
    return bad(ctx, name, "truncated Radiance HDR file (resolution)");
  char ysign, xsign;
  int height, width, used = 0;
  if (sscanf(line, "%cY %d %cX %d%n", &ysign, &height, &xsign, &width,
             &used) != 4 ||
      line[used] != '\0' || (ysign != '-' && ysign != '+') || xsign != '+')
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EUNSUPPORTED, NULL,
                    "%s: Radiance resolution line '%.40s' is not supported "
                    "(-Y height +X width is)", name, line);
  zr_image *image = NULL;
  zr_status s = zr__image_new_named(ctx, name, width, height, &image);
  if (s != ZR_OK)
    return s;
  unsigned char *rgbe = malloc((size_t)width * 4);
  if (!rgbe) {
    zr_image_free(image);
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "%s: %s", name,
                    zr_status_str(ZR_ENOMEM));
  }
  for (int row = 0; row < height; row++) {
    if (!read_scanline(b, n, &pos, width, rgbe)) {
      free(rgbe);
      zr_image_free(image);
      return bad(ctx, name, pos >= n ? "truncated Radiance HDR file "
                                       "(pixels)"
                                     : "damaged Radiance HDR file (a "
                                       "scanline's runs)");
    }
    int y = ysign == '-' ? row : height - 1 - row;
    float *dst = image->pixels + (size_t)y * width * 3;
    for (int x = 0; x < width; x++)
      rgbe_to_float(rgbe + 4 * (size_t)x, dst + 3 * (size_t)x);
  }
  free(rgbe);
  *out = image;
  return ZR_OK;
}

/* ---- writing ---- */

static void float_to_rgbe(const float *rgb, double assumed_gamma,
                          unsigned char *p) {
  float v[3];
  for (int c = 0; c < 3; c++)
    v[c] = zr__linear_sample(rgb[c], assumed_gamma);
  float top = v[0] > v[1] ? v[0] : v[1];
  top = top > v[2] ? top : v[2];
  if (!(top > 1e-32f)) {
    memset(p, 0, 4);
    return;
  }
  int e;
  double scale = frexp(top, &e) * 256.0 / top; /* top -> [128, 256) */
  if (e > 127) { /* beyond RGBE's range: the largest value */
    memset(p, 255, 4);
    return;
  }
  for (int c = 0; c < 3; c++)
    p[c] = (unsigned char)(v[c] * scale);
  p[3] = (unsigned char)(e + 128);
}

/* One component of a scanline (stride 4) as runs and literal packets. */
static void write_component(const unsigned char *rgbe, int width, int c,
                            FILE *f) {
  int x = 0;
  while (x < width) {
    /* Find the next run of MIN_RUN or more equal bytes. */
    int run_start = x, run = 0;
    while (run_start < width) {
      run = 1;
      while (run_start + run < width && run < 127 &&
             rgbe[4 * (size_t)(run_start + run) + c] ==
                 rgbe[4 * (size_t)run_start + c])
        run++;
      if (run >= MIN_RUN)
        break;
      run_start += run;
    }
    if (run_start >= width)
      run = 0;
    /* Literal bytes up to the run, in packets of at most 128. */
    while (x < run_start) {
      int count = run_start - x > 128 ? 128 : run_start - x;
      fputc(count, f);
      for (int i = 0; i < count; i++)
        fputc(rgbe[4 * (size_t)(x + i) + c], f);
      x += count;
    }
    if (run >= MIN_RUN) {
      fputc(128 + run, f);
      fputc(rgbe[4 * (size_t)run_start + c], f);
      x += run;
    }
  }
}

zr_status zr__hdr_encode(zr_context *ctx, const char *name,
                         const zr_image *image, const zr_image_encoding *e,
                         FILE *f) {
  int w = image->width, h = image->height;
  unsigned char *rgbe = malloc((size_t)w * 4);
  if (!rgbe)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "%s: %s", name,
                    zr_status_str(ZR_ENOMEM));
  fprintf(f, "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\nSOFTWARE=zRcube\n\n"
             "-Y %d +X %d\n", h, w);
  bool rle = w >= 8 && w < 32768;
  for (int y = 0; y < h; y++) {
    const float *src = image->pixels + (size_t)y * w * 3;
    for (int x = 0; x < w; x++)
      float_to_rgbe(src + 3 * (size_t)x, e->assumed_gamma,
                    rgbe + 4 * (size_t)x);
    if (!rle) {
      fwrite(rgbe, 4, (size_t)w, f);
      continue;
    }
    unsigned char start[4] = {2, 2, (unsigned char)(w >> 8),
                              (unsigned char)(w & 0xff)};
    fwrite(start, 1, 4, f);
    for (int c = 0; c < 4; c++)
      write_component(rgbe, w, c, f);
  }
  free(rgbe);
  return ZR_OK;
}
