/*
 * image.c - zr_image: creation, gamma, choosing a codec, atomic writes.
 *
 * Images are kept as linear floats.  Files with integer samples are
 * decoded through their transfer function: a PNG's sRGB chunk, else its
 * gAMA chunk, else sRGB (the PNG 1.2 specification, section 10.5, and the
 * W3C's advice for untagged images); JPEG and PPM files are taken as sRGB.
 * Writing follows POV-Ray 3.7's gamma model (scene description reference,
 * "assumed_gamma"): scene colours live in a working space whose values,
 * raised to assumed_gamma, are linear light; we undo that exponent and
 * store the sRGB encoding, which is also what POV-Ray writes by default
 * (its PNGs carry an sRGB chunk).  PFM stores linear values untouched.
 *
 * HDR and OpenEXR files hold linear light: the working value raised to
 * assumed_gamma is stored, as the 8-bit formats store its sRGB code.
 *
 * Encoding goes to any stdio stream: a temporary file beside the target
 * (zr_image_save), the caller's stream (zr_image_write_file) or a
 * growing buffer from open_memstream (zr_image_encode, POSIX 2008).
 *
 * A file is read by its first bytes, not its name, so a misnamed file
 * still loads; the name only makes the message for an unknown file more
 * useful ("x.png: not a PNG file").
 *
 * Writing is atomic as far as POSIX rename() is: the codec writes a
 * temporary file in the same directory and it replaces the target only
 * once complete, so a failed or interrupted render never leaves half an
 * image under the final name.  There is no fsync: the guarantee is
 * against our own failures, not against a power cut.
 */
#include "image/image.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include "core/budget.h"
#include "core/context.h"
#include "core/arena.h"
#include "core/iopolicy.h"

static zr_status check_size(int width, int height) {
  if (width <= 0 || height <= 0)
    return ZR_EINVAL;
  if (width > ZR_IMAGE_MAX_SIDE || height > ZR_IMAGE_MAX_SIDE ||
      (size_t)width * (size_t)height > ZR_IMAGE_MAX_PIXELS)
    return ZR_ELIMIT;
  return ZR_OK;
}

static zr_image *image_alloc(int width, int height) {
  zr_image *image = calloc(1, sizeof *image);
  if (image) {
    image->width = width;
    image->height = height;
    image->layout = ZR_LAYOUT_FLOAT;
  }
  return image;
}

/*
 * Zeroed memory for the pixels of a new image, bytes long, freed by
 * zr_image_free (pixels_bytes says how).  From ZR__MAP_FROM on, a fresh
 * mapping in huge pages (core/arena.h): a render writes into this image,
 * and on this project's virtual machine first touching each of its 4 KiB
 * pages costs about 14 us (a 512x512 render's 3 MiB of floats in a
 * calloc'ed block, which glibc maps at a 4 KiB boundary: 768 page
 * faults, about 0.011 s of CPU, perf record -e page-faults, peers flake
 * 512^2).  The mapping is zero as the kernel gives it, so nothing writes
 * it here: its pages are touched as the render's rows first reach them,
 * by the thread that writes them.  Zeroed here, a 2048^2 image's 48 MiB
 * took rank 0 of `mpirun -n 2` 0.012 s alone before the render while the
 * other rank waited for it (bench/timeline.sh, terrain 2048^2); during
 * the render the ranks take rows from a shared counter, so the pages'
 * cost is shared too.
 */
static float *pixels_alloc(size_t n, size_t *bytes) {
  if (n > SIZE_MAX / sizeof(float))
    return NULL;
  *bytes = n * sizeof(float);
  return zr__map_zeroed(*bytes);
}

ZR_API zr_status zr_image_new(int width, int height, zr_image **out) {
  zr_status s = check_size(width, height);
  if (s != ZR_OK)
    return s;
  zr_image *image = image_alloc(width, height);
  if (!image)
    return ZR_ENOMEM;
  image->pixels = pixels_alloc((size_t)width * (size_t)height * 3,
                               &image->pixels_bytes);
  if (!image->pixels) {
    free(image);
    return ZR_ENOMEM;
  }
  *out = image;
  return ZR_OK;
}

