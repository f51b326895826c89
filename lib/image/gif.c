/*
 * gif.c - GIF87a and GIF89a images (the GIF89a specification of
 * CompuServe, 1990), read from memory: the first image of the file, its
 * palette colours decoded as sRGB, its indices kept for image_map's
 * per-index filter and transmit and for height fields.
 *
 * A file is a header, a logical screen descriptor with an optional
 * global colour table, then blocks: extensions (0x21, skipped: a
 * graphic control extension's transparent index has no meaning for an
 * image_map, which takes transparency from filter and transmit) and
 * images (0x2C: a descriptor, an optional local colour table, the LZW
 * minimum code size and the compressed data in sub-blocks of up to 255
 * bytes), and a trailer (0x3B).  The image read is the first image's
 * own rectangle, whatever the logical screen around it; interlaced rows
 * are put back in order.
 *
 * LZW (specification, appendix F): codes of 3 to 12 bits, packed least
 * significant bit first; the clear code 2^min resets the table, 2^min
 * + 1 ends the data, and the code width grows by one bit when the table
 * reaches its power of two, up to 4096 entries, after which the table
 * is frozen until the next clear code.  Data that ends early leaves
 * the rest of the image at index 0 with a warning, as damaged GIFs are
 * common and every viewer shows what it could decode; data that is
 * malformed (a code that is not yet in the table) is an error.
 */
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/budget.h"
#include "core/context.h"
#include "image/image.h"

#define LZW_MAX_CODES 4096

/* A read position in a memory file. */
typedef struct gif_cursor {
  const unsigned char *b;
  size_t n, pos;
} gif_cursor;

static bool take(gif_cursor *c, size_t k, const unsigned char **out) {
  if (k > c->n - c->pos)
    return false;
  *out = c->b + c->pos;
  c->pos += k;
  return true;
}

static unsigned le16(const unsigned char *p) {
  return (unsigned)p[0] | (unsigned)p[1] << 8;
}

/* Skips a chain of sub-blocks up to and including its empty block. */
static bool skip_sub_blocks(gif_cursor *c) {
  for (;;) {
    const unsigned char *len;
    if (!take(c, 1, &len))
      return false;
    if (*len == 0)
      return true;
    const unsigned char *data;
    if (!take(c, *len, &data))
      return false;
  }
}

/* The bit reader over the image's data sub-blocks. */
typedef struct lzw_bits {
  gif_cursor *c;
  unsigned left;   /* bytes left in the current sub-block */
  bool ended;      /* the empty sub-block (or the file's end) was met */
  uint32_t acc;    /* bits not yet consumed, least significant first */
  unsigned have;   /* how many */
} lzw_bits;

/* The next code of width bits, or -1 when the data has run out. */
static int next_code(lzw_bits *r, unsigned width) {
  while (r->have < width) {
    if (r->ended)
      return -1;
    if (r->left == 0) {
      const unsigned char *len;
      if (!take(r->c, 1, &len) || *len == 0) {
        r->ended = true;
        continue;
      }
      r->left = *len;
    }
    const unsigned char *byte;
    if (!take(r->c, 1, &byte)) {
      r->ended = true;
      continue;
    }
    r->left--;
    r->acc |= (uint32_t)*byte << r->have;
    r->have += 8;
  }
  int code = (int)(r->acc & ((1u << width) - 1));
  r->acc >>= width;
  r->have -= width;
  return code;
}

/* The LZW string table: each code is a prefix code and a last byte. */
typedef struct lzw_table {
  uint16_t prefix[LZW_MAX_CODES];
  unsigned char suffix[LZW_MAX_CODES];
  unsigned char first[LZW_MAX_CODES]; /* the string's first byte */
  uint16_t length[LZW_MAX_CODES];
  unsigned char stack[LZW_MAX_CODES];
} lzw_table;

/*
 * Decodes into out[0 .. count).  Returns how many indices were written
 * (less than count when the data ended early), or -1 for malformed data.
 */
