/*
 * test_directives.c - POV-Ray 3.7's directive language and values
 * (lib/sdl/directive.c, control.c, builtins.c, symtab.c): declarations
 * and scopes, conditionals, loops, #switch, macros, strings, arrays,
 * built-in functions and constants, and the messages of bad input.
 *
 * Most checks print values with #debug and compare the text: the scenes
 * are their own oracle, written as the reference manual (r3_3) documents
 * each directive and function, and where the manual and POV-Ray 3.7.0
 * differ (#switch fall-through, the clock of a still image) as povray
 * behaves, measured on the same input.  Numbers are printed with
 * str(V, 0, 6): six decimals is far coarser than any rounding of the few
 * double operations involved, and fine enough to catch a wrong formula.
 * Included files are served from memory through the context's reader.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "config.h"
#include "scene/scene.h"
#include "zrcube.h"
#include "parse_fixture.h"
#include "test_util.h"

/* Parses text, which must succeed, and checks what it printed. */
static void prints(fixture *f, const char *text, const char *expected) {
  zr_status s = parse(f, text);
  if (s != ZR_OK)
    fail_msg("unexpected failure:\n%s", f->diag.text);
  assert_string_equal(f->diag.debug, expected);
}

/* ---- declarations and scopes ---- */

static void test_directives_declare_and_local(void **state) {
  fixture *f = *state;
  static const vfile files[] = {
      {"scope.inc",
       "#local L = 5;\n"
       "#declare G = G + L;\n"
       "#debug concat(\"inc L=\", str(L, 0, 0), \"\\n\")\n"},
      {NULL, NULL}};
  f->files = files;
  /* #local in an include file ends with the file; #declare there changes
     the global; #local in the main file is global. */
  prints(f,
         "#declare G = 1;\n"
         "#local L = 2;\n"
         "#include \"scope.inc\"\n"
         "#debug concat(\"G=\", str(G, 0, 0), \" L=\", str(L, 0, 0), "
         "\"\\n\")\n",
         "inc L=5\nG=6 L=2\n");
  /* #undef removes the most local version only. */
  prints(f,
         "#declare A = 1;\n"
         "#macro M() #local A = 2; #undef A "
         "#debug str(A, 0, 0) #end\n"
         "M()\n"
         "#undef A\n"
         "#ifndef (A) #debug \" gone\" #end\n",
         "1 gone");
  /* A declaration of an object needs no ';', of a float it warns below
     version 3.5 (and is refused from 3.5 on: test_parser.c). */
  prints(f,
         "#version 3.1;\n"
         "#declare S = sphere { 0, 2 }\n"
         "#declare T = 3\n"
         "object { S }\n"
         "#debug str(T, 0, 0)\n",
         "3");
  assert_int_equal(f->diag.warnings, 1);
  assert_non_null(strstr(f->diag.warning, "'#declare' of a float, vector or "
                                     "colour should end with ';'"));
  assert_int_equal(f->scene->n_objects, 1);
}

static void test_directives_nested_macros_shadow(void **state) {
  fixture *f = *state;
  /* Locals shadow globals in each macro; #declare changes the innermost
     existing name (the manual's "Identifier Name Collisions"). */
  prints(f,
         "#declare X = 1;\n"
         "#declare D = 0;\n"
         "#macro Inner()\n"
         "  #debug concat(\"inner sees X=\", str(X, 0, 0), \"\\n\")\n"
         "  #local X = 3;\n"
         "  #declare D = D + 1;\n"
         "  #debug concat(\"inner X=\", str(X, 0, 0), \"\\n\")\n"
         "#end\n"
         "#macro Outer()\n"
         "  #local X = 2;\n"
         "  #local D = 10;\n"
         "  Inner()\n"
         "  #debug concat(\"outer X=\", str(X, 0, 0), \" D=\", "
         "str(D, 0, 0), \"\\n\")\n"
         "#end\n"
         "Outer()\n"
         "#debug concat(\"global X=\", str(X, 0, 0), \" D=\", "
         "str(D, 0, 0), \"\\n\")\n",
         "inner sees X=2\ninner X=3\nouter X=2 D=11\nglobal X=1 D=0\n");
}

/* ---- conditionals ---- */

static void test_directives_if_family(void **state) {
  fixture *f = *state;
  prints(f,
         "#declare A = 2;\n"
         "#if (A = 1) #debug \"1\" #elseif (A = 2) #debug \"2\" "
         "#elseif (A = 2) #debug \"2b\" #else #debug \"e\" #end\n"
         "#if (0) #debug \"no\" #else #debug \"E\" #end\n"
         "#if (1e-11) #debug \"tiny\" #else #debug \"F\" #end\n"
         "#if (-1) #if (0) #debug \"x\" #else #debug \"N\" #end #end\n"
         "#ifdef (A) #debug \"d\" #end\n"
         "#ifndef (B) #debug \"u\" #elseif (1) #debug \"x\" #end\n"
         "#ifdef (B) #debug \"x\" #elseif (A > 1) #debug \"i\" #end\n"
         "#if (defined(A) & !defined(B)) #debug \"!\" #end\n"
         /* Comparisons chain from the left, as in povray: (0<A)<360. */
         "#if (0 < A < 360) #debug \"c\" #end\n"
         "#if ((3 < 2 < 1) = 1) #debug \"C\" #end\n",
         "2EFNdui!cC");
}

