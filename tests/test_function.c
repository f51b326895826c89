/*
 * test_function.c - user-defined functions (lib/sdl/function.c): the
 * language of function bodies, calls from float expressions, the
 * internal functions of functions.inc against povray 3.7's own values,
 * the limits, the error messages, and a speed figure.
 *
 * A value is read back by placing it where the scene keeps it: the
 * x of a sphere's centre.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "config.h"
#include "core/context.h"
#include "scene/scene.h"
#include "sdl/function.h"
#include "sdl/sdl.h"
#include "zrcube.h"
#include "parse_fixture.h"

/* The functions below combine a few decimals with a few operations, so
   they agree with the same C expression to the last bits; 1e-12 leaves
   room for the order of rounding and nothing more. */
#define EPS 1e-12
/* povray's #debug str(v, 0, 9) shows 9 decimals: its values are known
   to 5e-10, and a wrong formula misses by far more. */
#define POV_EPS 1e-9

/* The value of expr after the declarations decls. */
static double value(fixture *f, const char *decls, const char *expr) {
  size_t size = strlen(decls) + strlen(expr) + 64;
  char *text = malloc(size);
  assert_non_null(text);
  snprintf(text, size, "%s\nsphere { <%s, 0, 0>, 1 }\n", decls, expr);
  zr_status s = parse(f, text);
  free(text);
  if (s != ZR_OK)
    fprintf(stderr, "unexpected failure:\n%s", f->diag.text);
  assert_int_equal(s, ZR_OK);
  assert_int_equal(f->scene->n_objects, 1);
  return f->scene->objects[0]->u.sphere.centre.x;
}

static void test_function_arithmetic(void **state) {
  fixture *f = *state;
  const char *d = "#declare F = function(a, b) { a + b * 2 - a / b }\n";
  assert_true(fabs(value(f, d, "F(3, 4)") - (3 + 4 * 2 - 3.0 / 4)) < EPS);
  d = "#declare F = function(a) { -a * -a - (1 - a) * 3 }\n";
  assert_true(fabs(value(f, d, "F(2.5)") - (6.25 - (1 - 2.5) * 3)) < EPS);
  /* Constants fold at compile time and still give the same value. */
  d = "#declare F = function { 2 * pi / 360 + x }\n";
  assert_true(fabs(value(f, d, "F(1, 0, 0)") - (1 + 2 * M_PI / 360)) <
              EPS);
}

static void test_function_logic(void **state) {
  fixture *f = *state;
  /* The manual's precedence: & binds tighter than |. */
  const char *d = "#declare F = function(a, b) { a | b & 0 }\n";
  assert_true(value(f, d, "F(1, 1)") == 1);
  assert_true(value(f, d, "F(0, 1)") == 0);
  d = "#declare L = function(a, b) { (a < b) + 2 * (a <= b) + 4 * (a = b)"
      " + 8 * (a != b) + 16 * (a >= b) + 32 * (a > b) }\n";
  assert_true(value(f, d, "L(1, 2)") == 1 + 2 + 8);
  assert_true(value(f, d, "L(2, 2)") == 2 + 4 + 16);
  assert_true(value(f, d, "L(3, 2)") == 8 + 16 + 32);
  /* povray 3.7: in functions any non-zero value is true (1e-11 & 1 is 1),
     unlike #if, which treats values within 1e-10 of zero as false. */
  d = "#declare F = function(a) { a & 1 }\n";
  assert_true(value(f, d, "F(1e-11)") == 1);
  assert_true(value(f, d, "F(0)") == 0);
  d = "#declare F = function(a) { !a }\n";
  assert_true(value(f, d, "F(0)") == 1);
  assert_true(value(f, d, "F(3)") == 0);
}

static void test_function_builtins(void **state) {
  fixture *f = *state;
  struct {
    const char *body;
    double expected;
  } cases[] = {
      {"sin(0.3) + cos(0.4) + tan(0.5)", sin(0.3) + cos(0.4) + tan(0.5)},
      {"asin(0.3) + acos(0.4) + atan(0.5)",
       asin(0.3) + acos(0.4) + atan(0.5)},
      {"atan2(1, 2)", atan2(1, 2)},
      {"sinh(0.3) + cosh(0.4) + tanh(0.5)",
       sinh(0.3) + cosh(0.4) + tanh(0.5)},
      {"asinh(0.3) + acosh(1.4) + atanh(0.5)",
       asinh(0.3) + acosh(1.4) + atanh(0.5)},
      {"exp(1.5) + ln(3) + log(1000)", exp(1.5) + log(3.0) + 3},
      {"sqrt(2) + pow(2, 0.5) + abs(-3)", 2 * sqrt(2.0) + 3},
      {"floor(-1.5) + ceil(-1.5) + int(-1.5)", -2 - 1 - 1},
      /* mod keeps the dividend's sign: povray gives -1.5 for mod(-7.5, 3). */
      {"mod(-7.5, 3)", -1.5},
      {"degrees(pi) + radians(180)", 180 + M_PI},
      {"min(3, 1, 2) + 10 * max(3, 1, 2)", 1 + 30},
      {"true + yes + on + false + no + off", 3},
      /* select(a, b, c): a < 0 gives b, else c; with a fourth value
         a = 0 gives c and a > 0 gives d (povray 3.7: 1 2 3, 1 2 2). */
      {"select(-1, 1, 2, 3) + 10 * select(0, 1, 2, 3) + "
       "100 * select(1, 1, 2, 3)",
       321},
      {"select(-1, 1, 2) + 10 * select(0, 1, 2) + 100 * select(1, 1, 2)",
       221},
  };
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
    char d[512];
    snprintf(d, sizeof d, "#declare F = function { %s + 0 * x }\n",
             cases[i].body);
    double v = value(f, d, "F(0, 0, 0)");
    if (fabs(v - cases[i].expected) > EPS)
      fail_msg("%s: %.17g, expected %.17g", cases[i].body, v,
               cases[i].expected);
  }
}