static long lzw_decode(gif_cursor *c, unsigned min_size, unsigned char *out,
                       size_t count, lzw_table *t) {
  const unsigned clear = 1u << min_size, end = clear + 1;
  for (unsigned k = 0; k < clear; k++) {
    t->prefix[k] = 0;
    t->suffix[k] = (unsigned char)k;
    t->first[k] = (unsigned char)k;
    t->length[k] = 1;
  }
  lzw_bits r = {c, 0, false, 0, 0};
  unsigned width = min_size + 1, next = end + 1;
  int prev = -1;
  size_t done = 0;
  while (done < count) {
    int code = next_code(&r, width);
    if (code < 0)
      break;
    if ((unsigned)code == clear) {
      width = min_size + 1;
      next = end + 1;
      prev = -1;
      continue;
    }
    if ((unsigned)code == end)
      break;
    unsigned cur = (unsigned)code;
    if (prev < 0) {
      if (cur >= clear)
        return -1; /* the first code after a clear must be a root */
      out[done++] = (unsigned char)cur;
      prev = (int)cur;
      continue;
    }
    unsigned char head;
    if (cur < next)
      head = t->first[cur];
    else if (cur == next && next < LZW_MAX_CODES)
      head = t->first[prev]; /* the string is prev's plus its own head */
    else
      return -1;
    if (next < LZW_MAX_CODES) {
      t->prefix[next] = (uint16_t)prev;
      t->suffix[next] = head;
      t->first[next] = t->first[prev];
      t->length[next] = (uint16_t)(t->length[prev] + 1);
      next++;
      if (next == (1u << width) && width < 12)
        width++;
    }
    /* Write cur's string, last byte first from the back. */
    unsigned len = t->length[cur];
    unsigned k = cur;
    for (unsigned i = len; i-- > 0;) {
      t->stack[i] = t->suffix[k];
      k = t->prefix[k];
    }
    for (unsigned i = 0; i < len && done < count; i++)
      out[done++] = t->stack[i];
    prev = (int)cur;
  }
  /* The rest of the data (to the empty sub-block) is not needed. */
  if (!r.ended) {
    while (r.left > 0) {
      const unsigned char *byte;
      if (!take(c, 1, &byte))
        return (long)done;
      r.left--;
    }
    if (!skip_sub_blocks(c))
      return (long)done;
  }
  return (long)done;
}

/* The row of the image that the k-th stored row is, for interlacing. */
static int interlaced_row(int k, int height) {
  static const int start[4] = {0, 4, 2, 1}, step[4] = {8, 8, 4, 2};
  for (int pass = 0; pass < 4; pass++) {
    int rows = start[pass] < height
                   ? (height - start[pass] + step[pass] - 1) / step[pass]
                   : 0;
    if (k < rows)
      return start[pass] + k * step[pass];
    k -= rows;
  }
  return height - 1; /* not reached for k < height */
}

static zr_status bad(zr_context *ctx, const char *name, const char *why) {
  return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL, "%s: %s", name, why);
}

