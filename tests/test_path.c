/*
 * test_path.c - the path-traced reference (lib/gi/path.c, issue 11):
 *   - the furnace: a diffuse sphere under a uniform sky sees only the
 *     sky, so every sample is exact: albedo * diffuse * L (1e-6);
 *   - inside a closed sphere that emits e and reflects rho every point
 *     has radiance e / (1 - rho) (the furnace of RADIOSITY-ANALYTIC.md
 *     in ../shared/reference): every bounce, Russian roulette and the
 *     sky-free escape are in it; 1% allows the Monte Carlo noise of
 *     this image's 27,648 samples, whose standard error is 0.2%;
 *   - an area light shines from one random point of its grid a vertex,
 *     which averages to the tracer's full grid (1%);
 *   - samples taken in pieces give the mean of all of them (float
 *     rounding, 1e-6), and the bytes do not depend on which pixels one
 *     call renders or in which order (ranks and threads);
 *   - the emissive Cornell box against ../shared/reference's ground
 *     truth (4096 samples a pixel, 256 x 256, box filter; skipped when
 *     the folder is absent): at 64 x 64 each of our pixels covers 4 x 4
 *     of its pixels, so their mean is the same quantity.  The RMS error
 *     against it must be the noise of our estimate (measured apart,
 *     from two seeds: |a - b| / sqrt 2), within 15%; four times the
 *     samples must halve the error (1/sqrt(spp), 1.7 to 2.3); sampling
 *     the emitter directly or not gives the same mean (1%), with at
 *     least 1.5x less error when it is sampled (1.81x measured).
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

#include "parse_fixture.h"
#include "zrcube.h"

#define W 24
#define H 18

static double rms(const float *a, const float *b, size_t n) {
  double s = 0.0;
  for (size_t i = 0; i < n; i++)
    s += ((double)a[i] - b[i]) * ((double)a[i] - b[i]);
  return sqrt(s / n);
}

static double mean(const float *a, size_t n) {
  double s = 0.0;
  for (size_t i = 0; i < n; i++)
    s += a[i];
  return s / n;
}

static void render_path(const zr_scene *s, const zr_path *p, int w, int h,
                        int first, int samples, float *rgb) {
  zr_render_params rp;
  zr_render_params_init(&rp);
  rp.width = w;
  rp.height = h;
  rp.path = p;
  rp.path_first_sample = first;
  rp.path_samples = samples;
  assert_int_equal(zr_render_image(s, &rp, rgb, NULL), ZR_OK);
}

static zr_path *new_path(const zr_scene *s, uint32_t seed, int light) {
  zr_path_params pp;
  zr_path_params_init(&pp);
  pp.seed = seed;
  pp.light_sampling = light;
  zr_path *p = NULL;
  assert_int_equal(zr_path_new(NULL, s, &pp, &p), ZR_OK);
  return p;
}

static void test_path_furnace(void **state) {
  fixture *f = *state;
  const zr_scene *s = good(
      f, "#version 3.7; global_settings { radiosity { } }"
         "camera { location <0, 0, -4> look_at 0 angle 40 }"
         "sky_sphere { pigment { rgb 0.8 } }"
         "sphere { 0, 1 pigment { rgb <1, 0.5, 0.25> }"
         " finish { ambient 0 diffuse 0.6 } }");
  zr_path *p = new_path(s, 0, 1);
  float rgb[W * H * 3];
  render_path(s, p, W, H, 0, 8, rgb);
  const float *c = rgb + 3 * ((H / 2) * W + W / 2);
  assert_true(fabs(c[0] - 0.48) < 1e-6);
  assert_true(fabs(c[1] - 0.24) < 1e-6);
  assert_true(fabs(c[2] - 0.12) < 1e-6);
  /* Outside the sphere the camera sees the sky. */
  assert_true(fabs(rgb[0] - 0.8) < 1e-6);
  zr_path_free(p);
}

