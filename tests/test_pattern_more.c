/*
 * test_pattern_more.c - transform blocks and identifiers, the fractal
 * patterns, the function pattern, the tiling pattern
 * (lib/scene/pattern_tiling.c), min_extent/max_extent, bare default and
 * font names without their extension (lib/sdl/build_pattern.c,
 * lib/scene/pattern_more.c), and warps (lib/sdl/build_warp.c,
 * lib/scene/warp.c), parsed from scene text and evaluated.
 *
 * The fractal values are povray 3.7.0's own, printed with
 * #declare F = function { pattern { mandel 25 } } #debug str(F(x,y,0),0,6)
 * at the five points below; they are exact ratios of iteration counts
 * or products of a few complex multiplications, so 1e-5 (the digits
 * povray printed) is the tolerance.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "parse_fixture.h"
#include "scene/pattern.h"
#include "scene/scene.h"
#include "scene/texture.h"

#define POV_EPS 1e-5

/* The points povray was asked about, in (x, y). */
static const double points[5][2] = {
    {-0.2, 0.1}, {0.5, 0.5}, {-1.5, 0.6}, {1, 1}, {0.3, -0.1}};

static const zr_pigment *first_pigment(const zr_scene *s) {
  assert_true(s->n_objects >= 1);
  assert_non_null(s->objects[0]->texture);
  return s->objects[0]->texture->pigment;
}

/* Parses "box { 0, 1 pigment { PATTERN color_map { black to white } } }"
   and checks the grey at the five points against povray's values. */
static void check_fractal_eps(fixture *f, const char *pattern,
                              const double want[5], double eps) {
  char text[512];
  snprintf(text, sizeof text,
           "box { 0, 1 pigment { %s color_map { [0 rgb 0] [1 rgb 1] } } }",
           pattern);
  const zr_pigment *pg = first_pigment(good(f, text));
  for (int i = 0; i < 5; i++) {
    zr_colour c = zr__pigment_eval(pg, zr_v3(points[i][0], points[i][1], 0));
    if (fabs(c.r - want[i]) > eps)
      fail_msg("%s at (%g, %g): %.6f, povray %.6f", pattern, points[i][0],
               points[i][1], c.r, want[i]);
  }
}

static void check_fractal(fixture *f, const char *pattern,
                          const double want[5]) {
  check_fractal_eps(f, pattern, want, POV_EPS);
}

static void test_pattern_more_mandel(void **state) {
  fixture *f = *state;
  const double mandel[5] = {1, 0.12, 0.04, 0, 1};
  check_fractal(f, "mandel 25", mandel);
  const double cubic[5] = {1, 1, 0, 0, 1};
  check_fractal(f, "mandel 25 exponent 3", cubic);
  const double julia[5] = {1, 1, 0, 0, 0.566667};
  check_fractal(f, "julia <0.353, 0.288>, 30", julia);
}

static void test_pattern_more_magnet(void **state) {
  fixture *f = *state;
  const double m1[5] = {0.366667, 1, 0.1, 1, 1};
  check_fractal(f, "magnet 1 mandel 30", m1);
  const double m2[5] = {1, 1, 1, 0.1, 1};
  check_fractal(f, "magnet 2 julia <0.2, 0.3>, 30", m2);
}

static void test_pattern_more_colouring(void **state) {
  fixture *f = *state;
  /* interior 1: the smallest |z| of the orbit; exterior 2: the last
     point's real part times the factor, through the ramp wave. */
  /* povray's ramp wave wraps values above 1 modulo 1.00001, ours
     modulo 1: a value that wrapped k times differs by k * 1e-5, and
     the largest here (10.79) wrapped 10 times, hence 2e-4. */
  const double i1[5] = {0.180278, 0.642568, 0.606060, 0.5, 0.316228};
  check_fractal_eps(f, "mandel 25 interior 1, 1 exterior 2, 0.5", i1,
                    2e-4);
  const double i3[5] = {0.074085, 0.792152, 0.772316, 1.0, 0.716608};
  check_fractal_eps(f, "mandel 25 interior 3, 1 exterior 4, 1", i3, 2e-4);
  /* magnet's mandel starts its orbit at 0, but the smallest |z| starts
     at the point's own |(x, y)|: 0.2, 0.100528 and 0.172414 are points
     of the set (the orbit's start gave 0 there). */
  const double m1[5] = {0.22, 0.2, 0.06, 0.100528, 0.172414};
  check_fractal(f, "magnet 1 mandel 50 interior 1, 1 exterior 1, 1", m1);
}