static void test_function_parameters(void **state) {
  fixture *f = *state;
  /* The manual's examples ("Declaring User-Defined Float Functions"). */
  const char *d = "#declare foo = function { x + y * z }\n";
  assert_true(value(f, d, "foo(1, 2, 3)") == 7);
  d = "#declare foo4 = function(h) { h * h + h }\n";
  assert_true(value(f, d, "foo4(3)") == 12);
  d = "#declare foo4 = function(u, v) { x + y * v }\n"; /* = u + v*v */
  assert_true(value(f, d, "foo4(2, 3)") == 11);
  d = "#declare foo4 = function(x, v, z) { u + y * v + z }\n";
  assert_true(value(f, d, "foo4(2, 3, 4)") == 2 + 9 + 4);
  /* A parameter hides a declared identifier of the same name. */
  d = "#declare h = 100;\n#declare F = function(h) { h + 1 }\n";
  assert_true(value(f, d, "F(1)") == 2);
}

static void test_function_captures_floats(void **state) {
  fixture *f = *state;
  /* A declared float is captured when the function is declared. */
  const char *d = "#declare K = 2;\n"
                  "#declare F = function(a) { a * K }\n"
                  "#declare K = 10;\n"
                  "#declare V = <1, 2, 3>;\n"
                  "#declare G = function { V.y + V.z * x }\n";
  assert_true(value(f, d, "F(3)") == 6);
  assert_true(value(f, d, "G(2, 0, 0)") == 8);
  assert_true(value(f, d, "F(3) + K") == 16);
  /* Built-in constants are constants in functions too (trace2.pov puts
     clock in one): a still image's clock is 0, tau is 2 pi. */
  d = "#declare H = function { x + clock + tau }\n";
  assert_true(fabs(value(f, d, "H(1, 0, 0)") - (1 + 2 * M_PI)) < 1e-12);
}

static void test_function_nested_calls(void **state) {
  fixture *f = *state;
  const char *d = "#declare F = function(a) { a * 2 }\n"
                  "#declare G = function(a, b) { F(a) + F(b) + 1 }\n"
                  "#declare H = function { G(x, F(y)) * G(z, z) }\n"
                  "#declare J = H;\n";
  assert_true(value(f, d, "F(3)") == 6);
  assert_true(value(f, d, "G(1, 2)") == 7);
  assert_true(value(f, d, "H(1, 2, 3)") == (2 + 8 + 1) * (6 + 6 + 1));
  assert_true(value(f, d, "J(1, 2, 3)") == (2 + 8 + 1) * (6 + 6 + 1));
  /* Calls inside an argument list of a float expression. */
  assert_true(value(f, d, "max(F(1), G(1, 1)) + F(F(1))") == 5 + 4);
}

static void test_function_sum_prod(void **state) {
  fixture *f = *state;
  /* The manual's example: factorial(5) is 120. */
  const char *d = "#declare factorial = function(C) { prod(i, 1, C, i) }\n"
                  "#declare S = function(n) { sum(i, 1, n, "
                  "sum(j, 1, i, j)) }\n"
                  "#declare E = function { sum(i, 3, 2, 1) + prod(i, 3, 2,"
                  " 5) }\n";
  assert_true(value(f, d, "factorial(5)") == 120);
  /* sum of triangular numbers 1..4: 1 + 3 + 6 + 10. */
  assert_true(value(f, d, "S(4)") == 20);
  /* Empty ranges give the neutral elements 0 and 1. */
  assert_true(value(f, d, "E(0, 0, 0)") == 1);
}

/* The internal functions' values, each checked against povray 3.7.0:
     #include "functions.inc"
     #debug concat(str(f_sphere(1, 2, 3, 0.5), 0, 9), "\n") ...  */
