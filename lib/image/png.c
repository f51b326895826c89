/*
 * png.c - PNG reading and writing through libpng 1.6.
 *
 * Reading accepts every PNG colour type and depth (PNG specification,
 * section 11.2.2) into the smallest faithful form (image.h): grey stays
 * one sample a pixel, colour three, a palette image one index a pixel
 * (also for image_map's per-index filter and transmit) beside its
 * palette; libpng decodes the rows straight into that store.  1/2/4-bit
 * samples are widened to 8, 16-bit samples kept at full precision.  Alpha
 * (an alpha channel, or tRNS transparency: a palette's per entry, a
 * grey or RGB image's one transparent colour) goes to the image's alpha,
 * straight (unassociated) as the PNG specification stores it, beside
 * colour codes left as their author stored them: image_map takes it as
 * transmittance (the manual's "Using the Alpha Channel").  Samples are
 * decoded to linear light by the sRGB
 * chunk if present, else the gAMA chunk, else the sRGB curve (section
 * 10.5; iCCP and cHRM are ignored: everything is taken as sRGB
 * primaries).
 *
 * Writing produces 8 or 16-bit RGB with sRGB, gAMA and cHRM chunks, as
 * POV-Ray 3.7 does, or RGBA when the image has an alpha channel (+UA):
 * alpha is stored linearly and unassociated, as the PNG specification
 * (section 4.3.2) defines it.
 *
 * libpng reports errors by longjmp.  Everything that must be released
 * after a jump lives in a struct owned by the caller of the function that
 * calls setjmp, so no automatic variable of that function is relied upon
 * after the jump (C11 7.13.2.1).
 */
#include <errno.h>
#include <png.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>

#include "core/context.h"
#include "image/image.h"

/* Where libpng's messages and our memory cursor meet. */
typedef struct png_job {
  zr_context *ctx;
  const char *name;
  const unsigned char *bytes;
  size_t size;
  size_t pos;
  int truncated;
  char message[256];
  png_structp png;
  png_infop info;
  unsigned char *rows; /* writing: one row of samples */
  png_bytep *row_ptrs;
  unsigned char *with_alpha; /* reading: rows holding alpha, split after */
  zr_image *image;
} png_job;

static void on_error(png_structp png, png_const_charp msg) {
  png_job *job = png_get_error_ptr(png);
  snprintf(job->message, sizeof job->message, "%s", msg);
  png_longjmp(png, 1);
}

static void on_warning(png_structp png, png_const_charp msg) {
  /* Benign issues (an odd ancillary chunk) do not stop a render. */
  (void)png;
  (void)msg;
}

static void read_memory(png_structp png, png_bytep data, size_t length) {
  png_job *job = png_get_io_ptr(png);
  if (length > job->size - job->pos) {
    job->truncated = 1;
    png_error(png, "truncated");
  }
  memcpy(data, job->bytes + job->pos, length);
  job->pos += length;
}

/* Sets libpng's transformations so that every row is grey or RGB, 8 or
   16 bit, the way the file stores them, followed in each pixel by its
   alpha when the file has any (a tRNS colour becomes an alpha channel),
   or for a palette image one 8-bit index a pixel (its tRNS is read
   apart): the rows are the image's codes, with alpha to be split off. */
static void request_codes(png_structp png, png_infop info) {
  int color_type = png_get_color_type(png, info);
  int depth = png_get_bit_depth(png, info);
  if (color_type == PNG_COLOR_TYPE_PALETTE) {
    /* Palette rows stay indices, one byte each: the palette's colours
       are looked up per pixel from the image's palette. */
    png_set_packing(png);
    png_set_interlace_handling(png);
    return;
  }
  if (color_type == PNG_COLOR_TYPE_GRAY && depth < 8)
    png_set_expand_gray_1_2_4_to_8(png);
  if (!(color_type & PNG_COLOR_MASK_ALPHA) &&
      png_get_valid(png, info, PNG_INFO_tRNS))
    png_set_tRNS_to_alpha(png);
  /* 16-bit samples are big-endian in the file; the codes array holds
     them as native unsigned shorts. */
  const unsigned short one = 1;
  if (depth == 16 && *(const unsigned char *)&one == 1)
    png_set_swap(png);
  png_set_interlace_handling(png);
}

/* The file's transfer function: its sRGB chunk, else its gAMA, else
   sRGB. */
static zr_transfer file_transfer(png_structp png, png_infop info,
                                 double *exponent) {
  double gamma = 0.0;
  *exponent = 0.0;
  if (!png_get_valid(png, info, PNG_INFO_sRGB) &&
      png_get_valid(png, info, PNG_INFO_gAMA) &&
      png_get_gAMA(png, info, &gamma) && gamma > 0.0) {
    *exponent = 1.0 / gamma;
    return ZR_TRANSFER_POWER;
  }
  return ZR_TRANSFER_SRGB;
}

