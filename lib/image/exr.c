/*
 * exr.c - OpenEXR files, read and written through OpenEXR's C library
 * (OpenEXRCore, OpenEXR 3.1 or newer): POV-Ray's +FE and the "exr"
 * image type (POV-Ray 3.7 reference, "Output File Type", "Image Maps").
 *
 * Writing makes one scanline part of half floats (OpenEXR's usual pixel
 * type), channels R, G, B and, when the image has one, A, ZIP
 * compressed, holding linear light (image.c).  The library writes its
 * chunk offset table last, back at the head of the file, so the bytes
 * are built in memory and then copied to the stream: a pipe or standard
 * output works as well as a file.  Floats are rounded to half here (IEEE
 * 754 binary16, to nearest even; beyond 65504 becomes 65504), so the
 * encoder copies samples as they are.
 *
 * Reading takes the first part of a scanline file: R, G and B (or Y,
 * luminance, as grey), any pixel type, converted to float by the
 * library's unpacking; other channels are skipped.  Tiled, deep and
 * subsampled files are refused by name.  The data window gives the
 * picture; its origin is ignored.
 *
 * Without OpenEXR (configure --without-openexr, or no libopenexr-dev),
 * both directions report that the build lacks it.
 */
#include "config.h"

#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/context.h"
#include "image/image.h"

bool zr__exr_looks_like(const unsigned char *b, size_t n) {
  /* The magic number 20000630, little-endian (OpenEXR file layout). */
  return n >= 4 && b[0] == 0x76 && b[1] == 0x2f && b[2] == 0x31 &&
         b[3] == 0x01;
}

#ifndef HAVE_OPENEXR

bool zr__exr_available(void) { return false; }

static zr_status missing(zr_context *ctx, const char *name) {
  return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EUNSUPPORTED, NULL,
                  "%s: this zRcube was built without OpenEXR (configure "
                  "found no libopenexr-dev)", name);
}

zr_status zr__exr_decode(zr_context *ctx, const char *name,
                         const unsigned char *bytes, size_t size,
                         zr_image **out) {
  (void)bytes;
  (void)size;
  *out = NULL;
  return missing(ctx, name);
}

zr_status zr__exr_encode(zr_context *ctx, const char *name,
                         const zr_image *image, const zr_image_encoding *e,
                         FILE *stream) {
  (void)image;
  (void)e;
  (void)stream;
  return missing(ctx, name);
}

#else

#include <openexr.h>

bool zr__exr_available(void) { return true; }

/* ---- half floats ---- */

/* IEEE 754 binary16 of a finite non-negative float, rounded to nearest
   even; above the largest half (65504) gives 65504. */
static uint16_t half_of(float value) {
  union {
    float f;
    uint32_t u;
  } v = {value};
  uint32_t sign = (v.u >> 16) & 0x8000;
  uint32_t bits = v.u & 0x7fffffff;
  if (bits >= 0x477ff000) /* rounds to 65520 or more: clamp */
    return (uint16_t)(sign | 0x7bff);
  if (bits < 0x38800000) { /* below the smallest normal half */
    if (bits < 0x33000000)
      return (uint16_t)sign; /* below half the smallest subnormal */
    uint32_t mant = (bits & 0x7fffff) | 0x800000;
    int shift = 126 - (int)(bits >> 23); /* 14 .. 24 */
    uint32_t h = mant >> shift;
    uint32_t rest = mant & ((1u << shift) - 1), halfway = 1u << (shift - 1);
    if (rest > halfway || (rest == halfway && (h & 1)))
      h++;
    return (uint16_t)(sign | h);
  }
  uint32_t h = ((bits >> 13) - (112u << 10)); /* rebias 127 -> 15 */
  uint32_t rest = bits & 0x1fff;
  if (rest > 0x1000 || (rest == 0x1000 && (h & 1)))
    h++;
  return (uint16_t)(sign | h);
}

/* ---- a growing buffer written at offsets ---- */

typedef struct exr_sink {
  unsigned char *bytes;
  size_t size, cap;
} exr_sink;

typedef struct exr_message {
  char text[256];
} exr_message;

typedef struct exr_writer {
  exr_message *message; /* first: see keep_message */
  exr_sink sink;
} exr_writer;

