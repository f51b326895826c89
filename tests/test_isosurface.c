/*
 * test_isosurface.c - the isosurface from scene text through the parser
 * (lib/sdl/build_iso.c) to the tracer's crossings, normals, inside
 * tests and bounds (lib/trace/obj_isosurface.c).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "config.h"
#include "scene/scene.h"
#include "trace/intersect.h"
#include "trace/obj_isosurface.h"
#include "zrcube.h"
#include "parse_fixture.h"
#include "test_util.h"

/* Crossings are refined to a few ulps of t once bracketed, so 1e-9
   leaves a wide margin; normals come from forward differences of step
   accuracy (0.001 by default), as povray's do, which tilt a quadratic's
   by about the step, twice that under a scale of 2: 5e-3. */
#define ROOT_EPS 1e-9
#define NORMAL_EPS 5e-3

static void test_isosurface_sphere(void **state) {
  fixture *f = *state;
  const zr_object *o = only(f, "isosurface { function { x*x + y*y + z*z - "
                               "0.25 } all_intersections }\n");
  assert_int_equal(o->kind, ZR_OBJ_ISOSURFACE);
  assert_near(o->u.isosurface.accuracy, 0.001, 0);
  assert_near(o->u.isosurface.max_gradient, 1.1, 0);
  assert_int_equal(o->u.isosurface.max_trace, 0);
  zr_hit h[ZR_MAX_CROSSINGS];
  assert_int_equal(cross(o, zr_v3(0, 0, -5), zr_v3(0, 0, 1), 0, h), 2);
  assert_near(h[0].t, 4.5, ROOT_EPS);
  assert_near(h[1].t, 5.5, ROOT_EPS);
  assert_vec(h[0].normal, 0, 0, -1, NORMAL_EPS);
  assert_vec(h[1].normal, 0, 0, 1, NORMAL_EPS);
  /* Asked again beyond the first, the second is the same crossing. */
  assert_int_equal(cross(o, zr_v3(0, 0, -5), zr_v3(0, 0, 1), h[0].t, h), 1);
  assert_near(h[0].t, 5.5, ROOT_EPS);
  /* A slanted ray with a long direction vector: t is in its units. */
  assert_int_equal(cross(o, zr_v3(0.3, -4, 0), zr_v3(0, 2, 0), 0, h), 2);
  assert_near(h[0].t, (4 - 0.4) / 2, ROOT_EPS);
  assert_vec(h[0].normal, 0.6, -0.8, 0, NORMAL_EPS);
  assert_true(zr__inside(o, zr_v3(0.1, 0.2, 0.1)));
  assert_false(zr__inside(o, zr_v3(0.4, 0.3, 0)));
  zr_vec3 lo, hi;
  assert_true(zr__object_bounds(o, &lo, &hi));
  assert_vec(lo, -1, -1, -1, 1e-6);
  assert_vec(hi, 1, 1, 1, 1e-6);
}

/* By default only the first crossing along a ray counts (max_trace 1),
   as in POV-Ray; max_trace 2 finds the second. */
static void test_isosurface_max_trace(void **state) {
  fixture *f = *state;
  const char *fn = "function { x*x + y*y + z*z - 0.25 }";
  char text[256];
  snprintf(text, sizeof text, "isosurface { %s }\n", fn);
  const zr_object *o = only(f, text);
  assert_int_equal(o->u.isosurface.max_trace, 1);
  zr_hit h[ZR_MAX_CROSSINGS];
  assert_int_equal(cross(o, zr_v3(0, 0, -5), zr_v3(0, 0, 1), 0, h), 1);
  assert_near(h[0].t, 4.5, ROOT_EPS);
  assert_int_equal(cross(o, zr_v3(0, 0, -5), zr_v3(0, 0, 1), 4.6, h), 0);
  /* From inside, the first crossing is the way out. */
  assert_int_equal(cross(o, zr_v3(0, 0, 0), zr_v3(0, 0, 1), 0, h), 1);
  assert_near(h[0].t, 0.5, ROOT_EPS);
  snprintf(text, sizeof text, "isosurface { %s max_trace 2 }\n", fn);
  o = only(f, text);
  assert_int_equal(cross(o, zr_v3(0, 0, -5), zr_v3(0, 0, 1), 4.6, h), 1);
  assert_near(h[0].t, 5.5, ROOT_EPS);
}