static void test_function_internals_match_povray(void **state) {
  fixture *f = *state;
  const char *d =
      "#declare f_ellipsoid = function { internal(17) }\n"
      "#declare f_paraboloid = function { internal(45) }\n"
      "#declare f_ph = function { internal(47) }\n"
      "#declare f_r = function { internal(57) }\n"
      "#declare f_sphere = function { internal(61) }\n"
      "#declare f_th = function { internal(69) }\n"
      "#declare f_torus = function { internal(70) }\n"
      "#declare f_rounded_box = function { internal(60) }\n"
      "#declare f_superellipsoid = function { internal(68) }\n"
      "#declare f_torus2 = function { internal(71) }\n";
  struct {
    const char *call;
    double povray;
  } cases[] = {
      {"f_sphere(1, 2, 3, 0.5)", 3.241657387},
      {"f_r(1, 2, 3)", 3.741657387},
      {"f_th(1, 2, 3)", 0.321750554},
      {"f_ph(1, 2, 3)", 1.006853685},
      {"f_torus(1, 2, 3, 0.7, 0.2)", 2.972193449},
      {"f_ellipsoid(1, 2, 3, 0.5, 0.25, 2)", 6.041522987},
      {"f_paraboloid(1, 2, 3, 0.5)", -4},
      {"f_paraboloid(0.5, 0.3, -0.2, 2)", 0.02},
      /* Field strength functions are clipped to [-10, 10]. */
      {"f_paraboloid(3, 1, 3, -2)", 10},
      {"f_paraboloid(3, 1, 3, 2)", -10},
      {"f_ph(0, 0, 0) + f_th(0, 1, 0)", 0},
      {"f_sphere(100, 0, 0, 1)", 99},
      {"f_rounded_box(0, 0, 0, 0.1, 0.5, 0.6, 0.7)", -0.100001},
      {"f_rounded_box(0.45, 0, 0, 0.1, 0.5, 0.6, 0.7)", -0.050001},
      {"f_rounded_box(0.49, 0.55, 0, 0.1, 0.5, 0.6, 0.7)", 0.002955301},
      {"f_rounded_box(-0.6, -0.7, 0.1, 0.1, 0.5, 0.6, 0.7)", 0.182841712},
      {"f_rounded_box(0.6, 0, 0, 0, 0.5, 0.6, 0.7)", 0.099999},
      {"f_superellipsoid(0.3, 0.2, 0.4, 0.5, 0.7)", 0.539011867},
      {"f_superellipsoid(-0.3, 0.2, -0.4, 0.5, 0.7)", 0.539011867},
      {"f_superellipsoid(0.3, 0.2, 0.4, 1, 1)", 0.461483519},
      {"f_superellipsoid(0.3, 0.2, 0.4, 0.5, 1)", 0.491582280},
      {"f_superellipsoid(0.3, 0.2, 0.4, 1, 0.5)", 0.545956741},
      {"f_superellipsoid(100, 0, 0, 1, 1)", -99},
      {"f_torus2(1, 0, 0, 1, 1, 0.5)", 0.9375},
      {"f_torus2(0, 1, 0, 1, 1, 0.5)", -3.0625},
      {"f_torus2(0, 0, 1, 1, 1, 0.5)", 0.9375},
      {"f_torus2(1.2, 0.1, 0.3, 0.3, 1, 0.5)", 0.26277},
      {"f_torus2(3, 0, 0, 1, 1, 0.5)", -10},
      {"f_torus2(3, 0, 0, -1, 1, 0.5)", 10},
  };
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
    double v = value(f, d, cases[i].call);
    if (fabs(v - cases[i].povray) > POV_EPS)
      fail_msg("%s: %.10f, povray %.9f", cases[i].call, v, cases[i].povray);
  }
  /* Used inside another function, with the parameters it declares. */
  d = "#declare f_sphere = function { internal(61) }\n"
      "#declare B = function { f_sphere(x, y, z, 1) - f_sphere(x, 0, 0,"
      " 1) }\n";
  assert_true(fabs(value(f, d, "B(3, 4, 0)") - (4 - 2)) < EPS);
}

/* f_helix1 and f_helix2 (function.c's helix1, helix2) against povray
   3.7.0's values, printed to 9 digits as above: each cross section
   type (0 square to 3 concave diamond, beyond and below), rotation,
   shape, several helixes, abyss.pov's cable, the bound far from the
   strands and with period or shape 0. */
static void test_function_helixes_match_povray(void **state) {
  fixture *f = *state;
  const char *d = "#declare f_helix1 = function { internal(25) }\n"
                  "#declare f_helix2 = function { internal(26) }\n";
  struct {
    const char *call;
    double povray;
  } cases[] = {
      {"f_helix1(-0.9, 0.15, 0.05, 1, 1, 0.3, 1, 1, 1, 0)",
       -0.163417077},
      {"f_helix1(-0.9, 0.15, 0.05, 1, 1, 0.3, 1, 1, 4, 0)",
       0.086183596},
      {"f_helix1(-0.9, 0.15, 0.05, 1, 1, 0.3, 1, 1, -1, 0)",
       -0.231770398},
      {"f_helix1(0.3, 0.2, -0.8, 2, 1.5, 0.2, 0.8, 1.5, 0, 20)",
       0.093735774},
      {"f_helix1(0.3, 0.7, -0.8, 2, 1.5, 0.2, 0.8, 1.5, 3, 20)",
       0.823040065},
      {"f_helix1(0.01, 0.5, 0.012, 3, 35, 0.0105, 0.0165, 2, 1, 0)",
       -0.002257235},
      {"f_helix1(1, 0, 0, 1, 1, 0.1, 1, 1, 1, 0)",
       1.900000000},
      {"f_helix1(10, 0, 0, 1, 1, 0.1, 1, 1, 1, 0)",
       9.432554978},
      {"f_helix1(-0.9, 0.15, 0.05, 1, 0, 0.3, 1, 1, 1, 0)",
       1.601387819},
      {"f_helix1(-0.9, 0.15, 0.05, 1, 1, 0.3, 1, 0, 1, 0)",
       1.601387819},
      {"f_helix2(-0.9, 0.15, 0.05, 1, 1, 0.3, 1, 1, 4, 0)",
       2.943196980},
      {"f_helix2(0.3, 0.4, -0.2, 3, 2, 0.6, 0.3, 2, 1, 0)",
       -0.174940565},
      {"f_helix2(0.3, 0.4, -0.2, 2, 1.5, 0.6, 0.1, 1.5, 0, 20)",
       -0.265540135},
      {"f_helix2(0.5, -0.4, 0.7, 1, 1, 0.5, 0.2, 1, 2.5, 45)",
       0.374823741},
  };
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
    double v = value(f, d, cases[i].call);
    if (fabs(v - cases[i].povray) > 1e-8)
      fail_msg("%s: %.10f, povray %.9f", cases[i].call, v, cases[i].povray);
  }
}

