/*
 * bmp.c - Windows and OS/2 bitmap (BMP) files read from memory, for the
 * "bmp" image type of image maps (POV-Ray 3.7 reference, "Image Maps").
 *
 * The layout is Microsoft's documented one (BITMAPFILEHEADER, then
 * BITMAPCOREHEADER of 12 bytes or BITMAPINFOHEADER of 40 and its
 * V2/V3/V4/V5 extensions of 52, 56, 108 and 124 bytes):
 *   - the file header: "BM", file size, two reserved words, and the
 *     offset of the pixels;
 *   - the info header: width, height (negative: rows top to bottom,
 *     else bottom to top), planes, bits a pixel (1, 4, 8 with a colour
 *     table; 16, 24, 32 direct), compression (0 none, 1 RLE8, 2 RLE4,
 *     3 bit fields), then the number of colours used;
 *   - for bit fields, three masks of red, green and blue after a 40-byte
 *     header (or inside the larger ones); 16 bits default to 5-5-5 and
 *     32 bits to 8-8-8;
 *   - the colour table of blue, green, red[, reserved] entries (three
 *     bytes each after a core header, else four);
 *   - rows padded to four bytes.
 * RLE8 and RLE4 are the documented escape codes: a count and a value
 * (for RLE4 two alternating indices), or 0 then 0 end of line, 1 end of
 * bitmap, 2 dx dy a jump, n >= 3 literal indices padded to a word.
 * Pixels a jump skips or a short stream leaves are index 0, as Windows
 * draws them.  Colours are sRGB, like every 8-bit format here.  A
 * 32-bit pixel's fourth byte (or, with bit fields in a header of 56
 * bytes or more, its alpha mask) is its straight alpha, as POV-Ray 3.7
 * reads it ("Using the Alpha Channel": "TGA and BMP 32-bit RGBA will use
 * straight alpha"; its renders take the byte as alpha even where every
 * one is 0, tests/test_image_alpha.sh).  Colour profiles are not read.
 * A colour-mapped image keeps its indices for image_map's per-index
 * filter and transmit.
 */
#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/context.h"
#include "image/image.h"

static unsigned le16(const unsigned char *p) {
  return (unsigned)p[0] | (unsigned)p[1] << 8;
}

static uint32_t le32(const unsigned char *p) {
  return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 |
         (uint32_t)p[3] << 24;
}

static zr_status bad(zr_context *ctx, const char *name, const char *why) {
  return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL, "%s: %s", name, why);
}

/* A colour channel of a bit-field pixel, scaled to 0 .. 255. */
typedef struct channel_mask {
  uint32_t mask;
  int shift, bits;
} channel_mask;

static channel_mask mask_of(uint32_t mask) {
  channel_mask m = {mask, 0, 0};
  if (!mask)
    return m;
  while (!(mask & 1)) {
    mask >>= 1;
    m.shift++;
  }
  while (mask & 1) {
    mask >>= 1;
    m.bits++;
  }
  return m;
}

static unsigned channel_value(uint32_t px, channel_mask m) {
  if (!m.bits)
    return 0;
  /* Scaled by the whole mask, not its lowest run of ones: a damaged
     file's mask with gaps must still give at most 255 (found by
     tests/fuzz/fuzz_image). */
  uint32_t v = (px & m.mask) >> m.shift;
  uint32_t top = m.mask >> m.shift;
  return (unsigned)((uint64_t)v * 255 / top);
}

/* Everything the header says. */
typedef struct bmp_info {
  int width, height;
  bool top_down;
  unsigned bits, compression;
  const unsigned char *palette;
  size_t palette_entries, entry_size;
  channel_mask masks[4]; /* red, green, blue, alpha (none: 16 bits) */
  size_t data;
} bmp_info;

