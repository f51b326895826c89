/*
 * test_warp.c - the pattern warps (lib/scene/warp.c) against the values
 * POV-Ray 3.7 gives for the same warps and points, as measured with
 * bench/warp_probe.sh (each group names its probe lines), and against
 * the manual's formulas where it gives them.
 *
 * The probe prints 9 decimals, so a value agrees within 1e-9 (half a
 * unit of the last printed digit, plus rounding).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>

#include "scene/pattern.h"
#include "scene/warp.h"
#include "test_util.h"

#define PRINTED 1e-9

static zr_warp make(zr_warp_kind kind) {
  zr_warp w;
  zr__warp_init(&w, kind);
  return w;
}

static zr_warp repeat_warp(int axis, double width) {
  zr_warp w = make(ZR_WARP_REPEAT);
  w.axis = axis;
  w.width = width;
  return w;
}

static void expect(const zr_warp *w, zr_vec3 p, double x, double y,
                   double z) {
  assert_vec(zr__warp_apply(w, p), x, y, z, PRINTED);
}

/* warp_probe.sh: repeat, repeat_offset, repeat_neg. */
static void test_warp_repeat_blocks(void **state) {
  (void)state;
  zr_warp w = repeat_warp(0, 2);
  expect(&w, zr_v3(2.5, 0.25, 0.125), 0.5, 0.25, 0.125);
  expect(&w, zr_v3(-0.5, 0.25, 0.125), 1.5, 0.25, 0.125);
  expect(&w, zr_v3(-4, 0, 0), 0, 0, 0);
  expect(&w, zr_v3(1.999, 0, 0), 1.999, 0, 0);
  w.offset = zr_v3(0.1, 0.2, 0.3);
  expect(&w, zr_v3(4.5, 1, 1), 0.7, 1.4, 1.6);
  expect(&w, zr_v3(-3.5, 1, 1), 0.3, 0.6, 0.4);
  zr_warp n = repeat_warp(1, -2);
  expect(&n, zr_v3(0, 0.5, 0), 0, -1.5, 0);
  expect(&n, zr_v3(0, 2.5, 0), 0, -1.5, 0);
  expect(&n, zr_v3(0, -2.5, 0), 0, -0.5, 0);
}

/* warp_probe.sh: repeat_flip_yz, repeat_flip_x, repeat_flip_offset,
   repeat_neg_flip, repeat_z. */
static void test_warp_repeat_flip(void **state) {
  (void)state;
  zr_warp w = repeat_warp(0, 2);
  w.flip = zr_v3(1, -1, -1);
  expect(&w, zr_v3(2.5, 0.25, 0.125), 0.5, -0.25, -0.125);
  expect(&w, zr_v3(-1.5, 0.25, 0.125), 0.5, -0.25, -0.125);
  expect(&w, zr_v3(-3.5, 0.25, 0.125), 0.5, 0.25, 0.125);
  w.flip = zr_v3(-1, 1, 1);
  expect(&w, zr_v3(2.5, 0.25, 0.125), 1.5, 0.25, 0.125);
  expect(&w, zr_v3(3.5, 0.25, 0.125), 0.5, 0.25, 0.125);
  expect(&w, zr_v3(-1.5, 0.25, 0.125), 1.5, 0.25, 0.125);
  w.flip = zr_v3(-1, -1, 1);
  w.offset = zr_v3(0.1, 0.2, 0.3);
  expect(&w, zr_v3(2.5, 0.25, 0.125), 1.6, -0.05, 0.425);
  expect(&w, zr_v3(-1.5, 0.25, 0.125), 1.4, -0.45, -0.175);
  zr_warp n = repeat_warp(1, -2);
  n.flip = zr_v3(1, -1, 1);
  n.offset = zr_v3(1, 0, 0);
  expect(&n, zr_v3(0, 0.5, 0), -1, -0.5, 0);
  expect(&n, zr_v3(0, -2.5, 0), 1, -1.5, 0);
  expect(&n, zr_v3(0, -4.5, 0), 2, -0.5, 0);
  zr_warp z = repeat_warp(2, 0.5);
  z.flip = zr_v3(-1, 1, -1);
  expect(&z, zr_v3(0.25, 0.5, 0.6), -0.25, 0.5, 0.4);
  expect(&z, zr_v3(0.25, 0.5, -0.1), -0.25, 0.5, 0.1);
}

