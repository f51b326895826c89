/*
 * test_pattern.c - patterns, noise and colour maps evaluated directly
 * (lib/scene/pattern.c, lib/scene/texture.c).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "scene/pattern.h"
#include "scene/texture.h"

/* Exact patterns are sums and floors of the point: 1e-12 covers rounding. */
#define EPS 1e-12

static void test_pattern_checker_cells(void **state) {
  (void)state;
  zr_pattern pt;
  zr__pattern_init(&pt, ZR_PAT_CHECKER);
  double a = zr__pattern_eval(&pt, zr_v3(0.5, 0.5, 0.5));
  double b = zr__pattern_eval(&pt, zr_v3(1.5, 0.5, 0.5));
  double c = zr__pattern_eval(&pt, zr_v3(1.5, 1.5, 0.5));
  double d = zr__pattern_eval(&pt, zr_v3(-0.5, 0.5, 0.5));
  /* Neighbouring unit cells alternate; diagonal ones agree. */
  assert_true(a == 0.0 || a == 1.0);
  assert_true(fabs(a + b - 1.0) < EPS);
  assert_true(fabs(a - c) < EPS);
  assert_true(fabs(b - d) < EPS);
  assert_true(zr__pattern_is_block(ZR_PAT_CHECKER));
  assert_false(zr__pattern_is_block(ZR_PAT_GRADIENT));
}

static void test_pattern_gradient_ramp_repeats(void **state) {
  (void)state;
  zr_pattern pt;
  zr__pattern_init(&pt, ZR_PAT_GRADIENT);
  /* gradient x with the default ramp wave: the fraction of x. */
  assert_true(fabs(zr__pattern_eval(&pt, zr_v3(0.25, 7, 3)) - 0.25) < EPS);
  assert_true(fabs(zr__pattern_eval(&pt, zr_v3(1.25, 0, 0)) - 0.25) < EPS);
  assert_true(fabs(zr__pattern_eval(&pt, zr_v3(2.75, 0, 0)) - 0.75) < EPS);
}

static void test_pattern_colour_map_interpolates(void **state) {
  (void)state;
  const zr_colour_map_entry entries[] = {
      {0.0, {0, 0, 0, 0, 0}},
      {0.5, {1, 0, 0, 0, 0}},
      {1.0, {1, 1, 1, 0, 1}},
  };
  zr_colour_map map = {3, entries};
  zr_colour c = zr__colour_map_eval(&map, 0.25);
  assert_true(fabs(c.r - 0.5) < EPS && fabs(c.g) < EPS);
  c = zr__colour_map_eval(&map, 0.75);
  assert_true(fabs(c.r - 1.0) < EPS && fabs(c.g - 0.5) < EPS);
  assert_true(fabs(c.t - 0.5) < EPS);
  /* Values outside the entries take the end colours. */
  c = zr__colour_map_eval(&map, -1.0);
  assert_true(fabs(c.r) < EPS);
}

static void test_pattern_colour_map_out_of_order(void **state) {
  (void)state;
  /* POV-Ray 3.7 (a gradient x render, 20 pixels) blends from red to
     green up to 0.6, then from blue to white: the first entry above the
     value ends the interval, and the one before it starts it, wherever
     that one stands. */
  const zr_colour_map_entry entries[] = {
      {0.0, {1, 0, 0, 0, 0}},
      {0.6, {0, 1, 0, 0, 0}},
      {0.5, {0, 0, 1, 0, 0}},
      {1.0, {1, 1, 1, 0, 0}},
  };
  zr_colour_map map = {4, entries};
  zr_colour c = zr__colour_map_eval(&map, 0.55);
  assert_true(fabs(c.r - 0.05 / 0.6) < EPS && fabs(c.g - 0.55 / 0.6) < EPS);
  assert_true(fabs(c.b) < EPS);
  c = zr__colour_map_eval(&map, 0.625);
  assert_true(fabs(c.r - 0.25) < EPS && fabs(c.b - 1.0) < EPS);
  c = zr__colour_map_eval(&map, 1.5);
  assert_true(fabs(c.r - 1.0) < EPS && fabs(c.g - 1.0) < EPS);
}

static void test_pattern_noise_range_and_mean(void **state) {
  (void)state;
  /* 20000 points on an irrational lattice: a mean within 0.05 of 0.5
     allows for the noise's own correlation over the sampled region. */
  double sum = 0.0, lo = 1.0, hi = 0.0;
  const int n = 20000;
  for (int i = 0; i < n; i++) {
    zr_vec3 p = zr_v3(i * 0.7548776662, i * 0.5698402910, i * 0.1234567);
    double v = zr__noise(p);
    assert_true(v >= 0.0 && v <= 1.0);
    sum += v;
    lo = fmin(lo, v);
    hi = fmax(hi, v);
  }
  assert_true(fabs(sum / n - 0.5) < 0.05);
  assert_true(hi - lo > 0.5); /* it varies, it is no constant */
  /* Deterministic: the same point gives the same bits. */
  zr_vec3 p = zr_v3(1.37, -2.11, 5.5);
  assert_true(zr__noise(p) == zr__noise(p));
}

static void test_pattern_pigment_eval_uses_transform(void **state) {
  (void)state;
  zr_pigment pg;
  zr__pigment_init(&pg);
  zr__pigment_set_pattern(&pg, ZR_PAT_CHECKER);
  pg.list[0] = zr_colour5(1, 0, 0, 0, 0);
  pg.list[1] = zr_colour5(0, 0, 1, 0, 0);
  zr_colour a = zr__pigment_eval(&pg, zr_v3(0.5, 0.5, 0.5));
  zr_colour b = zr__pigment_eval(&pg, zr_v3(1.5, 0.5, 0.5));
  assert_true(fabs(a.r + b.r - 1.0) < EPS);
  assert_true(fabs(a.b + b.b - 1.0) < EPS);
  /* Scaled by 2, the cell at 1.5 is the one at 0.5. */
  zr_transform t;
  zr__transform_identity(&t);
  zr__transform_scale(&t, zr_v3(2, 2, 2));
  pg.transform = &t;
  zr_colour c = zr__pigment_eval(&pg, zr_v3(1.5, 0.5, 0.5));
  assert_true(fabs(c.r - a.r) < EPS && fabs(c.b - a.b) < EPS);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_pattern_checker_cells),
      cmocka_unit_test(test_pattern_gradient_ramp_repeats),
      cmocka_unit_test(test_pattern_colour_map_interpolates),
      cmocka_unit_test(test_pattern_colour_map_out_of_order),
      cmocka_unit_test(test_pattern_noise_range_and_mean),
      cmocka_unit_test(test_pattern_pigment_eval_uses_transform),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