static void test_directives_switch(void **state) {
  fixture *f = *state;
  /* As povray 3.7.0 runs them: a true clause without #break falls
     through into the next clauses, #else included, whatever their
     conditions. */
  prints(f,
         "#switch (3)\n"
         "  #case (1) #debug \"one \" #break\n"
         "  #range (2, 4) #debug \"2-4 \"\n"
         "  #case (5) #debug \"five \" #break\n"
         "  #else #debug \"else \"\n"
         "#end\n"
         "#switch (3) #case (3) #debug \"three \" #else #debug \"E \" #end\n"
         "#switch (9) #case (3) #debug \"x\" #break #else #debug \"none \" "
         "#end\n"
         "#switch (2.00000000001) #case (2) #debug \"eps \" #end\n"
         "#switch (1) #case (1) #if (1) #break #end #debug \"x\" "
         "#case (2) #debug \"x\" #end\n"
         "#debug \"end\"\n",
         "2-4 five three E none eps end");
}

/* ---- loops ---- */

static void test_directives_while_and_for(void **state) {
  fixture *f = *state;
  prints(f,
         "#declare I = 0; #declare S = 0;\n"
         "#while (I < 10) #declare S = S + I; #declare I = I + 1; #end\n"
         "#debug concat(str(S, 0, 0), \" \")\n"
         "#for (J, 0, 330, 30) #end\n"
         "#debug concat(str(J, 0, 0), \" \")\n"
         "#for (K, 3, 1, -1) #debug str(K, 0, 0) #end\n"
         "#for (K, 1, 0) #debug \"x\" #end\n"
         "#debug concat(\" \", str(K, 0, 0), \" \")\n"
         "#declare N = 0;\n"
         "#while (1) #declare N = N + 1; #if (N = 4) #break #end #end\n"
         "#for (M, 1, 100) #if (M = 3) #break #end #end\n"
         "#debug concat(str(N, 0, 0), str(M, 0, 0))\n",
         "45 360 321 1 43");
  /* The body of a loop makes scene items each time round. */
  assert_int_equal(parse(f, "#for (I, 1, 5) sphere { x * I, 1 } #end"),
                   ZR_OK);
  assert_int_equal(f->scene->n_objects, 5);
  assert_near(f->scene->objects[4]->u.sphere.centre.x, 5, 0);
}

static void test_directives_while_in_macro_in_include(void **state) {
  fixture *f = *state;
  static const vfile files[] = {
      {"rings.inc",
       "#macro Ring(N, R)\n"
       "  #local I = 0;\n"
       "  #while (I < N)\n"
       "    sphere { vrotate(<R, 0, 0>, y * 360 * I / N), 0.1 }\n"
       "    #local I = I + 1;\n"
       "  #end\n"
       "  #declare Made = Made + N;\n"
       "#end\n"},
      {NULL, NULL}};
  f->files = files;
  prints(f,
         "#declare Made = 0;\n"
         "#include \"rings.inc\"\n"
         "Ring(4, 2)\n"
         "union { Ring(3, 1) }\n"
         "#debug str(Made, 0, 0)\n"
         "#ifndef (I) #debug \" no I\" #end\n",
         "7 no I");
  assert_int_equal(f->scene->n_objects, 5);
  /* The second sphere of the first ring is y*90 round from <2,0,0>:
     rotate is left-handed, x goes to -z. */
  zr_vec3 c = f->scene->objects[1]->u.sphere.centre;
  assert_near(c.x, 0, 1e-12);
  assert_near(c.z, -2, 1e-12);
}

/* ---- macros ---- */

static void test_directives_macros(void **state) {
  fixture *f = *state;
  prints(f,
         /* A macro as an expression, recursive. */
         "#macro Fact(N) #if (N <= 1) 1 #else N * Fact(N - 1) #end #end\n"
         "#debug concat(str(Fact(6), 0, 0), \" \")\n"
         /* Parameters by identifier change the caller's variable; by
            value they do not. */
         "#macro Inc(V) #declare V = V + 1; #end\n"
         "#declare K = 5; Inc(K) Inc(K) Inc(K + 0)\n"
         "#debug concat(str(K, 0, 0), \" \")\n"
         "#macro Outer(W) Inc(W) #end\n"
         "Outer(K)\n"
         "#debug concat(str(K, 0, 0), \" \")\n"
         /* Also when the macro ends before the #declare's value does
            (no ';' after an object, macros/macro2.pov): POV-Ray 3.7
            prints 1 here. */
         "#macro Move(O) #declare O = object { O translate x } #end\n"
         "#declare S = sphere { 0, 1 } Move(S)\n"
         "#debug concat(str(min_extent(S).x + 1, 0, 0), \" \")\n"
         /* Optional parameters and #break out of a macro. */
         "#macro Opt(A, optional B) #ifdef (B) #debug \"B\" #else "
         "#debug \"-\" #end #end\n"
         "Opt(1) Opt(1, 2)\n"
         "#macro Early() #debug \"a\" #break #debug \"b\" #end\n"
         "Early()\n"
         /* Values of every kind pass: vectors, strings, objects. */
         "#macro Show(V, S, O) #debug concat(\" \", S, vstr(3, V, \",\", "
         "0, 0)) object { O } #end\n"
         "Show(<1, 2, 3>, \"v=\", sphere { 0, 1 })\n"
         /* A comma after the last parameter, or none between two, as
            in shapes3.inc. */
         "#macro Two(A, B,) #debug str(A + B, 0, 0) #end\n"
         "Two(1, 2)\n"
         "#macro Three(A, B C) #debug str(A + B + C, 0, 0) #end\n"
         "Three(1, 2, 3)\n",
         "720 7 8 1 -Ba v=1,2,336");
  assert_int_equal(f->scene->n_objects, 1);
}