/* The manual's closeness, force, clipping and inverse; warp_probe.sh:
   hole, hole_falloff, hole_strong, hole_inverse, hole_inverse_strong,
   hole_falloff0. */
static void test_warp_black_hole(void **state) {
  (void)state;
  zr_warp w = make(ZR_WARP_BLACK_HOLE);
  w.centre = zr_v3(1, 0, 0);
  w.radius = 2;
  expect(&w, zr_v3(1.5, 0, 0), 1.78125, 0, 0);
  expect(&w, zr_v3(1, 1, 0), 1, 1.25, 0);
  expect(&w, zr_v3(-0.5, 0, 0), -0.59375, 0, 0);
  expect(&w, zr_v3(3, 0, 0), 3, 0, 0);
  expect(&w, zr_v3(1, 0, 0), 1, 0, 0);
  zr_warp u = make(ZR_WARP_BLACK_HOLE);
  u.falloff = 1;
  u.strength = 0.5;
  expect(&u, zr_v3(0.25, 0, 0), 0.34375, 0, 0);
  expect(&u, zr_v3(0, 0, 0.5), 0, 0, 0.625);
  u = make(ZR_WARP_BLACK_HOLE);
  u.strength = 3;
  expect(&u, zr_v3(0.1, 0, 0), 0.2, 0, 0);
  expect(&u, zr_v3(0.75, 0, 0), 0.890625, 0, 0);
  u = make(ZR_WARP_BLACK_HOLE);
  u.inverse = true;
  expect(&u, zr_v3(0.25, 0, 0), 0.109375, 0, 0);
  expect(&u, zr_v3(0, -0.5, 0), 0, -0.375, 0);
  u.strength = 4;
  expect(&u, zr_v3(0.25, 0, 0), 0, 0, 0);
  expect(&u, zr_v3(0.75, 0, 0), 0.5625, 0, 0);
  u = make(ZR_WARP_BLACK_HOLE);
  u.falloff = 0;
  expect(&u, zr_v3(0.9, 0, 0), 1.8, 0, 0);
  expect(&u, zr_v3(1.1, 0, 0), 1.1, 0, 0);
}

/* warp_probe.sh: hole_repeat_ok (sizes already fitting the manual's
   rule), and the turbulence's shifts: each block's centre moves by at
   most the turbulence, the same at every call. */
static void test_warp_black_hole_repeat(void **state) {
  (void)state;
  zr_warp w = make(ZR_WARP_BLACK_HOLE);
  w.centre = zr_v3(1.5, 1.5, 0);
  w.repeat = zr_v3(4, 4, 0);
  expect(&w, zr_v3(2, 1.5, 0), 2.125, 1.5, 0);
  expect(&w, zr_v3(6, 1.5, 0), 6.125, 1.5, 0);
  expect(&w, zr_v3(-2, -2.5, 0), -1.875, -2.5, 0);
  expect(&w, zr_v3(2, 1.5, 7), 2, 1.5, 7);
  /* A hole of radius 1 at <1, 0, 0> in blocks of 3, its centre moved
     by up to 0.5 in x: the move p' - p has the sign of p - c, so its
     sign change along x finds each block's centre, which must lie in
     [1, 1.5) of the block, differ between blocks and not change from
     call to call. */
  zr_warp t = make(ZR_WARP_BLACK_HOLE);
  t.centre = zr_v3(1, 0, 0);
  t.repeat = zr_v3(3, 0, 0);
  t.turbulence = zr_v3(0.5, 0, 0);
  double first = -1;
  int differ = 0;
  for (int block = -3; block <= 3; block++) {
    double base = 3.0 * block;
    int changes = 0;
    double centre = 0;
    double prev = zr__warp_apply(&t, zr_v3(base + 0.9, 0, 0)).x -
                  (base + 0.9);
    for (int i = 1; i <= 700; i++) {
      double x = base + 0.9 + i * 0.001;
      double move = zr__warp_apply(&t, zr_v3(x, 0, 0)).x - x;
      if ((prev < 0) != (move < 0)) {
        changes++;
        centre = x - base;
      }
      prev = move;
    }
    assert_int_equal(changes, 1);
    assert_true(centre >= 1.0 && centre <= 1.501);
    if (first < 0)
      first = centre;
    else if (fabs(centre - first) > 0.002)
      differ++;
    zr_vec3 a = zr__warp_apply(&t, zr_v3(base + 1.2, 0, 0));
    zr_vec3 b = zr__warp_apply(&t, zr_v3(base + 1.2, 0, 0));
    assert_true(a.x == b.x);
  }
  assert_true(differ > 0);
}