static void test_pattern_more_fractal_errors(void **state) {
  fixture *f = *state;
  bad(f, "box { 0, 1 pigment { mandel 25 exterior 7, 1 } }", ZR_ESCENE,
      "the exterior type must be 0 to 6", NULL);
  bad(f, "box { 0, 1 pigment { mandel 25 exponent 40 } }", ZR_ESCENE,
      "exponent must be from 2 to 33", NULL);
  bad(f, "box { 0, 1 pigment { magnet 3 mandel 25 } }", ZR_ESCENE,
      "the magnet type must be from 1 to 2",
      "t.pov:1:29: error: the magnet type must be from 1 to 2\n"
      "    1 | box { 0, 1 pigment { magnet 3 mandel 25 } }\n"
      "      |                             ^\n");
  bad(f, "box { 0, 1 pigment { julia 1, 25 } }", ZR_ESCENE,
      "julia wants a 2-D vector (a complex number)", NULL);
}

static void test_pattern_more_function(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "#declare F = function(a, b, c) { a * b + c }\n"
                        "box { 0, 1 pigment { function { F(x, y, 0.25) }"
                        " color_map { [0 rgb 0] [1 rgb 1] } } }");
  const zr_pigment *pg = first_pigment(s);
  zr_colour c = zr__pigment_eval(pg, zr_v3(0.5, 0.5, 0));
  assert_true(fabs(c.r - 0.5) < 1e-12);
  /* Beyond 1 the ramp wave repeats the map. */
  c = zr__pigment_eval(pg, zr_v3(2.5, 0.5, 0));
  assert_true(fabs(c.r - 0.5) < 1e-12);
  /* A normal takes a function and its bump size. */
  s = good(f, "box { 0, 1 normal { function { x * x } 0.3 } }");
  assert_non_null(s->objects[0]->texture->normal);
  assert_true(fabs(s->objects[0]->texture->normal->amount - 0.3) < 1e-12);
  assert_int_equal(s->objects[0]->texture->normal->pattern.kind,
                   ZR_PAT_FUNCTION);
}

/* The centre of an object's box, which min_extent and max_extent give. */
static void assert_centre(fixture *f, const char *object, double x,
                          double y, double z) {
  char text[512];
  snprintf(text, sizeof text,
           "#declare O = %s\n"
           "#declare C = (min_extent(O) + max_extent(O)) / 2;\n"
           "#debug concat(vstr(3, C, \",\", 0, 3), \"\\n\")\n",
           object);
  good(f, text);
  char want[64];
  snprintf(want, sizeof want, "%.3f,%.3f,%.3f\n", x, y, z);
  assert_string_equal(f->diag.debug, want);
}