/* Functions pass through macros as values (manual, "Functions and
   Macros"), and a function written in a macro captures its arguments. */
static void test_function_in_macros(void **state) {
  fixture *f = *state;
  const char *d = "#macro Foo(Bar, X)\n"
                  "  #declare Y = Bar(X);\n"
                  "  #declare Z = Bar(Y);\n"
                  "#end\n"
                  "#declare FUNC = function(n) { n + 2 }\n"
                  "Foo(FUNC, 1)\n"
                  "#macro Scaled(Fn, K) function { Fn(x) * K + 0 * y * z } "
                  "#end\n"
                  "#declare G = Scaled(FUNC, 10)\n";
  assert_true(value(f, d, "Y") == 3);
  assert_true(value(f, d, "Z") == 5);
  assert_true(value(f, d, "G(1, 0, 0)") == 30);
  /* One function per turn of a loop, each with its own capture. */
  d = "#declare I = 0;\n"
      "#while (I < 3)\n"
      "  #declare F = function { x + I }\n"
      "  #declare I = I + 1;\n"
      "#end\n";
  assert_true(value(f, d, "F(10, 0, 0)") == 12);
  /* Calls in directive conditions. */
  d = "#declare F = function(a) { a * a }\n"
      "#if (F(3) = 9) #declare R = 1; #else #declare R = 2; #end\n";
  assert_true(value(f, d, "R") == 1);
}

/* The standard include files declare their functions with this code:
   they parse, and their functions give povray 3.7's values. */
static void test_function_standard_includes(void **state) {
  fixture *f = *state;
  if (access(ZR_POVRAY_INCLUDE_DIR "/functions.inc", R_OK) != 0 ||
      access(ZR_POVRAY_INCLUDE_DIR "/math.inc", R_OK) != 0) {
    printf("# skipped: POV-Ray's include files are not in "
           ZR_POVRAY_INCLUDE_DIR "\n");
    skip();
  }
  const char *d = "#include \"functions.inc\"\n#include \"math.inc\"\n";
  assert_true(fabs(value(f, d, "f_sphere(1, 2, 3, 0.5)") - 3.241657387) <
              POV_EPS);
  assert_true(fabs(value(f, d, "f_torus(1, 2, 3, 0.7, 0.2)") -
                   2.972193449) < POV_EPS);
  /* math.inc: sind(30) is sin(30 degrees); even() and sgn() are select
     over mod; clip() clamps; adj_range2 maps [0, 10] onto [0, 1]. */
  assert_true(fabs(value(f, d, "sind(30)") - 0.5) < EPS);
  assert_true(value(f, d, "even(4) + 10 * odd(4)") == 1);
  assert_true(value(f, d, "sgn(-3) + 10 * sgn(2)") == 9);
  assert_true(value(f, d, "clip(5, 0, 1)") == 1);
  assert_true(fabs(value(f, d, "adj_range2(5, 0, 10, 0, 1)") - 0.5) < EPS);
  /* f_sine_wave = function { sin(x * z * pi) * y }. */
  assert_true(fabs(value(f, d, "f_sine_wave(0.25, 2, 2)") - 2) < EPS);
}

static void test_function_unsupported_internal(void **state) {
  fixture *f = *state;
  /* Declaring is fine (functions.inc declares them all); using is not. */
  const char *d = "#declare f_ridge = function { internal(58) }\n"
                  "#declare N = function { 2 * f_ridge(x, y, z, 1, 3, 1, "
                  "0.2, 0, 0) - 1 }\n"
                  "#declare P = function { transform { scale 2 } }\n";
  char text[1024];
  snprintf(text, sizeof text, "%s#declare V = N(1, 2, 3);\n", d);
  bad(f, text, ZR_EUNSUPPORTED,
      "function 'N' uses internal function 58 (f_ridge), which is not "
      "supported yet", NULL);
  /* Transform functions work (tests/test_meshcam.c checks them). */
  snprintf(text, sizeof text, "%s#declare V = P(1, 2, 3);\n"
           "#debug vstr(3, V, \",\", 0, 1)\n", d);
  good(f, text);
  assert_string_equal(f->diag.debug, "2.0,4.0,6.0");
  bad(f, "#declare F = function { internal(77) }\n", ZR_ESCENE,
      "there is no internal function 77", NULL);
  bad(f, "#declare F = function { internal(6.5) }\n", ZR_ESCENE,
      "there is no internal function 6.5", NULL);
  bad(f, "#declare F = function { internal(6e96) }\n", ZR_ESCENE,
      "there is no internal function 6e+96", NULL);
  bad(f, "#declare F = function(a) { internal(61) }\n", ZR_ESYNTAX,
      "internal function 61 (f_sphere) takes 4 parameters", NULL);
}