/* Strings compare in conditions, as strcmp orders them (povray 3.7
   prints the same three words; meshcam_macros.inc relies on it). */
static void test_directives_string_comparison(void **state) {
  fixture *f = *state;
  prints(f,
         "#declare S = \"abc\";\n"
         "#if (S != \"\") #debug \"ne \" #end\n"
         "#if (S = \"abc\") #debug \"eq \" #end\n"
         "#if (\"abc\" < \"abd\") #debug \"lt\" #end\n"
         "#if (\"b\" <= \"a\") #debug \" wrong\" #end\n",
         "ne eq lt");
}

/* shapes.pov calls "Align_Object(Center_Object(...) -y, <0,0,0>)": an
   argument that is a block ends without its comma. */
static void test_directives_block_argument_without_comma(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "#macro Place(O, V) object { O translate V } #end\n"
                        "Place(sphere { 0, 1 } -y)\n");
  assert_int_equal(s->n_objects, 1);
  assert_true(s->objects[0]->transform != NULL);
  /* Numbers still need their commas: "1 -y" is one expression. */
  bad(f, "#macro Two(A, B) #end\nTwo(1 -y)\n", ZR_ESYNTAX,
      "macro 'Two' takes 2 arguments, not 1", NULL);
}

/* ---- values ---- */

static void test_directives_vectors_promote(void **state) {
  fixture *f = *state;
  prints(f,
         "#declare A = <1, 2> + 1;\n"
         "#declare B = <1, 2, 3> + <1, 2>;\n"
         "#declare C = <1, 2, 3, 4> * 2;\n"
         "#declare D = rgb 1 + <0, 0.5, 1>;\n"
         "#debug concat(vstr(2, A, \",\", 0, 0), \" \", "
         "vstr(3, B, \",\", 0, 0), \" \", vstr(4, C, \",\", 0, 0), \" \", "
         "vstr(5, D, \",\", 0, 1), \" \", str(D.green, 0, 1))\n"
         "#debug concat(\" \", str(vlength(x + y), 0, 6), \" \", "
         "vstr(3, vcross(x, y), \",\", 0, 0), \" \", str(vdot(<1,2,3>, "
         "<4,5,6>), 0, 0), \" \", vstr(3, vnormalize(<0, 3, 4>), \",\", "
         "0, 1))\n",
         "2,3 2,4,3 2,4,6,8 1.0,1.5,2.0,0.0,0.0 1.5"
         " 1.414214 0,0,1 32 0.0,0.6,0.8");
  /* POV-Ray's own files leave commas out ("< -1 0 0 >", woods.inc) and
     put one before the '>' (float4.pov); an operator still continues a
     component. */
  prints(f,
         "#declare E = < -1 0 0 >;\n"
         "#declare F = <0.2, 0.1, 0.5,>;\n"
         "#declare G = <1, 2 -1 3>;\n"
         "#debug concat(vstr(3, E, \",\", 0, 0), \" \", "
         "vstr(3, F, \",\", 0, 1), \" \", vstr(3, G, \",\", 0, 0))\n",
         "-1,0,0 0.2,0.1,0.5 1,1,3");
}