/* warp_probe.sh: cyl, cyl_exp, cyl_exp2, axis_cyl. */
static void test_warp_cylindrical(void **state) {
  (void)state;
  zr_warp w = make(ZR_WARP_CYLINDRICAL);
  expect(&w, zr_v3(0, 0.3, 1), 0.25, 0.3, 1);
  expect(&w, zr_v3(-1, 0.3, 0), 0.5, 0.3, 1);
  expect(&w, zr_v3(1, 0.3, -1), 0.875, 0.3, sqrt(2));
  expect(&w, zr_v3(-2, 0.1, -0.0001), 0.500007958, 0.1, 2.000000003);
  expect(&w, zr_v3(0, 5, 0), 0, 5, 0);
  w.dist_exp = 1;
  expect(&w, zr_v3(-3, 0.3, 0), 1.5, 0.3, 3);
  expect(&w, zr_v3(0, 0.3, -0.5), 0.375, 0.3, 0.5);
  w.dist_exp = 2.5;
  expect(&w, zr_v3(-0.5, -1, 0), 0.088388348, -1, 0.5);
  zr_warp a = make(ZR_WARP_CYLINDRICAL);
  a.orientation = zr_v3(0, 1, 0);
  expect(&a, zr_v3(0, -2, 0), 0, -2, 0);
}

/* warp_probe.sh: sph, sph_exp, axis_sph. */
static void test_warp_spherical(void **state) {
  (void)state;
  zr_warp w = make(ZR_WARP_SPHERICAL);
  expect(&w, zr_v3(1, 1, 0), 0, 0.75, sqrt(2));
  expect(&w, zr_v3(0, -2, 0), 0, 0, 2);
  expect(&w, zr_v3(2, 1, -1), 0.926208191, 0.633860236, 2.449489743);
  expect(&w, zr_v3(0, -3, 0.000001), 0.25, 0.000000106, 3);
  expect(&w, zr_v3(0, 0, 0), 0, 0, 0);
  w.dist_exp = 1;
  expect(&w, zr_v3(1, 1, 1), 0.216506351, 1.205357152, 1.732050808);
  expect(&w, zr_v3(0, 3, 0), 0, 3, 3);
  zr_warp a = make(ZR_WARP_SPHERICAL);
  a.orientation = zr_v3(1, 0, 0);
  expect(&a, zr_v3(0, 2, 0), 2, 1, 0);
}

/* warp_probe.sh: tor, tor_r, axis_tor. */
static void test_warp_toroidal(void **state) {
  (void)state;
  zr_warp w = make(ZR_WARP_TOROIDAL);
  expect(&w, zr_v3(2, 0, 0), 0, 0.5, 1);
  expect(&w, zr_v3(1, 1, 0), 0, 0.75, 1);
  expect(&w, zr_v3(0.5, 0, 0), 0, 0, 0.5);
  expect(&w, zr_v3(1, -1, 0), 0, 0.25, 1);
  expect(&w, zr_v3(0, 0.5, -1), 0.75, 0.75, 0.5);
  expect(&w, zr_v3(-1.5, 0.25, 0.25), 0.473715772, 0.571242031,
         0.577597381);
  expect(&w, zr_v3(0, 3, 0), 0, 3, 0);
  w.major_radius = 2;
  w.dist_exp = 1;
  expect(&w, zr_v3(2, 0.5, 0), 0, 0.375, 0.5);
  expect(&w, zr_v3(0, -1, 2), 0.25, 0.25, 1);
  /* On the ring POV-Ray's v is not a number; ours is 0. */
  zr_vec3 ring = zr__warp_apply(&w, zr_v3(2, 0, 0));
  assert_true(isfinite(ring.y));
}

