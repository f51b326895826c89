/*
 * test_parametric.c - the parametric surface from scene text through the
 * parser (lib/sdl/build_iso.c) to the tracer's crossings and normals
 * (lib/trace/obj_parametric.c).
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

#define SPHERE                                                            \
  "parametric { function { sin(u) * cos(v) } function { sin(u) * sin(v) }" \
  " function { cos(u) } <0, 0>, <2 * pi, pi>\n"                          \
  "  contained_by { sphere { 0, 1.1 } } max_gradient 1.5 }\n"

/* Crossings are refined by Newton's method to the rounding of the
   functions: 1e-9 is a wide margin.  The normal is Pu x Pv by central
   differences (relative step 1e-6): 1e-6. */
static void test_parametric_sphere(void **state) {
  fixture *f = *state;
  const zr_object *o = only(f, SPHERE);
  assert_int_equal(o->kind, ZR_OBJ_PARAMETRIC);
  zr_hit h[ZR_MAX_CROSSINGS];
  assert_int_equal(cross(o, zr_v3(0.3, 0.2, -5), zr_v3(0, 0, 1), 0, h), 2);
  double z = sqrt(1 - 0.09 - 0.04);
  assert_near(h[0].t, 5 - z, 1e-9);
  assert_near(h[1].t, 5 + z, 1e-9);
  /* The normal is along the radius (either way: a shell has no
     outside). */
  assert_near(fabs(h[0].normal.z), z, 1e-6);
  assert_near(fabs(h[0].normal.x), 0.3, 1e-6);
  /* Asked again beyond the first, the second. */
  assert_int_equal(cross(o, zr_v3(0.3, 0.2, -5), zr_v3(0, 0, 1), h[0].t, h),
                   1);
  assert_near(h[0].t, 5 + z, 1e-9);
  /* A shell has no inside. */
  assert_false(zr__inside(o, zr_v3(0, 0, 0)));
  assert_int_equal(cross(o, zr_v3(2, 2, -5), zr_v3(0, 0, 1), 0, h), 0);
}

static void test_parametric_bad_input(void **state) {
  fixture *f = *state;
  bad(f, "parametric { function { u } function { v } function { 0 }\n"
         "  <1, 0>, <0, 1> }\n",
      ZR_ESCENE, "the parametric's <u2, v2> must exceed <u1, v1>", NULL);
  bad(f, "parametric { function { u } function { v } function { 0 }\n"
         "  <0, 0>, <1, 1> precompute 30 x, y, z }\n",
      ZR_ESCENE, "precompute's depth must be 0 to 20", NULL);
}

#define TEST(fn) cmocka_unit_test_setup_teardown(fn, setup, teardown)

int main(void) {
  const struct CMUnitTest tests[] = {
      TEST(test_parametric_sphere),
      TEST(test_parametric_bad_input),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
