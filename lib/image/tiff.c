/*
 * tiff.c - TIFF files read from memory through libtiff (4.5 or newer),
 * for the "tiff" image type of image maps (POV-Ray 3.7 reference,
 * "Image Maps").
 *
 * libtiff's RGBA interface reads every kind of TIFF it knows (grey,
 * palette, RGB, YCbCr, CMYK, 1 to 16 bits, strips or tiles, any
 * compression it was built with) into 8-bit red, green, blue and alpha,
 * which is the precision the other 8-bit formats have here; the first
 * image of the file is read.  An image_map takes the samples as they
 * are, in the scene's working space (code / 255 under any
 * assumed_gamma), as PPM's (codes_working), which is what POV-Ray
 * 3.7.0.10 does, though its manual's "Gamma in Input Images" presumes
 * sRGB for "any other file formats": under assumed_gamma 1 its image_map
 * of a TIFF shows code 60 as 0.235, where the same picture as PNG, JPEG
 * or BMP shows 0.045, and under assumed_gamma 2.2 as 0.235 ^ 2.2
 * (tests/test_image_gamma_formats.sh).  "gamma G" or "gamma srgb" after
 * the file name decodes them as it does a PNG's.
 * Alpha is kept: libtiff's RGBA interface hands colours over
 * associated with (multiplied by) alpha, whichever kind the file
 * stores, and POV-Ray 3.7 takes a TIFF's alpha as associated ("Using
 * the Alpha Channel"), so each code is divided by its alpha again
 * (rounded, at most 255): straight colour and alpha, as for PNG
 * (tests/test_image_alpha.sh).
 *
 * libtiff's default handlers print errors and warnings on stderr; they
 * are replaced per file (TIFFOpenOptions, libtiff 4.5) so that the first
 * error reaches the context and warnings are dropped.  Bytes are served
 * from memory by client procedures, so files handed over by the MPI
 * reader work as local ones.
 *
 * libtiff is opened (dlopen) when the first TIFF is read, not linked:
 * loading it and what it needs (libstdc++ through LERC, zstd, lzma,
 * webp, jbig, deflate: 9 libraries) at start-up cost every process
 * about 5 ms of CPU on this project's machine, a scene without a TIFF
 * as much as one with (issue 13: zrcube --version took 17 ms; a
 * program linked with libpng, libjpeg and OpenEXRCore started in
 * 5.5 ms, 10.6 with libtiff as well).  It stays open for the process.
 * The header still gives the types, so the calls are checked against
 * it as before.
 */
#include "config.h"

#include <dlfcn.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <tiffio.h>

#include "core/context.h"
#include "image/image.h"

/* The largest single allocation libtiff may make for a hostile file:
   more than a strip or tile of the largest image read needs. */
#define MAX_TIFF_ALLOC ((tmsize_t)1 << 29)

#ifndef ZR_TIFF_SONAME
#define ZR_TIFF_SONAME "libtiff.so.6"
#endif

/* The libtiff functions used here, from the library opened at run time. */
typedef struct tiff_api {
  __typeof__(TIFFOpenOptionsAlloc) *OpenOptionsAlloc;
  __typeof__(TIFFOpenOptionsFree) *OpenOptionsFree;
  __typeof__(TIFFOpenOptionsSetErrorHandlerExtR) *SetErrorHandlerExtR;
  __typeof__(TIFFOpenOptionsSetWarningHandlerExtR) *SetWarningHandlerExtR;
  __typeof__(TIFFOpenOptionsSetMaxSingleMemAlloc) *SetMaxSingleMemAlloc;
  __typeof__(TIFFClientOpenExt) *ClientOpenExt;
  __typeof__(TIFFGetField) *GetField;
  __typeof__(TIFFRGBAImageOK) *RGBAImageOK;
  __typeof__(TIFFReadRGBAImageOriented) *ReadRGBAImageOriented;
  __typeof__(TIFFClose) *Close;
} tiff_api;

static pthread_once_t api_once = PTHREAD_ONCE_INIT;
static bool api_ok;
static tiff_api api;
static char api_why[160];

