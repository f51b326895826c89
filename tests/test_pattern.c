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

/*
 * slope: povray 3.7 renders a plane whose normal is a degrees from the
 * direction (ambient 1, grey colour map 0 to 1, 8-bit PPM at File_Gamma
 * 1.0) as 1, 0.8353, 0.6667, 0.5020, 0.3333, 0.1686 for a = 0, 30 ...
 * 150: 1 - a / 180 to within 2.5 / 255.
 */
static void test_pattern_slope_matches_povray(void **state) {
  (void)state;
  static const double pov[] = {1, 0.8353, 0.6667, 0.5020, 0.3333, 0.1686};
  zr_pattern pt;
  zr__pattern_init(&pt, ZR_PAT_SLOPE);
  pt.slope.direction = zr_v3(0, 0, -1);
  for (int i = 0; i < 6; i++) {
    double a = i * 30 * M_PI / 180;
    /* -z rotated about x by a. */
    zr_vec3 n = zr_v3(0, sin(a), -cos(a));
    double v = zr__pattern_eval_n(&pt, zr_v3(0, 0, 0), n);
    assert_true(fabs(v - pov[i]) < 2.5 / 255);
    assert_true(fabs(v - (1 - i * 30 / 180.0)) < EPS);
  }
  /* Without a surface (a zero normal) the slope is 0.5, and other
     patterns ignore the normal. */
  assert_true(fabs(zr__pattern_eval(&pt, zr_v3(0, 0, 0)) - 0.5) < EPS);
  zr_pattern g;
  zr__pattern_init(&g, ZR_PAT_GRADIENT);
  zr_vec3 p = zr_v3(0.25, 0.5, 0.75);
  assert_true(zr__pattern_eval_n(&g, p, zr_v3(0, 1, 0)) ==
              zr__pattern_eval(&g, p));
}

/* slope { -y*3, 0, 0.5 altitude y, 0.005, 0.4 } (slopemt_36.pov): the
   slope part maps [0, 0.5] to [0, 1], the altitude part [0.005, 0.4],
   and they mix 3 : 1 by the vectors' lengths (the manual's rule). */
static void test_pattern_slope_ranges_and_altitude(void **state) {
  (void)state;
  zr_pattern pt;
  zr__pattern_init(&pt, ZR_PAT_SLOPE);
  pt.slope.direction = zr_v3(0, -3, 0);
  pt.slope.lo = 0;
  pt.slope.hi = 0.5;
  pt.slope.altitude = zr_v3(0, 1, 0);
  pt.slope.alt_lo = 0.005;
  pt.slope.alt_hi = 0.4;
  zr_vec3 up = zr_v3(0, 1, 0);
  zr_vec3 side = zr_v3(1, 0, 0);
  zr_vec3 tilted = zr_v3(sin(M_PI / 4), cos(M_PI / 4), 0); /* 45 deg */
  /* Flat ground at altitude 0.2: slope 0, altitude 0.195 / 0.395. */
  double alt = 0.195 / 0.395;
  assert_true(fabs(zr__pattern_eval_n(&pt, zr_v3(0, 0.2, 0), up) -
                   alt / 4) < EPS);
  /* A cliff: slope 0.5 maps to 1. */
  assert_true(fabs(zr__pattern_eval_n(&pt, zr_v3(0, 0.2, 0), side) -
                   (3 + alt) / 4) < EPS);
  /* 45 degrees: 1 - 135/180 = 0.25, mapped to 0.5; above the altitude
     range the altitude part holds at 1. */
  assert_true(fabs(zr__pattern_eval_n(&pt, zr_v3(0, 2, 0), tilted) -
                   (3 * 0.5 + 1) / 4) < EPS);
  /* Below it at 0. */
  assert_true(fabs(zr__pattern_eval_n(&pt, zr_v3(0, -1, 0), tilted) -
                   3 * 0.5 / 4) < EPS);
}

/* A slope pigment takes the normal given to zr__pigment_eval_n, and the
   normal is not turned with the pigment (povray: a plane rotated with
   its pigment 60 degrees from the direction gives 0.6667, not 1). */
static void test_pattern_slope_pigment_uses_world_normal(void **state) {
  (void)state;
  zr_pigment pg;
  zr__pigment_init(&pg);
  zr__pigment_set_pattern(&pg, ZR_PAT_SLOPE);
  pg.pattern.slope.direction = zr_v3(0, 1, 0);
  zr_transform t;
  zr__transform_identity(&t);
  zr__transform_rotate(&t, zr_v3(60, 0, 0));
  pg.transform = &t;
  zr_vec3 n = zr_v3(0, cos(M_PI / 3), sin(M_PI / 3));
  zr_colour c = zr__pigment_eval_n(&pg, zr_v3(0, 0, 0), n);
  assert_true(fabs(c.r - 2.0 / 3) < EPS);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_pattern_slope_matches_povray),
      cmocka_unit_test(test_pattern_slope_ranges_and_altitude),
      cmocka_unit_test(test_pattern_slope_pigment_uses_world_normal),
      cmocka_unit_test(test_pattern_checker_cells),
      cmocka_unit_test(test_pattern_gradient_ramp_repeats),
      cmocka_unit_test(test_pattern_colour_map_interpolates),
      cmocka_unit_test(test_pattern_colour_map_out_of_order),
      cmocka_unit_test(test_pattern_noise_range_and_mean),
      cmocka_unit_test(test_pattern_pigment_eval_uses_transform),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
