/*
 * test_image_io.c - the writers and readers of issue 12 (lib/image:
 * jpeg_write.c, tga_write.c, hdr.c, exr.c, bmp.c, tiff.c) and encoding
 * to memory and to a stream (image.c).
 *
 * Every writer is checked by reading its bytes back: TGA exactly (the
 * stored sRGB codes), JPEG within a tolerance (lossy: mean error in
 * codes), HDR within RGBE's precision (8-bit mantissa: 1/128 relative
 * at worst, plus the half-step of the rounding), OpenEXR within half's
 * (11-bit mantissa: 2^-11 relative).  Alpha is checked in the stored
 * bytes (our readers drop alpha).  BMP files are built here byte by byte
 * from Microsoft's documented layout, TIFF files with libtiff, and the
 * damaged ones must give their exact message.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <tiffio.h>

#include "image/image.h"
#include "zrcube.h"

typedef struct fixture {
  zr_context *ctx;
  char message[1024];
  int errors;
} fixture;

static void catch_diag(const zr_diag *d, void *user) {
  fixture *fx = user;
  if (d->level == ZR_DIAG_ERROR) {
    fx->errors++;
    snprintf(fx->message, sizeof fx->message, "%s", d->message);
  }
}

static int setup(void **state) {
  fixture *fx = calloc(1, sizeof *fx);
  if (!fx || zr_context_new(&fx->ctx) != ZR_OK)
    return -1;
  zr_context_set_diag(fx->ctx, catch_diag, fx);
  *state = fx;
  return 0;
}

static int teardown(void **state) {
  fixture *fx = *state;
  zr_context_free(fx->ctx);
  free(fx);
  return 0;
}

/* A w x h picture: smooth ramps, a flat band (runs for the encoders),
   values up to scale. */
static zr_image *picture(int w, int h, float scale) {
  zr_image *im = NULL;
  assert_int_equal(zr_image_new(w, h, &im), ZR_OK);
  float *p = zr_image_pixels(im);
  for (int y = 0; y < h; y++)
    for (int x = 0; x < w; x++) {
      float *q = p + 3 * ((size_t)y * w + x);
      if (y % 3 == 1) { /* flat rows */
        q[0] = 0.25f * scale;
        q[1] = 0.5f * scale;
        q[2] = 0.75f * scale;
      } else {
        q[0] = scale * (float)x / (float)(w - 1);
        q[1] = scale * (float)y / (float)(h - 1);
        q[2] = scale * (float)((x * 7 + y * 13) % 17) / 16.0f;
      }
    }
  return im;
}

static zr_image *decode(fixture *fx, const unsigned char *bytes, size_t n) {
  zr_image *im = NULL;
  zr_status s = zr__image_decode(fx->ctx, "mem", (const char *)bytes, n, &im);
  if (s != ZR_OK)
    fail_msg("decode failed: %s (%s)", zr_status_str(s), fx->message);
  return im;
}

static unsigned char *encode(fixture *fx, const zr_image *im,
                             zr_image_format format, int quality,
                             size_t *n) {
  zr_image_encoding e;
  zr_image_encoding_init(&e, format);
  e.quality = quality;
  unsigned char *bytes = NULL;
  zr_status s = zr_image_encode(fx->ctx, im, &e, &bytes, n);
  if (s != ZR_OK)
    fail_msg("encode failed: %s (%s)", zr_status_str(s), fx->message);
  assert_non_null(bytes);
  return bytes;
}

static void test_image_io_tga_exact(void **state) {
  fixture *fx = *state;
  zr_image *im = picture(37, 11, 1.0f);
  for (int rle = 0; rle < 2; rle++) {
    size_t n = 0;
    unsigned char *b =
        encode(fx, im, rle ? ZR_FORMAT_TGA_RLE : ZR_FORMAT_TGA, 0, &n);
    assert_int_equal(b[2], rle ? 10 : 2);
    assert_int_equal(b[16], 24);
    if (!rle)
      assert_int_equal(n, 18 + 37 * 11 * 3);
    else
      assert_true(n < 18 + 37 * 11 * 3); /* the flat rows are runs */
    zr_image *back = decode(fx, b, n);
    assert_int_equal(zr_image_width(back), 37);
    assert_int_equal(zr_image_height(back), 11);
    const float *p = zr_image_pixels_const(im);
    for (size_t i = 0; i < 37 * 11 * 3; i++)
      assert_int_equal(zr__image_stored(back, i),
                       zr__encode_sample(p[i], 1.0, 255));
    zr_image_free(back);
    free(b);
  }
  zr_image_free(im);
}

