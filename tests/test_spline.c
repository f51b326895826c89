/*
 * test_spline.c - splines of the scene language (lib/sdl/spline.c, the
 * grammar's spline rules and spline functions in lib/sdl/function.c):
 * the four interpolations, copies, the call with another type, function
 * { spline { } } called in a scene and in another function, and the
 * messages of bad input.
 *
 * Every expected value was printed by povray 3.7.0 from the same text
 * (a scene with #debug vstr(3, S(t), ",", 0, 6) rendered at +W8 +H8 -D).
 * Six decimals are far coarser than the rounding of the few double
 * operations a spline takes, and fine enough to catch a wrong formula,
 * so the printed text is compared exactly.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <string.h>

#include "config.h"
#include "zrcube.h"
#include "parse_fixture.h"

/* Parses text, which must succeed, and checks what it printed. */
static void prints(fixture *f, const char *text, const char *expected) {
  zr_status s = parse(f, text);
  if (s != ZR_OK)
    fail_msg("unexpected failure:\n%s", f->diag.text);
  assert_string_equal(f->diag.debug, expected);
}

/* Five points with uneven spacing, so that every segment and both ends
   of each interpolation are tried. */
#define POINTS                                                            \
  "0,<0,0,0> 1,<1,2,0> 2.5,<3,1,1> 3,<4,4,2> 4.5,<2,0,5>"

#define SHOW                                                              \
  "#macro Show(S, T) #debug concat(vstr(3, S(T), \",\", 0, 6), \" \") "  \
  "#end\n"

static void test_spline_linear(void **state) {
  fixture *f = *state;
  prints(f,
         SHOW "#declare S = spline { linear_spline " POINTS " }\n"
              "Show(S, -0.5) Show(S, 0.25) Show(S, 2.75) Show(S, 4.25) "
              "Show(S, 5)\n",
         "0.000000,0.000000,0.000000 0.250000,0.500000,0.000000 "
         "3.500000,2.500000,1.500000 2.333333,0.666667,4.500000 "
         "2.000000,0.000000,5.000000 ");
  /* The default type is linear, and commas may come between points. */
  prints(f,
         SHOW "#declare S = spline { 0, <0,0,0>, 1, <1,2,0>, }\n"
              "Show(S, 0.25)\n",
         "0.250000,0.500000,0.000000 ");
}

static void test_spline_quadratic(void **state) {
  fixture *f = *state;
  prints(f,
         SHOW "#declare S = spline { quadratic_spline " POINTS " }\n"
              "Show(S, -0.25) Show(S, 0.25) Show(S, 1.5) Show(S, 2.75) "
              "Show(S, 4.25) Show(S, 4.75)\n",
         "0.000000,0.000000,0.000000 0.225000,0.700000,-0.050000 "
         "1.600000,2.200000,0.200000 3.479167,2.291667,1.458333 "
         "2.854167,2.020833,4.500000 2.000000,0.000000,5.000000 ");
}

static void test_spline_cubic(void **state) {
  fixture *f = *state;
  /* Valid from the second to the next-to-last point only. */
  prints(f,
         SHOW "#declare S = spline { cubic_spline " POINTS " }\n"
              "Show(S, 0.5) Show(S, 1.25) Show(S, 1.5) Show(S, 2.25) "
              "Show(S, 2.75) Show(S, 4)\n",
         "1.000000,2.000000,0.000000 1.292824,1.949074,0.085648 "
         "1.592593,1.592593,0.185185 2.603009,0.634259,0.706019 "
         "3.583333,2.562500,1.458333 4.000000,4.000000,2.000000 ");
  /* Three points make no segment: the middle one everywhere; two
     points are linear. */
  prints(f,
         SHOW "#declare S = spline { cubic_spline 0,<0,0,0> 1,<1,2,0> "
              "2,<3,1,1> }\nShow(S, 0.5) Show(S, 1.5)\n"
              "#declare S = spline { cubic_spline 0,<1,2,3> 1,<2,3,4> }\n"
              "Show(S, 0.5)\n",
         "1.000000,2.000000,0.000000 1.000000,2.000000,0.000000 "
         "1.500000,2.500000,3.500000 ");
}