static void test_pattern_more_transform_blocks(void **state) {
  fixture *f = *state;
  /* inverse inverts the whole block wherever it stands (povray 3.7:
     both give <-1,-2,0>); nested blocks compose in order (<0.5,2,0>). */
  assert_centre(f, "sphere { 0, 0.1 transform { translate x inverse "
                   "translate 2*y } }", -1, -2, 0);
  assert_centre(f, "sphere { 0, 0.1 transform { inverse translate x "
                   "translate 2*y } }", -1, -2, 0);
  assert_centre(f, "sphere { 0, 0.1 transform { translate x "
                   "transform { scale 2 inverse } translate 2*y } }",
                0.5, 2, 0);
  /* Identifiers, in blocks and after transform, in pigments too. */
  zr_scene *s = good(f, "#declare T = transform { scale 2 translate x }\n"
                        "#declare U = transform { T rotate 90*z }\n"
                        "#declare V = U\n"
                        "sphere { 0, 1 transform V pigment { gradient x "
                        "transform { T inverse } } }");
  const zr_object *o = s->objects[0];
  assert_non_null(o->transform);
  zr_vec3 q = zr__xform_point(o->transform->m, zr_v3(1, 0, 0));
  /* scale 2: <2,0,0>; translate x: <3,0,0>; rotate 90 about z: <0,3,0>. */
  assert_true(fabs(q.x) < 1e-12 && fabs(q.y - 3) < 1e-12 &&
              fabs(q.z) < 1e-12);
  bad(f, "sphere { 0, 1 transform { skew 2 } }", ZR_EUNDEFINED,
      "undefined identifier 'skew'", NULL);
}

static void test_pattern_more_extent_unbounded(void **state) {
  fixture *f = *state;
  good(f, "#declare P = plane { y, 0 }\n"
          "#debug vstr(3, max_extent(P), \",\", 0, 0)\n");
  assert_string_equal(f->diag.debug, "10000000000,10000000000,10000000000");
}

static void test_pattern_more_trace(void **state) {
  fixture *f = *state;
  /* povray 3.7 prints exactly these for the same scene. */
  good(f, "#declare N = <0, 0, 0>;\n"
          "#declare O = union { sphere { <0, 1, 0>, 1 scale <1, 2, 1> }\n"
          "  box { <-3, -1, -1>, <-2, 1, 1> rotate 30 * y } }\n"
          "#declare P = trace(O, <0, 10, 0>, -y, N);\n"
          "#debug concat(vstr(3, P, \",\", 0, 4), \" \", "
          "vstr(3, N, \",\", 0, 4), \"\\n\")\n"
          "#declare P = trace(O, <-10, 0.2, 0>, x, N);\n"
          "#debug concat(vstr(3, P, \",\", 0, 4), \" \", "
          "vstr(3, N, \",\", 0, 4), \"\\n\")\n"
          "#declare P = trace(O, <-10, 5, 0>, x, N);\n"
          "#debug concat(vstr(3, P, \",\", 0, 4), \" \", "
          "vstr(3, N, \",\", 0, 4), \"\\n\")\n"
          "#declare P = trace(O, <0.3, 1, 0.2>, <1, 0.2, 0.1>);\n"
          "#debug concat(vstr(3, P, \",\", 0, 4), \"\\n\")\n");
  assert_string_equal(f->diag.debug,
                      "0.0000,4.0000,0.0000 0.0000,1.0000,0.0000\n"
                      "-0.4359,0.2000,0.0000 -0.6958,-0.7183,0.0000\n"
                      "0.0000,0.0000,0.0000 0.0000,0.0000,0.0000\n"
                      "0.8586,1.1117,0.2559\n");
  bad(f, "#declare O = sphere { 0, 1 }\n"
         "#declare P = trace(O, <0, 10, 0>, -y, M);\n",
      ZR_EUNDEFINED, "trace's normal variable 'M' is not declared", NULL);
  bad(f, "#declare O = sphere { 0, 1 }\n#declare M = 1;\n"
         "#declare P = trace(O, <0, 10, 0>, -y, M);\n",
      ZR_ESYNTAX, "trace's normal variable 'M' must be a vector", NULL);
}

/* trace()'s limits, povray 3.7's output for this scene: a plane is
   missed within 1e-10 of parallel (n . unit direction), nothing is found
   at 1e7 or farther, and crossings nearer than 1e-4 are passed over (the
   sphere's entry 5e-5 ahead gives its exit at 2).  tracevines.pov's
   vines are grown on these. */