/* A row that alternates runs and literal stretches across the 128-pixel
   packet limit. */
static void test_image_io_tga_rle_packets(void **state) {
  fixture *fx = *state;
  zr_image *im = NULL;
  assert_int_equal(zr_image_new(300, 2, &im), ZR_OK);
  float *p = zr_image_pixels(im);
  for (int x = 0; x < 300; x++)
    for (int c = 0; c < 3; c++) {
      float v = x < 140 ? 0.5f : x < 290 ? (float)(x % 5) / 4.0f : 1.0f;
      p[3 * x + c] = v;
      p[3 * (300 + x) + c] = (float)((x * 31) % 256) / 255.0f;
    }
  size_t n = 0;
  unsigned char *b = encode(fx, im, ZR_FORMAT_TGA_RLE, 0, &n);
  zr_image *back = decode(fx, b, n);
  for (size_t i = 0; i < 600 * 3; i++)
    assert_int_equal(zr__image_stored(back, i),
                       zr__encode_sample(p[i], 1.0, 255));
  zr_image_free(back);
  free(b);
  zr_image_free(im);
}

/* Mean and largest difference of stored sRGB codes. */
static void code_error(const zr_image *a, const zr_image *b, double *mean,
                       unsigned *worst) {
  size_t n = (size_t)a->width * a->height * 3;
  double sum = 0;
  *worst = 0;
  for (size_t i = 0; i < n; i++) {
    int d = (int)zr__encode_sample(a->pixels[i], 1.0, 255) -
            (int)zr__encode_sample(zr__image_linear(b, i), 1.0, 255);
    unsigned ad = (unsigned)abs(d);
    sum += ad;
    if (ad > *worst)
      *worst = ad;
  }
  *mean = sum / (double)n;
}

static void test_image_io_jpeg(void **state) {
  fixture *fx = *state;
  zr_image *im = picture(64, 48, 1.0f);
  size_t n95 = 0, n2 = 0, n0 = 0, n85 = 0;
  unsigned char *b95 = encode(fx, im, ZR_FORMAT_JPEG, 95, &n95);
  unsigned char *b2 = encode(fx, im, ZR_FORMAT_JPEG, 2, &n2);
  unsigned char *b0 = encode(fx, im, ZR_FORMAT_JPEG, 0, &n0);
  unsigned char *b85 = encode(fx, im, ZR_FORMAT_JPEG, 85, &n85);
  /* 0 means the default, 85 (POV-Ray 3.7 reference). */
  assert_int_equal(n0, n85);
  assert_memory_equal(b0, b85, n0);
  assert_true(n2 < n95);
  zr_image *back = decode(fx, b95, n95);
  double mean;
  unsigned worst;
  code_error(im, back, &mean, &worst);
  print_message("JPEG quality 95: mean %.3f codes, worst %u\n", mean, worst);
  /* Quality 95 without chroma subsampling: measured mean 3.1 codes,
     worst 20, on this picture whose blue channel is noise of period 17
     (the hardest case for a DCT); the bounds leave room for another
     libjpeg's rounding.  Quality 2 must be far worse. */
  assert_true(mean < 4.5);
  assert_true(worst < 32);
  zr_image *rough = decode(fx, b2, n2);
  double mean2;
  unsigned worst2;
  code_error(im, rough, &mean2, &worst2);
  print_message("JPEG quality 2: mean %.3f codes, worst %u\n", mean2,
                worst2);
  assert_true(mean2 > 3 * mean);
  zr_image_free(rough);
  /* 4:4:4: every component's sampling factors are 1 (SOF0 at its
     place after the tables: find the marker). */
  for (size_t i = 0; i + 18 < n95; i++)
    if (b95[i] == 0xff && b95[i + 1] == 0xc0) {
      assert_int_equal(b95[i + 9], 3);        /* components */
      assert_int_equal(b95[i + 11], 0x11);    /* Y 1x1 */
      assert_int_equal(b95[i + 14], 0x11);    /* Cb 1x1 */
      assert_int_equal(b95[i + 17], 0x11);    /* Cr 1x1 */
      break;
    }
  zr_image_free(back);
  free(b95);
  free(b2);
  free(b0);
  free(b85);
  zr_image_free(im);
}