static zr_status size_error(zr_context *ctx, zr_status s, const char *name,
                            int width, int height) {
  switch (s) {
  case ZR_EINVAL:
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL,
                    "%s: invalid image size %dx%d", name, width, height);
  case ZR_ELIMIT:
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ELIMIT, NULL,
                    "%s: image of %dx%d pixels is larger than the limit "
                    "(%d per side, %zu pixels)",
                    name, width, height, ZR_IMAGE_MAX_SIDE,
                    ZR_IMAGE_MAX_PIXELS);
  default:
    return zr__diag(ctx, ZR_DIAG_ERROR, s, NULL, "%s: %s", name,
                    zr_status_str(s));
  }
}

/* Charges bytes for the image called name, or says why not. */
static zr_status charge(zr_context *ctx, const char *name, int width,
                        int height, size_t bytes) {
  if (!ctx || zr__budget_charge(ctx->budget, bytes))
    return ZR_OK;
  char what[200];
  snprintf(what, sizeof what, "the %dx%d image '%.120s'", width, height,
           name);
  return zr__context_over_budget(ctx, bytes, NULL, what);
}

static void attach_budget(zr_context *ctx, zr_image *image, size_t bytes) {
  if (ctx) {
    image->budget = zr__budget_ref(ctx->budget);
    image->charged = bytes;
  }
}

zr_status zr__image_new_named(zr_context *ctx, const char *name, int width,
                              int height, zr_image **out) {
  zr_status s = check_size(width, height);
  if (s != ZR_OK)
    return size_error(ctx, s, name, width, height);
  size_t bytes = (size_t)width * (size_t)height * 3 * sizeof(float);
  if ((s = charge(ctx, name, width, height, bytes)) != ZR_OK)
    return s;
  s = zr_image_new(width, height, out);
  if (s != ZR_OK) {
    if (ctx)
      zr__budget_release(ctx->budget, bytes);
    return size_error(ctx, s, name, width, height);
  }
  attach_budget(ctx, *out, bytes);
  return ZR_OK;
}

int zr__image_channels(const zr_image *image) {
  return image->layout == ZR_LAYOUT_RGB ? 3 : 1;
}

size_t zr__image_bytes(const zr_image *image) {
  size_t n = (size_t)image->width * (size_t)image->height, bytes = 0;
  if (image->pixels)
    bytes += n * 3 * sizeof(float);
  if (image->codes)
    bytes += n * (size_t)zr__image_channels(image) *
             (image->maxval > 255 ? 2 : 1);
  if (image->indices)
    bytes += n;
  if (image->palette)
    bytes += 3 * 256 * sizeof *image->palette;
  if (image->table)
    bytes += ((size_t)image->maxval + 1) * sizeof *image->table;
  return bytes;
}

zr_status zr__image_new_coded(zr_context *ctx, const char *name, int width,
                              int height, zr_image_layout layout,
                              unsigned maxval, zr_transfer transfer,
                              double exponent, size_t extra,
                              zr_image **out) {
  *out = NULL;
  zr_status s = check_size(width, height);
  if (s != ZR_OK)
    return size_error(ctx, s, name, width, height);
  zr_image *image = image_alloc(width, height);
  if (!image)
    return size_error(ctx, ZR_ENOMEM, name, width, height);
  image->layout = layout;
  image->maxval = maxval;
  size_t n = (size_t)width * (size_t)height;
  /* Charged before anything large is allocated. */
  size_t bytes = (layout == ZR_LAYOUT_INDEX
                      ? n + 3 * 256 * sizeof *image->palette
                      : n * (size_t)zr__image_channels(image) *
                            (maxval > 255 ? 2 : 1)) +
                 ((size_t)maxval + 1) * sizeof(float);
  if (extra > SIZE_MAX - bytes ||
      (s = charge(ctx, name, width, height, bytes + extra)) != ZR_OK) {
    free(image);
    return s != ZR_OK ? s : size_error(ctx, ZR_ELIMIT, name, width, height);
  }
  attach_budget(ctx, image, bytes + extra);
  image->table = zr__decode_table(maxval, transfer, exponent);
  bool ok = image->table != NULL;
  if (layout == ZR_LAYOUT_INDEX) {
    image->indices = calloc(n, 1);
    image->palette = calloc(3 * 256, sizeof *image->palette);
    ok = ok && image->indices && image->palette;
  } else {
    image->codes = calloc(n * (size_t)zr__image_channels(image),
                          maxval > 255 ? 2 : 1);
    ok = ok && image->codes;
  }
  if (!ok) {
    zr_image_free(image);
    return size_error(ctx, ZR_ENOMEM, name, width, height);
  }
  *out = image;
  return ZR_OK;
}

