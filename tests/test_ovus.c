/*
 * test_ovus.c - the ovus from scene text through the parser
 * (lib/sdl/build_iso.c) to the tracer's crossings, normals, inside
 * tests and bounds (lib/trace/obj_ovus.c).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "config.h"
#include "scene/scene.h"
#include "trace/intersect.h"
#include "zrcube.h"
#include "parse_fixture.h"
#include "test_util.h"

/*
 * ovus { 1, 0.5 } against POV-Ray 3.7's own surface: trace() from x = 5
 * towards -x at several heights gave these points and normals (printed
 * to 6 decimals, hence the tolerance): the bottom sphere, the lemon and
 * the top sphere.
 */
static void test_ovus_matches_povray(void **state) {
  fixture *f = *state;
  const zr_object *o = only(f, "ovus { 1, 0.5 }\n");
  assert_int_equal(o->kind, ZR_OBJ_OVUS);
  static const double ref[][4] = {
      /* y, x, normal x, normal y */
      {-0.5, 0.866025, 0.866025, -0.5},
      {0.0, 1.0, 1.0, 0.0},
      {0.3, 0.962165, 0.977161, 0.2125},
      {0.9, 0.725218, 0.858687, 0.5125},
      {1.3, 0.411187, 0.701672, 0.7125},
      {1.45, 0.217945, 0.435890, 0.9},
  };
  zr_hit h[ZR_MAX_CROSSINGS];
  for (size_t i = 0; i < sizeof ref / sizeof *ref; i++) {
    assert_int_equal(cross(o, zr_v3(5, ref[i][0], 0), zr_v3(-1, 0, 0), 0.0, h),
                     2);
    assert_near(5 - h[0].t, ref[i][1], 2e-6);
    assert_near(h[0].normal.x, ref[i][2], 2e-6);
    assert_near(h[0].normal.y, ref[i][3], 2e-6);
    /* Symmetric about the y axis. */
    assert_near(h[1].t - h[0].t, 2 * ref[i][1], 4e-6);
  }
  assert_int_equal(cross(o, zr_v3(0, 5, 0), zr_v3(0, -1, 0), 0.0, h), 2);
  assert_near(h[0].t, 5 - 1.5, 1e-12);
  assert_near(h[1].t, 5 + 1, 1e-12);
  assert_true(zr__inside(o, zr_v3(0, 1.4, 0)));
  assert_true(zr__inside(o, zr_v3(0.86, 0.6, 0)));
  assert_false(zr__inside(o, zr_v3(0.88, 0.6, 0)));
  assert_false(zr__inside(o, zr_v3(0, 1.6, 0)));
  zr_vec3 lo, hi;
  assert_true(zr__object_bounds(o, &lo, &hi));
  assert_true(lo.y <= -1 && hi.y >= 1.5 && hi.x >= 1 && lo.z <= -1);
}

/* A top radius of twice the bottom one or more leaves the top sphere,
   as POV-Ray does, with a warning; radii must be positive. */
static void test_ovus_sphere_and_bad_input(void **state) {
  fixture *f = *state;
  const zr_object *o = only(f, "ovus { 0.3, 0.7 translate y }\n");
  assert_int_equal(f->diag.warnings, 1);
  zr_hit h[ZR_MAX_CROSSINGS];
  assert_int_equal(cross(o, zr_v3(0, 5, 0), zr_v3(0, -1, 0), 0.0, h), 2);
  assert_near(h[0].t, 5 - (1 + 0.3 + 0.7), 1e-12);
  assert_near(h[1].t, 5 - (1 + 0.3 - 0.7), 1e-12);
  bad(f, "ovus { 1, -1 }\n", ZR_ESCENE, "an ovus's radii must be positive",
      "t.pov:1:11: error: an ovus's radii must be positive\n"
      "    1 | ovus { 1, -1 }\n"
      "      |           ^~\n");
}

#define TEST(fn) cmocka_unit_test_setup_teardown(fn, setup, teardown)

int main(void) {
  const struct CMUnitTest tests[] = {
      TEST(test_ovus_matches_povray),
      TEST(test_ovus_sphere_and_bad_input),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