/* Opens libtiff and finds its functions: run once per process. */
static void open_api(void) {
  void *h = dlopen(ZR_TIFF_SONAME, RTLD_NOW | RTLD_LOCAL);
  bool ok = h != NULL;
  const char *missing = NULL;
#define ZR_TIFF_SYM(field, name)                                             \
  do {                                                                       \
    void *sym = ok ? dlsym(h, name) : NULL;                                  \
    if (!sym && ok)                                                          \
      ok = false, missing = name;                                            \
    /* POSIX dlsym: an object pointer that holds a function's address. */   \
    memcpy(&api.field, &sym, sizeof sym);                                    \
  } while (0)
  ZR_TIFF_SYM(OpenOptionsAlloc, "TIFFOpenOptionsAlloc");
  ZR_TIFF_SYM(OpenOptionsFree, "TIFFOpenOptionsFree");
  ZR_TIFF_SYM(SetErrorHandlerExtR, "TIFFOpenOptionsSetErrorHandlerExtR");
  ZR_TIFF_SYM(SetWarningHandlerExtR, "TIFFOpenOptionsSetWarningHandlerExtR");
  ZR_TIFF_SYM(SetMaxSingleMemAlloc, "TIFFOpenOptionsSetMaxSingleMemAlloc");
  ZR_TIFF_SYM(ClientOpenExt, "TIFFClientOpenExt");
  ZR_TIFF_SYM(GetField, "TIFFGetField");
  ZR_TIFF_SYM(RGBAImageOK, "TIFFRGBAImageOK");
  ZR_TIFF_SYM(ReadRGBAImageOriented, "TIFFReadRGBAImageOriented");
  ZR_TIFF_SYM(Close, "TIFFClose");
#undef ZR_TIFF_SYM
  if (!h)
    snprintf(api_why, sizeof api_why, "cannot open %s", ZR_TIFF_SONAME);
  else if (!ok)
    snprintf(api_why, sizeof api_why, "%s lacks %s", ZR_TIFF_SONAME,
             missing);
  if (h && !ok)
    dlclose(h);
  api_ok = ok;
}

/* libtiff's functions, opened at the first call of any thread (others
   wait for it); NULL (api_why says why) without it. */
static const tiff_api *tiff_open_api(void) {
  pthread_once(&api_once, open_api);
  return api_ok ? &api : NULL;
}

typedef struct tiff_source {
  const unsigned char *bytes;
  size_t size, pos;
  char message[256];
} tiff_source;

static tmsize_t on_read(thandle_t h, void *buf, tmsize_t n) {
  tiff_source *src = (tiff_source *)h;
  if (n < 0)
    return -1;
  size_t left = src->size - src->pos;
  size_t k = (size_t)n < left ? (size_t)n : left;
  memcpy(buf, src->bytes + src->pos, k);
  src->pos += k;
  return (tmsize_t)k;
}

static tmsize_t on_write(thandle_t h, void *buf, tmsize_t n) {
  (void)h;
  (void)buf;
  (void)n;
  return -1; /* read only */
}

static toff_t on_seek(thandle_t h, toff_t off, int whence) {
  tiff_source *src = (tiff_source *)h;
  uint64_t base = whence == SEEK_CUR   ? src->pos
                  : whence == SEEK_END ? src->size
                                       : 0;
  uint64_t to = base + off;
  if (to > src->size)
    return (toff_t)-1;
  src->pos = (size_t)to;
  return to;
}

static int on_close(thandle_t h) {
  (void)h;
  return 0;
}

static toff_t on_size(thandle_t h) { return ((tiff_source *)h)->size; }

static int on_map(thandle_t h, void **base, toff_t *size) {
  (void)h;
  (void)base;
  (void)size;
  return 0; /* no mapping: libtiff reads through on_read */
}

static void on_unmap(thandle_t h, void *base, toff_t size) {
  (void)h;
  (void)base;
  (void)size;
}

static int on_error(TIFF *tif, void *user, const char *module,
                    const char *fmt, va_list ap) {
  (void)tif;
  (void)module;
  tiff_source *src = user;
  if (!src->message[0])
    vsnprintf(src->message, sizeof src->message, fmt, ap);
  return 1; /* handled: nothing printed */
}

static int on_warning(TIFF *tif, void *user, const char *module,
                      const char *fmt, va_list ap) {
  (void)tif;
  (void)user;
  (void)module;
  (void)fmt;
  (void)ap;
  return 1;
}