static void check_relative(const zr_image *a, const zr_image *b,
                           double tolerance) {
  size_t n = (size_t)a->width * a->height * 3;
  for (size_t i = 0; i < n; i++) {
    double want = a->pixels[i], got = b->pixels[i];
    /* RGBE shares one exponent: a small component next to a large one
       keeps the large one's absolute precision. */
    size_t px = i / 3 * 3;
    double top = fmax(a->pixels[px], fmax(a->pixels[px + 1],
                                          a->pixels[px + 2]));
    if (fabs(got - want) > tolerance * top + 1e-30)
      fail_msg("sample %zu: %.6g read back as %.6g", i, want, got);
  }
}

static void test_image_io_hdr(void **state) {
  fixture *fx = *state;
  /* Width 5 is stored flat, 40 run-length encoded by component. */
  int widths[2] = {5, 40};
  for (int k = 0; k < 2; k++) {
    zr_image *im = picture(widths[k], 9, 37.0f);
    size_t n = 0;
    unsigned char *b = encode(fx, im, ZR_FORMAT_HDR, 0, &n);
    assert_memory_equal(b, "#?RADIANCE\n", 11);
    if (k == 0)
      assert_true(n > 5 * 9 * 4);
    zr_image *back = decode(fx, b, n);
    /* Mantissas of 8 bits, the largest at least 128: 1/128 of the
       largest component at worst. */
    check_relative(im, back, 1.0 / 128);
    zr_image_free(back);
    free(b);
    zr_image_free(im);
  }
}

static void test_image_io_hdr_broken(void **state) {
  fixture *fx = *state;
  zr_image *im = NULL;
  const char *xyz = "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n";
  assert_int_equal(
      zr__image_decode(fx->ctx, "x.hdr", xyz, strlen(xyz), &im),
      ZR_EUNSUPPORTED);
  assert_string_equal(fx->message, "x.hdr: Radiance files of "
                                   "FORMAT=32-bit_rle_xyze are not "
                                   "supported (32-bit_rle_rgbe is)");
  const char *cut = "#?RADIANCE\n\n-Y 2 +X 2\n\x80\x80\x80\x81";
  assert_int_equal(zr__image_decode(fx->ctx, "c.hdr", cut, strlen(cut), &im),
                   ZR_EFORMAT);
  assert_string_equal(fx->message,
                      "c.hdr: truncated Radiance HDR file (pixels)");
  const char *rot = "#?RADIANCE\n\n+X 2 -Y 2\n";
  assert_int_equal(zr__image_decode(fx->ctx, "r.hdr", rot, strlen(rot), &im),
                   ZR_EUNSUPPORTED);
  assert_null(im);
}