/* The declarations of functions.inc that the noise tests use. */
static const char *const noise_decls =
    "#declare f_noise3d = function { internal(76) }\n"
    "#declare f_snoise3d = function { 2 * f_noise3d(x, y, z) - 1 }\n"
    "#declare f_noise_generator = function { internal(78) }\n"
    "#declare f_hetero_mf = function { internal(29) }\n"
    "#declare f_ridged_mf = function { internal(59) }\n"
    "#declare Bozo = function { pattern { bozo } }\n";

/* The value of an SDL call built from a format. */
static double valuef(fixture *f, const char *format, ...) {
  char call[256];
  va_list ap;
  va_start(ap, format);
  vsnprintf(call, sizeof call, format, ap);
  va_end(ap);
  return value(f, noise_decls, call);
}

/* f_noise3d is the bozo pattern's noise, in [0, 1] as the manual says
   ("Functions.inc"), f_snoise3d its [-1, 1] form, and noise generators 0
   and 2 select it (1 and 3 are other noises; tests/test_noise.c checks
   generator 1 against POV-Ray's values).  The same code computes both
   sides, so they agree to EPS; the range holds exactly. */
static void test_function_noise3d(void **state) {
  fixture *f = *state;
  static const double at[][3] = {
      {0.3, 0.7, 1.1}, {-2.25, 4.5, 0.125}, {10.6, -3.3, 7.7}, {0, 0, 0}};
  for (size_t i = 0; i < sizeof at / sizeof at[0]; i++) {
    double x = at[i][0], y = at[i][1], z = at[i][2];
    double n = valuef(f, "f_noise3d(%g, %g, %g)", x, y, z);
    assert_true(n >= 0 && n <= 1);
    assert_true(fabs(n - valuef(f, "Bozo(%g, %g, %g)", x, y, z)) < EPS);
    assert_true(fabs(2 * n - 1 - valuef(f, "f_snoise3d(%g, %g, %g)", x, y,
                                        z)) < EPS);
    for (int g = 0; g <= 2; g += 2)
      assert_true(fabs(n - valuef(f, "f_noise_generator(%g, %g, %g, %d)",
                                  x, y, z, g)) < EPS);
    double n1 = valuef(f, "f_noise_generator(%g, %g, %g, 1)", x, y, z);
    assert_true(n1 >= 0 && n1 <= 1);
  }
  /* Over 1000 points the values stay in [0, 1] around the mean 0.5: a
     noise scaled wrongly (the [-1, 1] of functions.inc's comment) fails.
     The mean of a lattice noise over 1000 scattered points is within
     0.05 of its expectation (its deviation is about 0.2 / sqrt(1000)). */
  char d[1024];
  snprintf(d, sizeof d,
           "%s#declare N = function(i) { f_noise3d(i * 0.37, i * 0.19 + 0.5,"
           " i * 0.11 + 0.25) }\n"
           "#declare Mean = function { sum(i, 0, 999, N(i)) / 1000 }\n"
           "#declare In = function { prod(i, 0, 999, (N(i) >= 0) & "
           "(N(i) <= 1)) }\n",
           noise_decls);
  assert_true(fabs(value(f, d, "Mean(0, 0, 0)") - 0.5) < 0.05);
  assert_true(value(f, d, "In(0, 0, 0)") == 1);
}

/* f_ridged_mf and f_hetero_mf are Musgrave's sums over the signed noise,
   checked against the same sums written out from f_snoise3d at the
   octaves' points (p, then p * lacunarity); the arithmetic differs only
   in rounding, hence 1e-12. */