static int64_t on_write(exr_const_context_t c, void *user, const void *buf,
                        uint64_t sz, uint64_t offset,
                        exr_stream_error_func_ptr_t error_cb) {
  (void)c;
  (void)error_cb;
  exr_sink *sink = &((exr_writer *)user)->sink;
  if (offset > SIZE_MAX - sz)
    return -1;
  size_t end = (size_t)(offset + sz);
  if (end > sink->cap) {
    size_t cap = sink->cap ? sink->cap : 1 << 16;
    while (cap < end)
      cap *= 2;
    unsigned char *b = realloc(sink->bytes, cap);
    if (!b)
      return -1;
    sink->bytes = b;
    sink->cap = cap;
  }
  if (offset > sink->size) /* a gap: zeros, as a file would read */
    memset(sink->bytes + sink->size, 0, (size_t)offset - sink->size);
  memcpy(sink->bytes + offset, buf, (size_t)sz);
  if (end > sink->size)
    sink->size = end;
  return (int64_t)sz;
}

/* The library's messages: the first is kept for ours.  Our user data
   always begins with a pointer to the message, so one handler serves
   reading and writing. */
static void keep_message(exr_const_context_t c, exr_result_t code,
                         const char *msg) {
  void *user = NULL;
  (void)code;
  if (exr_get_user_data(c, &user) != EXR_ERR_SUCCESS || !user)
    return;
  exr_message *m = *(exr_message **)user;
  if (m && !m->text[0])
    snprintf(m->text, sizeof m->text, "%s", msg);
}

static zr_status exr_failed(zr_context *ctx, const char *name,
                            const char *what, exr_result_t r,
                            const exr_message *m) {
  return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL, "%s: %s: %s", name,
                  what,
                  m->text[0] ? m->text : exr_get_default_error_message(r));
}

static exr_result_t write_chunks(exr_context_t c, int part,
                                 const zr_image *image, const uint16_t *half,
                                 int channels) {
  int32_t lines = 1;
  exr_result_t r = exr_get_scanlines_per_chunk(c, part, &lines);
  exr_encode_pipeline_t enc = EXR_ENCODE_PIPELINE_INITIALIZER;
  bool ready = false;
  size_t row_bytes = (size_t)image->width * channels * 2;
  for (int y = 0; r == EXR_ERR_SUCCESS && y < image->height; y += lines) {
    exr_chunk_info_t ci;
    r = exr_write_scanline_chunk_info(c, part, y, &ci);
    if (r != EXR_ERR_SUCCESS)
      break;
    r = ready ? exr_encoding_update(c, part, &ci, &enc)
              : exr_encoding_initialize(c, part, &ci, &enc);
    if (r != EXR_ERR_SUCCESS)
      break;
    for (int k = 0; k < enc.channel_count; k++) {
      exr_coding_channel_info_t *ch = &enc.channels[k];
      /* Our planes interleave R, G, B[, A]; the file sorts by name. */
      const char *n = ch->channel_name;
      int at = n[0] == 'R' ? 0 : n[0] == 'G' ? 1 : n[0] == 'B' ? 2 : 3;
      ch->user_pixel_stride = channels * 2;
      ch->user_line_stride = (int32_t)row_bytes;
      ch->user_bytes_per_element = 2;
      ch->user_data_type = EXR_PIXEL_HALF;
      ch->encode_from_ptr =
          (const uint8_t *)(half + ((size_t)y * image->width) * channels +
                            at);
    }
    if (!ready) {
      r = exr_encoding_choose_default_routines(c, part, &enc);
      ready = true;
    }
    if (r == EXR_ERR_SUCCESS)
      r = exr_encoding_run(c, part, &enc);
  }
  if (ready || enc.channels)
    exr_encoding_destroy(c, &enc);
  return r;
}