static void test_directives_float_values(void **state) {
  fixture *f = *state;
  prints(f,
         "#declare e = exp(1);\n"
         "#macro P(V) #debug concat(str(V, 0, 6), \" \") #end\n"
         "P(abs(-2)) P(acos(0)) P(acosh(2)) P(asin(1)) P(asinh(1)) "
         "P(atan(1)) P(atan2(1, -1)) P(atanh(0.5))\n"
         "P(bitwise_and(12, 10)) P(bitwise_or(12, 10, 1)) "
         "P(bitwise_xor(12, 10))\n"
         "P(ceil(1.2)) P(cos(pi)) P(cosh(1)) P(degrees(pi)) P(div(-7, 2)) "
         "P(exp(1)) P(floor(-1.5)) P(int(-2.5)) P(ln(e)) P(log(1000))\n"
         "P(max(1, 5, 3)) P(min(4, 2, 8)) P(mod(-7, 3)) P(pow(2, 10)) "
         "P(radians(180)) P(select(-1, 1, 2)) P(select(0, 1, 2, 3)) "
         "P(select(1, 1, 2, 3))\n"
         "P(sin(pi / 2)) P(sinh(1)) P(sqrt(2)) P(tan(pi / 4)) P(tanh(1))\n"
         "P(true) P(false) P(on) P(off) P(yes) P(no) P(tau)\n"
         "P((2 < 3) + (3 <= 3) * 10 + (3 >= 4) * 100 + (1 != 1) * 1000)\n"
         "P((1 > 0 ? 7 : 8)) P((0 | 0.5) + (1 & 0))\n",
         "2.000000 1.570796 1.316958 1.570796 0.881374 0.785398 2.356194 "
         "0.549306 "
         "8.000000 15.000000 6.000000 "
         "2.000000 -1.000000 1.543081 180.000000 -3.000000 2.718282 "
         "-2.000000 -2.000000 1.000000 3.000000 "
         "5.000000 2.000000 -1.000000 1024.000000 3.141593 1.000000 "
         "2.000000 3.000000 "
         "1.000000 1.175201 1.414214 1.000000 0.761594 "
         "1.000000 0.000000 1.000000 0.000000 1.000000 0.000000 6.283185 "
         "11.000000 7.000000 1.000000 ");
}

static void test_directives_fast_path_agrees(void **state) {
  fixture *f = *state;
  /* Each expression is evaluated twice: alone after #declare (the fast
     path of fastexpr.c) and inside a vector (the grammar); both must
     print the same, precedence and comparisons included. */
  static const char *const exprs[] = {
      "1 + 2 * 3",         "-2 * -3 - -1",     "(1 + 2) * 3 / 4",
      "10 - 4 - 3",        "2 < 3",            "3 <= 2",
      "1 + 1 = 2",         "0.1 + 0.2 != 0.3", "1 < 2 & 2 < 1",
      "0 | 2 > 1",         "I * I + J / 2",    "-(I - J) * +2",
      "1 & 0 | 1",         "(I >= 3) + (J > 4)",
  };
  char scene[4096] = "#declare I = 3; #declare J = 5;\n";
  for (size_t i = 0; i < sizeof exprs / sizeof exprs[0]; i++) {
    size_t n = strlen(scene);
    snprintf(scene + n, sizeof scene - n,
             "#declare A = %s;\n#declare B = <(%s), 0>;\n"
             "#if (A != B.x) #debug \"%s differs \" #end\n"
             "#debug concat(str(A, 0, 4), \" \")\n",
             exprs[i], exprs[i], exprs[i]);
  }
  prints(f, scene,
         "7.0000 7.0000 2.2500 3.0000 1.0000 0.0000 1.0000 0.0000 0.0000 "
         "1.0000 11.5000 4.0000 1.0000 2.0000 ");
}

static void test_directives_vector_functions(void **state) {
  fixture *f = *state;
  /* vaxis_rotate(x, y, 90) is <0,0,-1> in povray 3.7.0, as is
     vrotate(x, y*90): both turn left-handed. */
  prints(f,
         "#debug concat(vstr(3, vaxis_rotate(x, y, 90), \",\", 0, 3), \" \","
         " vstr(3, vrotate(x, <0, 90, 0>), \",\", 0, 3), \" \", "
         "vstr(3, vrotate(x, z * 90), \",\", 0, 3), \" \", "
         "vstr(3, vaxis_rotate(<1, 1, 0>, x, 90), \",\", 0, 3), \" \", "
         "vstr(3, vrotate(<1, 1, 0>, x * 90), \",\", 0, 3))\n",
         "0.000,0.000,-1.000 0.000,0.000,-1.000 0.000,1.000,0.000 "
         "1.000,0.000,1.000 1.000,0.000,1.000");
}

static void test_directives_inside(void **state) {
  fixture *f = *state;
  /* The same answers as povray 3.7.0 on this scene, inverse unions
     included. */
  prints(f,
         "#declare S = sphere { 0, 1 translate x * 2 }\n"
         "#declare U = union { sphere { 0, 1 } box { <2,2,2>, <3,3,3> } }\n"
         "#declare N = union { sphere { 0, 1 } box { <2,2,2>, <3,3,3> } "
         "inverse }\n"
         "#declare B = box { -1, 1 scale 2 }\n"
         "#debug concat(str(inside(S, <2, 0, 0>), 0, 0), "
         "str(inside(S, 0), 0, 0), str(inside(U, 0), 0, 0), "
         "str(inside(U, 2.5), 0, 0), str(inside(U, 1.5), 0, 0), "
         "str(inside(N, 0), 0, 0), str(inside(N, 1.5), 0, 0), "
         "str(inside(B, <1.5, 1.5, 0>), 0, 0))\n",
         "10110011");
}