static void test_image_io_exr(void **state) {
  fixture *fx = *state;
  if (!zr_image_format_supported(ZR_FORMAT_EXR)) {
    skip();
    return;
  }
  zr_image *im = picture(45, 21, 300.0f);
  size_t n = 0;
  unsigned char *b = encode(fx, im, ZR_FORMAT_EXR, 0, &n);
  assert_true(zr__exr_looks_like(b, n));
  zr_image *back = decode(fx, b, n);
  assert_int_equal(zr_image_width(back), 45);
  assert_int_equal(zr_image_height(back), 21);
  /* Half floats: 11 significant bits, rounded: 2^-11 relative. */
  size_t count = 45 * 21 * 3;
  for (size_t i = 0; i < count; i++)
    assert_true(fabs(back->pixels[i] - im->pixels[i]) <=
                im->pixels[i] / 2048.0 + 1e-7);
  zr_image_free(back);
  /* With alpha: four channels, the colours premultiplied by it (as
     OpenEXR and povray keep them), the others read back the same. */
  assert_int_equal(zr_image_add_alpha(im), ZR_OK);
  zr_image_alpha(im)[0] = 0.25f;
  size_t n4 = 0;
  unsigned char *b4 = encode(fx, im, ZR_FORMAT_EXR, 0, &n4);
  assert_true(n4 > n);
  back = decode(fx, b4, n4);
  for (int k = 0; k < 6; k++) {
    float want = k < 3 ? 0.25f * im->pixels[k] : im->pixels[k];
    assert_true(fabs(back->pixels[k] - want) <= want / 2048.0 + 1e-7);
  }
  zr_image_free(back);
  free(b4);
  /* A damaged file is an error, not a crash. */
  zr_image *none = NULL;
  assert_int_not_equal(zr__image_decode(fx->ctx, "d.exr", (const char *)b,
                                        n / 2, &none),
                       ZR_OK);
  assert_null(none);
  assert_non_null(strstr(fx->message, "d.exr: "));
  free(b);
  zr_image_free(im);
}

static void test_image_io_alpha(void **state) {
  fixture *fx = *state;
  zr_image *im = picture(4, 3, 1.0f);
  assert_null(zr_image_alpha(im));
  assert_int_equal(zr_image_add_alpha(im), ZR_OK);
  float *a = zr_image_alpha(im);
  assert_non_null(a);
  assert_true(a[5] == 1.0f); /* made opaque */
  a[0] = 0.0f;
  a[1] = 0.5f;
  size_t n = 0;
  unsigned char *b = encode(fx, im, ZR_FORMAT_TGA, 0, &n);
  assert_int_equal(b[16], 32);
  assert_int_equal(b[17], 0x28); /* top-down, 8 alpha bits */
  assert_int_equal(n, 18 + 4 * 3 * 4);
  assert_int_equal(b[18 + 3], 0);    /* alpha is linear: 0 */
  assert_int_equal(b[18 + 7], 128);  /* 0.5 -> 127.5 -> 128 */
  assert_int_equal(b[18 + 11], 255);
  zr_image *back = decode(fx, b, n);
  for (size_t i = 0; i < 4 * 3 * 3; i++)
    assert_int_equal(zr__image_stored(back, i),
                     zr__encode_sample(im->pixels[i], 1.0, 255));
  zr_image_free(back);
  free(b);
  /* PNG: colour type 6 (RGBA), and it still reads (alpha dropped). */
  b = encode(fx, im, ZR_FORMAT_PNG8, 0, &n);
  assert_int_equal(b[25], 6);
  back = decode(fx, b, n);
  assert_int_equal(zr_image_width(back), 4);
  zr_image_free(back);
  free(b);
  /* Asked not to: plain RGB. */
  zr_image_encoding e;
  zr_image_encoding_init(&e, ZR_FORMAT_PNG8);
  e.alpha = 0;
  assert_int_equal(zr_image_encode(fx->ctx, im, &e, &b, &n), ZR_OK);
  assert_int_equal(b[25], 2);
  free(b);
  zr_image_free(im);
}

/* zr_image_encode, zr_image_write_file and zr_image_save give the same
   bytes; bad requests are refused with a message. */