zr_status zr__exr_encode(zr_context *ctx, const char *name,
                         const zr_image *image, const zr_image_encoding *e,
                         FILE *stream) {
  bool alpha = e->alpha && image->alpha;
  int channels = alpha ? 4 : 3;
  size_t count = (size_t)image->width * image->height;
  uint16_t *half = malloc(count * channels * sizeof *half);
  exr_message message = {""};
  exr_writer w = {&message, {NULL, 0, 0}};
  if (!half)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "%s: %s", name,
                    zr_status_str(ZR_ENOMEM));
  for (size_t i = 0; i < count; i++) {
    /* OpenEXR keeps colours premultiplied by alpha, and povray 3.7 +UA
       +FE writes them so (measured: the colours of a +UA file are those
       of the same render on black without +UA, also where the working
       gamma is not 1: the working colour is premultiplied, then made
       linear). */
    float a = alpha ? image->alpha[i] : 1.0f;
    a = !(a > 0.0f) ? 0.0f : a > 1 ? 1 : a;
    for (int c = 0; c < 3; c++)
      half[i * channels + c] = half_of(zr__linear_sample(
          a * image->pixels[3 * i + c], e->assumed_gamma));
    if (alpha)
      half[i * channels + 3] = half_of(a);
  }
  exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
  init.error_handler_fn = keep_message;
  init.user_data = &w;
  init.write_fn = on_write;
  exr_context_t c = NULL;
  exr_result_t r = exr_start_write(&c, name, EXR_WRITE_FILE_DIRECTLY, &init);
  int part = 0;
  if (r == EXR_ERR_SUCCESS)
    r = exr_add_part(c, "rgba", EXR_STORAGE_SCANLINE, &part);
  if (r == EXR_ERR_SUCCESS)
    r = exr_initialize_required_attr_simple(c, part, image->width,
                                            image->height,
                                            EXR_COMPRESSION_ZIP);
  static const char *const names[4] = {"R", "G", "B", "A"};
  for (int k = 0; k < channels && r == EXR_ERR_SUCCESS; k++)
    r = exr_add_channel(c, part, names[k], EXR_PIXEL_HALF,
                        k == 3 ? EXR_PERCEPTUALLY_LINEAR
                               : EXR_PERCEPTUALLY_LOGARITHMIC,
                        1, 1);
  if (r == EXR_ERR_SUCCESS)
    r = exr_write_header(c);
  if (r == EXR_ERR_SUCCESS)
    r = write_chunks(c, part, image, half, channels);
  /* exr_finish writes the offset table, so it decides success too. */
  exr_result_t f = c ? exr_finish(&c) : EXR_ERR_SUCCESS;
  if (r == EXR_ERR_SUCCESS)
    r = f;
  free(half);
  zr_status s = ZR_OK;
  if (r != EXR_ERR_SUCCESS)
    s = exr_failed(ctx, name, "cannot write OpenEXR", r, &message);
  else /* a short write: the caller checks the stream and says why */
    fwrite(w.sink.bytes, 1, w.sink.size, stream);
  free(w.sink.bytes);
  return s;
}

/* ---- reading ---- */

typedef struct exr_reader {
  exr_message *message; /* first: see keep_message */
  const unsigned char *bytes;
  size_t size;
} exr_reader;

static int64_t on_read(exr_const_context_t c, void *user, void *buf,
                       uint64_t sz, uint64_t offset,
                       exr_stream_error_func_ptr_t error_cb) {
  (void)c;
  (void)error_cb;
  exr_reader *src = user;
  if (offset >= src->size)
    return 0;
  uint64_t left = src->size - offset;
  size_t k = (size_t)(sz < left ? sz : left);
  memcpy(buf, src->bytes + offset, k);
  return (int64_t)k;
}

static int64_t on_size(exr_const_context_t c, void *user) {
  (void)c;
  return (int64_t)((exr_reader *)user)->size;
}

/* Which of our three colour planes a channel fills (-1: none; 3: Y,
   which fills all three). */
static int plane_of(const char *name) {
  if (!strcmp(name, "R"))
    return 0;
  if (!strcmp(name, "G"))
    return 1;
  if (!strcmp(name, "B"))
    return 2;
  if (!strcmp(name, "Y"))
    return 3;
  return -1;
}

static exr_result_t read_chunks(exr_context_t c, const exr_attr_box2i_t *dw,
                                zr_image *image, bool grey) {
  int32_t lines = 1;
  exr_result_t r = exr_get_scanlines_per_chunk(c, 0, &lines);
  exr_decode_pipeline_t dec = EXR_DECODE_PIPELINE_INITIALIZER;
  bool ready = false;
  int w = image->width;
  for (int y = dw->min.y; r == EXR_ERR_SUCCESS && y <= dw->max.y;
       y += lines) {
    exr_chunk_info_t ci;
    r = exr_read_scanline_chunk_info(c, 0, y, &ci);
    if (r != EXR_ERR_SUCCESS)
      break;
    r = ready ? exr_decoding_update(c, 0, &ci, &dec)
              : exr_decoding_initialize(c, 0, &ci, &dec);
    if (r != EXR_ERR_SUCCESS)
      break;
    size_t row = (size_t)(ci.start_y - dw->min.y);
    for (int k = 0; k < dec.channel_count; k++) {
      exr_coding_channel_info_t *ch = &dec.channels[k];
      int plane = plane_of(ch->channel_name);
      if (plane < 0 || (grey && plane != 3) || (!grey && plane == 3)) {
        ch->decode_to_ptr = NULL; /* skipped */
        continue;
      }
      ch->user_pixel_stride = 3 * sizeof(float);
      ch->user_line_stride = (int32_t)(3 * sizeof(float) * (size_t)w);
      ch->user_bytes_per_element = 4;
      ch->user_data_type = EXR_PIXEL_FLOAT;
      ch->decode_to_ptr =
          (uint8_t *)(image->pixels + row * w * 3 + (plane == 3 ? 0 : plane));
    }
    if (!ready) {
      r = exr_decoding_choose_default_routines(c, 0, &dec);
      ready = true;
    }
    if (r == EXR_ERR_SUCCESS)
      r = exr_decoding_run(c, 0, &dec);
  }
  if (ready || dec.channels)
    exr_decoding_destroy(c, &dec);
  return r;
}