static void test_function_multifractals(void **state) {
  fixture *f = *state;
  const double x = 0.3, y = 0.7, z = 1.1, h = 0.5, lac = 2.2;
  double s0 = valuef(f, "f_snoise3d(%.17g, %.17g, %.17g)", x, y, z);
  double s1 = valuef(f, "f_snoise3d(%.17g, %.17g, %.17g)", x * lac,
                     y * lac, z * lac);
  double s2 = valuef(f, "f_snoise3d(%.17g, %.17g, %.17g)", x * lac * lac,
                     y * lac * lac, z * lac * lac);
  double w1 = pow(lac, -h);
  /* Ridged: one octave is (offset - |noise|)^2; the next is weighted by
     the previous signal times gain, clamped to [0, 1]. */
  double offset = 0.9, gain = 0.8;
  double r0 = (offset - fabs(s0)) * (offset - fabs(s0));
  double wt = fmin(fmax(r0 * gain, 0), 1);
  double r1 = (offset - fabs(s1)) * (offset - fabs(s1)) * wt;
  double got = valuef(f, "f_ridged_mf(%g, %g, %g, %g, %g, 1, %g, %g, 1)", x,
                      y, z, h, lac, offset, gain);
  assert_true(fabs(got - r0) < EPS);
  got = valuef(f, "f_ridged_mf(%g, %g, %g, %g, %g, 2, %g, %g, 1)", x, y, z,
               h, lac, offset, gain);
  assert_true(fabs(got - (r0 + r1 * w1)) < EPS);
  /* Gain 0 silences every octave after the first. */
  got = valuef(f, "f_ridged_mf(%g, %g, %g, %g, %g, 7, %g, 0, 1)", x, y, z,
               h, lac, offset);
  assert_true(fabs(got - r0) < EPS);
  /* Hetero: T = 0 is the plain 1/f sum of noise + offset, T = 1 scales
     each octave by the altitude so far; 1.5 octaves add half of the
     second. */
  offset = 0.26;
  double v0 = offset + s0, inc1 = (s1 + offset) * w1;
  got = valuef(f, "f_hetero_mf(%g, %g, %g, %g, %g, 1, %g, 0, 1)", x, y, z,
               h, lac, offset);
  assert_true(fabs(got - v0) < EPS);
  got = valuef(f, "f_hetero_mf(%g, %g, %g, %g, %g, 2, %g, 0, 1)", x, y, z,
               h, lac, offset);
  assert_true(fabs(got - (v0 + inc1)) < EPS);
  got = valuef(f, "f_hetero_mf(%g, %g, %g, %g, %g, 2, %g, 1, 1)", x, y, z,
               h, lac, offset);
  assert_true(fabs(got - (v0 + inc1 * v0)) < EPS);
  got = valuef(f, "f_hetero_mf(%g, %g, %g, %g, %g, 1.5, %g, 1, 1)", x, y, z,
               h, lac, offset);
  assert_true(fabs(got - (v0 + 0.5 * inc1 * v0)) < EPS);
  double v1 = v0 + inc1 * v0, inc2 = (s2 + offset) * w1 * w1;
  got = valuef(f, "f_hetero_mf(%g, %g, %g, %g, %g, 3, %g, 1, 1)", x, y, z,
               h, lac, offset);
  assert_true(fabs(got - (v1 + inc2 * v1)) < EPS);
  /* A huge octave count is capped, so it returns (a finite value). */
  got = valuef(f, "f_ridged_mf(%g, %g, %g, %g, %g, 1e9, %g, 1, 1)", x, y, z,
               h, lac, 0.9);
  assert_true(isfinite(got));
}

/* function { pattern { } } and function { pigment { } } ("Function
   Pattern"): checker's cells are exact, and a pigment function's
   channels are its colour's (the grey weights are POV-Ray's). */
static void test_function_pattern_and_pigment(void **state) {
  fixture *f = *state;
  const char *d =
      "#declare P = function { pattern { #if (1) checker #end scale 2 } }\n"
      "#declare C = pigment { checker rgb <1, 0.5, 0>, rgb <0, 0, 1> }\n"
      "#declare Q = function { pigment { C } }\n"
      "#declare G = function { Q(x, y, z).green + Q(x, y, z).gray }\n";
  assert_true(fabs(value(f, d, "P(1, 1, 1)") - 0) < EPS);
  assert_true(fabs(value(f, d, "P(3, 1, 1)") - 1) < EPS);
  assert_true(fabs(value(f, d, "G(0.5, 0.5, 0.5)") -
                   (0.5 + 0.297 + 0.589 * 0.5)) < EPS);
  assert_true(fabs(value(f, d, "G(1.5, 0.5, 0.5)") - 0.114) < EPS);
  /* Called directly, a pigment function gives its colour. */
  assert_true(fabs(value(f, d, "Q(1.5, 0.5, 0.5).blue") - 1) < EPS);
  bad(f, "#declare C = pigment { rgb 1 }\n"
         "#declare Q = function { pigment { C } }\n"
         "#declare G = function { Q(x, y, z) }\n",
      ZR_ESYNTAX, "expected '.' and a colour component after a pigment "
                  "function in function, got '}'", NULL);
}