static zr_status failed(zr_context *ctx, const char *name,
                        const tiff_source *src, const char *what) {
  return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL, "%s: %s%s%s", name,
                  what, src->message[0] ? ": " : "", src->message);
}

zr_status zr__tiff_decode(zr_context *ctx, const char *name,
                          const unsigned char *bytes, size_t size,
                          zr_image **out) {
  *out = NULL;
  tiff_source src = {bytes, size, 0, ""};
  const tiff_api *t = tiff_open_api();
  if (!t)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EUNSUPPORTED, NULL,
                    "%s: TIFF images need libtiff at run time: %s", name,
                    api_why);
  TIFFOpenOptions *opts = t->OpenOptionsAlloc();
  if (!opts)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "%s: %s", name,
                    zr_status_str(ZR_ENOMEM));
  t->SetErrorHandlerExtR(opts, on_error, &src);
  t->SetWarningHandlerExtR(opts, on_warning, &src);
  t->SetMaxSingleMemAlloc(opts, MAX_TIFF_ALLOC);
  /* "rm": read, and never memory-map (the bytes are ours already). */
  TIFF *tif = t->ClientOpenExt(name, "rm", (thandle_t)&src, on_read,
                                on_write, on_seek, on_close, on_size, on_map,
                                on_unmap, opts);
  t->OpenOptionsFree(opts);
  if (!tif)
    return failed(ctx, name, &src, "not a readable TIFF file");
  uint32_t w = 0, h = 0;
  t->GetField(tif, TIFFTAG_IMAGEWIDTH, &w);
  t->GetField(tif, TIFFTAG_IMAGELENGTH, &h);
  char why[1024] = "";
  if (w == 0 || h == 0 || w > INT32_MAX || h > INT32_MAX ||
      !t->RGBAImageOK(tif, why)) {
    t->Close(tif);
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EUNSUPPORTED, NULL,
                    "%s: this kind of TIFF is not supported%s%.200s", name,
                    why[0] ? ": " : "", why);
  }
  zr_image *image = NULL;
  zr_status s = zr__image_new_named(ctx, name, (int)w, (int)h, &image);
  if (s != ZR_OK) {
    t->Close(tif);
    return s;
  }
  size_t count = (size_t)w * h;
  uint32_t *raster = malloc(count * sizeof *raster);
  float *table = zr__decode_table(255, ZR_TRANSFER_SRGB, 0.0);
  image->codes = malloc(count * 3); /* 8-bit codes (image.h) */
  image->codes_working = true;
  image->maxval = 255;
  if (!raster || !table || !image->codes) {
    free(raster);
    free(table);
    zr_image_free(image);
    t->Close(tif);
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "%s: %s", name,
                    zr_status_str(ZR_ENOMEM));
  }
  /* stop_on_error = 1: a damaged file is an error, not a grey patch. */
  int ok = t->ReadRGBAImageOriented(tif, w, h, raster, ORIENTATION_TOPLEFT,
                                     1);
  t->Close(tif);
  bool alpha = false;
  for (size_t i = 0; ok && i < count && !alpha; i++)
    alpha = TIFFGetA(raster[i]) < 255;
  image->alpha_associated = alpha;
  if (alpha && zr_image_add_alpha(image) != ZR_OK) {
    free(raster);
    free(table);
    zr_image_free(image);
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "%s: %s", name,
                    zr_status_str(ZR_ENOMEM));
  }
  if (ok) {
    for (size_t i = 0; i < count; i++) {
      unsigned rgb[3] = {TIFFGetR(raster[i]), TIFFGetG(raster[i]),
                         TIFFGetB(raster[i])};
      unsigned a = TIFFGetA(raster[i]);
      if (alpha) {
        image->alpha[i] = (float)(a / 255.0);
        for (int c = 0; c < 3 && a > 0; c++) {
          unsigned v = (rgb[c] * 255 + a / 2) / a;
          rgb[c] = v > 255 ? 255 : v;
        }
      }
      for (int c = 0; c < 3; c++) {
        ((unsigned char *)image->codes)[3 * i + c] = (unsigned char)rgb[c];
        image->pixels[3 * i + c] = table[rgb[c]];
      }
    }
  }
  free(raster);
  free(table);
  if (!ok) {
    zr_image_free(image);
    return failed(ctx, name, &src, "damaged TIFF file");
  }
  *out = image;
  return ZR_OK;
}