/* Copies the palette's codes and warns of indices past it.  An index
   past the palette breaks the PNG specification (11.2.3) but libpng and
   POV-Ray read it as black, and so do we, with a warning. */
static void keep_palette(png_job *job, png_const_colorp palette,
                         int palette_size) {
  zr_image *image = job->image;
  for (int k = 0; k < palette_size && k < 256; k++) {
    image->palette[3 * k] = palette[k].red;
    image->palette[3 * k + 1] = palette[k].green;
    image->palette[3 * k + 2] = palette[k].blue;
  }
  image->palette_size = palette_size;
  size_t n = (size_t)image->width * (size_t)image->height, past = 0;
  for (size_t i = 0; i < n; i++)
    past += image->indices[i] >= palette_size;
  if (past)
    zr__diag(job->ctx, ZR_DIAG_WARNING, ZR_EFORMAT, NULL,
             "%s: %zu pixel(s) with a palette index past the %d entries "
             "of the palette, read as black", job->name, past,
             palette_size);
}

/* Whether a palette image's tRNS chunk makes any entry transparent. */
static bool palette_alpha(png_structp png, png_infop info) {
  png_bytep trans = NULL;
  int n = 0;
  if (png_get_color_type(png, info) != PNG_COLOR_TYPE_PALETTE ||
      !png_get_valid(png, info, PNG_INFO_tRNS) ||
      !png_get_tRNS(png, info, &trans, &n, NULL) || !trans)
    return false;
  for (int k = 0; k < n; k++)
    if (trans[k] != 255)
      return true;
  return false;
}

/* Each pixel's alpha from its palette entry's tRNS value (entries past
   the chunk's are opaque). */
static void index_alpha(png_structp png, png_infop info, zr_image *image) {
  png_bytep trans = NULL;
  int n = 0;
  png_get_tRNS(png, info, &trans, &n, NULL);
  size_t count = (size_t)image->width * (size_t)image->height;
  for (size_t i = 0; i < count; i++) {
    int k = image->indices[i];
    image->alpha[i] = k < n ? (float)(trans[k] / 255.0) : 1.0f;
  }
}

/* Splits rows of colours + 1 samples a pixel (8 or 16 bit) into the
   image's codes and its alpha (straight, in [0, 1]). */
static void split_alpha(zr_image *image, const unsigned char *rows,
                        size_t colours, bool wide) {
  size_t n = (size_t)image->width * (size_t)image->height;
  size_t step = colours + 1;
  if (wide) {
    const unsigned short *s = (const unsigned short *)(const void *)rows;
    unsigned short *c = image->codes;
    for (size_t i = 0; i < n; i++) {
      for (size_t k = 0; k < colours; k++)
        c[colours * i + k] = s[step * i + k];
      image->alpha[i] = (float)(s[step * i + colours] / 65535.0);
    }
    return;
  }
  unsigned char *c = image->codes;
  for (size_t i = 0; i < n; i++) {
    for (size_t k = 0; k < colours; k++)
      c[colours * i + k] = rows[step * i + k];
    image->alpha[i] = (float)(rows[step * i + colours] / 255.0);
  }
}