static void test_path_closed_sphere(void **state) {
  fixture *f = *state;
  const zr_scene *s = good(
      f, "#version 3.7; global_settings { radiosity { } }"
         "camera { location <0, 0, -0.5> look_at 0 angle 90 }"
         "sphere { 0, 1 pigment { rgb 1 }"
         " finish { ambient 0 emission 0.5 diffuse 0.5 } }");
  zr_path *p = new_path(s, 0, 1);
  float rgb[W * H * 3];
  render_path(s, p, W, H, 0, 64, rgb);
  double mean[3] = {0, 0, 0};
  for (int i = 0; i < W * H; i++)
    for (int k = 0; k < 3; k++)
      mean[k] += rgb[3 * i + k] / (W * H);
  /* e / (1 - rho) = 0.5 / 0.5 */
  for (int k = 0; k < 3; k++)
    assert_true(fabs(mean[k] - 1.0) < 0.01);
  zr_path_free(p);
}

static void test_path_pieces_and_order(void **state) {
  fixture *f = *state;
  const zr_scene *s = good(
      f, "#version 3.7; global_settings { radiosity { } }"
         "camera { location <0, 1, -4> look_at <0, 0.5, 0> }"
         "sky_sphere { pigment { gradient y color_map { [0 rgb 1]"
         " [1 rgb <0.2, 0.3, 1>] } } }"
         "light_source { <3, 5, -2> rgb 1 }"
         "plane { y, 0 pigment { rgb 0.7 } }"
         "box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> pigment { rgb <1, 0.2, 0.1> }"
         " finish { phong 0.5 reflection 0.2 } }");
  zr_path *p = new_path(s, 7, 1);
  float all[W * H * 3], a[W * H * 3], b[W * H * 3];
  render_path(s, p, W, H, 0, 8, all);
  render_path(s, p, W, H, 0, 3, a);
  render_path(s, p, W, H, 3, 5, b);
  for (int i = 0; i < W * H * 3; i++) {
    double joined = (3.0 * a[i] + 5.0 * b[i]) / 8.0;
    assert_true(fabs(joined - all[i]) <= 1e-6 * fmax(1.0, fabs(all[i])));
  }
  /* Pixels one at a time, last first: the same bytes. */
  zr_render_params rp;
  zr_render_params_init(&rp);
  rp.width = W;
  rp.height = H;
  rp.path = p;
  rp.path_samples = 8;
  for (int i = W * H - 1; i >= 0; i--) {
    uint32_t px = (uint32_t)i;
    float one[3];
    assert_int_equal(zr_render_pixels(s, &rp, &px, 1, NULL, one, NULL),
                     ZR_OK);
    assert_memory_equal(one, all + 3 * i, sizeof one);
  }
  /* A path tracer belongs to its scene and takes no other model. */
  rp.path_samples = 0;
  assert_int_equal(zr_render_image(s, &rp, all, NULL), ZR_EINVAL);
  zr_path_free(p);
}

/* An area light's soft shadow: the path tracer's one random grid point a
   vertex averages to the classic tracer's full grid (every point, no
   jitter), where nothing else lights the floor (black sky, an occluder
   that reflects nothing).  1% of the mean: the noise of 64 samples a
   pixel over the image, measured 0.2%. */
static void test_path_area_light(void **state) {
  fixture *f = *state;
  const zr_scene *s = good(
      f, "#version 3.7; global_settings { radiosity { } }"
         "camera { location <0, 4, -4> look_at 0 angle 50 }"
         "light_source { <0, 3, 0> rgb 1 area_light 2*x, 2*z, 5, 5 }"
         "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 0.7 } }"
         "box { <-0.6, 0.8, -0.6>, <0.6, 1, 0.6> pigment { rgb 0 }"
         " finish { ambient 0 diffuse 0 } }");
  zr_path *p = new_path(s, 0, 1);
  float path[W * H * 3], classic[W * H * 3];
  render_path(s, p, W, H, 0, 64, path);
  zr_render_params rp;
  zr_render_params_init(&rp);
  rp.width = W;
  rp.height = H;
  /* The classic render supersamples every pixel (threshold 0, a 9 x 9
     grid) to take the pixel's mean as the path tracer does. */
  rp.antialias = 1;
  rp.aa_threshold = 0.0;
  rp.aa_depth = 9;
  assert_int_equal(zr_render_image(s, &rp, classic, NULL), ZR_OK);
  double a = mean(path, W * H * 3), b = mean(classic, W * H * 3);
  print_message("area light: path %.5f classic %.5f\n", a, b);
  assert_true(fabs(a / b - 1.0) < 0.01);
  zr_path_free(p);
}

