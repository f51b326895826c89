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

/* A sheet whose partial derivatives (64 in x and z, 2 pi in y) are far
   above the default max_gradient 1 (the corpus' GSprites_Terrain_demo.pov
   water): POV-Ray 3.7 draws it whole, so zRcube measures the slopes and
   traces with them (build_iso.c zr__sdl_parametric_done).  Before, the
   boxes of 1 were too small: this ray's crossing was found only by
   Newton's method from a neighbouring box, and not at all when asked from
   just before it, as the tracer asks again for the winner's normal (the
   sheet was dark there); a ray through the middle found nothing. */
#define SHEET                                                             \
  "parametric { function { u * 64 - 32 }\n"                              \
  "  function { 0.25 * (sin(u * 2 * pi * 4) + sin(v * 2 * pi * 4)) }\n"  \
  "  function { v * 64 - 32 } <0, 0>, <1, 1> accuracy 0.01\n"            \
  "  contained_by { box { -32, 32 } } }\n"

static void test_parametric_gradient_too_small(void **state) {
  fixture *f = *state;
  const zr_object *o = only(f, SHEET);
  /* The largest difference quotient on the 64 x 64 grid is 64 (x and z
     are linear), times 1.25. */
  assert_near(o->u.parametric.max_gradient, 80.0, 1e-9);
  zr_hit h[ZR_MAX_CROSSINGS];
  zr_vec3 org = zr_v3(0, 80, -120);
  zr_vec3 dir = zr_v3(-0.18347199, -0.46477018, 0.86621401);
  assert_int_equal(cross(o, org, dir, 0, h), 1);
  double t = h[0].t;
  zr_vec3 p = zr_v3_madd(org, dir, t);
  double u = (p.x + 32) / 64, v = (p.z + 32) / 64;
  assert_near(p.y, 0.25 * (sin(u * 8 * M_PI) + sin(v * 8 * M_PI)), 1e-9);
  assert_true(h[0].normal.y > 0.99);
  assert_int_equal(cross(o, org, dir, t - 1e-9 * t, h), 1);
  assert_near(h[0].t, t, 1e-9);
  /* Straight down through the middle of the sheet: y there is 0. */
  assert_int_equal(cross(o, zr_v3(0.1, 50, 0.1), zr_v3(0, -1, 0), 0, h), 1);
  assert_near(h[0].t, 50 - 0.25 * (2 * sin(8 * M_PI * 0.1 / 64 + 4 * M_PI)),
              1e-9);
  /* A max_gradient above the slopes is kept as given. */
  o = only(f, "parametric { function { u } function { v } function { 0 }"
              " <0, 0>, <1, 1> max_gradient 3 }\n");
  assert_near(o->u.parametric.max_gradient, 3.0, 0);
}

#define TEST(fn) cmocka_unit_test_setup_teardown(fn, setup, teardown)

int main(void) {
  const struct CMUnitTest tests[] = {
      TEST(test_parametric_sphere),
      TEST(test_parametric_bad_input),
      TEST(test_parametric_gradient_too_small),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