static void test_pattern_more_trace_limits(void **state) {
  fixture *f = *state;
  good(f,
          "#declare N = <0, 0, 0>;\n"
          "#declare P = plane { y, 0 }\n"
          "#macro T(O, A, D) #local Q = trace(O, A, D, N);\n"
          "#debug concat(vstr(3, Q, \",\", 0, 4), \" \", "
          "str(vlength(N), 0, 0), \"\\n\") #end\n"
          "T(P, <0, 1e-6, 0>, <1, -1e-10, 0>)\n"
          "T(P, <0, 1e-6, 0>, <1, -0.9e-10, 0>)\n"
          "T(P, <0, 1, 0>, <1, -1 / 0.99e7, 0>)\n"
          "T(P, <0, 1, 0>, <1, -1 / 1.01e7, 0>)\n"
          "T(sphere { <0.99e7, 0, 0>, 1 }, 0, x)\n"
          "T(sphere { <1.01e7, 0, 0>, 1 }, 0, x)\n"
          "T(sphere { x, 1 }, <-5e-5, 0, 0>, x)\n"
          "T(sphere { x, 1 }, <-2e-4, 0, 0>, x)\n"
          "T(plane { y, 0 scale 3 }, <0, 1e-6, 0>, <1, -0.9e-10, 0>)\n"
          "T(plane { y, 0 scale 3 }, <0, 1e-6, 0>, <3, -3.3e-10, 0>)\n");
  assert_string_equal(f->diag.debug,
                      "10000.0000,0.0000,0.0000 1\n"
                      "0.0000,0.0000,0.0000 0\n"
                      "9900000.0000,0.0000,0.0000 1\n"
                      "0.0000,0.0000,0.0000 0\n"
                      "9899999.0000,0.0000,0.0000 1\n"
                      "0.0000,0.0000,0.0000 0\n"
                      "2.0000,0.0000,0.0000 1\n"
                      "-0.0000,0.0000,0.0000 1\n"
                      "0.0000,0.0000,0.0000 0\n"
                      "9090.9091,0.0000,0.0000 1\n");
}

/* A repeated black hole's turbulence is named (its random moves are not
   povray's, blkhole.pov), at the second of repeat and turbulence; not
   without repeat (it does nothing there) nor with a zero turbulence. */
static void test_pattern_more_hole_turbulence(void **state) {
  fixture *f = *state;
  good(f, "plane { y, 0 pigment { wood warp { black_hole 0, 0.5\n"
          "  repeat <2, 1.5, 0> turbulence <1, 0.5, 0> } } }\n");
  assert_int_equal(f->diag.warnings, 1);
  assert_non_null(strstr(f->diag.warning,
                         "t.pov:2:22: warning: black_hole turbulence moves "
                         "each repeated hole by random amounts that are "
                         "not povray's"));
  good(f, "plane { y, 0 pigment { wood warp { black_hole 0, 0.5\n"
          "  turbulence 1 repeat 2 } } }\n");
  assert_int_equal(f->diag.warnings, 1);
  assert_non_null(strstr(f->diag.warning, "t.pov:2:16: warning: "));
  good(f, "plane { y, 0 pigment { wood warp { black_hole 0, 0.5 "
          "turbulence 1 } } }\n");
  assert_int_equal(f->diag.warnings, 0);
  good(f, "plane { y, 0 pigment { wood warp { black_hole 0, 0.5 "
          "repeat 2 turbulence 0 } } }\n");
  assert_int_equal(f->diag.warnings, 0);
}

static void test_pattern_more_tiles(void **state) {
  fixture *f = *state;
  /* povray 3.7 paints tiles { A tile2 B } as checker texture { B }
     texture { A }: B where checker's value is 0 (measured). */
  zr_scene *s = good(f, "plane { y, 0 texture { tiles {"
                        " texture { pigment { rgb 1 } }"
                        " tile2 texture { pigment { rgb <0, 0, 1> } } } } }");
  const zr_texture *tx = s->objects[0]->texture, *second;
  double t;
  const zr_texture *a = zr__texture_pick(tx, zr_v3(0.5, 0.5, 0.5),
                                         &second, &t);
  assert_true(fabs(a->pigment->colour.b - 1) < 1e-12 &&
              fabs(a->pigment->colour.r) < 1e-12);
  const zr_texture *b = zr__texture_pick(tx, zr_v3(1.5, 0.5, 0.5),
                                         &second, &t);
  assert_true(fabs(b->pigment->colour.r - 1) < 1e-12);
}