static void test_directives_vturbulence(void **state) {
  fixture *f = *state;
  /* zRcube's noise is its own (lib/scene/pattern.c), not POV-Ray's, so
     values differ from povray's; what holds is determinism, the bound
     of one octave (each dnoise component lies in [-1, 1]) and that the
     vector varies over space. */
  prints(f,
         "#declare A = vturbulence(2, 0.5, 6, <0.3, 0.7, 1.1>);\n"
         "#declare B = vturbulence(2, 0.5, 6, <0.3, 0.7, 1.1>);\n"
         "#declare Ok = vlength(A - B) = 0;\n"
         "#declare Varies = 0;\n"
         "#for (I, 0, 20)\n"
         "  #declare V = vturbulence(2, 0.5, 1, <I * 0.37, 0.2, 0.9>);\n"
         "  #if (abs(V.x) > 1 | abs(V.y) > 1 | abs(V.z) > 1) "
         "#declare Ok = 0; #end\n"
         "  #if (vlength(V - A) > 1e-6) #declare Varies = 1; #end\n"
         "#end\n"
         "#debug concat(str(Ok, 0, 0), str(Varies, 0, 0))\n",
         "11");
  bad(f, "#declare V = vturbulence(2, 0.5, 0, x);", ZR_ESCENE,
      "vturbulence: octaves must be from 1 to 10, not 0", NULL);
}

static void test_directives_constants(void **state) {
  fixture *f = *state;
  /* A still image in povray 3.7.0: every clock value is 0; the render
     size defaults to 320x240. */
  prints(f,
         "#debug concat(str(clock, 0, 0), str(clock_delta, 0, 0), "
         "str(clock_on, 0, 0), str(frame_number, 0, 0), "
         "str(initial_clock, 0, 0), str(final_clock, 0, 0), "
         "str(initial_frame, 0, 0), str(final_frame, 0, 0), \" \", "
         "str(image_width, 0, 0), \"x\", str(image_height, 0, 0), \" \", "
         "str(version, 0, 1))\n"
         "#version 3.5;\n"
         "#debug str(version, 0, 1)\n",
         "00000000 320x240 3.73.5");
  assert_int_equal(zr_context_set_render_size(f->ctx, 0, 5), ZR_EINVAL);
  assert_int_equal(zr_context_set_render_size(f->ctx, 640, 480), ZR_OK);
  prints(f, "#debug concat(str(image_width, 0, 0), \"x\", "
            "str(image_height, 0, 0))\n",
         "640x480");
}

static void test_directives_strings(void **state) {
  fixture *f = *state;
  prints(f,
         "#declare S = \"tab\\there \\\"q\\\" back\\\\slash\";\n"
         "#debug concat(S, \"|\", str(strlen(S), 0, 0), \"\\n\")\n"
         "#debug concat(str(123.456, 9, 3), \"|\", str(123.456, -9, 3), "
         "\"|\", str(123.456, 0, 0), \"|\", str(123.456, 0, -1), \"\\n\")\n"
         "#debug concat(substr(\"ABCDEFGHI\", 4, 2), chr(65), "
         "str(asc(\"a\"), 0, 0), strupr(\"MiX\"), strlwr(\"MiX\"), "
         "str(val(\"12.5e1\"), 0, 1), str(strcmp(\"a\", \"b\"), 0, 0), "
         "str(strcmp(\"b\", \"b\"), 0, 0), \"\\n\")\n"
         "#debug concat(vstr(2, <1, 2>, \", \", 0, 1), \"|\", "
         "vstr(5, 1, \", \", 0, 1), \"|\", vstr(3, <1, 2>, \",\", 0, 1), "
         "\"\\n\")\n"
         "#debug concat(\"multi\n"
         "line\", str(file_exists(\"t.pov\"), 0, 0), "
         "str(file_exists(\"nothing.inc\"), 0, 0))\n",
         "tab\there \"q\" back\\slash|23\n"
         "  123.456|00123.456|123|123.456000\n"
         "DEA97MIXmix125.0-10\n"
         "1.0, 2.0|1.0, 1.0, 1.0, 1.0, 1.0|1.0,2.0,0.0\n"
         "multi\nline00");
}

static void test_directives_arrays(void **state) {
  fixture *f = *state;
  prints(f,
         "#declare A = array[2][3] { {1, 2, 3}, {4, 5, 6}, }\n"
         "#declare B = A;\n"
         "#declare A[1][2] = 60;\n"
         "#declare V = array[2];\n"
         "#declare V[0] = <1, 2, 3>;\n"
         "#ifdef (V[1]) #debug \"x\" #else #debug \"unset \" #end\n"
         "#debug concat(str(A[1][2], 0, 0), \" \", str(B[1][2], 0, 0), "
         "\" \", str(dimensions(A), 0, 0), str(dimension_size(A, 1), 0, 0),"
         " str(dimension_size(A, 2), 0, 0), \" \", str(V[0].y, 0, 0), "
         "\" \", str(A[1][0] + A[0][2] * 2, 0, 0))\n"
         "#declare O = array[2] { sphere { 0, 1 }, box { 0, 1 } }\n"
         "object { O[1] }\n",
         "unset 60 6 223 2 10");
  assert_int_equal(f->scene->objects[0]->kind, ZR_OBJ_BOX);
  bad(f, "#declare A = array[3];\n#declare B = A[1];\n", ZR_EUNDEFINED,
      "element of array 'A' used before it was assigned", NULL);
  bad(f, "#declare A = array[3] {1, 2, 3}\n#declare B = A[3];\n",
      ZR_ESCENE, "index 3 of 'A' is out of range 0 to 2", NULL);
  bad(f, "#declare A = array[3] {1, 2}\n", ZR_ESCENE,
      "the array has 3 elements but its initialiser gives 2", NULL);
}

