/*
 * test_height_field.c - the height field from scene text and image files
 * through the parser (lib/sdl/build_hf.c, lib/image/heights.c) to the
 * tracer's crossings, normals, inside tests and bounds
 * (lib/trace/obj_height_field.c).
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
#include "trace/obj_isosurface.h"
#include "zrcube.h"
#include "parse_fixture.h"
#include "test_util.h"

/* The first crossing straight down onto (x, z), in object space. */
static int down(const zr_object *o, double x, double z,
                zr_hit h[ZR_MAX_CROSSINGS]) {
  zr_ray r = {zr_v3(x, 5, z), zr_v3(0, -1, 0)};
  return zr__intersect(o, &r, 0, INFINITY, h);
}

/* Samples are stored as floats: 1e-6 is their rounding and more.  Rays
   aimed at a grid point are moved EDGE inside, off the mesh's border,
   which changes the height by no more than EDGE times the slope. */
#define SAMPLE_EPS 1e-6
#define EDGE 1e-9

static const vfile files[] = {
    /* Row 0 (the back, z = 1) rises to the left; 16-bit samples. */
    {"a.pgm", "P2\n3 3\n65535\n65535 32768 0\n0 0 0\n0 0 13107\n"},
    /* A colour file holds 256 r + g. */
    {"c.ppm", "P3\n2 2\n255\n1 2 0  0 0 0\n0 0 0  255 255 255\n"},
    {"t.tif", "not read"},
    {NULL, NULL}};

static void test_height_field_image_layout(void **state) {
  fixture *f = *state;
  f->files = files;
  const zr_object *o = only(f, "height_field { pgm \"a.pgm\" }\n");
  assert_int_equal(o->kind, ZR_OBJ_HEIGHT_FIELD);
  assert_int_equal(o->u.height_field.w, 3);
  assert_int_equal(o->u.height_field.h, 3);
  zr_hit h[ZR_MAX_CROSSINGS];
  /* Image pixel (0, 0) is at x = 0, z = 1; (2, 2) at x = 1, z = 0. */
  assert_int_equal(down(o, EDGE, 1 - EDGE, h), 1);
  assert_near(h[0].t, 5 - 1, SAMPLE_EPS);
  assert_int_equal(down(o, 0.5, 1 - EDGE, h), 1);
  assert_near(h[0].t, 5 - 32768.0 / 65535, SAMPLE_EPS);
  assert_int_equal(down(o, 1 - EDGE, EDGE, h), 1);
  assert_near(h[0].t, 5 - 0.2, SAMPLE_EPS);
  /* Flat ground faces up. */
  assert_int_equal(down(o, 0.3, 0.3, h), 1);
  assert_near(h[0].t, 5, SAMPLE_EPS);
  assert_vec(h[0].normal, 0, 1, 0, 1e-12);
  assert_near(zr__height_field_height(o, 0.25, 1), 0.75, 1e-4);
  assert_true(zr__inside(o, zr_v3(0.05, 0.5, 0.95)));
  assert_false(zr__inside(o, zr_v3(0.9, 0.5, 0.95)));
  assert_false(zr__inside(o, zr_v3(1.2, 0.01, 0.5)));
  zr_vec3 lo, hi;
  assert_true(zr__object_bounds(o, &lo, &hi));
  assert_vec(lo, 0, 0, 0, 1e-6);
  assert_vec(hi, 1, 1, 1, 1e-6);
  /* Without a type keyword the file says what it is. */
  o = only(f, "height_field { \"c.ppm\" scale <2, 3, 2> }\n");
  assert_int_equal(down(o, EDGE, 2 - EDGE, h), 1);
  assert_near(h[0].t, 5 - 3 * 258.0 / 65535, 1e-6);
  assert_int_equal(down(o, 2 - EDGE, EDGE, h), 1);
  assert_near(h[0].t, 5 - 3, 1e-6);
}

/* function W, H { f(x, y) }: sample (i, j) at x = i / (W - 1),
   y = j / (H - 1), placed like image pixel (i, j); clamped to [0, 1]. */