static void test_pattern_more_object(void **state) {
  fixture *f = *state;
  /* The second colour inside the object, the first outside; the
     pigment's own transform moves the object with it. */
  zr_scene *s = good(f, "#declare O = union { sphere { 0, 1 }"
                        " box { <2, -1, -1>, <3, 1, 1> } }\n"
                        "plane { z, 0 pigment { object { O rgb <1, 0, 0>,"
                        " rgb <0, 0, 1> } translate 10 * y } }");
  const zr_pigment *pg = first_pigment(s);
  assert_true(fabs(zr__pigment_eval(pg, zr_v3(0, 10, 0)).b - 1) < 1e-12);
  assert_true(fabs(zr__pigment_eval(pg, zr_v3(2.5, 10, 0)).b - 1) < 1e-12);
  assert_true(fabs(zr__pigment_eval(pg, zr_v3(1.5, 10, 0)).r - 1) < 1e-12);
  assert_true(fabs(zr__pigment_eval(pg, zr_v3(0, 0, 0)).r - 1) < 1e-12);
  bad(f, "plane { z, 0 pigment { object { sphere { 0, 1 } rgb 1, rgb 0,"
         " rgb 0.5 } } }", ZR_ESYNTAX, "too many colours for this pattern",
      NULL);
}

static void test_pattern_more_crackle_options(void **state) {
  fixture *f = *state;
  /* Our crackle is our own noise, so these are its definitions
     ("Crackle"): form <1,0,0> metric 1 offset 0.5 is the nearest
     distance plus 0.5, at least 0.5; solid is constant near a point. */
  zr_scene *s = good(f, "plane { z, 0 pigment { crackle form <1, 0, 0>"
                        " metric 1 offset 0.5 color_map { [0 rgb 0]"
                        " [1 rgb 1] } } }\n"
                        "plane { z, 0 pigment { crackle solid color_map {"
                        " [0 rgb 0] [1 rgb 1] } } }");
  const zr_pigment *a = s->objects[0]->texture->pigment;
  const zr_pigment *b = s->objects[1]->texture->pigment;
  assert_int_equal(a->pattern.crackle_metric, 1);
  for (int i = 0; i < 50; i++) {
    zr_vec3 q = zr_v3(i * 0.37, i * 0.11, i * 0.23);
    assert_true(zr__pigment_eval(a, q).r >= 0.5 - 1e-12);
    double v = zr__pigment_eval(b, q).r;
    double w = zr__pigment_eval(b, zr_v3_add(q, zr_v3(1e-6, 0, 0))).r;
    assert_true(v >= 0 && v <= 1 && fabs(v - w) < 1e-12);
  }
  bad(f, "plane { z, 0 pigment { crackle metric 0 } }", ZR_ESCENE,
      "crackle's metric must be positive", NULL);
}

static void test_pattern_more_bare_default(void **state) {
  fixture *f = *state;
  /* povray 3.7 takes "default { }" without its '#'. */
  zr_scene *s = good(f, "default { finish { ambient 0.7 } }\n"
                        "sphere { 0, 1 }");
  assert_true(fabs(s->default_texture->finish->ambient.r - 0.7) < 1e-12);
}

/* The grey of "pigment { gradient x color_map { black to white } MODS }"
   at world point (x, y, z). */
static double warped_grey(fixture *f, const char *mods, zr_vec3 at) {
  char text[512];
  snprintf(text, sizeof text,
           "box { 0, 1 pigment { gradient x "
           "color_map { [0 rgb 0] [1 rgb 1] } %s } }",
           mods);
  return zr__pigment_eval(first_pigment(good(f, text)), at).r;
}