/* A copy of a small array costs its own elements: 20 000 copies of an
   array[4] (a macro's #local Candidate = Haystack[Index] in the corpus'
   tesseract_lattice scenes) took 65 KB each before, 1.3 GB here. */
static void test_directives_small_array_copies(void **state) {
  fixture *f = *state;
  prints(f,
         "#declare Arr = array[8];\n"
         "#for (I, 0, 7) #declare Arr[I] = array[4] {1, 2, 3, I}; #end\n"
         "#declare S = 0;\n"
         "#for (I, 0, 19999)\n"
         "  #local C = Arr[mod(I, 8)];\n"
         "  #declare S = S + C[3];\n"
         "#end\n"
         "#debug str(S, 0, 0)\n",
         "70000");
  assert_true(zr_context_memory_peak(f->ctx) < 64ull << 20);
}

/* Initialiser elements need no commas between them (lemon.inc), as
   povray 3.7 reads them (measured: each line's values are povray's). */
static void test_directives_arrays_without_commas(void **state) {
  fixture *f = *state;
  prints(f,
         "#declare A = array[4] { 1 2, 3 4 }\n"
         "#declare B = array[4] { <1,2> <3,4>, <5,6> < 7,8> }\n"
         "#declare C = array[3] { 1 -2, <1,2>.x (3) }\n"
         "#declare D = array[2][2] { {1 2} {3 4} }\n"
         "#declare E = array[2] { rgb 1 red 0 rgb <0,1,0> }\n"
         "#declare S = array[2] { \"a\" \"b\" }\n"
         "#declare P = array[2] { (1 < 2) (3 > 4) }\n"
         "#debug concat(str(A[3], 0, 0), vstr(2, B[3], \",\", 0, 0), \" \","
         " str(C[0], 0, 0), str(C[1], 0, 0), str(C[2], 0, 0), \" \","
         " str(D[1][0], 0, 0),"
         " \" \", str(E[0].red, 0, 0), str(E[0].green, 0, 0),"
         " str(E[1].red, 0, 0), str(E[1].green, 0, 0), \" \", S[1],"
         " str(P[0], 0, 0), str(P[1], 0, 0))\n",
         "47,8 -113 3 0101 b10");
  /* "<1,2> < 3" is two elements, so the vector is one too many. */
  bad(f, "#declare A = array[1] { <1, 2> < 3, 4> }\n", ZR_ESCENE,
      "the array has 1 elements but its initialiser gives 2", NULL);
  bad(f, "#declare A = array[2] { 1 2 3 }\n", ZR_ESCENE,
      "the array has 2 elements but its initialiser gives 3", NULL);
}

/* vstr writes the first n components of a longer vector or colour, as
   povray 3.7 does (measured). */
static void test_directives_vstr_truncates(void **state) {
  fixture *f = *state;
  prints(f,
         "#declare C = rgb <0.25, 0.5, 1>;\n"
         "#debug concat(vstr(2, <1, 2, 3>, \",\", 0, 1), \" \","
         " vstr(3, C, \",\", 0, 2))\n",
         "1.0,2.0 0.25,0.50,1.00");
}

static void test_directives_rand(void **state) {
  fixture *f = *state;
  /* The same seed gives the same stream, values lie in [0, 1]
     (POV-Ray divides by 2^32 - 1, so 1 itself can come). */
  const char *scene =
      "#declare R = seed(42); #declare Q = seed(42); #declare W = seed(7);\n"
      "#declare Ok = 1; #declare Differ = 0;\n"
      "#for (I, 1, 1000)\n"
      "  #declare A = rand(R); #declare B = rand(Q); #declare C = rand(W);\n"
      "  #if (A != B | A < 0 | A > 1) #declare Ok = 0; #end\n"
      "  #if (A != C) #declare Differ = Differ + 1; #end\n"
      "#end\n"
      "#debug concat(str(Ok, 0, 0), \" \", str(Differ > 990, 0, 0))\n";
  prints(f, scene, "1 1");
}

static void test_directives_messages(void **state) {
  fixture *f = *state;
  prints(f, "#debug \"hello\\n\" #warning concat(\"w\", \"1\")\n",
         "hello\n");
  assert_int_equal(f->diag.warnings, 1);
  assert_string_equal(f->diag.warning,
                      "t.pov:1:18: warning: w1\n"
                      "    1 | #debug \"hello\\n\" #warning concat(\"w\", "
                      "\"1\")\n"
                      "      |                  ^~~~~~~~\n");
  bad(f, "#if (1)\n  #error \"stop here\\n\"\n#end\n", ZR_ESCENE,
      "stop here",
      "t.pov:2:3: error: stop here\n"
      "    2 |   #error \"stop here\\n\"\n"
      "      |   ^~~~~~\n");
  prints(f, "#version 3.7\n#debug \"v\"\n", "v");
  assert_int_equal(f->diag.warnings, 1);
  assert_non_null(strstr(f->diag.warning, "'#version' should end with ';'"));
}