/* Runs libpng; returns ZR_OK or leaves a message in job and says so. */
static zr_status decode_rows(png_job *job) {
  if (setjmp(png_jmpbuf(job->png)))
    return ZR_EFORMAT;
  png_set_read_fn(job->png, job, read_memory);
  png_set_user_limits(job->png, ZR_IMAGE_MAX_SIDE, ZR_IMAGE_MAX_SIDE);
  png_read_info(job->png, job->info);
  request_codes(job->png, job->info);
  png_read_update_info(job->png, job->info);
  int width = (int)png_get_image_width(job->png, job->info);
  int height = (int)png_get_image_height(job->png, job->info);
  int depth = png_get_bit_depth(job->png, job->info);
  size_t rowbytes = png_get_rowbytes(job->png, job->info);
  size_t channels = png_get_channels(job->png, job->info);
  png_colorp palette = NULL;
  int palette_size = 0;
  if (png_get_color_type(job->png, job->info) == PNG_COLOR_TYPE_PALETTE &&
      !png_get_PLTE(job->png, job->info, &palette, &palette_size)) {
    snprintf(job->message, sizeof job->message, "palette image without "
             "a PLTE chunk");
    return ZR_EFORMAT;
  }
  /* Grey or RGB, each with or without alpha after it. */
  size_t colours = palette ? 1 : channels == 2 || channels == 4
                                     ? channels - 1
                                     : channels;
  if ((palette ? channels != 1 || depth != 8
               : colours != 1 && colours != 3) ||
      (depth != 8 && depth != 16) ||
      rowbytes != (size_t)width * channels * (depth == 16 ? 2 : 1)) {
    snprintf(job->message, sizeof job->message,
             "unexpected row layout after conversion");
    return ZR_EFORMAT;
  }
  double exponent;
  zr_transfer transfer = file_transfer(job->png, job->info, &exponent);
  zr_image_layout layout = palette        ? ZR_LAYOUT_INDEX
                           : colours == 1 ? ZR_LAYOUT_GREY
                                          : ZR_LAYOUT_RGB;
  /* The rows are decoded straight into the image's codes; the row
     pointers are charged while the decoder runs. */
  size_t extra = (size_t)height * sizeof *job->row_ptrs;
  zr_status s = zr__image_new_coded(
      job->ctx, job->name, width, height, layout,
      depth == 16 ? 65535u : 255u, transfer, exponent, extra, &job->image);
  if (s != ZR_OK)
    return s;
  job->image->stored_codes = true;
  job->image->transfer_stated =
      png_get_valid(job->png, job->info, PNG_INFO_sRGB) ||
      png_get_valid(job->png, job->info, PNG_INFO_gAMA);
  unsigned char *rows = palette ? job->image->indices
                                : (unsigned char *)job->image->codes;
  bool alpha = colours != channels;
  if (alpha) {
    /* Rows with alpha are read whole, then split into codes and alpha. */
    job->with_alpha = malloc((size_t)height * rowbytes);
    rows = job->with_alpha;
  }
  job->row_ptrs = malloc((size_t)height * sizeof *job->row_ptrs);
  if (!job->row_ptrs || (alpha && !job->with_alpha) ||
      ((alpha || palette_alpha(job->png, job->info)) &&
       zr_image_add_alpha(job->image) != ZR_OK))
    return zr__diag(job->ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "%s: %s",
                    job->name, zr_status_str(ZR_ENOMEM));
  for (int y = 0; y < height; y++)
    job->row_ptrs[y] = rows + (size_t)y * rowbytes;
  png_read_image(job->png, job->row_ptrs);
  png_read_end(job->png, NULL);
  zr__image_release_extra(job->image, extra);
  if (alpha)
    split_alpha(job->image, job->with_alpha, colours, depth == 16);
  if (palette)
    keep_palette(job, palette, palette_size);
  if (palette && job->image->alpha)
    index_alpha(job->png, job->info, job->image);
  return ZR_OK;
}

zr_status zr__png_decode(zr_context *ctx, const char *name,
                         const unsigned char *bytes, size_t size,
                         zr_image **out) {
  png_job job;
  memset(&job, 0, sizeof job);
  job.ctx = ctx;
  job.name = name;
  job.bytes = bytes;
  job.size = size;
  job.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &job, on_error,
                                   on_warning);
  if (job.png)
    job.info = png_create_info_struct(job.png);
  zr_status s;
  if (!job.png || !job.info)
    s = zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "%s: %s", name,
                 zr_status_str(ZR_ENOMEM));
  else
    s = decode_rows(&job);
  /* A message in job means libpng failed; other failures were reported. */
  if (s != ZR_OK && job.truncated)
    s = zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL,
                 "%s: truncated PNG file", name);
  else if (s != ZR_OK && job.message[0])
    s = zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL,
                 "%s: invalid PNG file: %s", name, job.message);
  png_destroy_read_struct(job.png ? &job.png : NULL,
                          job.info ? &job.info : NULL, NULL);
  free(job.row_ptrs);
  free(job.with_alpha);
  if (s == ZR_OK)
    *out = job.image;
  else
    zr_image_free(job.image);
  return s;
}

/* ---- writing ---- */