static zr_status read_header(zr_context *ctx, const char *name,
                             const unsigned char *b, size_t n,
                             bmp_info *bi) {
  if (n < 26)
    return bad(ctx, name, "truncated BMP file (header)");
  uint32_t data = le32(b + 10), size = le32(b + 14);
  if (size == 12) {
    bi->width = (int)le16(b + 18);
    bi->height = (int)le16(b + 20);
    bi->bits = le16(b + 24);
    bi->compression = 0;
    bi->entry_size = 3;
  } else if (size >= 40 && size <= 124 && n >= 14 + (size_t)size) {
    int32_t w = (int32_t)le32(b + 18), h = (int32_t)le32(b + 22);
    if (w <= 0 || h == 0 || h == INT32_MIN)
      return bad(ctx, name, "damaged BMP file (size)");
    bi->width = (int)w;
    bi->top_down = h < 0;
    bi->height = (int)(h < 0 ? -h : h);
    bi->bits = le16(b + 28);
    bi->compression = le32(b + 30);
    bi->entry_size = 4;
  } else {
    return bad(ctx, name, "not a BMP file (or an unknown BMP header)");
  }
  unsigned bits = bi->bits;
  if (bits != 1 && bits != 4 && bits != 8 && bits != 16 && bits != 24 &&
      bits != 32)
    return bad(ctx, name, "damaged BMP file (bits per pixel)");
  unsigned comp = bi->compression;
  bool ok = comp == 0 || (comp == 1 && bits == 8) || (comp == 2 && bits == 4) ||
            (comp == 3 && (bits == 16 || bits == 32));
  if (!ok)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EUNSUPPORTED, NULL,
                    "%s: BMP compression %u with %u bits per pixel is not "
                    "supported (none, RLE8, RLE4 and bit fields are)",
                    name, comp, bits);
  size_t after = 14 + (size_t)size;
  if (comp == 3) {
    /* Masks follow a 40-byte header; larger headers hold them. */
    size_t at = 14 + 40;
    if (n < at + 12)
      return bad(ctx, name, "truncated BMP file (bit fields)");
    for (int c = 0; c < 3; c++)
      bi->masks[c] = mask_of(le32(b + at + 4 * (size_t)c));
    /* V3 and later headers hold an alpha mask after the three. */
    if (bits == 32 && size >= 56)
      bi->masks[3] = mask_of(le32(b + at + 12));
    if (size == 40)
      after += 12;
  } else if (bits == 16) {
    bi->masks[0] = mask_of(0x7c00);
    bi->masks[1] = mask_of(0x03e0);
    bi->masks[2] = mask_of(0x001f);
  } else if (bits == 32) {
    bi->masks[0] = mask_of(0x00ff0000);
    bi->masks[1] = mask_of(0x0000ff00);
    bi->masks[2] = mask_of(0x000000ff);
    bi->masks[3] = mask_of(0xff000000);
  }
  if (bits <= 8) {
    size_t used = size >= 40 ? le32(b + 46) : 0;
    size_t most = (size_t)1 << bits;
    bi->palette_entries = used == 0 || used > most ? most : used;
    if (after > n || bi->palette_entries * bi->entry_size > n - after) {
      /* Some writers declare more entries than they store: take those
         that fit before the pixels. */
      size_t room = data > after && data <= n ? (data - after) : 0;
      bi->palette_entries = room / bi->entry_size;
      if (bi->palette_entries == 0)
        return bad(ctx, name, "truncated BMP file (colour table)");
    }
    bi->palette = b + after;
  }
  if (data >= n)
    return bad(ctx, name, "truncated BMP file (pixels)");
  bi->data = data;
  return ZR_OK;
}

/* Reads RLE8 or RLE4 data into indices (rows as stored, bottom up). */
static bool decode_rle(const unsigned char *p, size_t n, const bmp_info *bi,
                       unsigned char *indices) {
  size_t w = (size_t)bi->width, h = (size_t)bi->height;
  size_t x = 0, y = 0, pos = 0;
  bool four = bi->compression == 2;
  while (pos + 1 < n) {
    unsigned count = p[pos], value = p[pos + 1];
    pos += 2;
    if (count > 0) {
      for (unsigned i = 0; i < count && x < w && y < h; i++, x++)
        indices[y * w + x] =
            (unsigned char)(four ? (i & 1 ? value & 15 : value >> 4) : value);
      continue;
    }
    if (value == 0) { /* end of line */
      x = 0;
      y++;
    } else if (value == 1) { /* end of bitmap */
      return true;
    } else if (value == 2) { /* jump */
      if (pos + 1 >= n)
        return false;
      x += p[pos];
      y += p[pos + 1];
      pos += 2;
    } else { /* literal run of value indices */
      size_t bytes = four ? (value + 1) / 2 : value;
      if (bytes > n - pos)
        return false;
      for (unsigned i = 0; i < value; i++, x++) {
        unsigned char v = four ? (unsigned char)(i & 1 ? p[pos + i / 2] & 15
                                                       : p[pos + i / 2] >> 4)
                               : p[pos + i];
        if (x < w && y < h)
          indices[y * w + x] = v;
      }
      pos += bytes + (bytes & 1); /* padded to a word */
    }
    if (y >= h)
      return true;
  }
  return true; /* a stream without its end code: the rest is index 0 */
}