static void test_directives_file_io(void **state) {
  fixture *f = *state;
  /* Written in the working directory (the build tree), read back
     through the default reader, as povray 3.7.0 writes and reads. */
  zr_context_set_reader(f->ctx, NULL, NULL);
  remove("zr_test_fileio.txt");
  prints(f,
         "#fopen F \"zr_test_fileio.txt\" write\n"
         "#write (F, 1, \",\", -123.45, \",\", <1, 2, -3>, \",\", 1/3, "
         "\",\\\"str\\\"\\n\")\n"
         "#fclose F\n"
         "#fopen F \"zr_test_fileio.txt\" append\n"
         "#write (F \", 7\")\n"
         "#fclose F\n"
         "#fopen G \"zr_test_fileio.txt\" read\n"
         "#declare N = 0;\n"
         "#while (defined(G)) #read (G, V) #declare N = N + 1; #end\n"
         "#fopen G \"zr_test_fileio.txt\" read\n"
         "#read (G, A, B, C, D, S)\n"
         "#debug concat(str(N, 0, 0), \" \", str(A, 0, 0), \" \", "
         "str(B, 0, 2), \" \", vstr(3, C, \",\", 0, 0), \" \", "
         "str(D, 0, 6), \" \", S)\n",
         "6 1 -123.45 1,2,-3 0.333333 str");
  FILE *file = fopen("zr_test_fileio.txt", "r");
  assert_non_null(file);
  char line[128] = "";
  assert_non_null(fgets(line, sizeof line, file));
  fclose(file);
  remove("zr_test_fileio.txt");
  assert_string_equal(line, "1,-123.45,<1,2,-3> ,0.333333,\"str\"\n");
  /* The I/O restrictions (tests/test_iopolicy.c has the rest). */
  bad(f, "#fopen F \"/etc/x.txt\" write\n", ZR_EACCESS,
      "'#fopen' cannot open a file for writing: '/etc/x.txt' is outside "
      "the folders a scene may write (the working directory and the write "
      "paths; --write-path=DIR adds one)", NULL);
  assert_int_equal(parse(f, "#fopen F \"../x.txt\" append\n"),
                   ZR_EACCESS);
  assert_non_null(strstr(f->diag.message, "'../x.txt' leads to '"));
  assert_non_null(strstr(f->diag.message, "/x.txt', outside the folders "
                                          "a scene may write"));
  bad(f, "#fopen F \"/etc/passwd\" read\n", ZR_EACCESS,
      "cannot read data file: '/etc/passwd' is outside the folders a "
      "scene may read (the scene's folder, the working directory, the "
      "include paths and the read paths; --read-path=DIR adds one)", NULL);
  bad(f, "#fopen F \"no_such_file.txt\" read\n", ZR_ENOTFOUND,
      "cannot find data file 'no_such_file.txt'", NULL);
}

static void test_directives_default(void **state) {
  fixture *f = *state;
  /* #default affects what follows: the first sphere keeps the default
     finish (ambient 0.1), later objects get the new one. */
  assert_int_equal(parse(f, "sphere { 0, 1 }\n"
                            "#default { finish { ambient 0.3 } "
                            "pigment { rgb <1, 0, 0> } }\n"
                            "sphere { 0, 2 }\n"),
                   ZR_OK);
  const zr_texture *first = f->scene->objects[0]->texture;
  assert_non_null(first);
  assert_near(first->finish->ambient.r, 0.1, 0);
  const zr_texture *now = f->scene->default_texture;
  assert_near(now->finish->ambient.r, 0.3, 0);
  assert_near(now->pigment->colour.r, 1, 0);
  assert_near(now->pigment->colour.g, 0, 0);
}

/* ---- bad input ---- */

static void test_directives_bad_blocks(void **state) {
  fixture *f = *state;
  bad(f, "#declare A = 1;\n#if (A)\nsphere { 0, 1 }\n", ZR_ESYNTAX,
      "'#if' without a matching '#end'",
      "t.pov:2:1: error: '#if' without a matching '#end'\n"
      "    2 | #if (A)\n"
      "      | ^~~\n");
  bad(f, "#if (0) sphere { 0, 1 }\n", ZR_ESYNTAX,
      "'#if' without a matching '#end'", NULL);
  bad(f, "sphere { 0, 1 }\n#end\n", ZR_ESYNTAX,
      "'#end' without a matching '#if', '#while', '#for', '#switch' or "
      "'#macro'", NULL);
  bad(f, "#else\n", ZR_ESYNTAX, "'#else' without a matching '#if'", NULL);
  bad(f, "#break\n", ZR_ESYNTAX,
      "'#break' outside '#switch', '#while', '#for' or a macro", NULL);
  bad(f, "#while (1 sphere { 0, 1 } #end", ZR_ESYNTAX,
      "unexpected 'sphere', expected '<=', '>=', '!=', '?', '|', '&', '<', "
      "'>', '=', '+', '-', '*', '/', ')' or '.'",
      NULL);
  bad(f, "#for (I, 0, 1, 0) #end", ZR_ESCENE,
      "the step of '#for' is zero", NULL);
  bad(f, "#if (<1, 2, 3>) #end", ZR_ESYNTAX,
      "expected a float, got a vector", NULL);
  bad(f, "#switch (1) #case (1) #elseif (1) #end", ZR_ESYNTAX,
      "'#elseif' without a matching '#if'", NULL);
}