/* The warps' formulas as the reference manual ("Warps") gives them and
   POV-Ray 3.7's renders show them, at points worked by hand: exact but
   for rounding, so 1e-9.  (Whole images of each warp, rendered beside
   povray 3.7 on a flat, ambient-lit plane, match at SSIM 0.9998 to 1.) */
static void test_pattern_more_warp_formulas(void **state) {
  fixture *f = *state;
  const double eps = 1e-9;
  /* repeat x*2 offset y*0.5 flip x: x = 3.2 is in block 1 (odd), so
     3.2 - 2 = 1.2, flipped to -1.2 + 2 = 0.8; y gains 0.5.  The grey is
     gradient x's value, frac(0.8). */
  assert_true(fabs(warped_grey(f, "warp { repeat x*2 offset y*0.5 flip x }",
                               zr_v3(3.2, 0.1, 0.5)) - 0.8) < eps);
  /* black_hole 0, 2 (falloff 2, strength 1): at x = 1 the point moves
     by ((2 - 1) / 2)^2 = 0.25 of its offset, to 1.25; inverse: 0.75. */
  assert_true(fabs(warped_grey(f, "warp { black_hole 0, 2 }",
                               zr_v3(1, 0, 0)) - 0.25) < eps);
  assert_true(fabs(warped_grey(f, "warp { black_hole 0, 2 inverse }",
                               zr_v3(1, 0, 0)) - 0.75) < eps);
  /* strength 8 clips the move to the whole offset: x = 1 goes to 2. */
  assert_true(fabs(warped_grey(f, "warp { black_hole 0, 2 strength 8 }",
                               zr_v3(1, 0, 0)) - 0.0) < eps);
  /* cylindrical: <0, 0.3, 1> is a quarter turn from +x towards +z, so
     x becomes 0.25; dist_exp 1 multiplies it by the distance 2 at
     <0, 0.3, 2>: 0.5. */
  assert_true(fabs(warped_grey(f, "warp { cylindrical }",
                               zr_v3(0, 0.3, 1)) - 0.25) < eps);
  assert_true(fabs(warped_grey(f, "warp { cylindrical dist_exp 1 }",
                               zr_v3(0, 0.3, 2)) - 0.5) < eps);
  /* spherical: <-1, 0, 0> is half a turn round: x = 0.5. */
  assert_true(fabs(warped_grey(f, "warp { spherical }",
                               zr_v3(-1, 0, 0)) - 0.5) < eps);
  /* toroidal (major radius 1): <0, 0, 3> is a quarter turn about y. */
  assert_true(fabs(warped_grey(f, "warp { toroidal major_radius 2 }",
                               zr_v3(0, 0.5, 3)) - 0.25) < eps);
  /* planar: the x-y plane is kept, z is set; planar z, 0 with gradient
     x leaves x alone: 0.3. */
  assert_true(fabs(warped_grey(f, "warp { planar z, 0.5 }",
                               zr_v3(0.3, 0.2, 7)) - 0.3) < eps);
}

/* A mapping warp's orientation, against POV-Ray 3.7's own values: a
   spherical warp with orientation <1, 2, 3> sends <-2.5, 2.5, 0> to
   x = 1.613 and <2.5, 1.5, 0> to x = 0.779 (measured through a
   function pigment in a 16-bit linear render: within 0.0006), so
   gradient x reads 0.613 and 0.779 there. */
static void test_pattern_more_warp_orientation(void **state) {
  fixture *f = *state;
  const char *warp = "warp { spherical orientation <1, 2, 3> }";
  assert_true(fabs(warped_grey(f, warp, zr_v3(-2.5, 2.5, 0)) - 0.613) <
              1e-3);
  assert_true(fabs(warped_grey(f, warp, zr_v3(2.5, 1.5, 0)) - 0.779) <
              1e-3);
}

/* Warps and transforms apply in the order written: with warp before
   scale 2, world x = 1.8 is 0.9 in the warp's frame, block 1 of
   repeat x*0.5, giving 0.4; with the warp after the scale, 1.8 is in
   block 3, giving 0.3, which the scale halves to 0.15. */
