/*
 * tga.c - Truevision TGA images (Truevision TGA File Format
 * Specification 2.0, 1989), read from memory.
 *
 * An 18-byte header (ID length, colour map type, image type, colour map
 * first entry, length and entry size, origin, width, height, pixel depth
 * and the descriptor byte, whose bit 4 says right to left and bit 5 top
 * to bottom), the image ID, the colour map, then the pixels:
 *   - type 1 colour-mapped (8 or 16-bit indices), 2 true colour (15, 16,
 *     24 or 32 bits: blue, green, red, [alpha], or a little-endian word
 *     with five bits each of red, green and blue), 3 grey (8 bits; 16
 *     bits grey and alpha),
 *   - types 9, 10 and 11 the same run-length encoded: packets whose
 *     header byte's top bit says run (one pixel, repeated) or raw, and
 *     whose low 7 bits + 1 count the pixels; packets may cross rows.
 * Colours are sRGB like every 8-bit format here; five-bit samples are
 * widened to eight (v * 255 / 31).  A 32-bit true colour pixel's
 * fourth byte is its straight alpha, whatever the descriptor's
 * attribute bits say, as POV-Ray 3.7 reads it ("Using the Alpha
 * Channel"; its renders take the byte as alpha even where the
 * descriptor says none or every byte is 0: tests/test_image_alpha.sh).
 * A colour-mapped image keeps
 * its indices (for image_map's per-index filter and transmit and for
 * height fields) when its map has at most 256 entries.  The footer and
 * extension area of version 2 files are ignored.
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

/* A colour (red, green, blue codes 0 .. 255) from depth bits at p. */
static void colour_of(const unsigned char *p, unsigned depth,
                      unsigned rgb[3]) {
  if (depth == 15 || depth == 16) {
    unsigned w = le16(p);
    rgb[0] = ((w >> 10) & 31) * 255 / 31;
    rgb[1] = ((w >> 5) & 31) * 255 / 31;
    rgb[2] = (w & 31) * 255 / 31;
  } else if (depth == 8) {
    rgb[0] = rgb[1] = rgb[2] = p[0];
  } else { /* 24, 32: blue, green, red, [alpha] */
    rgb[0] = p[2];
    rgb[1] = p[1];
    rgb[2] = p[0];
  }
}

static zr_status bad(zr_context *ctx, const char *name, const char *why) {
  return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL, "%s: %s", name, why);
}

bool zr__tga_looks_like(const unsigned char *b, size_t n) {
  if (n < 18)
    return false;
  unsigned cmap = b[1], type = b[2], depth = b[16];
  bool type_ok = type == 1 || type == 2 || type == 3 || type == 9 ||
                 type == 10 || type == 11;
  bool depth_ok = depth == 8 || depth == 15 || depth == 16 || depth == 24 ||
                  depth == 32;
  return cmap <= 1 && type_ok && depth_ok && le16(b + 12) > 0 &&
         le16(b + 14) > 0 && (b[17] & 0xC0) == 0;
}