static void test_directives_bad_macros(void **state) {
  fixture *f = *state;
  static const vfile files[] = {
      {"m.inc",
       "#macro Use(A)\n"
       "  sphere { 0, Missing }\n"
       "#end\n"},
      {NULL, NULL}};
  f->files = files;
  bad(f, "#include \"m.inc\"\nUse(1)\n", ZR_EUNDEFINED,
      "undefined identifier 'Missing'",
      "m.inc:2:15: error: undefined identifier 'Missing'\n"
      "in macro Use called from t.pov:2:1\n"
      "    2 |   sphere { 0, Missing }\n"
      "      |               ^~~~~~~\n");
  bad(f, "#macro M(A, B) #end\nM(1)\n", ZR_ESYNTAX,
      "macro 'M' takes 2 arguments, not 1", NULL);
  bad(f, "#macro M() #end\nM\n", ZR_ESYNTAX,
      "expected '(' after macro name 'M'", NULL);
  bad(f, "#macro M(A) A\n", ZR_ESYNTAX, "'#macro' without a matching '#end'",
      NULL);
  /* Runaway recursion, as a statement and inside an expression (where
     each call nests a parser), ends in a message, not a crash. */
  bad(f, "#macro R(N) R(N + 1) #end\nR(0)\n", ZR_ELIMIT,
      "macro calls nested more than 128 deep (does 'R' call itself "
      "without end?)",
      NULL);
  bad(f, "#macro R(N) #local X = R(N + 1); X #end\n#declare Y = R(0);\n",
      ZR_ELIMIT,
      "macro calls nested more than 128 deep (does 'R' call itself "
      "without end?)",
      NULL);
  bad(f, "#declare A = 1;\n#declare A = A + \"s\";\n", ZR_ESYNTAX,
      "unexpected string", "t.pov:2:18: error: unexpected string\n"
      "    2 | #declare A = A + \"s\";\n"
      "      |                  ^~~\n");
}

static void test_directives_nesting_limit(void **state) {
  fixture *f = *state;
  /* Each macro argument is a nested parser on the C stack: 500 nested
     calls end in a message, not a stack overflow. */
  char scene[8192] = "#macro M(A) A #end\n#declare X = ";
  for (int i = 0; i < 500; i++)
    strcat(scene, "M(");
  strcat(scene, "1");
  for (int i = 0; i < 500; i++)
    strcat(scene, ")");
  strcat(scene, ";\n");
  bad(f, scene, ZR_ELIMIT,
      "directives and macro calls nest more than 400 levels deep", NULL);
}

static void test_directives_deprecated(void **state) {
  fixture *f = *state;
  /* Declared quietly, warned about when used ("Deprecation Support"),
     once only with "once". */
  prints(f,
         "#declare deprecated Old = 1;\n"
         "#declare deprecated once \"use New\" Older = 2;\n"
         "#declare A = Old + Old + Older + Older;\n"
         "#debug str(A, 0, 0)\n",
         "6");
  assert_int_equal(f->diag.warnings, 3);
  assert_non_null(strstr(f->diag.warning, "warning: use New\n"));
}

int main(void) {
  const struct CMUnitTest tests[] = {
#define T(name) cmocka_unit_test_setup_teardown(name, setup, teardown)
      T(test_directives_declare_and_local),
      T(test_directives_nested_macros_shadow),
      T(test_directives_if_family),
      T(test_directives_switch),
      T(test_directives_while_and_for),
      T(test_directives_while_in_macro_in_include),
      T(test_directives_macros),
      T(test_directives_block_argument_without_comma),
      T(test_directives_small_array_copies),
      T(test_directives_string_comparison),
      T(test_directives_vectors_promote),
      T(test_directives_float_values),
      T(test_directives_fast_path_agrees),
      T(test_directives_vector_functions),
      T(test_directives_inside),
      T(test_directives_vturbulence),
      T(test_directives_constants),
      T(test_directives_strings),
      T(test_directives_arrays),
      T(test_directives_arrays_without_commas),
      T(test_directives_vstr_truncates),
      T(test_directives_rand),
      T(test_directives_messages),
      T(test_directives_file_io),
      T(test_directives_default),
      T(test_directives_bad_blocks),
      T(test_directives_bad_macros),
      T(test_directives_nesting_limit),
      T(test_directives_deprecated),
#undef T
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