void zr__image_release_extra(zr_image *image, size_t extra) {
  if (image && extra <= image->charged) {
    zr__budget_release(image->budget, extra);
    image->charged -= extra;
  }
}

zr_status zr__image_add_floats(zr_context *ctx, const char *name,
                               zr_image *image) {
  if (image->pixels)
    return ZR_OK;
  size_t n = (size_t)image->width * (size_t)image->height * 3;
  size_t bytes = n * sizeof(float);
  zr_status s = charge(ctx, name, image->width, image->height, bytes);
  if (s != ZR_OK)
    return s;
  float *pixels = malloc(bytes);
  if (!pixels) {
    if (ctx)
      zr__budget_release(ctx->budget, bytes);
    return size_error(ctx, ZR_ENOMEM, name, image->width, image->height);
  }
  for (size_t k = 0; k < n; k++)
    pixels[k] = zr__image_linear(image, k);
  image->pixels = pixels;
  if (ctx) {
    if (!image->budget)
      image->budget = zr__budget_ref(ctx->budget);
    image->charged += bytes;
  }
  return ZR_OK;
}

ZR_API void zr_image_free(zr_image *image) {
  if (!image)
    return;
  if (image->pixels_bytes)
    zr__map_free(image->pixels, image->pixels_bytes);
  else
    free(image->pixels);
  free(image->alpha);
  free(image->codes);
  free(image->table);
  free(image->indices);
  free(image->palette);
  zr__budget_release(image->budget, image->charged);
  zr__budget_unref(image->budget);
  free(image);
}

ZR_API int zr_image_width(const zr_image *image) { return image->width; }

ZR_API int zr_image_height(const zr_image *image) { return image->height; }

ZR_API float *zr_image_pixels(zr_image *image) { return image->pixels; }

ZR_API const float *zr_image_pixels_const(const zr_image *image) {
  return image->pixels;
}

ZR_API zr_status zr_image_add_alpha(zr_image *image) {
  if (!image)
    return ZR_EINVAL;
  if (image->alpha)
    return ZR_OK;
  size_t n = (size_t)image->width * (size_t)image->height;
  image->alpha = malloc(n * sizeof *image->alpha);
  if (!image->alpha)
    return ZR_ENOMEM;
  for (size_t i = 0; i < n; i++)
    image->alpha[i] = 1.0f;
  return ZR_OK;
}

ZR_API float *zr_image_alpha(zr_image *image) {
  return image ? image->alpha : NULL;
}

/* ---- transfer functions ---- */

double zr__srgb_encode(double linear) {
  if (linear <= 0.0031308)
    return 12.92 * linear;
  return 1.055 * pow(linear, 1.0 / 2.4) - 0.055;
}

double zr__srgb_decode(double encoded) {
  if (encoded <= 0.04045)
    return encoded / 12.92;
  return pow((encoded + 0.055) / 1.055, 2.4);
}

float *zr__decode_table(unsigned maxval, zr_transfer transfer,
                        double exponent) {
  float *table = malloc(((size_t)maxval + 1) * sizeof *table);
  if (!table)
    return NULL;
  for (unsigned i = 0; i <= maxval; i++) {
    double e = (double)i / maxval;
    table[i] = (float)(transfer == ZR_TRANSFER_SRGB ? zr__srgb_decode(e)
                                                     : pow(e, exponent));
  }
  return table;
}