zr_status zr__tga_decode(zr_context *ctx, const char *name,
                         const unsigned char *b, size_t n,
                         zr_image **out) {
  *out = NULL;
  if (!zr__tga_looks_like(b, n))
    return bad(ctx, name, "not a TGA file (or a kind of TGA that is not "
                          "read: types 1, 2, 3, 9, 10 and 11 are)");
  unsigned id_len = b[0], cmap_type = b[1], type = b[2];
  unsigned cmap_first = le16(b + 3), cmap_len = le16(b + 5);
  unsigned cmap_depth = b[7], depth = b[16], desc = b[17];
  int width = (int)le16(b + 12), height = (int)le16(b + 14);
  unsigned base = type & 7; /* 1 mapped, 2 true colour, 3 grey */
  if (base == 1 && (cmap_type != 1 || (depth != 8 && depth != 16)))
    return bad(ctx, name, "damaged TGA file (a colour-mapped image needs a "
                          "colour map and 8 or 16-bit indices)");
  if (base == 2 && depth == 8)
    return bad(ctx, name, "damaged TGA file (8-bit true colour)");
  if (base == 3 && depth != 8 && depth != 16)
    return bad(ctx, name, "damaged TGA file (grey pixels of 8 or 16 bits "
                          "only)");
  size_t pos = 18 + id_len;
  /* The image ID may claim more bytes than the file has: every later
     "bytes left" test computes n - pos, which must not wrap. */
  if (pos > n)
    return bad(ctx, name, "truncated TGA file (image ID)");
  const unsigned char *cmap = NULL;
  size_t cmap_bytes = (cmap_depth + 7) / 8;
  if (cmap_type == 1) {
    if (cmap_depth != 15 && cmap_depth != 16 && cmap_depth != 24 &&
        cmap_depth != 32)
      return bad(ctx, name, "damaged TGA file (colour map entry size)");
    if (pos > n || (size_t)cmap_len * cmap_bytes > n - pos)
      return bad(ctx, name, "truncated TGA file (colour map)");
    cmap = b + pos;
    pos += (size_t)cmap_len * cmap_bytes;
  }
  /* A colour map of at most 256 entries keeps its indices; grey stays
     one sample a pixel (image.h). */
  size_t count = (size_t)width * (size_t)height;
  bool keep_indices = base == 1 && cmap_first + cmap_len <= 256;
  zr_image *image = NULL;
  zr_status s = zr__image_new_coded(
      ctx, name, width, height,
      keep_indices ? ZR_LAYOUT_INDEX
                   : base == 3 ? ZR_LAYOUT_GREY : ZR_LAYOUT_RGB,
      255, ZR_TRANSFER_SRGB, 0.0, 0, &image);
  if (s != ZR_OK)
    return s;
  image->stored_codes = true;
  bool alpha = base == 2 && depth == 32;
  if (alpha && zr_image_add_alpha(image) != ZR_OK) {
    zr_image_free(image);
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "%s: %s", name,
                    zr_status_str(ZR_ENOMEM));
  }
  if (keep_indices) {
    image->palette_size = (int)(cmap_first + cmap_len);
    for (unsigned k = cmap_first; k < cmap_first + cmap_len; k++) {
      unsigned rgb[3];
      colour_of(cmap + (size_t)(k - cmap_first) * cmap_bytes, cmap_depth,
                rgb);
      for (int ch = 0; ch < 3; ch++)
        image->palette[3 * k + ch] = (unsigned short)rgb[ch];
    }
  }
  const size_t px_bytes = (depth + 7) / 8;
  bool rle = type >= 9;
  bool top_down = (desc & 0x20) != 0, right_left = (desc & 0x10) != 0;
  size_t outside = 0, run_left = 0, done = 0;
  bool in_run = false;
  const unsigned char *px = NULL;
  for (size_t i = 0; i < count; i++) {
    if (rle) {
      if (run_left == 0) {
        if (pos >= n)
          break;
        in_run = (b[pos] & 0x80) != 0;
        run_left = (size_t)(b[pos] & 0x7F) + 1;
        pos++;
        if (in_run) {
          if (px_bytes > n - pos)
            break;
          px = b + pos;
          pos += px_bytes;
        }
      }
      if (!in_run) {
        if (px_bytes > n - pos)
          break;
        px = b + pos;
        pos += px_bytes;
      }
      run_left--;
    } else {
      if (px_bytes > n - pos)
        break;
      px = b + pos;
      pos += px_bytes;
    }
    unsigned rgb[3];
    unsigned k = 0;
    if (base == 1) {
      k = depth == 8 ? px[0] : le16(px);
      if (k < cmap_first || k - cmap_first >= cmap_len) {
        rgb[0] = rgb[1] = rgb[2] = 0;
        outside++;
      } else {
        colour_of(cmap + (size_t)(k - cmap_first) * cmap_bytes, cmap_depth,
                  rgb);
      }
    } else if (base == 3) {
      rgb[0] = rgb[1] = rgb[2] = px[0];
    } else {
      colour_of(px, depth, rgb);
    }
    /* Stored row r, column c: where it goes in a top-down image. */
    size_t r = i / (size_t)width, c = i % (size_t)width;
    size_t y = top_down ? r : (size_t)height - 1 - r;
    size_t x = right_left ? (size_t)width - 1 - c : c;
    size_t at = y * (size_t)width + x;
    if (keep_indices)
      image->indices[at] = (unsigned char)k;
    else if (base == 3)
      zr__image_set_code(image, at, rgb[0]);
    else
      for (int ch = 0; ch < 3; ch++)
        zr__image_set_code(image, 3 * at + ch, rgb[ch]);
    if (alpha)
      image->alpha[at] = (float)(px[3] / 255.0);
    done++;
  }
  if (done < count) {
    zr_image_free(image);
    return bad(ctx, name, "truncated TGA file (pixels)");
  }
  if (outside)
    zr__diag(ctx, ZR_DIAG_WARNING, ZR_EFORMAT, NULL,
             "%s: %zu pixel(s) with an index outside the colour map, read "
             "as black", name, outside);
  *out = image;
  return ZR_OK;
}
