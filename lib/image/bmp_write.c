/*
 * bmp_write.c - writing Windows bitmap (BMP) files: POV-Ray's +FB.
 *
 * The layout is Microsoft's documented one, and the header fields are
 * those povray 3.7 writes (measured: `povray +FB` of a 5 x 3 scene;
 * tests/test_formats_povray.sh compares the headers): a 14-byte
 * BITMAPFILEHEADER ("BM", the file size, two reserved zero words, pixel
 * offset 54), a 40-byte BITMAPINFOHEADER (width, positive height: rows
 * bottom to top, one plane, 24 bits a pixel, or 32 with an alpha channel
 * (+UA), compression 0, the size of the pixels, resolution 0, no colour
 * table), then the rows, blue, green, red[, alpha], each padded to four
 * bytes with zeros.  Colours get the sRGB encoding every 8-bit format
 * here gets (image.c) and stay unmultiplied by alpha, as in povray's
 * 32-bit BMP.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/context.h"
#include "image/image.h"

static void put16(unsigned char *p, unsigned v) {
  p[0] = (unsigned char)(v & 0xff);
  p[1] = (unsigned char)(v >> 8 & 0xff);
}

static void put32(unsigned char *p, uint32_t v) {
  for (int i = 0; i < 4; i++)
    p[i] = (unsigned char)(v >> (8 * i) & 0xff);
}

zr_status zr__bmp_encode(zr_context *ctx, const char *name,
                         const zr_image *image, const zr_image_encoding *e,
                         FILE *f) {
  int alpha = e->alpha && image->alpha;
  size_t channels = alpha ? 4 : 3;
  size_t row_bytes = ((size_t)image->width * channels + 3) & ~(size_t)3;
  uint64_t pixel_bytes = (uint64_t)row_bytes * (uint64_t)image->height;
  if (pixel_bytes + 54 > UINT32_MAX)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ELIMIT, NULL,
                    "%s: a BMP file holds at most 4 GiB of pixels", name);
  unsigned char header[54] = {0};
  header[0] = 'B';
  header[1] = 'M';
  put32(header + 2, (uint32_t)(pixel_bytes + 54));
  put32(header + 10, 54);
  put32(header + 14, 40);
  put32(header + 18, (uint32_t)image->width);
  put32(header + 22, (uint32_t)image->height);
  put16(header + 26, 1);
  put16(header + 28, (unsigned)(channels * 8));
  put32(header + 34, (uint32_t)pixel_bytes);
  unsigned char *row = calloc(row_bytes, 1);
  if (!row)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "%s: %s", name,
                    zr_status_str(ZR_ENOMEM));
  fwrite(header, 1, sizeof header, f);
  double g = e->assumed_gamma, fg = e->file_gamma;
  for (int y = image->height - 1; y >= 0; y--) {
    const float *src = image->pixels + (size_t)y * image->width * 3;
    for (int x = 0; x < image->width; x++) {
      unsigned char *px = row + (size_t)x * channels;
      px[0] = (unsigned char)zr__encode_code(src[3 * x + 2], g, fg, 255);
      px[1] = (unsigned char)zr__encode_code(src[3 * x + 1], g, fg, 255);
      px[2] = (unsigned char)zr__encode_code(src[3 * x], g, fg, 255);
      if (alpha) /* coverage, stored linearly */
        px[3] = (unsigned char)zr__encode_linear(
            image->alpha[(size_t)y * image->width + x], 255);
    }
    fwrite(row, 1, row_bytes, f);
  }
  free(row);
  return ZR_OK; /* write errors: the caller checks the stream */
}