unsigned zr__encode_linear(float value, unsigned maxval) {
  double v = !(value > 0.0f) ? 0.0 : value >= 1.0f ? 1.0 : value;
  return (unsigned)lround(v * maxval);
}

float zr__linear_sample(float value, double assumed_gamma) {
  if (!(value > 0.0f))
    return 0.0f; /* negatives and NaN */
  if (!isfinite(value))
    return value > 0.0f ? 65504.0f : 0.0f; /* half's largest finite */
  return assumed_gamma == 1.0 ? value
                              : (float)pow((double)value, assumed_gamma);
}

unsigned zr__encode_sample(float value, double assumed_gamma,
                           unsigned maxval) {
  /* The negated test also sends NaN to black. */
  double v = !(value > 0.0f) ? 0.0 : value >= 1.0f ? 1.0 : value;
  if (assumed_gamma != 1.0)
    v = pow(v, assumed_gamma);
  return (unsigned)lround(zr__srgb_encode(v) * maxval);
}

unsigned zr__encode_code(float value, double assumed_gamma,
                         double file_gamma, unsigned maxval) {
  if (file_gamma <= 0.0)
    return zr__encode_sample(value, assumed_gamma, maxval);
  double v = !(value > 0.0f) ? 0.0 : value >= 1.0f ? 1.0 : value;
  if (assumed_gamma != file_gamma)
    v = pow(v, assumed_gamma / file_gamma);
  return (unsigned)lround(v * maxval);
}

static uint32_t float_bits(float f) {
  uint32_t u;
  memcpy(&u, &f, sizeof u);
  return u;
}

static float bits_float(uint32_t u) {
  float f;
  memcpy(&f, &u, sizeof f);
  return f;
}

void zr__encoder8_init(zr_encoder8 *e, double assumed_gamma,
                       double file_gamma) {
  e->assumed_gamma = assumed_gamma;
  e->file_gamma = file_gamma;
  e->zero = zr__encode_code(0.0f, assumed_gamma, file_gamma, 255);
  e->one = zr__encode_code(1.0f, assumed_gamma, file_gamma, 255);
  /* Positive floats order as their bits do. */
  const uint32_t lo_bits = 1, one_bits = float_bits(1.0f);
  e->first[0] = 0;
  e->first[256] = one_bits;
  for (unsigned k = 1; k < 256; k++) {
    uint32_t lo = lo_bits, hi = one_bits; /* the answer is in [lo, hi] */
    if (lo < e->first[k - 1])
      lo = e->first[k - 1];
    while (lo < hi) {
      uint32_t mid = lo + (hi - lo) / 2;
      if (zr__encode_code(bits_float(mid), assumed_gamma, file_gamma,
                          255) >= k)
        hi = mid;
      else
        lo = mid + 1;
    }
    e->first[k] = lo;
  }
  unsigned k = 0;
  for (uint32_t i = 0; i < sizeof e->start; i++) {
    while (k < 255 && e->first[k + 1] <= i << 16)
      k++;
    e->start[i] = (uint8_t)k;
  }
}

unsigned zr__encoder8_code(const zr_encoder8 *e, float value) {
  if (!(value > 0.0f))
    return e->zero;
  if (value >= 1.0f)
    return e->one;
  uint32_t b = float_bits(value);
  /* The largest k with first[k] <= b. */
  unsigned lo = e->start[b >> 16];
  while (lo < 255 && e->first[lo + 1] <= b)
    lo++;
  if (b - e->first[lo] <= 2 || e->first[lo + 1] - b <= 2)
    return zr__encode_code(value, e->assumed_gamma, e->file_gamma, 255);
  return lo;
}

/* ---- choosing a codec ---- */

static const char *extension(const char *path) {
  const char *slash = strrchr(path, '/');
  const char *dot = strrchr(path, '.');
  if (!dot || (slash && dot < slash))
    return "";
  return dot + 1;
}

