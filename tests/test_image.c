/*
 * test_image.c - image files: round trips, gamma, every PNG colour type,
 * JPEG, PPM/PGM, PFM, broken and truncated files, atomic writing.
 *
 * Test images are made here with libpng and libjpeg directly (not through
 * the code under test), so a reader bug cannot hide behind a matching
 * writer bug.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <jpeglib.h>
#include <png.h>

#include "core/context.h"
#include "image/image.h"

/* ---- fixture: a temporary directory and a diagnostics catcher ---- */

typedef struct fixture {
  char dir[256];
  char path[512];
  zr_context *ctx;
  char message[1024];
  char warning[1024];
  int errors;
} fixture;

static void catch_diag(const zr_diag *d, void *user) {
  fixture *fx = user;
  if (d->level == ZR_DIAG_ERROR) {
    fx->errors++;
    snprintf(fx->message, sizeof fx->message, "%s", d->message);
  } else if (d->level == ZR_DIAG_WARNING) {
    snprintf(fx->warning, sizeof fx->warning, "%s", d->message);
  }
}

static int setup(void **state) {
  fixture *fx = calloc(1, sizeof *fx);
  if (!fx)
    return -1;
  const char *tmp = getenv("TMPDIR");
  snprintf(fx->dir, sizeof fx->dir, "%s/zr-image-XXXXXX",
           tmp && *tmp ? tmp : "/tmp");
  if (!mkdtemp(fx->dir) || zr_context_new(&fx->ctx) != ZR_OK) {
    free(fx);
    return -1;
  }
  zr_context_set_diag(fx->ctx, catch_diag, fx);
  *state = fx;
  return 0;
}

static int teardown(void **state) {
  fixture *fx = *state;
  DIR *d = opendir(fx->dir);
  if (d) {
    struct dirent *e;
    char p[600];
    while ((e = readdir(d))) {
      if (e->d_name[0] == '.')
        continue;
      snprintf(p, sizeof p, "%s/%s", fx->dir, e->d_name);
      if (remove(p) != 0) {
        /* A directory made by a test: empty it one level down. */
        DIR *sub = opendir(p);
        struct dirent *f;
        char q[900];
        while (sub && (f = readdir(sub)))
          if (f->d_name[0] != '.') {
            snprintf(q, sizeof q, "%s/%s", p, f->d_name);
            remove(q);
          }
        if (sub)
          closedir(sub);
        remove(p);
      }
    }
    closedir(d);
  }
  rmdir(fx->dir);
  zr_context_free(fx->ctx);
  free(fx);
  return 0;
}

/* Sets fx->path to a file of the temporary directory. */
static const char *in_dir(fixture *fx, const char *name) {
  snprintf(fx->path, sizeof fx->path, "%s/%s", fx->dir, name);
  return fx->path;
}

static void write_bytes(const char *path, const void *bytes, size_t n) {
  FILE *f = fopen(path, "wb");
  assert_non_null(f);
  assert_int_equal(fwrite(bytes, 1, n, f), n);
  assert_int_equal(fclose(f), 0);
}

static size_t file_size(const char *path) {
  struct stat st;
  assert_int_equal(stat(path, &st), 0);
  return (size_t)st.st_size;
}

/* Keeps the first n bytes of a file. */
static void truncate_file(const char *path, size_t n) {
  assert_int_equal(truncate(path, (off_t)n), 0);
}

/* Asserts that reading path fails with status and exactly this message. */
static void assert_read_fails(fixture *fx, const char *path,
                              zr_status status, const char *message) {
  zr_image *img = (zr_image *)1;
  fx->message[0] = '\0';
  assert_int_equal(zr_image_read(fx->ctx, path, &img), status);
  assert_string_equal(fx->message, message);
}

/* A deterministic pseudo-random value in [0, 1). */
static float sample_value(size_t i) {
  uint32_t x = (uint32_t)i * 2654435761u + 12345u;
  x ^= x >> 15;
  x *= 2246822519u;
  x ^= x >> 13;
  return (float)(x % 100000u) / 100000.0f;
}

static zr_image *make_test_image(int w, int h) {
  zr_image *img;
  assert_int_equal(zr_image_new(w, h, &img), ZR_OK);
  float *px = zr_image_pixels(img);
  for (size_t i = 0; i < (size_t)w * h * 3; i++)
    px[i] = sample_value(i);
  /* Exact ends of the range must survive too. */
  px[0] = 0.0f;
  px[1] = 1.0f;
  return img;
}

/* ---- a small independent PNG writer (libpng directly) ---- */

typedef struct png_spec {
  int color_type;
  int depth;
  int width;
  int height;
  const unsigned char *rows; /* packed rows, libpng's layout */
  double file_gamma;         /* > 0: write a gAMA chunk */
  int srgb;                  /* write an sRGB chunk */
  const png_color *palette;
  int n_palette;
  int interlace;
  int n_trans; /* > 0: a tRNS chunk of this many palette alphas, all 0 */
} png_spec;