/* ../shared/reference's Cornell box, or NULL when it is not there. */
static float *read_truth(void) {
  const char *dir = getenv("ZR_SRCDIR");
  char path[4096];
  snprintf(path, sizeof path, "%s/../shared/reference/cbox_emissive-256.pfm",
           dir ? dir : "..");
  FILE *probe = fopen(path, "rb");
  if (!probe)
    return NULL;
  fclose(probe);
  zr_image *img = NULL;
  assert_int_equal(zr_image_read(NULL, path, &img), ZR_OK);
  assert_int_equal(zr_image_width(img), 256);
  const float *px = zr_image_pixels_const(img);
  /* 4 x 4 box means: 64 x 64. */
  float *t = calloc(64 * 64 * 3, sizeof *t);
  assert_non_null(t);
  for (int y = 0; y < 256; y++)
    for (int x = 0; x < 256; x++)
      for (int k = 0; k < 3; k++)
        t[3 * ((y / 4) * 64 + x / 4) + k] +=
            px[3 * (y * 256 + x) + k] / 16.0f;
  zr_image_free(img);
  return t;
}

static void test_path_cornell_truth(void **state) {
  (void)state;
  float *truth = read_truth();
  if (!truth)
    skip(); /* no ../shared/reference here */
  const char *dir = getenv("ZR_SRCDIR");
  char path[4096];
  snprintf(path, sizeof path, "%s/scenes/cornell.pov", dir ? dir : "..");
  zr_context *ctx = NULL;
  zr_scene *s = NULL;
  assert_int_equal(zr_context_new(&ctx), ZR_OK);
  assert_int_equal(zr_scene_parse_file(ctx, path, &s), ZR_OK);
  enum { N = 64 * 64 * 3 };
  float *a = malloc(4 * N * sizeof *a);
  assert_non_null(a);
  float *b = a + N, *c = a + 2 * N, *d = a + 3 * N;
  zr_path *p0 = new_path(s, 0, 1), *p1 = new_path(s, 1, 1);
  assert_int_equal(zr_path_emitters(p0), 2);
  render_path(s, p0, 64, 64, 0, 64, a);
  render_path(s, p1, 64, 64, 0, 64, b);
  double err64 = rms(a, truth, N), noise64 = rms(a, b, N) / sqrt(2.0);
  render_path(s, p0, 64, 64, 0, 16, c);
  double err16 = rms(c, truth, N);
  print_message("cornell: 64 spp error %.5f noise %.5f; 16 spp error "
                "%.5f; means %.5f truth %.5f\n", err64, noise64, err16,
                mean(a, N), mean(truth, N));
  assert_true(err64 / noise64 > 0.85 && err64 / noise64 < 1.15);
  assert_true(err16 / err64 > 1.7 && err16 / err64 < 2.3);
  assert_true(fabs(mean(a, N) / mean(truth, N) - 1.0) < 0.01);
  /* Without sampling the emitter: the same mean, more noise. */
  zr_path *q0 = new_path(s, 0, 0);
  assert_int_equal(zr_path_emitters(q0), 0);
  render_path(s, q0, 64, 64, 0, 64, d);
  print_message("cornell without light sampling: error %.5f mean %.5f\n",
                rms(d, truth, N), mean(d, N));
  assert_true(fabs(mean(d, N) / mean(truth, N) - 1.0) < 0.01);
  assert_true(rms(d, truth, N) > 1.5 * err64);
  zr_path_free(p0);
  zr_path_free(p1);
  zr_path_free(q0);
  free(a);
  free(truth);
  zr_scene_free(s);
  zr_context_free(ctx);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_path_furnace),
      cmocka_unit_test(test_path_closed_sphere),
      cmocka_unit_test(test_path_pieces_and_order),
      cmocka_unit_test(test_path_area_light),
      cmocka_unit_test(test_path_cornell_truth),
  };
  return cmocka_run_group_tests(tests, setup, teardown);
}