static void test_image_io_memory_and_stream(void **state) {
  fixture *fx = *state;
  zr_image *im = picture(20, 10, 1.0f);
  zr_image_format formats[] = {ZR_FORMAT_PNG8, ZR_FORMAT_PNG16,
                               ZR_FORMAT_PPM,  ZR_FORMAT_PFM,
                               ZR_FORMAT_JPEG, ZR_FORMAT_TGA,
                               ZR_FORMAT_TGA_RLE, ZR_FORMAT_HDR,
                               ZR_FORMAT_BMP};
  for (size_t k = 0; k < sizeof formats / sizeof *formats; k++) {
    size_t n = 0;
    unsigned char *mem = encode(fx, im, formats[k], 0, &n);
    FILE *f = tmpfile();
    assert_non_null(f);
    zr_image_encoding e;
    zr_image_encoding_init(&e, formats[k]);
    assert_int_equal(zr_image_write_file(fx->ctx, im, &e, f), ZR_OK);
    assert_int_equal(ftell(f), (long)n);
    rewind(f);
    unsigned char *back = malloc(n);
    assert_int_equal(fread(back, 1, n, f), n);
    assert_memory_equal(back, mem, n);
    fclose(f);
    char path[] = "/tmp/zr-io-XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    assert_int_equal(zr_image_save(fx->ctx, im, path, &e), ZR_OK);
    f = fopen(path, "rb");
    assert_non_null(f);
    assert_int_equal(fread(back, 1, n, f), n);
    assert_int_equal(fgetc(f), EOF);
    fclose(f);
    unlink(path);
    assert_memory_equal(back, mem, n);
    free(back);
    free(mem);
  }
  zr_image_encoding e;
  zr_image_encoding_init(&e, ZR_FORMAT_AUTO);
  unsigned char *b = (unsigned char *)"x";
  size_t n = 7;
  assert_int_equal(zr_image_encode(fx->ctx, im, &e, &b, &n), ZR_EINVAL);
  assert_null(b);
  assert_int_equal(n, 0);
  assert_string_equal(fx->message, "(memory): unknown image format 0");
  zr_image_encoding_init(&e, ZR_FORMAT_JPEG);
  e.quality = 101;
  assert_int_equal(zr_image_encode(fx->ctx, im, &e, &b, &n), ZR_EINVAL);
  assert_string_equal(fx->message,
                      "(memory): JPEG quality must be 0 to 100, not 101");
  assert_int_equal(zr_image_write_file(fx->ctx, im, &e, NULL), ZR_EINVAL);
  /* Names choose formats. */
  assert_int_equal(zr_image_format_from_name("a.TGA"), ZR_FORMAT_TGA);
  assert_int_equal(zr_image_format_from_name("a.hdr"), ZR_FORMAT_HDR);
  assert_int_equal(zr_image_format_from_name("a.exr"), ZR_FORMAT_EXR);
  assert_int_equal(zr_image_format_from_name("a.jpg"), ZR_FORMAT_JPEG);
  zr_image_free(im);
}

/* BMP (+FB): the header povray writes (tests/test_formats_povray.sh compares
   with povray's own), rows bottom up padded to four bytes, and back
   through our reader to the same codes; 32 bits with alpha. */
static void test_image_io_bmp_write(void **state) {
  fixture *fx = *state;
  zr_image *im = picture(5, 3, 1.0f);
  size_t n = 0;
  unsigned char *b = encode(fx, im, ZR_FORMAT_BMP, 0, &n);
  assert_int_equal(n, 54 + 16 * 3); /* 15 bytes a row, padded to 16 */
  assert_memory_equal(b, "BM", 2);
  assert_int_equal(b[2], 102);
  assert_int_equal(b[10], 54);
  assert_int_equal(b[14], 40);
  assert_int_equal(b[18], 5);
  assert_int_equal(b[22], 3); /* positive: bottom row first */
  assert_int_equal(b[26], 1);
  assert_int_equal(b[28], 24);
  assert_int_equal(b[30], 0);
  assert_int_equal(b[34], 48);
  /* The first stored pixel is the bottom row's first, blue first. */
  const float *bottom = im->pixels + 3 * 5 * 2;
  assert_int_equal(b[54], zr__encode_sample(bottom[2], 1.0, 255));
  assert_int_equal(b[56], zr__encode_sample(bottom[0], 1.0, 255));
  assert_int_equal(b[54 + 15], 0); /* padding */
  zr_image *back = decode(fx, b, n);
  assert_int_equal(zr_image_width(back), 5);
  assert_int_equal(zr_image_height(back), 3);
  for (size_t i = 0; i < 5 * 3 * 3; i++)
    assert_int_equal(zr__image_stored(back, i),
                     zr__encode_sample(im->pixels[i], 1.0, 255));
  zr_image_free(back);
  free(b);
  assert_int_equal(zr_image_add_alpha(im), ZR_OK);
  zr_image_alpha(im)[10] = 0.5f; /* bottom row, first pixel */
  b = encode(fx, im, ZR_FORMAT_BMP, 0, &n);
  assert_int_equal(n, 54 + 20 * 3);
  assert_int_equal(b[28], 32);
  assert_int_equal(b[54 + 3], 128);
  assert_int_equal(b[54 + 7], 255);
  back = decode(fx, b, n);
  for (size_t i = 0; i < 5 * 3 * 3; i++)
    assert_int_equal(zr__image_stored(back, i),
                     zr__encode_sample(im->pixels[i], 1.0, 255));
  zr_image_free(back);
  free(b);
  assert_int_equal(zr_image_format_from_name("a.BMP"), ZR_FORMAT_BMP);
  zr_image_free(im);
}