static void write_png(const char *path, const png_spec *sp) {
  FILE *f = fopen(path, "wb");
  assert_non_null(f);
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
  png_infop info = png_create_info_struct(png);
  assert_non_null(info);
  assert_int_equal(setjmp(png_jmpbuf(png)), 0);
  png_init_io(png, f);
  png_set_IHDR(png, info, (png_uint_32)sp->width, (png_uint_32)sp->height,
               sp->depth, sp->color_type,
               sp->interlace ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (sp->palette)
    png_set_PLTE(png, info, sp->palette, sp->n_palette);
  if (sp->n_trans > 0) {
    png_byte alpha[256] = {0};
    png_set_tRNS(png, info, alpha, sp->n_trans, NULL);
  }
  if (sp->file_gamma > 0)
    png_set_gAMA(png, info, sp->file_gamma);
  if (sp->srgb)
    png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  png_write_info(png, info);
  int channels = sp->color_type == PNG_COLOR_TYPE_RGB         ? 3
                 : sp->color_type == PNG_COLOR_TYPE_RGB_ALPHA ? 4
                 : sp->color_type == PNG_COLOR_TYPE_GRAY_ALPHA ? 2
                                                               : 1;
  size_t rowbytes =
      ((size_t)sp->width * (size_t)channels * (size_t)sp->depth + 7) / 8;
  png_bytep *ptrs = malloc((size_t)sp->height * sizeof *ptrs);
  assert_non_null(ptrs);
  for (int y = 0; y < sp->height; y++)
    ptrs[y] = (png_bytep)sp->rows + (size_t)y * rowbytes;
  png_write_image(png, ptrs);
  png_write_end(png, NULL);
  png_destroy_write_struct(&png, &info);
  free(ptrs);
  assert_int_equal(fclose(f), 0);
}

/* ---- a small JPEG writer (libjpeg directly) ---- */

static void write_jpeg(const char *path, int w, int h, int components,
                       const unsigned char *pixels) {
  struct jpeg_compress_struct ci;
  struct jpeg_error_mgr err;
  ci.err = jpeg_std_error(&err);
  jpeg_create_compress(&ci);
  FILE *f = fopen(path, "wb");
  assert_non_null(f);
  jpeg_stdio_dest(&ci, f);
  ci.image_width = (JDIMENSION)w;
  ci.image_height = (JDIMENSION)h;
  ci.input_components = components;
  ci.in_color_space = components == 3 ? JCS_RGB : JCS_GRAYSCALE;
  jpeg_set_defaults(&ci);
  jpeg_set_quality(&ci, 100, TRUE);
  jpeg_start_compress(&ci, TRUE);
  while (ci.next_scanline < ci.image_height) {
    JSAMPROW row = (JSAMPROW)pixels + ci.next_scanline * (size_t)w *
                                          (size_t)components;
    jpeg_write_scanlines(&ci, &row, 1);
  }
  jpeg_finish_compress(&ci);
  jpeg_destroy_compress(&ci);
  assert_int_equal(fclose(f), 0);
}

/* ---- tests ---- */

static void test_image_new_checks_size(void **state) {
  (void)state;
  zr_image *img = NULL;
  assert_int_equal(zr_image_new(0, 5, &img), ZR_EINVAL);
  assert_int_equal(zr_image_new(5, -1, &img), ZR_EINVAL);
  assert_int_equal(zr_image_new(ZR_IMAGE_MAX_SIDE + 1, 1, &img), ZR_ELIMIT);
  assert_int_equal(zr_image_new(40000, 40000, &img), ZR_ELIMIT);
  assert_int_equal(zr_image_new(3, 2, &img), ZR_OK);
  assert_int_equal(zr_image_width(img), 3);
  assert_int_equal(zr_image_height(img), 2);
  for (int i = 0; i < 18; i++)
    assert_true(zr_image_pixels_const(img)[i] == 0.0f);
  zr_image_free(img);
  zr_image_free(NULL);
}

/* A new image is black, whatever its size: big ones are fresh mappings
   (zr__map_zeroed) that nothing writes before the render, small ones
   calloc's.  A first image filled and freed leaves memory that a
   malloc'ed second one could reuse; the second must still be zero. */
static void test_image_new_is_zero(void **state) {
  (void)state;
  static const int sides[][2] = {{3, 2}, {1024, 768}, {2048, 1}};
  for (size_t i = 0; i < sizeof sides / sizeof *sides; i++) {
    int w = sides[i][0], h = sides[i][1];
    size_t n = (size_t)w * (size_t)h * 3;
    zr_image *a = NULL, *b = NULL;
    assert_int_equal(zr_image_new(w, h, &a), ZR_OK);
    float *pa = zr_image_pixels(a);
    for (size_t k = 0; k < n; k++)
      assert_true(pa[k] == 0.0f);
    for (size_t k = 0; k < n; k++)
      pa[k] = 1.0f;
    zr_image_free(a);
    assert_int_equal(zr_image_new(w, h, &b), ZR_OK);
    const float *pb = zr_image_pixels(b);
    size_t nonzero = 0;
    for (size_t k = 0; k < n; k++)
      nonzero += pb[k] != 0.0f;
    assert_int_equal(nonzero, 0);
    zr_image_free(b);
  }
}

static void test_image_format_from_name(void **state) {
  (void)state;
  assert_int_equal(zr_image_format_from_name("a/b.png"), ZR_FORMAT_PNG8);
  assert_int_equal(zr_image_format_from_name("B.PNG"), ZR_FORMAT_PNG8);
  assert_int_equal(zr_image_format_from_name("x.ppm"), ZR_FORMAT_PPM);
  assert_int_equal(zr_image_format_from_name("x.pfm"), ZR_FORMAT_PFM);
  assert_int_equal(zr_image_format_from_name("x.jpg"), ZR_FORMAT_JPEG);
  assert_int_equal(zr_image_format_from_name("x.jpeg"), ZR_FORMAT_JPEG);
  assert_int_equal(zr_image_format_from_name("x.tga"), ZR_FORMAT_TGA);
  assert_int_equal(zr_image_format_from_name("x.hdr"), ZR_FORMAT_HDR);
  assert_int_equal(zr_image_format_from_name("x.exr"), ZR_FORMAT_EXR);
  assert_int_equal(zr_image_format_from_name("x.bmp"), ZR_FORMAT_BMP);
  assert_int_equal(zr_image_format_from_name("x.gif"), ZR_FORMAT_AUTO);
  assert_int_equal(zr_image_format_from_name("dir.png/x"), ZR_FORMAT_AUTO);
  assert_int_equal(zr_image_format_from_name(NULL), ZR_FORMAT_AUTO);
}

static void test_image_srgb_known_values(void **state) {
  (void)state;
  /* Codes are exact integers: the analytic values are 187.52 (0.5 linear)
     and 127.5 + 0.7 (0.5 in a gamma 2.2 working space, 0.2176 linear). */
  assert_int_equal(zr__encode_sample(0.5f, 1.0, 255), 188);
  assert_int_equal(zr__encode_sample(0.0f, 1.0, 255), 0);
  assert_int_equal(zr__encode_sample(1.0f, 1.0, 255), 255);
  assert_int_equal(zr__encode_sample(-3.0f, 1.0, 255), 0);
  assert_int_equal(zr__encode_sample(7.0f, 1.0, 255), 255);
  assert_int_equal(zr__encode_sample(NAN, 1.0, 255), 0);
  assert_int_equal(zr__encode_sample(0.5f, 2.2, 255), 128);
  assert_int_equal(zr__encode_sample(0.5f, 1.0, 65535), 48192);
  /* The curve's two pieces meet: 1e-9 is far above rounding error. */
  assert_true(fabs(zr__srgb_decode(zr__srgb_encode(0.0031308)) -
                   0.0031308) < 1e-9);
  assert_true(fabs(zr__srgb_decode(188.0 / 255) - 0.5029) < 1e-4);
}

/* Compares two images in sRGB-encoded space within tol. */
static void assert_encoded_close(const zr_image *a, const zr_image *b,
                                 double tol) {
  assert_int_equal(zr_image_width(a), zr_image_width(b));
  assert_int_equal(zr_image_height(a), zr_image_height(b));
  const float *pa = zr_image_pixels_const(a);
  const float *pb = zr_image_pixels_const(b);
  size_t n = (size_t)zr_image_width(a) * zr_image_height(a) * 3;
  for (size_t i = 0; i < n; i++) {
    double d = fabs(zr__srgb_encode(pa[i]) - zr__srgb_encode(pb[i]));
    if (d > tol)
      fail_msg("sample %zu: %g vs %g", i, pa[i], pb[i]);
  }
}

static void round_trip(fixture *fx, const char *name, zr_image_format fmt,
                       double tol) {
  zr_image *img = make_test_image(37, 23);
  const char *path = in_dir(fx, name);
  assert_int_equal(zr_image_write(fx->ctx, img, path, fmt, 1.0), ZR_OK);
  zr_image *back = NULL;
  assert_int_equal(zr_image_read(fx->ctx, path, &back), ZR_OK);
  assert_encoded_close(img, back, tol);
  zr_image_free(img);
  zr_image_free(back);
}

static void test_image_png8_round_trip(void **state) {
  /* Rounding to a code loses at most half a step, 0.5/255, in encoded
     space; the tolerance is a whole step to allow float noise. */
  round_trip(*state, "rt8.png", ZR_FORMAT_AUTO, 1.0 / 255);
}

static void test_image_png16_round_trip(void **state) {
  /* Half a step of 1/65535 plus float error in the decode table (about
     1e-7 relative, magnified at most 12.92 times by the sRGB slope). */
  round_trip(*state, "rt16.png", ZR_FORMAT_PNG16, 1.0 / 65535 + 2e-6);
}

static void test_image_ppm_round_trip(void **state) {
  round_trip(*state, "rt.ppm", ZR_FORMAT_AUTO, 1.0 / 255);
}

static void test_image_pfm_round_trip_exact(void **state) {
  fixture *fx = *state;
  zr_image *img = make_test_image(5, 3);
  float *px = zr_image_pixels(img);
  px[3] = -2.5f; /* PFM keeps values outside [0, 1] */
  px[4] = 1e6f;
  px[5] = 1.0f / 3.0f;
  const char *path = in_dir(fx, "rt.pfm");
  assert_int_equal(zr_image_write(fx->ctx, img, path, ZR_FORMAT_AUTO, 2.2),
                   ZR_OK);
  zr_image *back = NULL;
  assert_int_equal(zr_image_read(fx->ctx, path, &back), ZR_OK);
  assert_memory_equal(zr_image_pixels_const(back), px, 5 * 3 * 3 * 4);
  zr_image_free(img);
  zr_image_free(back);
}

static void test_image_write_undoes_assumed_gamma(void **state) {
  fixture *fx = *state;
  zr_image *img;
  assert_int_equal(zr_image_new(1, 1, &img), ZR_OK);
  zr_image_pixels(img)[0] = 0.5f;
  const char *path = in_dir(fx, "g.ppm");
  assert_int_equal(zr_image_write(fx->ctx, img, path, ZR_FORMAT_PPM, 2.2),
                   ZR_OK);
  FILE *f = fopen(path, "rb");
  unsigned char buf[32];
  size_t n = fread(buf, 1, sizeof buf, f);
  fclose(f);
  assert_int_equal(n, 14); /* "P6\n1 1\n255\n" and one pixel */
  assert_memory_equal(buf, "P6\n1 1\n255\n", 11);
  assert_int_equal(buf[11], 128);
  assert_int_equal(buf[12], 0);
  zr_image_free(img);
}

/* Reads path and returns the first pixel's red channel as an sRGB code. */
static double first_code(fixture *fx, const char *path, zr_image **keep) {
  zr_image *img = NULL;
  assert_int_equal(zr_image_read(fx->ctx, path, &img), ZR_OK);
  double code = zr__srgb_encode(zr_image_pixels_const(img)[0]) * 255;
  if (keep)
    *keep = img;
  else
    zr_image_free(img);
  return code;
}

static void test_image_png_grey_palette_alpha(void **state) {
  fixture *fx = *state;
  /* 8-bit grey: one code maps to the same code on all three channels. */
  unsigned char grey[2] = {10, 200};
  png_spec sp = {PNG_COLOR_TYPE_GRAY, 8, 2, 1, grey, 0, 0, NULL, 0, 0, 0};
  const char *path = in_dir(fx, "grey.png");
  write_png(path, &sp);
  zr_image *img;
  assert_true(fabs(first_code(fx, path, &img) - 10) < 1e-3);
  const float *px = zr_image_pixels_const(img);
  assert_true(px[0] == px[1] && px[1] == px[2]);
  assert_true(fabs(zr__srgb_encode(px[3]) * 255 - 200) < 1e-3);
  zr_image_free(img);

  /* 2-bit grey: code 2 of 3 is 170 of 255. */
  unsigned char grey2[1] = {0x80}; /* first pixel 10b */
  png_spec sp2 = {PNG_COLOR_TYPE_GRAY, 2, 1, 1, grey2, 0, 0, NULL, 0, 0, 0};
  path = in_dir(fx, "grey2.png");
  write_png(path, &sp2);
  assert_true(fabs(first_code(fx, path, NULL) - 170) < 1e-3);

  /* A palette: index 1 is (40, 50, 60). */
  png_color pal[2] = {{0, 0, 0}, {40, 50, 60}};
  unsigned char idx[1] = {1};
  png_spec sp3 = {PNG_COLOR_TYPE_PALETTE, 8, 1, 1, idx, 0, 0, pal, 2, 0, 0};
  path = in_dir(fx, "pal.png");
  write_png(path, &sp3);
  assert_int_equal(zr_image_read(fx->ctx, path, &img), ZR_OK);
  px = zr_image_pixels_const(img);
  assert_true(fabs(zr__srgb_encode(px[1]) * 255 - 50) < 1e-3);
  assert_true(fabs(zr__srgb_encode(px[2]) * 255 - 60) < 1e-3);
  zr_image_free(img);
  /* The same with a tRNS chunk (POV-Ray's bumpmap_.png has one): libpng
     makes it an alpha channel, which is skipped. */
  sp3.n_trans = 1;
  path = in_dir(fx, "paltrns.png");
  write_png(path, &sp3);
  assert_int_equal(zr_image_read(fx->ctx, path, &img), ZR_OK);
  px = zr_image_pixels_const(img);
  assert_true(fabs(zr__srgb_encode(px[0]) * 255 - 40) < 1e-3);
  assert_true(fabs(zr__srgb_encode(px[2]) * 255 - 60) < 1e-3);
  zr_image_free(img);

  /* RGBA: alpha is dropped, the stored colour kept (not composited). */
  unsigned char rgba[4] = {100, 150, 200, 0};
  png_spec sp4 = {PNG_COLOR_TYPE_RGB_ALPHA, 8, 1, 1, rgba, 0, 0, NULL, 0, 0, 0};
  path = in_dir(fx, "rgba.png");
  write_png(path, &sp4);
  assert_true(fabs(first_code(fx, path, NULL) - 100) < 1e-3);

  /* 16-bit grey with alpha, interlaced. */
  unsigned char ga16[4 * 3] = {0x80, 0x00, 0xff, 0xff, 0, 0, 0, 0,
                               0, 0, 0, 0};
  png_spec sp5 = {PNG_COLOR_TYPE_GRAY_ALPHA, 16, 3, 1, ga16, 0, 0,
                  NULL, 0, 1, 0};
  path = in_dir(fx, "ga16.png");
  write_png(path, &sp5);
  assert_true(fabs(first_code(fx, path, NULL) - 32768.0 / 65535 * 255) <
              1e-3);
}

static void test_image_png_honours_gama(void **state) {
  fixture *fx = *state;
  /* gAMA 1.0 means the codes are linear: 128 is 128/255 of full light
     (1e-6: float precision of the table). */
  unsigned char v[1] = {128};
  png_spec sp = {PNG_COLOR_TYPE_GRAY, 8, 1, 1, v, 1.0, 0, NULL, 0, 0, 0};
  const char *path = in_dir(fx, "lin.png");
  write_png(path, &sp);
  zr_image *img;
  assert_int_equal(zr_image_read(fx->ctx, path, &img), ZR_OK);
  assert_true(fabs(zr_image_pixels_const(img)[0] - 128.0 / 255) < 1e-6);
  zr_image_free(img);
  /* gAMA 1/2.2: a pure power law, not the sRGB curve. */
  sp.file_gamma = 1.0 / 2.2;
  path = in_dir(fx, "g22.png");
  write_png(path, &sp);
  assert_int_equal(zr_image_read(fx->ctx, path, &img), ZR_OK);
  assert_true(fabs(zr_image_pixels_const(img)[0] -
                   pow(128.0 / 255, 2.2)) < 1e-5);
  zr_image_free(img);
  /* An sRGB chunk means the sRGB curve, though libpng also reports the
     gAMA of 1/2.2 that goes with it: the two differ by 4e-3 here. */
  sp.file_gamma = 0;
  sp.srgb = 1;
  path = in_dir(fx, "srgb.png");
  write_png(path, &sp);
  assert_int_equal(zr_image_read(fx->ctx, path, &img), ZR_OK);
  assert_true(fabs(zr_image_pixels_const(img)[0] -
                   zr__srgb_decode(128.0 / 255)) < 1e-6);
  zr_image_free(img);
}

static void test_image_jpeg_read(void **state) {
  fixture *fx = *state;
  enum { W = 16, H = 8 };
  unsigned char rgb[W * H * 3], grey[W * H];
  for (int i = 0; i < W * H; i++) {
    rgb[3 * i] = 200;
    rgb[3 * i + 1] = 100;
    rgb[3 * i + 2] = 30;
    grey[i] = 77;
  }
  const char *path = in_dir(fx, "flat.jpg");
  write_jpeg(path, W, H, 3, rgb);
  zr_image *img;
  assert_int_equal(zr_image_read(fx->ctx, path, &img), ZR_OK);
  assert_int_equal(zr_image_width(img), W);
  assert_int_equal(zr_image_height(img), H);
  /* A flat colour at quality 100 survives within the rounding of the
     YCbCr conversion: 2 codes. */
  const float *px = zr_image_pixels_const(img);
  for (int i = 0; i < W * H * 3; i++)
    assert_true(fabs(zr__srgb_encode(px[i]) * 255 - rgb[i]) <= 2.0);
  zr_image_free(img);
  path = in_dir(fx, "grey.jpg");
  write_jpeg(path, W, H, 1, grey);
  assert_int_equal(zr_image_read(fx->ctx, path, &img), ZR_OK);
  px = zr_image_pixels_const(img);
  assert_true(fabs(zr__srgb_encode(px[5]) * 255 - 77) <= 1.0);
  assert_true(px[3] == px[4] && px[4] == px[5]);
  zr_image_free(img);
}

static void test_image_ppm_variants(void **state) {
  fixture *fx = *state;
  /* P3 with comments and maxval 1000: 500/1000 is code 127.5. */
  const char p3[] = "P3\n# a comment\n2 1 # size\n1000\n"
                    "500 0 1000\n 0 0 0\n";
  const char *path = in_dir(fx, "a.ppm");
  write_bytes(path, p3, sizeof p3 - 1);
  zr_image *img;
  assert_int_equal(zr_image_read(fx->ctx, path, &img), ZR_OK);
  const float *px = zr_image_pixels_const(img);
  assert_true(fabs(px[0] - zr__srgb_decode(0.5)) < 1e-6);
  assert_true(px[2] == 1.0f);
  zr_image_free(img);
  /* P5, 16 bit big endian: 0x8000 of 65535. */
  const unsigned char p5[] = "P5 1 1 65535\n\x80\x00";
  path = in_dir(fx, "b.pgm");
  write_bytes(path, p5, sizeof p5 - 1);
  assert_int_equal(zr_image_read(fx->ctx, path, &img), ZR_OK);
  px = zr_image_pixels_const(img);
  assert_true(fabs(px[0] - zr__srgb_decode(32768.0 / 65535)) < 1e-6);
  assert_true(px[0] == px[2]);
  zr_image_free(img);
  /* P2 grey ASCII. */
  const char p2[] = "P2 2 1 255 0 255\n";
  path = in_dir(fx, "c.pgm");
  write_bytes(path, p2, sizeof p2 - 1);
  assert_int_equal(zr_image_read(fx->ctx, path, &img), ZR_OK);
  assert_true(zr_image_pixels_const(img)[4] == 1.0f);
  zr_image_free(img);
}

static void test_image_pfm_big_endian_bottom_up(void **state) {
  fixture *fx = *state;
  /* Grey, 1x2, big endian: the file's first row (2.0) is the bottom. */
  const unsigned char pf[] = "Pf\n1 2\n1.0\n"
                             "\x40\x00\x00\x00"  /* 2.0 */
                             "\x3f\x80\x00\x00"; /* 1.0 */
  const char *path = in_dir(fx, "be.pfm");
  write_bytes(path, pf, sizeof pf - 1);
  zr_image *img;
  assert_int_equal(zr_image_read(fx->ctx, path, &img), ZR_OK);
  const float *px = zr_image_pixels_const(img);
  assert_true(px[0] == 1.0f && px[2] == 1.0f);
  assert_true(px[3] == 2.0f && px[5] == 2.0f);
  zr_image_free(img);
}

/* A palette image keeps each pixel's palette entry (image_map's "filter
   INDEX, AMOUNT"), and every PNG its stored codes (image_map's "gamma");
   both are exact integers. */
static void test_image_png_keeps_indices_and_codes(void **state) {
  fixture *fx = *state;
  /* 4-bit indices 2, 0, 1: packed high nibble first. */
  png_color pal[3] = {{10, 20, 30}, {40, 50, 60}, {70, 80, 90}};
  unsigned char idx[2] = {0x20, 0x10};
  png_spec sp = {PNG_COLOR_TYPE_PALETTE, 4, 3, 1, idx, 0, 0, pal, 3, 0, 0};
  const char *path = in_dir(fx, "pal4.png");
  write_png(path, &sp);
  zr_image *img;
  assert_int_equal(zr_image_read(fx->ctx, path, &img), ZR_OK);
  assert_int_equal(img->palette_size, 3);
  assert_non_null(img->indices);
  assert_int_equal(img->indices[0], 2);
  assert_int_equal(img->indices[1], 0);
  assert_int_equal(img->indices[2], 1);
  assert_int_equal(img->maxval, 255);
  assert_int_equal(zr__image_stored(img, 0), 70);
  assert_int_equal(zr__image_stored(img, 5), 30);
  assert_int_equal(zr__image_stored(img, 8), 60);
  assert_true(fabs(zr__srgb_encode(zr__image_linear(img, 6)) * 255 - 40) <
              1e-3);
  zr_image_free(img);

  /* RGB: codes but no indices. */
  unsigned char rgb[3] = {1, 128, 255};
  png_spec sp2 = {PNG_COLOR_TYPE_RGB, 8, 1, 1, rgb, 0, 0, NULL, 0, 0, 0};
  path = in_dir(fx, "rgb.png");
  write_png(path, &sp2);
  assert_int_equal(zr_image_read(fx->ctx, path, &img), ZR_OK);
  assert_null(img->indices);
  assert_int_equal(img->palette_size, 0);
  assert_int_equal(zr__image_stored(img, 0), 1);
  assert_int_equal(zr__image_stored(img, 1), 128);
  assert_int_equal(zr__image_stored(img, 2), 255);
  zr_image_free(img);

  /* Indices 1 and 5 with a palette of 2 (made with Python's zlib): the
     index past the palette reads as black, as in libpng and POV-Ray. */
  static const unsigned char past[] = {
      0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00,
      0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00,
      0x00, 0x01, 0x08, 0x03, 0x00, 0x00, 0x00, 0xc3, 0xfc, 0x8f, 0xb8,
      0x00, 0x00, 0x00, 0x06, 0x50, 0x4c, 0x54, 0x45, 0x01, 0x02, 0x03,
      0x04, 0x05, 0x06, 0x95, 0x53, 0x6f, 0x48, 0x00, 0x00, 0x00, 0x0b,
      0x49, 0x44, 0x41, 0x54, 0x78, 0xda, 0x63, 0x60, 0x64, 0x05, 0x00,
      0x00, 0x0a, 0x00, 0x07, 0x69, 0x39, 0x66, 0x9e, 0x00, 0x00, 0x00,
      0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
  path = in_dir(fx, "past.png");
  write_bytes(path, (const char *)past, sizeof past);
  assert_int_equal(zr_image_read(fx->ctx, path, &img), ZR_OK);
  assert_int_equal(img->indices[1], 5);
  assert_int_equal(zr__image_stored(img, 0), 4);
  assert_true(zr__image_linear(img, 3) == 0 &&
              zr__image_linear(img, 5) == 0);
  char expect[900];
  snprintf(expect, sizeof expect, "%s: 1 pixel(s) with a palette index "
           "past the 2 entries of the palette, read as black", path);
  assert_string_equal(fx->warning, expect);
  zr_image_free(img);
}

static void test_image_broken_files(void **state) {
  fixture *fx = *state;
  char expect[900];
  const char *path = in_dir(fx, "broken.png");
  write_bytes(path, "hello, world\n", 13);
  snprintf(expect, sizeof expect, "%s: not a PNG file", path);
  assert_read_fails(fx, path, ZR_EFORMAT, expect);

  path = in_dir(fx, "empty.dat");
  write_bytes(path, "", 0);
  snprintf(expect, sizeof expect,
           "%s: not a PNG, JPEG, GIF, TGA, BMP, TIFF, PPM, PFM, HDR or "
           "OpenEXR file",
           path);
  assert_read_fails(fx, path, ZR_EFORMAT, expect);

  path = in_dir(fx, "missing.png");
  snprintf(expect, sizeof expect, "%s: file not found", path);
  assert_read_fails(fx, path, ZR_ENOTFOUND, expect);

  /* Truncated PNG: half of a valid file. */
  zr_image *img = make_test_image(40, 30);
  path = in_dir(fx, "trunc.png");
  assert_int_equal(zr_image_write(fx->ctx, img, path, ZR_FORMAT_PNG8, 1.0),
                   ZR_OK);
  truncate_file(path, file_size(path) / 2);
  snprintf(expect, sizeof expect, "%s: truncated PNG file", path);
  assert_read_fails(fx, path, ZR_EFORMAT, expect);
  /* Only the signature and part of IHDR. */
  truncate_file(path, 20);
  assert_read_fails(fx, path, ZR_EFORMAT, expect);

  /* A damaged IHDR: libpng's own words follow ours. */
  path = in_dir(fx, "crc.png");
  assert_int_equal(zr_image_write(fx->ctx, img, path, ZR_FORMAT_PNG8, 1.0),
                   ZR_OK);
  FILE *f = fopen(path, "r+b");
  assert_non_null(f);
  fseek(f, 17, SEEK_SET); /* inside the width field */
  fputc(0x55, f);
  assert_int_equal(fclose(f), 0);
  snprintf(expect, sizeof expect, "%s: invalid PNG file: IHDR: CRC error",
           path);
  assert_read_fails(fx, path, ZR_EFORMAT, expect);
  zr_image_free(img);

  /* Truncated JPEG, and one whose data after the markers is garbage. */
  unsigned char rgb[32 * 32 * 3];
  for (size_t i = 0; i < sizeof rgb; i++)
    rgb[i] = (unsigned char)(i * 7);
  path = in_dir(fx, "trunc.jpg");
  write_jpeg(path, 32, 32, 3, rgb);
  truncate_file(path, file_size(path) * 2 / 3);
  snprintf(expect, sizeof expect, "%s: truncated JPEG file", path);
  assert_read_fails(fx, path, ZR_EFORMAT, expect);
  /* A frame header asking for 12-bit samples, which libjpeg refuses. */
  path = in_dir(fx, "bad.jpg");
  write_jpeg(path, 32, 32, 3, rgb);
  f = fopen(path, "r+b");
  assert_non_null(f);
  unsigned char head[1024];
  size_t n = fread(head, 1, sizeof head, f);
  size_t sof = 0;
  for (size_t i = 2; i + 4 < n && !sof; i++)
    if (head[i] == 0xff && head[i + 1] == 0xc0)
      sof = i;
  assert_true(sof > 0);
  fseek(f, (long)sof + 4, SEEK_SET); /* marker, length, then precision */
  fputc(12, f);
  fclose(f);
  snprintf(expect, sizeof expect,
           "%s: invalid JPEG file: Unsupported JPEG data precision 12",
           path);
  assert_read_fails(fx, path, ZR_EFORMAT, expect);

  /* Damaged scan data still decodes, with one warning. */
  path = in_dir(fx, "damaged.jpg");
  write_jpeg(path, 32, 32, 3, rgb);
  f = fopen(path, "r+b");
  assert_non_null(f);
  n = fread(head, 1, sizeof head, f);
  size_t sos = 0;
  for (size_t i = 2; i + 1 < n; i++)
    if (head[i] == 0xff && head[i + 1] == 0xda)
      sos = i;
  assert_true(sos > 0 && sos + 40 < n);
  fseek(f, (long)(sos + (n - sos) / 2), SEEK_SET);
  fputc(0xff, f); /* a restart marker where none is due */
  fputc(0xd5, f);
  assert_int_equal(fclose(f), 0);
  fx->warning[0] = '\0';
  assert_int_equal(zr_image_read(fx->ctx, path, &img), ZR_OK);
  zr_image_free(img);
  snprintf(expect, sizeof expect,
           "%s: Corrupt JPEG data: premature end of data segment", path);
  assert_string_equal(fx->warning, expect);

  /* Netpbm and PFM. */
  path = in_dir(fx, "t.ppm");
  write_bytes(path, "P6 4 4 255\nabc", 14);
  snprintf(expect, sizeof expect, "%s: truncated PPM file", path);
  assert_read_fails(fx, path, ZR_EFORMAT, expect);
  path = in_dir(fx, "h.ppm");
  write_bytes(path, "P6 4", 4);
  snprintf(expect, sizeof expect, "%s: truncated PPM file", path);
  assert_read_fails(fx, path, ZR_EFORMAT, expect);
  path = in_dir(fx, "m.ppm");
  write_bytes(path, "P3 1 1 10 11 0 0\n", 17);
  snprintf(expect, sizeof expect,
           "%s: invalid PPM file: sample larger than maxval", path);
  assert_read_fails(fx, path, ZR_EFORMAT, expect);
  path = in_dir(fx, "w.ppm");
  write_bytes(path, "P6 x 1 255\n", 11);
  snprintf(expect, sizeof expect, "%s: invalid PPM file: bad width", path);
  assert_read_fails(fx, path, ZR_EFORMAT, expect);
  path = in_dir(fx, "big.ppm");
  write_bytes(path, "P6 60000 60000 255\n", 19);
  snprintf(expect, sizeof expect,
           "%s: image of 60000x60000 pixels is larger than the limit "
           "(65536 per side, 134217728 pixels)",
           path);
  assert_read_fails(fx, path, ZR_ELIMIT, expect);
  path = in_dir(fx, "bits.pbm");
  write_bytes(path, "P4 8 1\n\xff", 8);
  snprintf(expect, sizeof expect,
           "%s: Netpbm type P4 is not supported (use P2, P3, P5 or P6)",
           path);
  assert_read_fails(fx, path, ZR_EUNSUPPORTED, expect);
  path = in_dir(fx, "t.pfm");
  write_bytes(path, "PF\n2 2\n-1.0\n\0\0\0\0", 16);
  snprintf(expect, sizeof expect, "%s: truncated PFM file", path);
  assert_read_fails(fx, path, ZR_EFORMAT, expect);
  path = in_dir(fx, "s.pfm");
  write_bytes(path, "PF\n2 2\n0\n", 9);
  snprintf(expect, sizeof expect, "%s: invalid PFM file: bad scale", path);
  assert_read_fails(fx, path, ZR_EFORMAT, expect);
}

/* Counts the directory's entries other than . and .. */
static int count_entries(const char *dir) {
  DIR *d = opendir(dir);
  assert_non_null(d);
  int n = 0;
  struct dirent *e;
  while ((e = readdir(d)))
    if (strcmp(e->d_name, ".") && strcmp(e->d_name, ".."))
      n++;
  closedir(d);
  return n;
}

static void test_image_write_is_atomic(void **state) {
  fixture *fx = *state;
  zr_image *img = make_test_image(4, 4);
  char expect[900];
  /* The target is a non-empty directory: refused by name before any
     file is made, nothing is left behind and the directory is
     untouched. */
  const char *path = in_dir(fx, "out.png");
  assert_int_equal(mkdir(path, 0777), 0);
  char inner[600];
  snprintf(inner, sizeof inner, "%s/keep", path);
  write_bytes(inner, "x", 1);
  fx->message[0] = '\0';
  assert_int_equal(zr_image_write(fx->ctx, img, path, ZR_FORMAT_AUTO, 1.0),
                   ZR_EACCESS);
  assert_non_null(strstr(fx->message, "is a directory, not a regular "
                                      "file"));
  assert_int_equal(count_entries(fx->dir), 1);
  assert_int_equal(count_entries(path), 1);

  /* A missing directory: no file appears. */
  snprintf(inner, sizeof inner, "%s/no/such/x.png", fx->dir);
  assert_int_equal(zr_image_write(fx->ctx, img, inner, ZR_FORMAT_AUTO, 1.0),
                   ZR_EIO);
  assert_int_equal(count_entries(fx->dir), 1);

  /* An existing file is replaced whole, and no temporary remains. */
  path = in_dir(fx, "o.ppm");
  write_bytes(path, "old", 3);
  assert_int_equal(zr_image_write(fx->ctx, img, path, ZR_FORMAT_AUTO, 1.0),
                   ZR_OK);
  assert_int_equal(file_size(path), 11 + 4 * 4 * 3);
  assert_int_equal(count_entries(fx->dir), 2);

  path = in_dir(fx, "o.gif");
  snprintf(expect, sizeof expect,
           "%s: cannot tell the image format from the name (use .png, "
           ".jpg, .tga, .bmp, .hdr, .exr, .ppm or .pfm)",
           path);
  assert_int_equal(zr_image_write(fx->ctx, img, path, ZR_FORMAT_AUTO, 1.0),
                   ZR_EINVAL);
  assert_string_equal(fx->message, expect);
  assert_int_equal(count_entries(fx->dir), 2);
  zr_image_free(img);
}

/* The 8-bit encoder gives zr__encode_code's code for every float:
   checked on a comb over all floats in (0, 1) and on every float within
   300 of each code boundary, at gammas 1 and 2.2 with sRGB files and
   with power-law file gammas (File_Gamma; 2.2 over 2.2 is a legacy
   scene's identity). */
static void test_image_encoder8_same_codes(void **state) {
  (void)state;
  const double gammas[5][2] = {
      {1.0, 0.0}, {2.2, 0.0}, {2.2, 2.2}, {1.0, 2.2}, {2.2, 1.0}};
  for (int g = 0; g < 5; g++) {
    double ag = gammas[g][0], fg = gammas[g][1];
    zr_encoder8 e;
    zr__encoder8_init(&e, ag, fg);
    uint32_t one;
    float f1 = 1.0f;
    memcpy(&one, &f1, sizeof one);
    for (uint32_t b = 0; b <= one + 8; b += 4093) {
      float v;
      memcpy(&v, &b, sizeof v);
      assert_int_equal(zr__encoder8_code(&e, v),
                       zr__encode_code(v, ag, fg, 255));
    }
    for (int k = 1; k < 256; k++)
      for (int d = -300; d <= 300; d++) {
        uint32_t b = e.first[k] + (uint32_t)d;
        float v;
        memcpy(&v, &b, sizeof v);
        assert_int_equal(zr__encoder8_code(&e, v),
                         zr__encode_code(v, ag, fg, 255));
      }
    const float odd[] = {-1.0f, 0.0f, -0.0f, 1.0f, 2.0f, NAN, INFINITY};
    for (size_t i = 0; i < sizeof odd / sizeof *odd; i++)
      assert_int_equal(zr__encoder8_code(&e, odd[i]),
                       zr__encode_code(odd[i], ag, fg, 255));
  }
}

/* The codes POV-Ray 3.7 writes for flat colours seen with ambient 1
   (bench/conform/legacy_gamma_probe.py): a legacy scene's as they are
   (assumed_gamma 2.2 over file gamma 2.2), sRGB under assumed_gamma 1,
   and the power-law File_Gamma settings. */
static void test_image_file_gamma_codes(void **state) {
  (void)state;
  const float v[5] = {0.002f, 0.01f, 0.05f, 0.135f, 0.3f};
  const unsigned legacy[5] = {1, 3, 13, 34, 77};
  const unsigned srgb[5] = {7, 25, 63, 103, 149};
  const unsigned file22[5] = {15, 31, 65, 103, 148}; /* assumed 1 */
  const unsigned file1[5] = {0, 0, 0, 3, 18};        /* assumed 2.2 */
  for (int i = 0; i < 5; i++) {
    assert_int_equal(zr__encode_code(v[i], 2.2, 2.2, 255), legacy[i]);
    assert_int_equal(zr__encode_code(v[i], 1.0, 0.0, 255), srgb[i]);
    assert_int_equal(zr__encode_code(v[i], 1.0, 2.2, 255), file22[i]);
    assert_int_equal(zr__encode_code(v[i], 2.2, 1.0, 255), file1[i]);
  }
  assert_int_equal(zr__encode_code(0.5f, 1.0, 0.0, 255),
                   zr__encode_sample(0.5f, 1.0, 255));
}

/* The PNG level changes the bytes' size, never the pixels: level 0
   stores the rows, 9 compresses them (a smooth ramp shrinks a lot). */
static void test_image_png_level(void **state) {
  fixture *fx = *state;
  assert_int_equal(zr_context_set_png_level(fx->ctx, 10), ZR_EINVAL);
  assert_int_equal(zr_context_set_png_level(fx->ctx, -1), ZR_EINVAL);
  zr_image *img = make_test_image(64, 64);
  const char *names[2] = {"l0.png", "l9.png"};
  long size[2];
  for (int k = 0; k < 2; k++) {
    assert_int_equal(zr_context_set_png_level(fx->ctx, 9 * k), ZR_OK);
    const char *path = in_dir(fx, names[k]);
    assert_int_equal(zr_image_write(fx->ctx, img, path, ZR_FORMAT_PNG8, 1.0),
                     ZR_OK);
    size[k] = file_size(path);
    zr_image *back = NULL;
    assert_int_equal(zr_image_read(fx->ctx, path, &back), ZR_OK);
    assert_encoded_close(img, back, 1.0 / 255);
    zr_image_free(back);
  }
  /* Level 0: the 64 rows of 1 + 192 bytes, stored, plus headers. */
  assert_true(size[0] > 64 * 193);
  assert_true(size[1] < size[0]);
  zr_image_free(img);
}

/* Reads a big-endian 32-bit number (PNG chunk lengths). */
static size_t be32(const unsigned char *p) {
  return (size_t)p[0] << 24 | (size_t)p[1] << 16 | (size_t)p[2] << 8 | p[3];
}

/* Rows reach zlib unfiltered (png.c: libpng's five-filter search cost
   most of a write and saved nothing on rendered pictures).  At level 0
   zlib stores the bytes as they come, so the IDAT data, once its stored
   blocks (RFC 1951, 3.2.4) are unwrapped, is the rows themselves, each
   after its filter-type byte: 0 (None) on every row, then the codes.
   The test ramp is smooth, which libpng's own choice would filter with
   Sub, Up or Paeth. */
static void test_image_png_rows_unfiltered(void **state) {
  fixture *fx = *state;
  enum { W = 32, H = 16, ROW = 1 + 3 * W };
  assert_int_equal(zr_context_set_png_level(fx->ctx, 0), ZR_OK);
  zr_image *img = make_test_image(W, H);
  const char *path = in_dir(fx, "filter.png");
  assert_int_equal(zr_image_write(fx->ctx, img, path, ZR_FORMAT_PNG8, 1.0),
                   ZR_OK);
  size_t size = file_size(path);
  unsigned char *file = malloc(size);
  unsigned char *z = malloc(size);
  assert_non_null(file);
  assert_non_null(z);
  FILE *f = fopen(path, "rb");
  assert_non_null(f);
  assert_int_equal(fread(file, 1, size, f), size);
  fclose(f);
  /* The zlib stream: the IDAT chunks' data, end to end. */
  size_t nz = 0;
  for (size_t at = 8; at + 12 <= size;) {
    size_t len = be32(file + at);
    assert_true(at + 12 + len <= size);
    if (memcmp(file + at + 4, "IDAT", 4) == 0) {
      memcpy(z + nz, file + at + 8, len);
      nz += len;
    }
    at += 12 + len;
  }
  /* Two header bytes, then stored blocks: a type byte (0 or 1 for the
     last), LEN and its complement, LEN bytes. */
  unsigned char rows[H * ROW];
  size_t nrows = 0, at = 2;
  bool last = false;
  while (!last) {
    assert_true(at + 5 <= nz);
    assert_int_equal(z[at] & 6, 0); /* BTYPE 00: stored */
    last = z[at] & 1;
    size_t len = (size_t)z[at + 1] | (size_t)z[at + 2] << 8;
    assert_int_equal(len ^ ((size_t)z[at + 3] | (size_t)z[at + 4] << 8),
                     0xffff);
    assert_true(at + 5 + len <= nz && nrows + len <= sizeof rows);
    memcpy(rows + nrows, z + at + 5, len);
    nrows += len;
    at += 5 + len;
  }
  assert_int_equal(nrows, sizeof rows);
  const float *px = zr_image_pixels_const(img);
  for (int y = 0; y < H; y++) {
    assert_int_equal(rows[y * ROW], 0);
    for (int i = 0; i < 3 * W; i++)
      assert_int_equal(rows[y * ROW + 1 + i],
                       zr__encode_sample(px[y * 3 * W + i], 1.0, 255));
  }
  free(file);
  free(z);
  zr_image_free(img);
}

static void test_image_null_context_is_silent(void **state) {
  (void)state;
  zr_image *img = NULL;
  assert_int_equal(zr_image_read(NULL, "/nonexistent/zr.png", &img),
                   ZR_ENOTFOUND);
  assert_null(img);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_image_new_checks_size),
      cmocka_unit_test(test_image_new_is_zero),
      cmocka_unit_test(test_image_format_from_name),
      cmocka_unit_test(test_image_srgb_known_values),
      cmocka_unit_test(test_image_encoder8_same_codes),
      cmocka_unit_test(test_image_file_gamma_codes),
      cmocka_unit_test_setup_teardown(test_image_png_level, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_image_png_rows_unfiltered, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_image_png8_round_trip, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_image_png16_round_trip, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_image_ppm_round_trip, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_image_pfm_round_trip_exact, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_image_write_undoes_assumed_gamma,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_image_png_grey_palette_alpha,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_image_png_honours_gama, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_image_jpeg_read, setup, teardown),
      cmocka_unit_test_setup_teardown(test_image_ppm_variants, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_image_pfm_big_endian_bottom_up,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_image_png_keeps_indices_and_codes,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_image_broken_files, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_image_write_is_atomic, setup,
                                      teardown),
      cmocka_unit_test(test_image_null_context_is_silent),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