static zr_vec3 unit(double x, double y, double z) {
  return zr_v3_norm(zr_v3(x, y, z));
}

/* warp_probe.sh: sph_ox, sph_oy, sph_o123, sph_o68, sph_oneg, sph_onz,
   cyl_oy, tor_ox, cyl_onx, planar, planar_y, planar_n. */
static void test_warp_orientation(void **state) {
  (void)state;
  zr_warp w = make(ZR_WARP_SPHERICAL);
  w.orientation = unit(1, 0, 0);
  expect(&w, zr_v3(0, -1, 0.5), 1.118033989, 0.147583618, -0.25);
  w.orientation = unit(0, 1, 0);
  expect(&w, zr_v3(2, 1, -1), 0.926208191, -2.449489743, 0.633860236);
  w.orientation = unit(1, 2, 3);
  expect(&w, zr_v3(2, 1, -1), 1.892351428, -0.631682245, 2.055234009);
  expect(&w, zr_v3(0, -1, 0.5), 0.632883705, -0.439840781, 0.908492908);
  w.orientation = unit(0.6, 0.8, 0);
  expect(&w, zr_v3(2, 1, -1), 2.210660399, -1.579275652, -0.048636726);
  w.orientation = unit(-1, 0.5, 0.2);
  expect(&w, zr_v3(1, 1, 0), -1.245145613, -1.150843350, 0.579198212);
  w.orientation = unit(0, 0, -1);
  expect(&w, zr_v3(0, 0, 1), -0.25, -0.5, -1);
  zr_warp c = make(ZR_WARP_CYLINDRICAL);
  c.orientation = unit(-1, 0, 0);
  expect(&c, zr_v3(2, 1, -1), -2.236067977, -1, 0.926208191);
  zr_warp t = make(ZR_WARP_TOROIDAL);
  t.orientation = unit(1, 0, 0);
  expect(&t, zr_v3(0, 0.5, -1), 0.5, 0.75, -0.75);
  zr_warp p = make(ZR_WARP_PLANAR);
  expect(&p, zr_v3(-1, 2, 5), -1, 2, 0);
  p.orientation = unit(0, 1, 0);
  p.distance = 0.5;
  expect(&p, zr_v3(2, -3, 4), 2, -0.5, -3);
  p.orientation = unit(1, 2, 3);
  p.distance = 0.25;
  expect(&p, zr_v3(-1, 2, 5), -1.269490899, 2.004459314, 1.536752141);
}