static void test_pattern_more_warp_order(void **state) {
  fixture *f = *state;
  assert_true(fabs(warped_grey(f, "warp { repeat x*0.5 } scale 2",
                               zr_v3(1.8, 0, 0)) - 0.4) < 1e-9);
  assert_true(fabs(warped_grey(f, "scale 2 warp { repeat x*0.5 }",
                               zr_v3(1.8, 0, 0)) - 0.15) < 1e-9);
}

static void test_pattern_more_warp_errors(void **state) {
  fixture *f = *state;
  bad(f, "box { 0, 1 pigment { bozo warp { repeat <1,1,0> } } }",
      ZR_ESCENE, "a repeat warp repeats along one axis only", NULL);
  bad(f, "box { 0, 1 pigment { bozo warp { repeat 0*x } } }", ZR_ESCENE,
      "a repeat warp needs a non-zero direction", NULL);
  bad(f, "box { 0, 1 pigment { bozo warp { black_hole 0, 0 } } }",
      ZR_ESCENE, "a black_hole's radius must be positive", NULL);
  bad(f, "box { 0, 1 pigment { bozo warp { black_hole 0, 1 flip x } } }",
      ZR_ESCENE, "'flip' is not an item of a black_hole warp",
      "t.pov:1:50: error: 'flip' is not an item of a black_hole warp\n"
      "    1 | box { 0, 1 pigment { bozo warp { black_hole 0, 1 flip x } } }\n"
      "      |                                                  ^~~~\n");
  bad(f, "box { 0, 1 pigment { bozo warp { cylindrical orientation 0 } } }",
      ZR_ESCENE, "orientation must not be zero", NULL);
  bad(f, "box { 0, 1 pigment { bozo warp { spherical major_radius 2 } } }",
      ZR_ESCENE, "'major_radius' is not an item of a spherical warp", NULL);
  /* cubic takes no items (POV-Ray 3.7 stops there too). */
  bad(f, "box { 0, 1 pigment { bozo warp { cubic orientation y } } }",
      ZR_ESCENE, "'orientation' is not an item of a cubic warp", NULL);
}

/* tiling 1 to 13, 15 and 18 against povray 3.7.0's values, printed by
   #declare F = function { pigment { tiling N color_map { [0 rgb 0]
   [1 rgb 1] } } } #debug str(F(x, 0, z).red, 0, 7): each tile type k
   of N runs from k/N at its heart to (k + 1)/N at its edges.  The
   points are off the edges, where povray's ties between tiles would be
   its own; 1e-6 is the digits it printed. */