/* The colour and alpha (0 .. 255 codes; alpha 255 without a mask) of
   stored pixel x of a direct row. */
static void direct_colour(const unsigned char *row, size_t x,
                          const bmp_info *bi, unsigned rgba[4]) {
  rgba[3] = 255;
  if (bi->bits == 24) {
    const unsigned char *p = row + 3 * x;
    rgba[0] = p[2];
    rgba[1] = p[1];
    rgba[2] = p[0];
    return;
  }
  uint32_t px = bi->bits == 16 ? le16(row + 2 * x) : le32(row + 4 * x);
  for (int c = 0; c < 3; c++)
    rgba[c] = channel_value(px, bi->masks[c]);
  if (bi->masks[3].bits)
    rgba[3] = channel_value(px, bi->masks[3]);
}

static unsigned packed_index(const unsigned char *row, size_t x,
                             unsigned bits) {
  if (bits == 8)
    return row[x];
  size_t bit = x * bits;
  unsigned byte = row[bit / 8];
  return (byte >> (8 - bits - bit % 8)) & ((1u << bits) - 1);
}

zr_status zr__bmp_decode(zr_context *ctx, const char *name,
                         const unsigned char *b, size_t n, zr_image **out) {
  *out = NULL;
  bmp_info bi;
  memset(&bi, 0, sizeof bi);
  zr_status s = read_header(ctx, name, b, n, &bi);
  if (s != ZR_OK)
    return s;
  size_t w = (size_t)bi.width, h = (size_t)bi.height;
  size_t stride = (w * bi.bits + 31) / 32 * 4;
  bool rle = bi.compression == 1 || bi.compression == 2;
  if (!rle && (h > (n - bi.data) / stride))
    return bad(ctx, name, "truncated BMP file (pixels)");
  zr_image *image = NULL;
  s = zr__image_new_named(ctx, name, bi.width, bi.height, &image);
  if (s != ZR_OK)
    return s;
  bool mapped = bi.bits <= 8;
  float *table = zr__decode_table(255, ZR_TRANSFER_SRGB, 0.0);
  image->codes = malloc(w * h * 3); /* 8-bit codes (image.h) */
  image->maxval = 255;
  unsigned char *rle_indices = rle ? calloc(w * h, 1) : NULL;
  if (mapped) {
    image->indices = malloc(w * h);
    image->palette_size = (int)bi.palette_entries;
  }
  bool alpha = !mapped && bi.masks[3].bits;
  if (!table || !image->codes || (mapped && !image->indices) ||
      (rle && !rle_indices) ||
      (alpha && zr_image_add_alpha(image) != ZR_OK)) {
    free(table);
    free(rle_indices);
    zr_image_free(image);
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "%s: %s", name,
                    zr_status_str(ZR_ENOMEM));
  }
  if (rle && !decode_rle(b + bi.data, n - bi.data, &bi, rle_indices)) {
    free(table);
    free(rle_indices);
    zr_image_free(image);
    return bad(ctx, name, "truncated BMP file (run-length data)");
  }
  size_t outside = 0;
  for (size_t r = 0; r < h; r++) { /* stored row r */
    size_t y = bi.top_down ? r : h - 1 - r;
    const unsigned char *row = rle ? NULL : b + bi.data + r * stride;
    for (size_t x = 0; x < w; x++) {
      unsigned rgb[4];
      size_t at = y * w + x;
      if (mapped) {
        unsigned k = rle ? rle_indices[r * w + x]
                         : packed_index(row, x, bi.bits);
        image->indices[at] = (unsigned char)k;
        if (k >= bi.palette_entries) {
          rgb[0] = rgb[1] = rgb[2] = 0;
          outside++;
        } else {
          const unsigned char *e = bi.palette + k * bi.entry_size;
          rgb[0] = e[2];
          rgb[1] = e[1];
          rgb[2] = e[0];
        }
      } else {
        direct_colour(row, x, &bi, rgb);
        if (alpha)
          image->alpha[at] = (float)(rgb[3] / 255.0);
      }
      for (int c = 0; c < 3; c++) {
        ((unsigned char *)image->codes)[3 * at + c] = (unsigned char)rgb[c];
        image->pixels[3 * at + c] = table[rgb[c]];
      }
    }
  }
  free(table);
  free(rle_indices);
  if (outside)
    zr__diag(ctx, ZR_DIAG_WARNING, ZR_EFORMAT, NULL,
             "%s: %zu pixel(s) with an index outside the colour table, "
             "read as black", name, outside);
  *out = image;
  return ZR_OK;
}