/* ---- BMP, built from the documented layout ---- */

typedef struct bmp_out {
  unsigned char b[4096];
  size_t n;
} bmp_out;

static void put16(bmp_out *o, unsigned v) {
  o->b[o->n++] = (unsigned char)(v & 255);
  o->b[o->n++] = (unsigned char)(v >> 8);
}

static void put32(bmp_out *o, uint32_t v) {
  put16(o, v & 0xffff);
  put16(o, v >> 16);
}

/* Headers for a BITMAPINFOHEADER file; pixels at data_offset. */
static void bmp_header(bmp_out *o, int w, int h, unsigned bits,
                       unsigned compression, unsigned colours,
                       unsigned data_offset) {
  o->n = 0;
  o->b[o->n++] = 'B';
  o->b[o->n++] = 'M';
  put32(o, 0); /* file size: readers ignore it */
  put32(o, 0);
  put32(o, data_offset);
  put32(o, 40);
  put32(o, (uint32_t)w);
  put32(o, (uint32_t)h);
  put16(o, 1);
  put16(o, bits);
  put32(o, compression);
  put32(o, 0);
  put32(o, 2835);
  put32(o, 2835);
  put32(o, colours);
  put32(o, 0);
}

static void expect_codes(fixture *fx, bmp_out *o, int w, int h,
                         const unsigned *rgb) {
  zr_image *im = decode(fx, o->b, o->n);
  assert_int_equal(zr_image_width(im), w);
  assert_int_equal(zr_image_height(im), h);
  for (int i = 0; i < w * h * 3; i++)
    if (((const unsigned char *)im->codes)[i] != rgb[i])
      fail_msg("code %d: %u, want %u", i,
               ((const unsigned char *)im->codes)[i], rgb[i]);
  zr_image_free(im);
}

