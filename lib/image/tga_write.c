/*
 * tga_write.c - writing Truevision TGA files (Truevision TGA File Format
 * Specification 2.0, 1989): POV-Ray's +FT (uncompressed, image type 2)
 * and +FC (run-length encoded, type 10), 24 bits a pixel, or 32 with an
 * alpha channel (+UA; POV-Ray 3.7 reference, "Output File Type": "Targa
 * format also allows 8 bits of alpha transparency data").
 *
 * Pixels are stored blue, green, red[, alpha] from the top row down
 * (descriptor bit 5), with the sRGB encoding every 8-bit format here
 * gets (image.c).  The descriptor's low four bits give the alpha bits.
 * Run-length packets never cross a row, as the specification advises:
 * a header byte whose top bit says run (one pixel repeated) or raw and
 * whose low 7 bits + 1 count the pixels (1 to 128).
 */
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "core/context.h"
#include "image/image.h"

enum { MAX_PACKET = 128 };

/* The stored bytes of one row: channels (3 or 4) bytes a pixel. */
static void encode_row(const zr_image *image, int y, size_t channels,
                       const zr_image_encoding *e, unsigned char *row) {
  const float *src = image->pixels + (size_t)y * image->width * 3;
  double g = e->assumed_gamma, fg = e->file_gamma;
  for (int x = 0; x < image->width; x++) {
    unsigned char *px = row + (size_t)x * channels;
    px[0] = (unsigned char)zr__encode_code(src[3 * x + 2], g, fg, 255);
    px[1] = (unsigned char)zr__encode_code(src[3 * x + 1], g, fg, 255);
    px[2] = (unsigned char)zr__encode_code(src[3 * x], g, fg, 255);
    if (channels == 4) /* alpha is linear coverage, not a colour */
      px[3] = (unsigned char)zr__encode_linear(
          image->alpha[(size_t)y * image->width + x], 255);
  }
}

/* How many pixels from x on repeat the pixel at x (1 .. MAX_PACKET). */
static int run_length(const unsigned char *row, int x, int width,
                      size_t channels) {
  int n = 1;
  while (x + n < width && n < MAX_PACKET &&
         !memcmp(row + (size_t)x * channels, row + (size_t)(x + n) * channels,
                 channels))
    n++;
  return n;
}

static void write_rle_row(const unsigned char *row, int width,
                          size_t channels, FILE *f) {
  int x = 0;
  while (x < width) {
    int run = run_length(row, x, width, channels);
    if (run >= 2) {
      fputc(0x80 | (run - 1), f);
      fwrite(row + (size_t)x * channels, 1, channels, f);
      x += run;
      continue;
    }
    /* A raw packet up to the next run of two or more, or 128 pixels. */
    int start = x, count = 0;
    while (x < width && count < MAX_PACKET &&
           (x + 1 >= width || run_length(row, x, width, channels) < 2)) {
      x++;
      count++;
    }
    if (count == 0) { /* the loop met a run at once: take one pixel */
      x++;
      count = 1;
    }
    fputc(count - 1, f);
    fwrite(row + (size_t)start * channels, 1, (size_t)count * channels, f);
  }
}

zr_status zr__tga_encode(zr_context *ctx, const char *name,
                         const zr_image *image, const zr_image_encoding *e,
                         FILE *f) {
  if (image->width > 65535 || image->height > 65535)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ELIMIT, NULL,
                    "%s: TGA files hold at most 65535 x 65535 pixels", name);
  bool rle = e->format == ZR_FORMAT_TGA_RLE;
  bool alpha = e->alpha && image->alpha;
  size_t channels = alpha ? 4 : 3;
  unsigned char header[18] = {0};
  header[2] = rle ? 10 : 2; /* true colour, compressed or not */
  header[12] = (unsigned char)(image->width & 0xff);
  header[13] = (unsigned char)(image->width >> 8);
  header[14] = (unsigned char)(image->height & 0xff);
  header[15] = (unsigned char)(image->height >> 8);
  header[16] = (unsigned char)(channels * 8);
  header[17] = (unsigned char)(0x20 | (alpha ? 8 : 0)); /* top row first */
  unsigned char *row = malloc((size_t)image->width * channels);
  if (!row)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "%s: %s", name,
                    zr_status_str(ZR_ENOMEM));
  fwrite(header, 1, sizeof header, f);
  for (int y = 0; y < image->height; y++) {
    encode_row(image, y, channels, e, row);
    if (rle)
      write_rle_row(row, image->width, channels, f);
    else
      fwrite(row, 1, (size_t)image->width * channels, f);
  }
  free(row);
  return ZR_OK; /* write errors: the caller checks the stream */
}