static void test_height_field_function(void **state) {
  fixture *f = *state;
  const zr_object *o = only(
      f, "#declare F = function { 0.25 + 0.5 * x + 2 * (y > 0.9) }\n"
         "height_field { function 5, 3 { F(x, y, z) } smooth }\n");
  assert_int_equal(o->u.height_field.w, 5);
  assert_int_equal(o->u.height_field.h, 3);
  assert_true(o->u.height_field.smooth);
  zr_hit h[ZR_MAX_CROSSINGS];
  /* y = 0 is the back row (z = 1). */
  assert_int_equal(down(o, 0.5, 1 - EDGE, h), 1);
  assert_near(h[0].t, 5 - 0.5, SAMPLE_EPS);
  /* y = 1 went past 1 and is clamped, at the front (z = 0). */
  assert_int_equal(down(o, 0.5, EDGE, h), 1);
  assert_near(h[0].t, 5 - 1, SAMPLE_EPS);
  /* smooth: the normal in the middle of the back row follows the slope
     0.5 along x (the grid's central difference). */
  assert_int_equal(down(o, 0.5, 1 - EDGE, h), 1);
  double n = sqrt(1 + 0.25);
  assert_vec(h[0].normal, -0.5 / n, 1 / n, 0, 1e-6);
}

/* water_level hides the surface below it. */
static void test_height_field_water(void **state) {
  fixture *f = *state;
  f->files = files;
  const zr_object *o =
      only(f, "height_field { pgm \"a.pgm\" water_level 0.1 hierarchy off }\n");
  zr_hit h[ZR_MAX_CROSSINGS];
  assert_int_equal(down(o, 0.3, 0.3, h), 0);
  assert_int_equal(down(o, EDGE, 1 - EDGE, h), 1);
  /* A ray along the ground under the water meets nothing. */
  zr_ray r = {zr_v3(-1, 0.05, 0.3), zr_v3(1, 0, 0)};
  assert_int_equal(zr__intersect(o, &r, 0, INFINITY, h), 0);
}

static void test_height_field_bad_input(void **state) {
  fixture *f = *state;
  f->files = files;
  bad(f, "height_field { \"t.exr\" }\n", ZR_EUNSUPPORTED,
      "height_field: 'exr' files are not supported yet (use png, gif, pot, "
      "tga, bmp, tiff, pgm, ppm or jpeg)",
      "t.pov:1:16: error: height_field: 'exr' files are not supported yet "
      "(use png, gif, pot, tga, bmp, tiff, pgm, ppm or jpeg)\n"
      "    1 | height_field { \"t.exr\" }\n"
      "      |                ^~~~~~~\n");
  bad(f, "height_field { hdr \"t.hdr\" }\n", ZR_EUNSUPPORTED,
      "height_field: 'hdr' files are not supported yet (use png, gif, pot, "
      "tga, bmp, tiff, pgm, ppm or jpeg)", NULL);
  bad(f, "height_field { png \"none.png\" }\n", ZR_ENOTFOUND,
      "height_field file 'none.png' not found", NULL);
  bad(f, "height_field { function 1, 10 { x } }\n", ZR_ESCENE,
      "a height_field's resolution must be 2 to 65536", NULL);
  bad(f, "height_field { function 4, 4 { x } water_level <1, 2> }\n",
      ZR_ESYNTAX, "expected a float, got a 2-D vector", NULL);
}

/* hf_gray_16 in global_settings has been an output option since 3.7. */
static void test_height_field_hf_gray_16(void **state) {
  fixture *f = *state;
  good(f, "global_settings { hf_gray_16 on }\n");
  assert_int_equal(f->diag.warnings, 1);
  assert_non_null(strstr(f->diag.warning, "'hf_gray_16' is ignored"));
}

#define TEST(fn) cmocka_unit_test_setup_teardown(fn, setup, teardown)

int main(void) {
  const struct CMUnitTest tests[] = {
      TEST(test_height_field_image_layout),
      TEST(test_height_field_function),
      TEST(test_height_field_water),
      TEST(test_height_field_bad_input),
      TEST(test_height_field_hf_gray_16),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