zr_status zr__exr_decode(zr_context *ctx, const char *name,
                         const unsigned char *bytes, size_t size,
                         zr_image **out) {
  *out = NULL;
  exr_message message = {""};
  exr_reader src = {&message, bytes, size};
  exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
  init.error_handler_fn = keep_message;
  init.user_data = &src;
  init.read_fn = on_read;
  init.size_fn = on_size;
  init.max_image_width = ZR_IMAGE_MAX_SIDE;
  init.max_image_height = ZR_IMAGE_MAX_SIDE;
  init.flags = EXR_CONTEXT_FLAG_DISABLE_CHUNK_RECONSTRUCTION;
  exr_context_t c = NULL;
  exr_result_t r = exr_start_read(&c, name, &init);
  if (r != EXR_ERR_SUCCESS) {
    zr_status s = exr_failed(ctx, name, "not a readable OpenEXR file", r,
                             &message);
    if (c)
      exr_finish(&c);
    return s;
  }
  exr_storage_t storage = EXR_STORAGE_LAST_TYPE;
  exr_attr_box2i_t dw;
  const exr_attr_chlist_t *chans = NULL;
  const char *unsupported = NULL;
  bool has_rgb = false, has_y = false;
  if (exr_get_storage(c, 0, &storage) != EXR_ERR_SUCCESS ||
      exr_get_data_window(c, 0, &dw) != EXR_ERR_SUCCESS ||
      exr_get_channels(c, 0, &chans) != EXR_ERR_SUCCESS || !chans)
    unsupported = "a file without its required attributes";
  else if (storage != EXR_STORAGE_SCANLINE)
    unsupported = "tiled or deep OpenEXR files";
  for (int k = 0; !unsupported && k < chans->num_channels; k++) {
    const exr_attr_chlist_entry_t *ch = &chans->entries[k];
    int plane = plane_of(ch->name.str);
    if (plane < 0)
      continue;
    if (ch->x_sampling != 1 || ch->y_sampling != 1)
      unsupported = "subsampled OpenEXR channels";
    has_rgb |= plane < 3;
    has_y |= plane == 3;
  }
  if (!unsupported && !has_rgb && !has_y)
    unsupported = "OpenEXR files without R, G, B or Y channels";
  if (unsupported) {
    exr_finish(&c);
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EUNSUPPORTED, NULL,
                    "%s: %s are not supported", name, unsupported);
  }
  int64_t w = (int64_t)dw.max.x - dw.min.x + 1;
  int64_t h = (int64_t)dw.max.y - dw.min.y + 1;
  zr_image *image = NULL;
  zr_status s = zr__image_new_named(
      ctx, name, w > INT32_MAX ? -1 : (int)w, h > INT32_MAX ? -1 : (int)h,
      &image);
  if (s != ZR_OK) {
    exr_finish(&c);
    return s;
  }
  bool grey = !has_rgb;
  r = read_chunks(c, &dw, image, grey);
  exr_finish(&c);
  if (r != EXR_ERR_SUCCESS) {
    zr_image_free(image);
    return exr_failed(ctx, name, "damaged OpenEXR file", r, &message);
  }
  size_t count = (size_t)image->width * image->height;
  for (size_t i = 0; i < count; i++) {
    float *p = image->pixels + 3 * i;
    if (grey)
      p[1] = p[2] = p[0];
    for (int k = 0; k < 3; k++) /* NaN and infinities would poison */
      if (!(p[k] > -3.4e38f && p[k] < 3.4e38f))
        p[k] = 0.0f;
  }
  *out = image;
  return ZR_OK;
}

#endif /* HAVE_OPENEXR */