static void test_function_errors(void **state) {
  fixture *f = *state;
  bad(f, "#declare F = function(a) { a + b }\n", ZR_EUNDEFINED,
      "undefined identifier 'b' in function", NULL);
  bad(f, "#declare F = function(a) { a + y }\n", ZR_EUNDEFINED,
      "'y' is not a parameter of this function", NULL);
  bad(f,
      "#declare F = function(a, b) { a + b }\n"
      "#declare G = function { F(x) }\n",
      ZR_ESYNTAX, "function 'F' takes 2 arguments, not 1", NULL);
  bad(f,
      "#declare F = function(a, b) { a + b }\n"
      "#declare V = F(1, 2, 3);\n",
      ZR_ESYNTAX, "function 'F' takes 2 arguments, not 3", NULL);
  bad(f, "#declare F = function { x < 0 ? 1 : 2 }\n", ZR_EUNSUPPORTED,
      "'?:' cannot be used in a function (POV-Ray 3.7 does not allow it "
      "either: use select())", NULL);
  bad(f, "#declare F = function(a, a) { a }\n", ZR_ESYNTAX,
      "parameter 'a' is listed twice", NULL);
  bad(f, "#declare F = function { sin(x, y) }\n", ZR_ESYNTAX,
      "'sin' takes 1 argument", NULL);
  bad(f, "#declare F = function { select(x, y) }\n", ZR_ESYNTAX,
      "'select' takes 3 or 4 arguments", NULL);
  bad(f, "#declare F = function { x + }\n", ZR_ESYNTAX,
      "expected a float expression in function, got '}'", NULL);
  bad(f, "#declare F = function { x y }\n", ZR_ESYNTAX,
      "expected an operator or '}' in function, got 'y'", NULL);
  bad(f, "#declare F = function { box }\n", ZR_ESYNTAX,
      "'box' cannot be used in a function", NULL);
  bad(f, "#declare F = function { x", ZR_ESYNTAX,
      "expected an operator or '}' in function, got end of file", NULL);
  bad(f,
      "#declare P = pigment { rgb 1 }\n"
      "#declare F = function { P + x }\n",
      ZR_ESYNTAX,
      "'P' is not a float or a function, so it cannot be used in a "
      "function", NULL);
  /* The message points at the name, with the usual caret. */
  parse(f, "#declare F = function(a) {\n  a + nope }\n");
  assert_string_equal(f->diag.text,
                      "t.pov:2:7: error: undefined identifier 'nope' in "
                      "function\n"
                      "    2 |   a + nope }\n"
                      "      |       ^~~~\n");
}

/* A chain of n functions, each calling the one before. */
static char *chain(int n) {
  size_t cap = (size_t)n * 64 + 256;
  char *text = malloc(cap);
  assert_non_null(text);
  size_t len = (size_t)snprintf(text, cap,
                                "#declare F0 = function(a) { a + 1 }\n");
  for (int i = 1; i < n; i++)
    len += (size_t)snprintf(text + len, cap - len,
                            "#declare F%d = function(a) { F%d(a) + 1 }\n",
                            i, i - 1);
  return text;
}

static void test_function_depth_limit(void **state) {
  fixture *f = *state;
  /* 1024 levels are allowed and evaluate (the manual's limit)... */
  char *text = chain(ZR_FN_MAX_DEPTH);
  char decl[64];
  snprintf(decl, sizeof decl, "F%d(0)", ZR_FN_MAX_DEPTH - 1);
  assert_true(value(f, text, decl) == ZR_FN_MAX_DEPTH);
  free(text);
  /* ...one more is refused, where it is declared. */
  text = chain(ZR_FN_MAX_DEPTH + 1);
  bad(f, text, ZR_ELIMIT, "functions nested more than 1024 calls deep", NULL);
  free(text);
}

static void test_function_stack_limit(void **state) {
  fixture *f = *state;
  /* min() with 50 arguments keeps 49 of them on the stack while the
     last is computed: nested 100 deep that is more than ZR_FN_MAX_STACK
     values. */
  size_t cap = 100 * 160 + 64;
  char *text = malloc(cap);
  assert_non_null(text);
  size_t len = (size_t)snprintf(text, cap, "#declare F = function { ");
  for (int i = 0; i < 100; i++) {
    len += (size_t)snprintf(text + len, cap - len, "min(");
    for (int k = 0; k < 49; k++)
      len += (size_t)snprintf(text + len, cap - len, "x,");
  }
  len += (size_t)snprintf(text + len, cap - len, "x");
  for (int i = 0; i < 100; i++)
    len += (size_t)snprintf(text + len, cap - len, ")");
  snprintf(text + len, cap - len, " }\n");
  bad(f, text, ZR_ELIMIT, "the function needs more than 4096 values to "
                          "evaluate", NULL);
  free(text);
  /* Parentheses nested past ZR_FN_MAX_NESTING stop the compiler before
     its recursion could exhaust the C stack. */
  cap = 3000 * 2 + 64;
  text = malloc(cap);
  assert_non_null(text);
  len = (size_t)snprintf(text, cap, "#declare F = function { ");
  for (int i = 0; i < 3000; i++)
    text[len++] = '(';
  snprintf(text + len, cap - len, "x }\n");
  bad(f, text, ZR_ELIMIT, "the function nests more than 256 levels deep", NULL);
  free(text);
}

/*
 * Evaluates a 23-operation function directly, many times: the figure
 * goes in the report (a benchmark, never a timed assertion), and the
 * value is checked against the same expression in C.
 */
/* The test's 23-operation function: 9 of * and /, 9 of + and -, sin cos
   sqrt abs max. */
static const char *const speed_decl =
    "#declare F = function { x * y + y * z - z * x + sin(x) * cos(y) - "
    "sqrt(x * x + y * y + z * z) + abs(x - y) * 0.5 + max(x, z) / 3 }\n";

static double speed_in_c(double x, double y, double z) {
  return x * y + y * z - z * x + sin(x) * cos(y) -
         sqrt(x * x + y * y + z * z) + fabs(x - y) * 0.5 +
         (x > z ? x : z) / 3;
}

/*
 * A function declared in d is not reachable from the scene: this
 * compiles it again the way the grammar does, with a parser reading
 * the text after 'function', into f's scene.  file is freed by the
 * caller (zr__sdl_file_free).
 */