static void test_spline_natural(void **state) {
  fixture *f = *state;
  prints(f,
         SHOW "#declare S = spline { natural_spline " POINTS " }\n"
              "Show(S, -0.5) Show(S, 0.25) Show(S, 1.5) Show(S, 2.75) "
              "Show(S, 3.5) Show(S, 4.25)\n",
         "0.000000,0.000000,0.000000 0.254200,0.797379,-0.008401 "
         "1.493628,1.089606,0.086818 3.554996,2.502016,1.473342 "
         "4.057149,4.727599,3.033851 2.650002,1.568324,4.514810 ");
  /* Two points are linear. */
  prints(f,
         SHOW "#declare S = spline { natural_spline 0,<0,0,0> 1,<1,2,0> }\n"
              "Show(S, 0.5)\n",
         "0.500000,1.000000,0.000000 ");
}

static void test_spline_points(void **state) {
  fixture *f = *state;
  /* Points in any order; one point is a constant; the longest point
     sets the size, shorter ones are padded with zeros; a float counts as
     a 2-D vector of it.  D: povray drops a repeated parameter when it is
     the last point's (1 here, when the second 1 comes). */
  prints(f,
         "#declare D = spline { 1,<1,1,1> 0,<0,0,0> 1,<3,3,3> }\n"
         "#declare One = spline { 2,<1,2,3> }\n"
         "#declare E = spline { 0,<1,2> 1,<3,4> }\n"
         "#declare F5 = spline { 0,<1,2> 1,<3,4,5,6,7> }\n"
         "#declare G = spline { 0,1 1,3 }\n"
         "#debug concat(vstr(3, D(0.5), \",\", 0, 6), \" \", "
         "vstr(3, One(0.5), \",\", 0, 6), \" \", "
         "vstr(3, E(0.5), \",\", 0, 6), \" \", "
         "vstr(5, F5(0.5), \",\", 0, 6), \" \", "
         "vstr(3, G(0.5), \",\", 0, 6), \" \", str(E(0.5).y, 0, 6))\n",
         "0.500000,0.500000,0.500000 1.000000,2.000000,3.000000 "
         "2.000000,3.000000,0.000000 2.000000,3.000000,2.500000,3.000000,"
         "3.500000 2.000000,2.000000,0.000000 3.000000");
}

static void test_spline_repeated_parameter(void **state) {
  fixture *f = *state;
  /* A repeated parameter replaces the older point (reference manual),
     first, inside or alone; povray 3.7.0 drops it when it repeats the
     last point of two or more. */
  prints(f,
         SHOW "#declare D = spline { 0,<0,0,0> 1,<1,1,1> 2,<2,2,2> "
              "1,<3,3,3> }\nShow(D, 0.5) Show(D, 1) Show(D, 1.5)\n"
              "#declare D = spline { 0,<0,0,0> 1,<1,1,1> 2,<2,2,2> "
              "0,<3,3,3> }\nShow(D, 0) Show(D, 0.5)\n"
              "#declare D = spline { 1,<1,1,1> 1,<3,3,3> 0,<0,0,0> "
              "2,<2,2,2> }\nShow(D, 1)\n"
              "#declare D = spline { 0,<0,0,0> 1,<1,1,1> 2,<2,2,2> "
              "2,<3,3,3> 3,<4,4,4> }\nShow(D, 2) Show(D, 2.5)\n",
         "1.500000,1.500000,1.500000 3.000000,3.000000,3.000000 "
         "2.500000,2.500000,2.500000 3.000000,3.000000,3.000000 "
         "2.000000,2.000000,2.000000 3.000000,3.000000,3.000000 "
         "2.000000,2.000000,2.000000 3.000000,3.000000,3.000000 ");
}

static void test_spline_copy_and_type(void **state) {
  fixture *f = *state;
  /* A copy takes the points and type and may add to them without
     changing the original; S(t, type) interpolates as another type. */
  prints(f,
         SHOW "#declare D = spline { 1,<1,1,1> 0,<0,0,0> }\n"
              "#declare H = spline { D 2,<5,5,5> }\n"
              "Show(H, 1.5) Show(D, 1.5)\n"
              "#declare K = spline { cubic_spline " POINTS " }\n"
              "#declare L = spline { K linear_spline }\n"
              "Show(L, 2)\n"
              "#debug concat(vstr(3, K(2, linear_spline), \",\", 0, 6), \" \","
              " vstr(3, K(2, natural_spline), \",\", 0, 6), \" \", "
              "str(K(2).y, 0, 6))\n",
         "3.000000,3.000000,3.000000 1.000000,1.000000,1.000000 "
         "2.333333,1.333333,0.666667 2.333333,1.333333,0.666667 "
         "2.110315,0.136201,0.371963 0.740741");
}