static zr_status encode_rows(png_job *job, const zr_image *image, int bits,
                             bool alpha, double assumed_gamma,
                             double file_gamma, FILE *stream) {
  const size_t channels = alpha ? 4 : 3;
  if (setjmp(png_jmpbuf(job->png)))
    return ZR_EIO;
  png_init_io(job->png, stream);
  png_set_compression_level(job->png, job->ctx ? job->ctx->png_level
                                               : ZR_DEFAULT_PNG_LEVEL);
  /* Rows go to zlib unfiltered (filter type None, PNG 1.2, 6.2).
     libpng's default tries all five filters on every row and keeps the
     one with the smallest sum of bytes: that choice took two thirds of
     the write of a 512x512 sphereflake, and on rendered pictures (large
     flat areas, textures with no row-to-row trend) the unfiltered rows
     deflate as small or smaller (bench/png_filter.sh, results in
     bench/results/png-filter-2026-12-03.txt: at level 1 the write
     takes 0.45-0.62 of the adaptive filter's time and the files are
     0-20% smaller, the sphereflake's most).  The decoded pixels are the
     same whatever the filter. */
  png_set_filter(job->png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  png_set_IHDR(job->png, job->info, (png_uint_32)image->width,
               (png_uint_32)image->height, bits,
               alpha ? PNG_COLOR_TYPE_RGB_ALPHA : PNG_COLOR_TYPE_RGB,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  /* Codes pre-corrected for a display gamma say so in a gAMA chunk
     (PNG 1.2, 10.5), sRGB codes in an sRGB chunk with its gAMA. */
  if (file_gamma > 0.0)
    png_set_gAMA(job->png, job->info, 1.0 / file_gamma);
  else
    png_set_sRGB_gAMA_and_cHRM(job->png, job->info,
                               PNG_sRGB_INTENT_PERCEPTUAL);
  png_write_info(job->png, job->info);
  size_t bytes_per_sample = bits == 16 ? 2 : 1;
  size_t rowbytes = (size_t)image->width * channels * bytes_per_sample;
  job->rows = malloc(rowbytes);
  if (!job->rows) {
    snprintf(job->message, sizeof job->message, "%s",
             zr_status_str(ZR_ENOMEM));
    return ZR_ENOMEM;
  }
  unsigned maxval = bits == 16 ? 65535u : 255u;
  zr_encoder8 enc;
  if (bits == 8)
    zr__encoder8_init(&enc, assumed_gamma, file_gamma);
  for (int y = 0; y < image->height; y++) {
    if (zr__image_wait_rows(image, y + 1) != ZR_OK) {
      snprintf(job->message, sizeof job->message, "%s",
               zr_status_str(ZR_ECANCELLED));
      return ZR_ECANCELLED;
    }
    const float *src = image->pixels + (size_t)y * image->width * 3;
    const float *a = alpha ? image->alpha + (size_t)y * image->width : NULL;
    /* Sample i of the row is channel c of pixel x (no division a
       sample: channels is 3 or 4, not known when compiling). */
    size_t i = 0;
    for (size_t x = 0; x < (size_t)image->width; x++)
      for (size_t c = 0; c < channels; c++, i++) {
        unsigned code =
            c == 3      ? zr__encode_linear(a[x], maxval)
            : bits == 8 ? zr__encoder8_code(&enc, src[3 * x + c])
                        : zr__encode_code(src[3 * x + c], assumed_gamma,
                                          file_gamma, maxval);
        if (bits == 16) {
          job->rows[2 * i] = (unsigned char)(code >> 8);
          job->rows[2 * i + 1] = (unsigned char)(code & 0xff);
        } else {
          job->rows[i] = (unsigned char)code;
        }
      }
    png_write_row(job->png, job->rows);
  }
  png_write_end(job->png, NULL);
  return ZR_OK;
}

zr_status zr__png_encode(zr_context *ctx, const char *name,
                         const zr_image *image, int bits, bool alpha,
                         double assumed_gamma, double file_gamma,
                         FILE *stream) {
  png_job job;
  memset(&job, 0, sizeof job);
  job.ctx = ctx;
  job.name = name;
  job.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &job, on_error,
                                    on_warning);
  if (job.png)
    job.info = png_create_info_struct(job.png);
  zr_status s;
  if (!job.png || !job.info) {
    s = ZR_ENOMEM;
    snprintf(job.message, sizeof job.message, "%s",
             zr_status_str(ZR_ENOMEM));
  } else {
    s = encode_rows(&job, image, bits, alpha && image->alpha != NULL,
                    assumed_gamma, file_gamma, stream);
  }
  int write_errno = errno;
  /* A failed write (a full disk, ulimit -f) says why, as a failed flush
     does (image.c): with fast compression the data outgrow the stream's
     buffer and reach the file while the rows are written. */
  if (s != ZR_OK && ferror(stream) && write_errno != 0)
    s = zr__diag(ctx, ZR_DIAG_ERROR, s, NULL, "%s: write failed: %s", name,
                 strerror(write_errno));
  else if (s != ZR_OK)
    s = zr__diag(ctx, ZR_DIAG_ERROR, s, NULL, "%s: cannot write PNG: %s",
                 name, job.message);
  png_destroy_write_struct(job.png ? &job.png : NULL,
                           job.info ? &job.info : NULL);
  free(job.rows);
  return s;
}