static void test_image_io_bmp(void **state) {
  fixture *fx = *state;
  bmp_out o;
  /* 24 bits, 2 x 2 bottom-up: stored rows are bottom first, padded to
     4 bytes (6 + 2). */
  bmp_header(&o, 2, 2, 24, 0, 0, 54);
  const unsigned char rows24[] = {1, 2, 3, 4, 5, 6, 0, 0,
                                  7, 8, 9, 10, 11, 12, 0, 0};
  memcpy(o.b + o.n, rows24, sizeof rows24);
  o.n += sizeof rows24;
  const unsigned want24[] = {9, 8, 7, 12, 11, 10, 3, 2, 1, 6, 5, 4};
  expect_codes(fx, &o, 2, 2, want24);
  /* The same top-down (negative height). */
  bmp_header(&o, 2, -2, 24, 0, 0, 54);
  memcpy(o.b + o.n, rows24, sizeof rows24);
  o.n += sizeof rows24;
  const unsigned want24t[] = {3, 2, 1, 6, 5, 4, 9, 8, 7, 12, 11, 10};
  expect_codes(fx, &o, 2, 2, want24t);
  /* 8-bit palette of 3 colours, 3 x 1. */
  bmp_header(&o, 3, 1, 8, 0, 3, 54 + 12);
  const unsigned char pal[] = {10, 20, 30, 0, 40, 50, 60, 0, 70, 80, 90, 0};
  memcpy(o.b + o.n, pal, sizeof pal);
  o.n += sizeof pal;
  const unsigned char idx8[] = {2, 0, 1, 0};
  memcpy(o.b + o.n, idx8, sizeof idx8);
  o.n += sizeof idx8;
  const unsigned want8[] = {90, 80, 70, 30, 20, 10, 60, 50, 40};
  zr_image *im = decode(fx, o.b, o.n);
  assert_int_equal(im->indices[0], 2);
  assert_int_equal(im->palette_size, 3);
  zr_image_free(im);
  expect_codes(fx, &o, 3, 1, want8);
  /* 4 bits: two indices a byte, high nibble first. */
  bmp_header(&o, 3, 1, 4, 0, 3, 54 + 12);
  memcpy(o.b + o.n, pal, sizeof pal);
  o.n += sizeof pal;
  const unsigned char idx4[] = {0x20, 0x10, 0, 0};
  memcpy(o.b + o.n, idx4, sizeof idx4);
  o.n += sizeof idx4;
  expect_codes(fx, &o, 3, 1, want8);
  /* 1 bit: the top bit first. */
  bmp_header(&o, 3, 1, 1, 0, 2, 54 + 8);
  memcpy(o.b + o.n, pal, 8);
  o.n += 8;
  const unsigned char idx1[] = {0xa0, 0, 0, 0}; /* 1 0 1 */
  memcpy(o.b + o.n, idx1, sizeof idx1);
  o.n += sizeof idx1;
  const unsigned want1[] = {60, 50, 40, 30, 20, 10, 60, 50, 40};
  expect_codes(fx, &o, 3, 1, want1);
  /* 16 bits, bit fields 5-6-5: red 31 -> 255, green 32 -> 130, blue 0. */
  bmp_header(&o, 1, 1, 16, 3, 0, 54 + 12);
  put32(&o, 0xf800);
  put32(&o, 0x07e0);
  put32(&o, 0x001f);
  put16(&o, 0xf800 | (32 << 5));
  put16(&o, 0);
  const unsigned want565[] = {255, 32 * 255 / 63, 0};
  expect_codes(fx, &o, 1, 1, want565);
  /* 16 bits without fields: 5-5-5. */
  bmp_header(&o, 1, 1, 16, 0, 0, 54);
  put16(&o, (31u << 10) | (16u << 5) | 1u);
  put16(&o, 0);
  const unsigned want555[] = {255, 16 * 255 / 31, 255 / 31};
  expect_codes(fx, &o, 1, 1, want555);
  /* 32 bits: blue, green, red, unused. */
  bmp_header(&o, 1, 1, 32, 0, 0, 54);
  put32(&o, 0x00abcdef);
  const unsigned want32[] = {0xab, 0xcd, 0xef};
  expect_codes(fx, &o, 1, 1, want32);
  /* RLE8: a run of 3 index 1, end of line, literal 3 indices (padded),
     end of bitmap; a 3 x 2 picture stored bottom-up. */
  bmp_header(&o, 3, 2, 8, 1, 3, 54 + 12);
  memcpy(o.b + o.n, pal, sizeof pal);
  o.n += sizeof pal;
  const unsigned char rle[] = {3, 1, 0, 0, 0, 3, 2, 0, 1, 0, 0, 1};
  memcpy(o.b + o.n, rle, sizeof rle);
  o.n += sizeof rle;
  const unsigned wantrle[] = {90, 80, 70, 30, 20, 10, 60, 50, 40,
                              60, 50, 40, 60, 50, 40, 60, 50, 40};
  expect_codes(fx, &o, 3, 2, wantrle);
  /* Damaged: pixels missing, and an unknown compression. */
  bmp_header(&o, 4, 4, 24, 0, 0, 54);
  o.b[o.n++] = 0;
  im = NULL;
  assert_int_equal(zr__image_decode(fx->ctx, "t.bmp", (const char *)o.b,
                                    o.n, &im),
                   ZR_EFORMAT);
  assert_string_equal(fx->message, "t.bmp: truncated BMP file (pixels)");
  bmp_header(&o, 4, 4, 24, 4, 0, 54);
  o.b[o.n++] = 0;
  assert_int_equal(zr__image_decode(fx->ctx, "j.bmp", (const char *)o.b,
                                    o.n, &im),
                   ZR_EUNSUPPORTED);
  assert_string_equal(fx->message,
                      "j.bmp: BMP compression 4 with 24 bits per pixel is "
                      "not supported (none, RLE8, RLE4 and bit fields are)");
  assert_null(im);
}