ZR_API zr_image_format zr_image_format_from_name(const char *path) {
  if (!path)
    return ZR_FORMAT_AUTO;
  const char *ext = extension(path);
  if (!strcasecmp(ext, "png"))
    return ZR_FORMAT_PNG8;
  if (!strcasecmp(ext, "ppm"))
    return ZR_FORMAT_PPM;
  if (!strcasecmp(ext, "pfm"))
    return ZR_FORMAT_PFM;
  if (!strcasecmp(ext, "jpg") || !strcasecmp(ext, "jpeg"))
    return ZR_FORMAT_JPEG;
  if (!strcasecmp(ext, "tga"))
    return ZR_FORMAT_TGA;
  if (!strcasecmp(ext, "hdr") || !strcasecmp(ext, "pic"))
    return ZR_FORMAT_HDR;
  if (!strcasecmp(ext, "exr"))
    return ZR_FORMAT_EXR;
  if (!strcasecmp(ext, "bmp"))
    return ZR_FORMAT_BMP;
  return ZR_FORMAT_AUTO;
}

static zr_status not_an_image(zr_context *ctx, const char *path) {
  const char *kind = NULL;
  switch (zr_image_format_from_name(path)) {
  case ZR_FORMAT_PNG8:
  case ZR_FORMAT_PNG16:
    kind = "a PNG";
    break;
  case ZR_FORMAT_JPEG:
    kind = "a JPEG";
    break;
  case ZR_FORMAT_PPM:
    kind = "a PPM";
    break;
  case ZR_FORMAT_PFM:
    kind = "a PFM";
    break;
  case ZR_FORMAT_HDR:
    kind = "a Radiance HDR";
    break;
  case ZR_FORMAT_EXR:
    kind = "an OpenEXR";
    break;
  case ZR_FORMAT_BMP:
    kind = "a BMP";
    break;
  case ZR_FORMAT_TGA:
  case ZR_FORMAT_TGA_RLE:
  case ZR_FORMAT_AUTO:
    break;
  }
  if (kind)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL, "%s: not %s file",
                    path, kind);
  return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL,
                  "%s: not a PNG, JPEG, GIF, TGA, BMP, TIFF, PPM, PFM, "
                  "HDR or OpenEXR file", path);
}

static zr_status decode(zr_context *ctx, const char *path,
                        const unsigned char *b, size_t n, zr_image **out) {
  static const unsigned char png_sig[8] = {0x89, 'P', 'N', 'G',
                                           '\r', '\n', 0x1a, '\n'};
  if (n >= 8 && !memcmp(b, png_sig, 8))
    return zr__png_decode(ctx, path, b, n, out);
  if (n >= 3 && b[0] == 0xff && b[1] == 0xd8 && b[2] == 0xff)
    return zr__jpeg_decode(ctx, path, b, n, out);
  if (n >= 6 && (!memcmp(b, "GIF87a", 6) || !memcmp(b, "GIF89a", 6)))
    return zr__gif_decode(ctx, path, b, n, out);
  if (n >= 2 && b[0] == 'P' && (b[1] == 'F' || b[1] == 'f'))
    return zr__pfm_decode(ctx, path, b, n, out);
  if (n >= 2 && b[0] == 'P' && b[1] >= '1' && b[1] <= '7')
    return zr__pnm_decode(ctx, path, b, n, out);
  if (n >= 2 && b[0] == 'B' && b[1] == 'M')
    return zr__bmp_decode(ctx, path, b, n, out);
  if (n >= 4 && (!memcmp(b, "II*\0", 4) || !memcmp(b, "MM\0*", 4)))
    return zr__tiff_decode(ctx, path, b, n, out);
  if (zr__hdr_looks_like(b, n))
    return zr__hdr_decode(ctx, path, b, n, out);
  if (zr__exr_looks_like(b, n))
    return zr__exr_decode(ctx, path, b, n, out);
  /* TGA has no signature: last, when the header makes sense as one. */
  if (zr__tga_looks_like(b, n) || !strcasecmp(extension(path), "tga"))
    return zr__tga_decode(ctx, path, b, n, out);
  return not_an_image(ctx, path);
}

/* An image file's bytes (the caller frees them), with the message
   every image reader gives when the file is missing or unreadable. */