/* A solid wider than its container is closed by the container's faces,
   unless open; a sphere container likewise. */
static void test_isosurface_container(void **state) {
  fixture *f = *state;
  const zr_object *o = only(
      f, "isosurface { function { y } threshold 0.5 all_intersections\n"
         "  contained_by { box { <-1, -2, -1>, <1, 2, 1> } } }\n");
  zr_hit h[ZR_MAX_CROSSINGS];
  /* Down through the top: the plane y = 0.5, then the bottom face. */
  assert_int_equal(cross(o, zr_v3(0.2, 5, 0), zr_v3(0, -1, 0), 0, h), 2);
  assert_near(h[0].t, 4.5, ROOT_EPS);
  assert_vec(h[0].normal, 0, 1, 0, NORMAL_EPS);
  assert_near(h[1].t, 7, 1e-12);
  assert_vec(h[1].normal, 0, -1, 0, 0);
  /* Sideways below the plane: the two side faces. */
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0, h), 2);
  assert_near(h[0].t, 4, 1e-12);
  assert_vec(h[0].normal, -1, 0, 0, 0);
  assert_vec(h[1].normal, 1, 0, 0, 0);
  assert_true(zr__inside(o, zr_v3(0, -1.5, 0)));
  assert_false(zr__inside(o, zr_v3(0, -2.5, 0)));
  assert_false(zr__inside(o, zr_v3(0, 1, 0)));
  /* open: no faces, the sideways ray misses. */
  o = only(f, "isosurface { function { y } threshold 0.5 open\n"
              "  contained_by { box { <-1, -2, -1>, <1, 2, 1> } } }\n");
  assert_true(o->u.isosurface.open);
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0, h), 0);
  /* open given after an object modifier means the same. */
  o = only(f, "isosurface { function { y } translate x open }\n");
  assert_true(o->u.isosurface.open);
  o = only(f, "isosurface { function { y }\n"
              "  contained_by { sphere { <0, 0, 0>, 2 } } }\n");
  assert_true(o->u.isosurface.sphere);
  assert_int_equal(cross(o, zr_v3(-5, -1, 0), zr_v3(1, 0, 0), 0, h), 1);
  assert_near(h[0].t, 5 - sqrt(3.0), 1e-12);
  assert_vec(h[0].normal, -sqrt(3.0) / 2, -0.5, 0, 1e-12);
}

/* The normal is povray 3.7's: forward differences of step accuracy
   (bench/conform/iso_normal_probe.sh prints povray's normals: on
   y + 1000 x^2 + 2000 z^2 at x = z = 0, <0.408248290, 0.408248290,
   0.816496581> at accuracy 0.001 and <0.097590007, 0.975900073,
   0.195180015> at 0.0001, where the slope is <0, 1, 0>). */
static void test_isosurface_normal_steps(void **state) {
  fixture *f = *state;
  zr_hit h[ZR_MAX_CROSSINGS];
  const zr_object *o = only(
      f, "isosurface { function { y + 1000*x*x + 2000*z*z }\n"
         "  max_gradient 100000 contained_by { box { -1, 1 } } }\n");
  assert_int_equal(cross(o, zr_v3(0, 0.5, 0), zr_v3(0, -1, 0), 0, h), 1);
  assert_vec(h[0].normal, 0.408248290, 0.408248290, 0.816496581, 1e-6);
  o = only(f, "isosurface { function { y + 1000*x*x + 2000*z*z }\n"
              "  max_gradient 100000 accuracy 0.0001\n"
              "  contained_by { box { -1, 1 } } }\n");
  assert_int_equal(cross(o, zr_v3(0, 0.5, 0), zr_v3(0, -1, 0), 0, h), 1);
  assert_vec(h[0].normal, 0.097590007, 0.975900073, 0.195180015, 1e-6);
}

/* Transforms and CSG: a scaled isosurface, and a sphere with an
   isosurface cut out of it. */