/* ---- TIFF, written by libtiff ---- */

static void write_tiff(const char *path, int w, int h, int spp,
                       const unsigned char *samples, int compression) {
  TIFF *t = TIFFOpen(path, "w");
  assert_non_null(t);
  TIFFSetField(t, TIFFTAG_IMAGEWIDTH, (uint32_t)w);
  TIFFSetField(t, TIFFTAG_IMAGELENGTH, (uint32_t)h);
  TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, (uint16_t)spp);
  TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, (uint16_t)8);
  TIFFSetField(t, TIFFTAG_PHOTOMETRIC,
               spp == 1 ? PHOTOMETRIC_MINISBLACK : PHOTOMETRIC_RGB);
  TIFFSetField(t, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
  TIFFSetField(t, TIFFTAG_COMPRESSION, (uint16_t)compression);
  TIFFSetField(t, TIFFTAG_ROWSPERSTRIP, (uint32_t)2);
  for (int y = 0; y < h; y++)
    assert_int_equal(TIFFWriteScanline(t, (void *)(samples +
                                                   (size_t)y * w * spp),
                                       (uint32_t)y, 0),
                     1);
  TIFFClose(t);
}

static void test_image_io_tiff(void **state) {
  fixture *fx = *state;
  enum { W = 5, H = 3 };
  unsigned char rgb[W * H * 3], grey[W * H];
  for (int i = 0; i < W * H * 3; i++)
    rgb[i] = (unsigned char)(i * 17 % 256);
  for (int i = 0; i < W * H; i++)
    grey[i] = (unsigned char)(i * 40 % 256);
  char path[] = "/tmp/zr-tiff-XXXXXX";
  int fd = mkstemp(path);
  assert_true(fd >= 0);
  close(fd);
  int compressions[2] = {COMPRESSION_NONE, COMPRESSION_LZW};
  for (int k = 0; k < 2; k++) {
    write_tiff(path, W, H, 3, rgb, compressions[k]);
    zr_image *im = NULL;
    assert_int_equal(zr_image_read(fx->ctx, path, &im), ZR_OK);
    assert_int_equal(zr_image_width(im), W);
    assert_int_equal(zr_image_height(im), H);
    for (int i = 0; i < W * H * 3; i++)
      assert_int_equal(((const unsigned char *)im->codes)[i], rgb[i]);
    zr_image_free(im);
  }
  write_tiff(path, W, H, 1, grey, COMPRESSION_NONE);
  zr_image *im = NULL;
  assert_int_equal(zr_image_read(fx->ctx, path, &im), ZR_OK);
  for (int i = 0; i < W * H; i++)
    for (int c = 0; c < 3; c++)
      assert_int_equal(((const unsigned char *)im->codes)[3 * i + c], grey[i]);
  zr_image_free(im);
  /* Cut short: an error with libtiff's reason, nothing printed. */
  FILE *f = fopen(path, "rb");
  unsigned char bytes[4096];
  size_t n = fread(bytes, 1, sizeof bytes, f);
  fclose(f);
  unlink(path);
  im = NULL;
  assert_int_not_equal(zr__image_decode(fx->ctx, "cut.tif",
                                        (const char *)bytes, 12, &im),
                       ZR_OK);
  assert_null(im);
  assert_non_null(strstr(fx->message, "cut.tif: "));
  assert_true(n > 12);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test_setup_teardown(test_image_io_tga_exact, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_image_io_tga_rle_packets, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_image_io_jpeg, setup, teardown),
      cmocka_unit_test_setup_teardown(test_image_io_hdr, setup, teardown),
      cmocka_unit_test_setup_teardown(test_image_io_hdr_broken, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_image_io_exr, setup, teardown),
      cmocka_unit_test_setup_teardown(test_image_io_alpha, setup, teardown),
      cmocka_unit_test_setup_teardown(test_image_io_memory_and_stream, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_image_io_bmp, setup, teardown),
      cmocka_unit_test_setup_teardown(test_image_io_bmp_write, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_image_io_tiff, setup, teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