/* warp_probe.sh: frame_before, frame_after, far, far_fine, far_in. */
static void test_warp_frames_and_limit(void **state) {
  (void)state;
  zr_warp w = repeat_warp(0, 1);
  zr_transform scale2;
  zr__transform_identity(&scale2);
  zr__transform_scale(&scale2, zr_v3(2, 2, 2));
  /* "scale 2 warp { repeat x }": the point comes in the pattern's
     space (after the whole inverse transform: world 1.5 is 0.75); the
     warp acts in its frame, where that is 1.5 again, and its result
     goes back: 0.5 / 2 (frame_before). */
  w.frame = scale2;
  assert_vec(zr__warp_point(&w, 1, zr_v3(0.75, 0, 0)), 0.25, 0, 0, PRINTED);
  /* "warp { repeat x } scale 2": nothing before the warp, so it acts on
     the point as it comes (frame_after: world 1.5 reads 0.75). */
  zr__transform_identity(&w.frame);
  assert_vec(zr__warp_point(&w, 1, zr_v3(0.75, 0, 0)), 0.75, 0, 0,
             PRINTED);
  zr_warp far = repeat_warp(0, 1);
  far.offset = zr_v3(0, 1e14, 0);
  assert_vec(zr__warp_point(&far, 1, zr_v3(999.5, 0, 0)), 0.5, 9.99e16, 0,
             16);
  assert_vec(zr__warp_point(&far, 1, zr_v3(1001.5, 0, 0)), 0.5, 1e17, 0,
             0);
  assert_vec(zr__warp_point(&far, 1, zr_v3(-1001.5, 0, 0)), 0.5, -1e17, 0,
             0);
  zr_warp none = repeat_warp(0, 1e30);
  assert_vec(zr__warp_point(&none, 1, zr_v3(1, 2e17, -3e17)), 1, 1e17,
             -1e17, 0);
  /* No warp at all: the pattern still sees the cut point (far_nowarp). */
  zr_pattern pt;
  zr__pattern_init(&pt, ZR_PAT_GRADIENT);
  assert_vec(zr__pattern_point(&pt, zr_v3(4e17, 2e17, -3e17)), 1e17, 1e17,
             -1e17, 0);
  assert_vec(zr__pattern_point(&pt, zr_v3(1, 9e16, 0)), 1, 9e16, 0, 0);
}

/* warp_probe.sh: cubic, cubic_tie (POV-Ray 3.7's values). */
static void test_warp_cubic(void **state) {
  (void)state;
  zr_warp w = make(ZR_WARP_CUBIC);
  /* One point on each face of the cube, then twice as far out. */
  expect(&w, zr_v3(-1, 0.2, 0.3), 0.1625, 0.533333333, 1);
  expect(&w, zr_v3(1, 0.2, 0.3), 0.5875, 0.533333333, 1);
  expect(&w, zr_v3(0.2, -1, 0.3), 0.4, 0.216666667, 1);
  expect(&w, zr_v3(0.2, 1, 0.3), 0.4, 0.783333333, 1);
  expect(&w, zr_v3(0.2, 0.3, -1), 0.85, 0.55, 1);
  expect(&w, zr_v3(0.2, 0.3, 1), 0.4, 0.55, 1);
  expect(&w, zr_v3(0.2, 0.3, -2), 0.8625, 0.525, 2);
  expect(&w, zr_v3(-3, -1, 2), 0.208333333, 0.444444444, 3);
  expect(&w, zr_v3(0.1, 0.7, -0.4), 0.392857143, 0.928571429, 0.7);
  expect(&w, zr_v3(0, 0, 1e-9), 0.375, 0.5, 1e-9);
  /* Ties across the cuts of the unfolded cross: +x before +y, +y
     before -x, -x before -y and -z, -y before -z, +y before -z. */
  expect(&w, zr_v3(1, 1, 0.5), 0.5625, 0.666666667, 1);
  expect(&w, zr_v3(-1, 1, -1), 0.25, 1, 1);
  expect(&w, zr_v3(-1, -1, 0.5), 0.1875, 0.333333333, 1);
  expect(&w, zr_v3(-1, -1, -1), 0, 0.333333333, 1);
  expect(&w, zr_v3(0.5, -1, -1), 0.4375, 0, 1);
  expect(&w, zr_v3(0.5, 1, -1), 0.4375, 1, 1);
  /* The origin has no face (POV-Ray: NaN); it stays finite here. */
  zr_vec3 o = zr__warp_apply(&w, zr_v3(0, 0, 0));
  assert_true(isfinite(o.x) && isfinite(o.y) && isfinite(o.z));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_warp_repeat_blocks),
      cmocka_unit_test(test_warp_repeat_flip),
      cmocka_unit_test(test_warp_black_hole),
      cmocka_unit_test(test_warp_black_hole_repeat),
      cmocka_unit_test(test_warp_cylindrical),
      cmocka_unit_test(test_warp_spherical),
      cmocka_unit_test(test_warp_toroidal),
      cmocka_unit_test(test_warp_orientation),
      cmocka_unit_test(test_warp_frames_and_limit),
      cmocka_unit_test(test_warp_cubic),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