zr_status zr__image_read_bytes(zr_context *ctx, const char *path,
                               char **bytes, size_t *size) {
  zr_status s = zr__context_read(ctx, path, bytes, size);
  if (s == ZR_ENOTFOUND)
    return zr__diag(ctx, ZR_DIAG_ERROR, s, NULL, "%s: file not found",
                    path);
  if (s == ZR_EACCESS)
    return s; /* zr__context_read said why */
  if (s != ZR_OK) {
    char why[160];
    return zr__diag(ctx, ZR_DIAG_ERROR, s, NULL, "%s: cannot read: %s",
                    path, zr__context_read_error(ctx, s, why, sizeof why));
  }
  return ZR_OK;
}

ZR_API zr_status zr_image_read(zr_context *ctx, const char *path,
                               zr_image **out) {
  if (!path || !out)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EINVAL, NULL,
                    "zr_image_read: no path or no output");
  *out = NULL;
  char *bytes = NULL;
  size_t size = 0;
  zr_status s = zr__image_read_bytes(ctx, path, &bytes, &size);
  if (s != ZR_OK)
    return s;
  s = zr__image_decode(ctx, path, bytes, size, out);
  free(bytes);
  /* The public picture is floats (zr_image_pixels). */
  if (s == ZR_OK && (s = zr__image_add_floats(ctx, path, *out)) != ZR_OK) {
    zr_image_free(*out);
    *out = NULL;
  }
  return s;
}

zr_status zr__image_decode(zr_context *ctx, const char *name,
                           const char *bytes, size_t size, zr_image **out) {
  *out = NULL;
  zr_status s = decode(ctx, name, (const unsigned char *)bytes, size, out);
  if (s != ZR_OK && *out) {
    zr_image_free(*out);
    *out = NULL;
  }
  return s;
}

/* ---- encoding ---- */

ZR_API void zr_image_encoding_init(zr_image_encoding *e,
                                   zr_image_format format) {
  e->format = format;
  e->assumed_gamma = 1.0;
  e->file_gamma = 0.0;
  e->quality = 0;
  e->alpha = 1;
}

ZR_API int zr_image_format_supported(zr_image_format format) {
  switch (format) {
  case ZR_FORMAT_PNG8:
  case ZR_FORMAT_PNG16:
  case ZR_FORMAT_PPM:
  case ZR_FORMAT_PFM:
  case ZR_FORMAT_JPEG:
  case ZR_FORMAT_TGA:
  case ZR_FORMAT_TGA_RLE:
  case ZR_FORMAT_HDR:
  case ZR_FORMAT_BMP:
    return 1;
  case ZR_FORMAT_EXR:
    return zr__exr_available();
  case ZR_FORMAT_AUTO:
    break;
  }
  return 0;
}

ZR_API void zr_image_set_rows_wait(zr_image *image, zr_image_rows_fn wait,
                                   void *user) {
  if (image) {
    image->rows_wait = wait;
    image->rows_user = wait ? user : NULL;
  }
}

zr_status zr__image_wait_rows(const zr_image *image, int rows) {
  if (!image->rows_wait)
    return ZR_OK;
  return image->rows_wait(rows, image->rows_user) == 0 ? ZR_OK
                                                         : ZR_ECANCELLED;
}