zr_status zr__gif_decode_indices(zr_context *ctx, const char *name,
                                 const unsigned char *bytes, size_t size,
                                 zr_gif_indices *out) {
  memset(out, 0, sizeof *out);
  gif_cursor c = {bytes, size, 0};
  const unsigned char *h;
  if (!take(&c, 13, &h) || memcmp(h, "GIF", 3) != 0)
    return bad(ctx, name, "not a GIF file");
  if (memcmp(h + 3, "87a", 3) != 0 && memcmp(h + 3, "89a", 3) != 0)
    return bad(ctx, name, "unknown GIF version (not 87a or 89a)");
  unsigned char global_palette[768];
  int global_size = 0;
  if (h[10] & 0x80) {
    global_size = 2 << (h[10] & 7);
    const unsigned char *p;
    if (!take(&c, 3 * (size_t)global_size, &p))
      return bad(ctx, name, "truncated GIF colour table");
    memcpy(global_palette, p, 3 * (size_t)global_size);
  }
  for (;;) {
    const unsigned char *kind;
    if (!take(&c, 1, &kind))
      return bad(ctx, name, "GIF file without an image");
    if (*kind == 0x3B)
      return bad(ctx, name, "GIF file without an image");
    if (*kind == 0x21) {
      const unsigned char *label;
      if (!take(&c, 1, &label) || !skip_sub_blocks(&c))
        return bad(ctx, name, "truncated GIF extension block");
      continue;
    }
    if (*kind != 0x2C)
      return bad(ctx, name, "damaged GIF file (unknown block)");
    const unsigned char *d;
    if (!take(&c, 9, &d))
      return bad(ctx, name, "truncated GIF image descriptor");
    int width = (int)le16(d + 4), height = (int)le16(d + 6);
    bool interlaced = (d[8] & 0x40) != 0;
    if (d[8] & 0x80) {
      out->palette_size = 2 << (d[8] & 7);
      const unsigned char *p;
      if (!take(&c, 3 * (size_t)out->palette_size, &p))
        return bad(ctx, name, "truncated GIF colour table");
      memcpy(out->palette, p, 3 * (size_t)out->palette_size);
    } else {
      out->palette_size = global_size;
      memcpy(out->palette, global_palette, 3 * (size_t)global_size);
    }
    if (width < 1 || height < 1)
      return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL,
                      "%s: invalid image size %dx%d", name, width, height);
    size_t count = (size_t)width * (size_t)height;
    if (count > ZR_IMAGE_MAX_PIXELS)
      return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ELIMIT, NULL,
                      "%s: image of %dx%d pixels is larger than the limit "
                      "(%zu pixels)", name, width, height,
                      ZR_IMAGE_MAX_PIXELS);
    const unsigned char *min;
    if (!take(&c, 1, &min))
      return bad(ctx, name, "truncated GIF image data");
    if (*min < 2 || *min > 8)
      return bad(ctx, name, "damaged GIF image data (LZW code size)");
    /* The index buffers (two while an interlaced image is reordered)
       are charged to the memory budget while they are built: a header
       may declare 2^27 pixels in a few bytes (found by
       tests/fuzz/fuzz_image).  The indices handed back are small beside
       what the callers then charge for the picture or height field. */
    size_t need = interlaced ? 2 * count : count;
    if (ctx && !zr__budget_charge(ctx->budget, need)) {
      char what[200];
      snprintf(what, sizeof what, "the %dx%d GIF image '%.120s'", width,
               height, name);
      return zr__context_over_budget(ctx, need, NULL, what);
    }
    unsigned char *stored = calloc(count, 1);
    lzw_table *table = malloc(sizeof *table);
    unsigned char *indices = interlaced ? malloc(count) : stored;
    if (!stored || !table || !indices) {
      if (ctx)
        zr__budget_release(ctx->budget, need);
      free(stored);
      free(table);
      if (interlaced)
        free(indices);
      return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "%s: %s", name,
                      zr_status_str(ZR_ENOMEM));
    }
    long got = lzw_decode(&c, *min, stored, count, table);
    free(table);
    if (ctx)
      zr__budget_release(ctx->budget, need);
    if (got < 0) {
      free(stored);
      if (interlaced)
        free(indices);
      return bad(ctx, name, "damaged GIF image data (invalid LZW code)");
    }
    if ((size_t)got < count)
      zr__diag(ctx, ZR_DIAG_WARNING, ZR_EFORMAT, NULL,
               "%s: GIF image data ends after %ld of %zu pixels; the rest "
               "is read as palette entry 0", name, got, count);
    if (interlaced) {
      for (int k = 0; k < height; k++)
        memcpy(indices + (size_t)interlaced_row(k, height) * (size_t)width,
               stored + (size_t)k * (size_t)width, (size_t)width);
      free(stored);
    }
    out->width = width;
    out->height = height;
    out->indices = indices;
    return ZR_OK;
  }
}

zr_status zr__gif_decode(zr_context *ctx, const char *name,
                         const unsigned char *bytes, size_t size,
                         zr_image **out) {
  *out = NULL;
  zr_gif_indices g;
  zr_status s = zr__gif_decode_indices(ctx, name, bytes, size, &g);
  if (s != ZR_OK)
    return s;
  zr_image *image = NULL;
  s = zr__image_new_coded(ctx, name, g.width, g.height, ZR_LAYOUT_INDEX,
                          255, ZR_TRANSFER_SRGB, 0.0, 0, &image);
  if (s != ZR_OK) {
    free(g.indices);
    return s;
  }
  /* The image takes the decoded indices (the same size as its own). */
  free(image->indices);
  image->indices = g.indices;
  image->stored_codes = true;
  image->palette_size = g.palette_size;
  for (int k = 0; k < g.palette_size && k < 256; k++)
    for (int ch = 0; ch < 3; ch++)
      image->palette[3 * k + ch] = g.palette[3 * k + ch];
  size_t n = (size_t)g.width * (size_t)g.height, past = 0;
  for (size_t i = 0; i < n; i++)
    past += (int)image->indices[i] >= g.palette_size;
  if (past)
    zr__diag(ctx, ZR_DIAG_WARNING, ZR_EFORMAT, NULL,
             "%s: %zu pixel(s) with a palette index past the %d entries "
             "of the palette, read as black", name, past, g.palette_size);
  *out = image;
  return ZR_OK;
}