static const zr_fn *compile_direct(fixture *f, const char *d,
                                   zr_sdl_file *file) {
  assert_int_equal(parse(f, d), ZR_OK);
  zr_sdl_parser p;
  memset(&p, 0, sizeof p);
  p.ctx = f->ctx;
  p.scene = f->scene;
  memset(file, 0, sizeof *file);
  const char *body = strstr(d, "function") + strlen("function");
  size_t size = strlen(body);
  char *bytes = malloc(size + 1);
  char *path = malloc(8);
  assert_non_null(bytes);
  assert_non_null(path);
  memcpy(bytes, body, size + 1);
  strcpy(path, "t.pov");
  zr_sdl_loc err_loc;
  char err[200];
  assert_int_equal(zr__sdl_file_lex(file, 0, path, bytes, size, &err_loc,
                                    err, sizeof err),
                   ZR_OK);
  zr_sdl_frame frame;
  memset(&frame, 0, sizeof frame);
  p.files = file;
  p.n_files = 1;
  p.frames = &frame;
  p.n_frames = 1;
  zr_sdl_loc at = {0, 1, 1, 8};
  const zr_fn *fn = zr__sdl_function_parse(&p, &at);
  assert_non_null(fn);
  return fn;
}

static void test_function_speed(void **state) {
  fixture *f = *state;
  zr_sdl_file file;
  const zr_fn *fn = compile_direct(f, speed_decl, &file);
  assert_int_equal(zr__fn_params(fn), 3);
  assert_null(zr__fn_unsupported(fn));
  long n = 2000000;
  double sum = 0, args[3];
  struct timespec t0, t1;
  clock_gettime(CLOCK_MONOTONIC, &t0);
  for (long i = 0; i < n; i++) {
    args[0] = (double)(i % 1000) * 0.001;
    args[1] = 0.5;
    args[2] = -0.25;
    sum += zr__fn_eval(fn, args);
  }
  clock_gettime(CLOCK_MONOTONIC, &t1);
  double secs = (double)(t1.tv_sec - t0.tv_sec) +
                (double)(t1.tv_nsec - t0.tv_nsec) * 1e-9;
  /* The same expression compiled by the C compiler, for scale (the
     volatile keeps it from being folded out of the loop). */
  volatile double y = 0.5, z = -0.25;
  double expect = 0;
  clock_gettime(CLOCK_MONOTONIC, &t0);
  for (long i = 0; i < n; i++)
    expect += speed_in_c((double)(i % 1000) * 0.001, y, z);
  clock_gettime(CLOCK_MONOTONIC, &t1);
  double c_secs = (double)(t1.tv_sec - t0.tv_sec) +
                  (double)(t1.tv_nsec - t0.tv_nsec) * 1e-9;
  /* Sums of two million terms of order one: the orders of rounding
     differ, so compare relatively. */
  assert_true(fabs(sum - expect) <= 1e-9 * fabs(expect));
  printf("# function speed: %.3g evaluations/s of a 23-operation "
         "function (%.1f ns each; the same expression in C: %.1f ns)\n",
         (double)n / secs, secs / (double)n * 1e9,
         c_secs / (double)n * 1e9);
  zr__sdl_file_free(&file);
}

/* Threads evaluating one function at once each get exactly the serial
   results: evaluation shares no state. */
typedef struct worker {
  const zr_fn *fn;
  int seed;
  int mismatches;
} worker;

static void *evaluate_many(void *arg) {
  worker *w = arg;
  for (int i = 0; i < 200000; i++) {
    double a[3] = {(double)((i * 7 + w->seed) % 1000) * 0.001,
                   (double)(i % 13) * 0.1 - 0.6, (double)w->seed * 0.25};
    double got = zr__fn_eval(w->fn, a), want = speed_in_c(a[0], a[1], a[2]);
    if (fabs(got - want) > EPS * (1 + fabs(want)))
      w->mismatches++;
  }
  return NULL;
}

static void test_function_threads(void **state) {
  fixture *f = *state;
  zr_sdl_file file;
  const zr_fn *fn = compile_direct(f, speed_decl, &file);
  worker w[4];
  pthread_t t[4];
  for (int k = 0; k < 4; k++) {
    w[k].fn = fn;
    w[k].seed = k;
    w[k].mismatches = 0;
    assert_int_equal(pthread_create(&t[k], NULL, evaluate_many, &w[k]), 0);
  }
  for (int k = 0; k < 4; k++) {
    assert_int_equal(pthread_join(t[k], NULL), 0);
    /* The machine does the C expression's operations in the same order:
       EPS only allows for a compiler that fuses multiply-adds in C. */
    assert_int_equal(w[k].mismatches, 0);
  }
  zr__sdl_file_free(&file);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test_setup_teardown(test_function_arithmetic, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_function_logic, setup, teardown),
      cmocka_unit_test_setup_teardown(test_function_builtins, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_function_parameters, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_function_captures_floats, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_function_nested_calls, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_function_sum_prod, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_function_internals_match_povray,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_function_helixes_match_povray,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_function_in_macros, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_function_standard_includes,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_function_unsupported_internal,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_function_noise3d, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_function_multifractals, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_function_pattern_and_pigment,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_function_errors, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_function_depth_limit, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_function_stack_limit, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_function_speed, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_function_threads, setup,
                                      teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