static zr_status encode(zr_context *ctx, const zr_image *image,
                        const char *path, const zr_image_encoding *e,
                        FILE *f) {
  double g = e->assumed_gamma, fg = e->file_gamma;
  /* PNG reads its rows one after the other as they are final; the other
     formats wait for the whole image first. */
  if (e->format != ZR_FORMAT_PNG8 && e->format != ZR_FORMAT_PNG16) {
    zr_status s = zr__image_wait_rows(image, image->height);
    if (s != ZR_OK)
      return zr__diag(ctx, ZR_DIAG_ERROR, s, NULL, "%s: %s", path,
                      zr_status_str(s));
  }
  switch (e->format) {
  case ZR_FORMAT_PNG8:
    return zr__png_encode(ctx, path, image, 8, e->alpha, g, fg, f);
  case ZR_FORMAT_PNG16:
    return zr__png_encode(ctx, path, image, 16, e->alpha, g, fg, f);
  case ZR_FORMAT_PPM:
    return zr__ppm_encode(ctx, path, image, g, fg, f);
  case ZR_FORMAT_PFM:
    return zr__pfm_encode(ctx, path, image, f);
  case ZR_FORMAT_JPEG:
    return zr__jpeg_encode(ctx, path, image, e, f);
  case ZR_FORMAT_TGA:
  case ZR_FORMAT_TGA_RLE:
    return zr__tga_encode(ctx, path, image, e, f);
  case ZR_FORMAT_HDR:
    return zr__hdr_encode(ctx, path, image, e, f);
  case ZR_FORMAT_EXR:
    return zr__exr_encode(ctx, path, image, e, f);
  case ZR_FORMAT_BMP:
    return zr__bmp_encode(ctx, path, image, e, f);
  case ZR_FORMAT_AUTO:
    break;
  }
  return ZR_EINVAL; /* excluded by check_encoding */
}

/* The checks every entry point makes; path names the output. */
static zr_status check_encoding(zr_context *ctx, const zr_image *image,
                                const char *path,
                                const zr_image_encoding *e) {
  if (!image || !e)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EINVAL, NULL,
                    "%s: no image or no encoding", path);
  if (!(e->assumed_gamma > 0.0) || !isfinite(e->assumed_gamma))
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EINVAL, NULL,
                    "%s: assumed_gamma must be positive, not %g", path,
                    e->assumed_gamma);
  if (!(e->file_gamma >= 0.0) || !isfinite(e->file_gamma))
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EINVAL, NULL,
                    "%s: file_gamma must be 0 (sRGB) or positive, not %g",
                    path, e->file_gamma);
  if (e->format <= ZR_FORMAT_AUTO || e->format > ZR_FORMAT_BMP)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EINVAL, NULL,
                    "%s: unknown image format %d", path, (int)e->format);
  if (!zr_image_format_supported(e->format))
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EUNSUPPORTED, NULL,
                    "%s: this zRcube was built without OpenEXR (configure "
                    "found no libopenexr-dev)", path);
  if (e->quality < 0 || e->quality > 100)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EINVAL, NULL,
                    "%s: JPEG quality must be 0 to 100, not %d", path,
                    e->quality);
  return ZR_OK;
}

/* Encodes, then flushes and checks the stream for a write error. */
static zr_status encode_flushed(zr_context *ctx, const zr_image *image,
                                const char *path, const zr_image_encoding *e,
                                FILE *f) {
  zr_status s = encode(ctx, image, path, e, f);
  if (s == ZR_OK && (fflush(f) != 0 || ferror(f)))
    s = zr__diag(ctx, ZR_DIAG_ERROR, ZR_EIO, NULL, "%s: write failed: %s",
                 path, strerror(errno));
  return s;
}

ZR_API zr_status zr_image_write_file(zr_context *ctx, const zr_image *image,
                                     const zr_image_encoding *e,
                                     FILE *stream) {
  const char *name = "(stream)";
  zr_status s = check_encoding(ctx, image, name, e);
  if (s == ZR_OK && !stream)
    s = zr__diag(ctx, ZR_DIAG_ERROR, ZR_EINVAL, NULL,
                 "zr_image_write_file: no stream");
  return s == ZR_OK ? encode_flushed(ctx, image, name, e, stream) : s;
}

ZR_API zr_status zr_image_encode(zr_context *ctx, const zr_image *image,
                                 const zr_image_encoding *e,
                                 unsigned char **bytes, size_t *size) {
  const char *name = "(memory)";
  if (!bytes || !size)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EINVAL, NULL,
                    "zr_image_encode: no place for the bytes");
  *bytes = NULL;
  *size = 0;
  zr_status s = check_encoding(ctx, image, name, e);
  if (s != ZR_OK)
    return s;
  char *buffer = NULL;
  size_t length = 0;
  FILE *f = open_memstream(&buffer, &length);
  if (!f)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "%s: %s", name,
                    zr_status_str(ZR_ENOMEM));
  s = encode_flushed(ctx, image, name, e, f);
  /* The buffer and its length are final only after fclose. */
  if (fclose(f) != 0 && s == ZR_OK)
    s = zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "%s: %s", name,
                 zr_status_str(ZR_ENOMEM));
  if (s != ZR_OK) {
    free(buffer);
    return s;
  }
  *bytes = (unsigned char *)buffer;
  *size = length;
  return ZR_OK;
}