static void test_isosurface_transform_and_csg(void **state) {
  fixture *f = *state;
  const zr_object *o = only(
      f, "isosurface { function { x*x + y*y + z*z - 0.25 }\n"
         "  scale <2, 1, 1> translate <0, 0, 3> }\n");
  zr_hit h[ZR_MAX_CROSSINGS];
  assert_int_equal(cross(o, zr_v3(-5, 0, 3), zr_v3(1, 0, 0), 0, h), 1);
  assert_near(h[0].t, 4, 2 * ROOT_EPS);
  assert_vec(h[0].normal, -1, 0, 0, NORMAL_EPS);
  zr_vec3 lo, hi;
  assert_true(zr__object_bounds(o, &lo, &hi));
  assert_vec(lo, -2, -1, 2, 1e-6);
  assert_vec(hi, 2, 1, 4, 1e-6);
  zr_scene *s = good(f, "difference { sphere { 0, 1 }\n"
                        "  isosurface { function { x*x + y*y + z*z - 0.25 }"
                        " all_intersections } }\n");
  assert_int_equal(s->n_primitives, 1);
  o = s->primitives[0];
  assert_false(zr__inside(o, zr_v3(0, 0, 0)));
  assert_true(zr__inside(o, zr_v3(0, 0, 0.75)));
  assert_int_equal(cross(o, zr_v3(0, 0, -5), zr_v3(0, 0, 1), 0, h), 2);
  assert_near(h[0].t, 4, 1e-12);
  assert_near(h[1].t, 4.5, ROOT_EPS);
  /* The cut's surface faces into the hole. */
  assert_vec(h[1].normal, 0, 0, 1, NORMAL_EPS);
}

/* A function steeper than max_gradient may lose its crossings; with the
   right gradient it is found. */
static void test_isosurface_gradient(void **state) {
  fixture *f = *state;
  /* Its gradient reaches 50 * 2.61 at x = -1; the dip between its
     crossings is 0.00125 deep. */
  const char *fn = "function { 50 * (x - 0.3) * (x - 0.31) }";
  char text[256];
  snprintf(text, sizeof text,
           "isosurface { %s max_gradient 131 accuracy 0.0001 }\n", fn);
  const zr_object *o = only(f, text);
  zr_hit h[ZR_MAX_CROSSINGS];
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0, h), 1);
  assert_near(h[0].t, 5.3, ROOT_EPS);
  snprintf(text, sizeof text, "isosurface { %s }\n", fn);
  o = only(f, text);
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0, h), 0);
}

static void test_isosurface_bad_input(void **state) {
  fixture *f = *state;
  bad(f, "isosurface { function { x } contained_by { cylinder { 0, y, 1 } "
         "} }\n",
      ZR_ESCENE, "contained_by takes a plain sphere or box", NULL);
  bad(f, "isosurface { function { x } accuracy 0 }\n", ZR_ESCENE,
      "accuracy must be positive",
      "t.pov:1:38: error: accuracy must be positive\n"
      "    1 | isosurface { function { x } accuracy 0 }\n"
      "      |                                      ^\n");
  bad(f, "isosurface { function { x } max_gradient -1 }\n", ZR_ESCENE,
      "max_gradient must be positive", NULL);
  bad(f, "isosurface { function { x } max_trace 0 }\n", ZR_ESCENE,
      "max_trace must be at least 1", NULL);
  bad(f, "isosurface { function(a, b, c, d) { a } }\n", ZR_ESCENE,
      "an isosurface's function takes x, y and z, not 4 parameters",
      NULL);
  bad(f, "#include \"functions.inc\"\n"
         "isosurface { function { f_bicorn(x, y, z, 1, 1) } }\n",
      ZR_EUNSUPPORTED,
      "the isosurface's function uses internal function 4 (f_bicorn), "
      "which is not supported yet", NULL);
}

/* evaluate is traced with a fixed gradient, and says so. */
static void test_isosurface_evaluate(void **state) {
  fixture *f = *state;
  const zr_object *o =
      only(f, "isosurface { function { x } evaluate 2, 1.5, 0.7 }\n");
  assert_near(o->u.isosurface.max_gradient, 3, 1e-12);
  assert_int_equal(f->diag.warnings, 1);
}

#define TEST(fn) cmocka_unit_test_setup_teardown(fn, setup, teardown)

int main(void) {
  const struct CMUnitTest tests[] = {
      TEST(test_isosurface_sphere),
      TEST(test_isosurface_max_trace),
      TEST(test_isosurface_container),
      TEST(test_isosurface_normal_steps),
      TEST(test_isosurface_transform_and_csg),
      TEST(test_isosurface_gradient),
      TEST(test_isosurface_bad_input),
      TEST(test_isosurface_evaluate),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