static void test_spline_in_macro(void **state) {
  fixture *f = *state;
  /* The manual's "Splines and Macros" example: a spline passed to a
     macro is called there. */
  prints(f,
         "#macro Foo(Bar, Val) #declare Y = Bar(Val).y; #end\n"
         "#declare myspline = spline { 1, <4,5> 3, <5,5> 5, <6,5> }\n"
         "Foo(myspline, 2)\n#debug str(Y, 5, 5)\n",
         "5.00000");
}

static void test_spline_function(void **state) {
  fixture *f = *state;
  /* A spline function gives the vector in a scene and one component in
     another function (povray: 2.240741,0.740741,0.481481 and 1.740741). */
  prints(f,
         "#declare K = spline { cubic_spline " POINTS " }\n"
         "#declare Fn = function { spline { K } }\n"
         "#declare Fm = function { Fn(x).y + 1 }\n"
         "#declare Fi = function { spline { linear_spline 0, <0,1,2> "
         "1, <2,3,4> } }\n"
         "#declare Fz = function { Fi(x).z * 2 }\n"
         "#debug concat(vstr(3, Fn(2), \",\", 0, 6), \" \", "
         "str(Fm(2, 0, 0), 0, 6), \" \", vstr(3, Fi(0.5), \",\", 0, 6), "
         "\" \", str(Fz(0.5, 0, 0), 0, 6), \" \", str(Fn(2).z, 0, 6))\n",
         "2.240741,0.740741,0.481481 1.740741 1.000000,2.000000,3.000000 "
         "6.000000 0.481481");
  /* function { S } is a zRcube extension (povray 3.7 wants spline { S }
     there); it means the same. */
  prints(f,
         "#declare K = spline { cubic_spline " POINTS " }\n"
         "#declare Fs = function { K }\n"
         "#debug vstr(3, Fs(2), \",\", 0, 6)\n",
         "2.240741,0.740741,0.481481");
}

static void test_spline_bad(void **state) {
  fixture *f = *state;
  bad(f, "#declare S = spline { }\n", ZR_ESCENE,
      "a spline needs at least one point",
      "t.pov:1:14: error: a spline needs at least one point\n"
      "    1 | #declare S = spline { }\n"
      "      |              ^~~~~~~~~~\n");
  bad(f, "#declare S = spline { <1,2>, <1,2,3> }\n", ZR_ESYNTAX,
      "expected a float, got a 2-D vector",
      "t.pov:1:23: error: expected a float, got a 2-D vector\n"
      "    1 | #declare S = spline { <1,2>, <1,2,3> }\n"
      "      |                       ^~~~~\n");
  bad(f, "#declare S = spline { 0, <1,2,3> }\n#declare V = S(<1,2>);\n",
      ZR_ESYNTAX, "expected a float, got a 2-D vector",
      "t.pov:2:16: error: expected a float, got a 2-D vector\n"
      "    2 | #declare V = S(<1,2>);\n"
      "      |                ^~~~~\n");
  bad(f, "#declare S = spline { 0, <1,2,3> 1 }\n", ZR_ESYNTAX,
      "unexpected '}'", NULL);
  bad(f,
      "#declare F = function { spline { 0, <1,2,3> 1, <2,3,4> } }\n"
      "#declare V = F(1, 2);\n",
      ZR_ESYNTAX, "function 'F' takes 1 argument, not 2",
      "t.pov:2:14: error: function 'F' takes 1 argument, not 2\n"
      "    2 | #declare V = F(1, 2);\n"
      "      |              ^~~~~~~\n");
  bad(f,
      "#declare F = function { spline { 0, <1,2,3> 1, <2,3,4> } }\n"
      "#declare G = function { F(x) }\n",
      ZR_ESYNTAX,
      "expected '.' and a vector component after a spline function in "
      "function, got '}'",
      "t.pov:2:30: error: expected '.' and a vector component after a "
      "spline function in function, got '}'\n"
      "    2 | #declare G = function { F(x) }\n"
      "      |                              ^\n");
  bad(f,
      "#declare F = function { spline { 0, <1,2,3> 1, <2,3,4> } }\n"
      "#declare G = function { F(x, y).y }\n",
      ZR_ESYNTAX, "function 'F' takes 1 argument, not 2", NULL);
}

int main(void) {
  const struct CMUnitTest tests[] = {
#define T(name) cmocka_unit_test_setup_teardown(name, setup, teardown)
      T(test_spline_linear),
      T(test_spline_quadratic),
      T(test_spline_cubic),
      T(test_spline_natural),
      T(test_spline_points),
      T(test_spline_repeated_parameter),
      T(test_spline_copy_and_type),
      T(test_spline_in_macro),
      T(test_spline_function),
      T(test_spline_bad),
#undef T
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