/* ---- atomic writing ---- */

ZR_API zr_status zr_image_write(zr_context *ctx, const zr_image *image,
                                const char *path, zr_image_format format,
                                double assumed_gamma) {
  zr_image_encoding e;
  zr_image_encoding_init(&e, format);
  e.assumed_gamma = assumed_gamma;
  return zr_image_save(ctx, image, path, &e);
}

ZR_API zr_status zr_image_save(zr_context *ctx, const zr_image *image,
                               const char *path,
                               const zr_image_encoding *enc) {
  if (!image || !path || !enc)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EINVAL, NULL,
                    "zr_image_write: no image or no path");
  zr_image_encoding e = *enc;
  if (e.format == ZR_FORMAT_AUTO) {
    e.format = zr_image_format_from_name(path);
    if (e.format == ZR_FORMAT_AUTO)
      return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EINVAL, NULL,
                      "%s: cannot tell the image format from the name "
                      "(use .png, .jpg, .tga, .bmp, .hdr, .exr, .ppm or "
                      ".pfm)",
                      path);
  }
  zr_status cs = check_encoding(ctx, image, path, &e);
  if (cs != ZR_OK)
    return cs;

  /* The image goes to a new file beside the one it replaces, renamed
     over it once complete: a failure leaves the old file whole.  A
     symbolic link is followed, so the link stays and its file is
     replaced; a device, FIFO or directory is refused by name. */
  char why[512];
  char *target = NULL;
  zr_status ts = zr__io_output_target(path, &target, why, sizeof why);
  if (ts != ZR_OK)
    return ts == ZR_ENOMEM
               ? zr__diag(ctx, ZR_DIAG_ERROR, ts, NULL, "%s: %s", path,
                          zr_status_str(ts))
               : zr__diag(ctx, ZR_DIAG_ERROR, ts, NULL,
                          "cannot write the image: %s", why);
  /* A write that waits for rows (zr_image_set_rows_wait: rank 0's
     writer under mpirun, started with the render) makes its file only
     once the first row is final, and the file has no name until it is
     complete where the system allows (zr__io_temp_open): a process
     killed meanwhile leaves no temporary file behind. */
  zr_status ws = zr__image_wait_rows(image, 1);
  if (ws != ZR_OK) {
    free(target);
    return zr__diag(ctx, ZR_DIAG_ERROR, ws, NULL, "%s: %s", path,
                    zr_status_str(ws));
  }
  zr_io_temp tmp;
  if (zr__io_temp_open(&tmp, target) != 0) {
    zr_status s = zr__diag(ctx, ZR_DIAG_ERROR, ZR_EIO, NULL,
                           "%s: cannot create a file in its folder: %s",
                           path, strerror(errno));
    free(target);
    return s;
  }
  zr_status s = encode_flushed(ctx, image, path, &e, tmp.f);
  if (zr__io_temp_close(&tmp, s == ZR_OK) != 0 && s == ZR_OK)
    s = zr__diag(ctx, ZR_DIAG_ERROR, ZR_EIO, NULL, "%s: write failed: %s",
                 path, strerror(errno));
  if (s == ZR_OK && rename(tmp.name, target) != 0)
    s = zr__diag(ctx, ZR_DIAG_ERROR, ZR_EIO, NULL,
                 "%s: cannot rename %s to it: %s", path, tmp.name,
                 strerror(errno));
  if (s != ZR_OK && tmp.named)
    unlink(tmp.name);
  zr__io_temp_free(&tmp);
  free(target);
  return s;
}