static void test_pattern_more_tiling(void **state) {
  fixture *f = *state;
  static const struct {
    int tiling;
    double x, z, povray;
  } cases[] = {
      {1, -0.85, 0.5, 0.7}, {1, 0.3, 0.1, 0.8}, {1, 0.5, 0.5, 0},
      {2, -2, -2, 0.8452995}, {2, -1.7, 1.9, 0.7969655},
      {2, -1.3, -0.1, 0.357735}, {2, -1, 1.6, 0.1524791}, {2, -1, 0, 0},
      {3, 0.73741, 1.450722, 0.8497529}, {3, 1.771161, 2.654702, 0.4019212},
      {4, 0.73741, 1.450722, 0.7996705}, {4, 1.439391, 2.53395, 0.9528286},
      {5, -2, -2, 0.8968663}, {5, -1.8, 1.6, 0.5841597},
      {5, -1.5, 0.6, 0.5642734}, {5, -1.2, -0.2, 0.6103134},
      {5, -0.9, -0.8, 0.2825069}, {5, -0.7, 1.8, 0.9476927},
      {6, -2, 0.8, 0.3}, {6, -1.4, -1.6, 0.6}, {6, -0.9, 0.6, 0.9},
      {6, -0.4, 1.3, 0.2}, {7, -2, -1, 0.7928932}, {7, -1.4, -1.4, 0.2727922},
      {7, -0.9, -1.3, 0.2828427}, {7, 0.3, 0.2, 0.5},
      {8, 0.73741, 1.450722, 0.3309678}, {8, 1.771161, 2.654702, 0.7559848},
      {8, 1.439391, 2.53395, 0.9300148}, {9, 0.73741, 1.450722, 0.6751495},
      {9, 1.594353, -2.042375, 0.4401854},
      {9, -1.743262, -1.707113, 0.3045376}, {10, 0.73741, 1.450722, 0.52518},
      {10, 1.771161, 2.654702, 0.542322}, {11, 0.73741, 1.450722, 0.82494},
      {11, 1.771161, 2.654702, 0.5141073}, {11, 1.439391, 2.53395, 0.3559667},
      {12, 2.405403, -2.320764, 0.7297313},
      {12, -1.323106, 2.498072, 0.3346187},
      {12, 0.704715, -2.239805, 0.5067967},
      {13, 0.73741, 1.450722, 0.3047632}, {13, 1.771161, 2.654702, 0.5028771},
      {15, 0.73741, 1.450722, 0.549278}, {15, 1.771161, 2.654702, 0.771161},
      {18, 0.73741, 1.450722, 0.73741}, {18, 1.771161, 2.654702, 0.271161},
  };
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
    char text[200];
    snprintf(text, sizeof text, "plane { y, 0 pigment { tiling %d "
             "color_map { [0 rgb 0] [1 rgb 1] } } }", cases[i].tiling);
    const zr_pigment *pg = first_pigment(good(f, text));
    /* The same whatever y. */
    for (int y = -1; y <= 1; y++) {
      zr_colour c = zr__pigment_eval(pg, zr_v3(cases[i].x, y * 3.5,
                                               cases[i].z));
      if (fabs(c.r - cases[i].povray) > 1e-6)
        fail_msg("tiling %d at (%g, %d, %g): %.7f, povray %.7f",
                 cases[i].tiling, cases[i].x, y, cases[i].z, c.r,
                 cases[i].povray);
    }
  }
  bad(f, "plane { y, 0 pigment { tiling 0 } }", ZR_ESCENE,
      "the tiling number must be from 1 to 27, not 0", NULL);
  bad(f, "plane { y, 0 pigment { tiling 28.5 } }", ZR_ESCENE,
      "the tiling number must be from 1 to 27, not 28.5", NULL);
  bad(f, "plane { y, 0 pigment { tiling <1, 2> } }", ZR_ESYNTAX,
      "expected a float, got a 2-D vector", NULL);
  bad(f, "plane { y, 0 pigment { tiling 27 } }", ZR_EUNSUPPORTED,
      "tiling 27 is not supported yet",
      "t.pov:1:31: error: tiling 27 is not supported yet\n"
      "    1 | plane { y, 0 pigment { tiling 27 } }\n"
      "      |                               ^~\n");
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_pattern_more_warp_formulas),
      cmocka_unit_test(test_pattern_more_warp_orientation),
      cmocka_unit_test(test_pattern_more_warp_order),
      cmocka_unit_test(test_pattern_more_warp_errors),
      cmocka_unit_test(test_pattern_more_mandel),
      cmocka_unit_test(test_pattern_more_magnet),
      cmocka_unit_test(test_pattern_more_colouring),
      cmocka_unit_test(test_pattern_more_fractal_errors),
      cmocka_unit_test(test_pattern_more_function),
      cmocka_unit_test(test_pattern_more_tiling),
      cmocka_unit_test(test_pattern_more_transform_blocks),
      cmocka_unit_test(test_pattern_more_extent_unbounded),
      cmocka_unit_test(test_pattern_more_trace),
      cmocka_unit_test(test_pattern_more_trace_limits),
      cmocka_unit_test(test_pattern_more_hole_turbulence),
      cmocka_unit_test(test_pattern_more_tiles),
      cmocka_unit_test(test_pattern_more_object),
      cmocka_unit_test(test_pattern_more_crackle_options),
      cmocka_unit_test(test_pattern_more_bare_default),
  };
  return cmocka_run_group_tests(tests, setup, teardown);
}
