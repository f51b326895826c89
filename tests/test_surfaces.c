/*
 * test_surfaces.c - bicubic_patch, sphere_sweep and julia_fractal, from
 * scene text through the parser (lib/sdl/build_surface.c) to the
 * tracer's crossings, normals, inside tests and bounds
 * (lib/trace/obj_sweep.c, obj_julia.c, and obj_mesh.c for the patch).
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
#include "trace/obj_mesh.h"
#include "trace/obj_sweep.h"
#include "zrcube.h"
#include "parse_fixture.h"
#include "test_util.h"

/* ---- sphere_sweep ---- */

/* Sweep crossings are roots of polynomials in u refined to rounding,
   then square roots of well-scaled quadratics: 1e-9 leaves a margin. */
#define SWEEP_EPS 1e-9

/* Two equal spheres: a capsule, met square to its axis (where the
   envelope's polynomial has only double roots) and along it. */
static void test_surfaces_sweep_capsule(void **state) {
  fixture *f = *state;
  const zr_object *o = only(
      f, "sphere_sweep { linear_spline 2, <-1, 0, 0>, 0.5, <1, 0, 0>, 0.5 "
         "}\n");
  assert_int_equal(o->kind, ZR_OBJ_SPHERE_SWEEP);
  zr_hit h[2];
  assert_int_equal(cross(o, zr_v3(0.3, 5, 0), zr_v3(0, -1, 0), 0.0, h), 2);
  assert_near(h[0].t, 4.5, SWEEP_EPS);
  assert_near(h[1].t, 5.5, SWEEP_EPS);
  assert_vec(h[0].normal, 0, 1, 0, SWEEP_EPS);
  assert_vec(h[1].normal, 0, -1, 0, SWEEP_EPS);
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(2, 0, 0), 0.0, h), 2);
  assert_near(h[0].t, 1.75, SWEEP_EPS);
  assert_near(h[1].t, 3.25, SWEEP_EPS);
  assert_vec(h[0].normal, -1, 0, 0, SWEEP_EPS);
  assert_vec(h[1].normal, 1, 0, 0, SWEEP_EPS);
  /* From inside, only the exit is ahead. */
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 4.0, h), 1);
  assert_near(h[0].t, 6.5, SWEEP_EPS);
  assert_int_equal(cross(o, zr_v3(0, 0.6, -5), zr_v3(0, 0, 1), 0.0, h), 0);
  assert_true(zr__inside(o, zr_v3(0, 0.49, 0)));
  assert_true(zr__inside(o, zr_v3(1.45, 0, 0)));
  assert_false(zr__inside(o, zr_v3(0, 0.51, 0)));
  zr_vec3 lo, hi;
  assert_true(zr__object_bounds(o, &lo, &hi));
  /* The scene pads boxes by a few parts in 1e9. */
  assert_vec(lo, -1.5, -0.5, -0.5, 1e-8);
  assert_vec(hi, 1.5, 0.5, 0.5, 1e-8);
}

/* Radii 1 and 0.5, 3 apart: a cone tangent to both spheres, of half
   angle asin(1/6).  Square to the axis at x = 1.5 its radius is
   4.5 / sqrt(35) and its normal (sin, cos) of that angle. */
static void test_surfaces_sweep_cone(void **state) {
  fixture *f = *state;
  const zr_object *o = only(
      f, "sphere_sweep { linear_spline 2, <0, 0, 0>, 1, <3, 0, 0>, 0.5 "
         "translate <0, 0, 2> }\n");
  zr_hit h[2];
  double rho = 4.5 / sqrt(35.0), s = 1.0 / 6.0, c = sqrt(35.0) / 6.0;
  assert_int_equal(cross(o, zr_v3(1.5, 5, 2), zr_v3(0, -1, 0), 0.0, h), 2);
  assert_near(h[0].t, 5.0 - rho, SWEEP_EPS);
  assert_near(h[1].t, 5.0 + rho, SWEEP_EPS);
  assert_vec(h[0].normal, s, c, 0, SWEEP_EPS);
  assert_vec(h[1].normal, s, -c, 0, SWEEP_EPS);
  /* Beyond the small end's cap, along the axis. */
  assert_int_equal(cross(o, zr_v3(10, 0, 2), zr_v3(-1, 0, 0), 0.0, h), 2);
  assert_near(h[0].t, 6.5, SWEEP_EPS);
  assert_near(h[1].t, 11.0, SWEEP_EPS);
}

/* Evenly spaced points on a line make both cubic splines move the ball
   along it at constant speed: the middle piece is a capsule from 0 to
   1. */
static void test_surfaces_sweep_cubic_splines_on_a_line(void **state) {
  fixture *f = *state;
  const char *const kinds[2] = {"b_spline", "cubic_spline"};
  for (int k = 0; k < 2; k++) {
    char text[256];
    snprintf(text, sizeof text,
             "sphere_sweep { %s 4, <-1, 0, 0>, 0.5, <0, 0, 0>, 0.5,\n"
             "  <1, 0, 0>, 0.5, <2, 0, 0>, 0.5 tolerance 1e-4 }\n",
             kinds[k]);
    const zr_object *o = only(f, text);
    assert_int_equal(o->u.sweep.data->n_segments, 1);
    zr_hit h[2];
    assert_int_equal(cross(o, zr_v3(0.5, 5, 0), zr_v3(0, -1, 0), 0.0, h),
                     2);
    assert_near(h[0].t, 4.5, SWEEP_EPS);
    assert_vec(h[0].normal, 0, 1, 0, SWEEP_EPS);
    assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0.0, h), 2);
    assert_near(h[0].t, 4.5, SWEEP_EPS);
    assert_near(h[1].t, 6.5, SWEEP_EPS);
    assert_false(zr__inside(o, zr_v3(-0.6, 0, 0)));
    assert_true(zr__inside(o, zr_v3(1.4, 0, 0)));
  }
}

/* The entry of a ray into the balls of a piece, by brute force over u:
   the reference for a curved piece. */
static double brute_entry(const zr_sweep_segment *g, zr_vec3 o,
                          zr_vec3 d) {
  double best = INFINITY;
  for (int i = 0; i <= 200000; i++) {
    double u = i / 200000.0;
    zr_vec3 c = zr_v3_madd(zr_v3_madd(zr_v3_madd(g->c[0], g->c[1], u),
                                      g->c[2], u * u),
                           g->c[3], u * u * u);
    double r = g->r[0] + u * (g->r[1] + u * (g->r[2] + u * g->r[3]));
    zr_vec3 oc = zr_v3_sub(c, o);
    double b = zr_v3_dot(d, oc), hh = b * b - zr_v3_dot(oc, oc) + r * r;
    if (hh > 0.0)
      best = fmin(best, b - sqrt(hh));
  }
  return best;
}

/* A b_spline wave with a changing radius: the first crossing of rays
   square to its plane and slanted matches the brute-force entry (whose
   sampling error is below 1e-8 here). */
static void test_surfaces_sweep_curved_piece(void **state) {
  fixture *f = *state;
  const zr_object *o =
      only(f, "sphere_sweep { b_spline 4, <0, 0, 0>, 0.2, <1, 2, 0>, 0.4,\n"
              "  <2, -2, 0>, 0.4, <3, 0, 0>, 0.2 }\n");
  const zr_sweep_segment *g = &o->u.sweep.data->segments[0];
  zr_vec3 dirs[3] = {zr_v3(0, 0, 1), zr_v3(0.3, 0.2, 1),
                     zr_v3(-0.5, 0.1, 0.8)};
  for (int k = 0; k < 3; k++) {
    zr_vec3 d = zr_v3_norm(dirs[k]);
    for (double x = 1.0; x <= 2.0; x += 0.25) {
      zr_vec3 org = zr_v3_madd(zr_v3(x, 0.1, 0), d, -5.0);
      zr_hit h[2];
      double ref = brute_entry(g, org, d);
      int n = cross(o, org, d, 0.0, h);
      if (ref == INFINITY) {
        assert_int_equal(n, 0);
        continue;
      }
      assert_true(n >= 1);
      assert_near(h[0].t, ref, 1e-7);
      /* The normal points out of the ball the crossing is on. */
      assert_true(zr_v3_dot(h[0].normal, d) < 0.0);
    }
  }
}

static void test_surfaces_sweep_bad_input(void **state) {
  fixture *f = *state;
  bad(f, "sphere_sweep { linear_spline 1, <0, 0, 0>, 1 }\n", ZR_ESCENE,
      "a linear_spline sphere_sweep needs at least 2 spheres, not 1",
      "t.pov:1:30: error: a linear_spline sphere_sweep needs at least 2 "
      "spheres, not 1\n"
      "    1 | sphere_sweep { linear_spline 1, <0, 0, 0>, 1 }\n"
      "      |                              ^\n");
  bad(f, "sphere_sweep { b_spline 3, 0, 1, <1, 0, 0>, 1, <2, 0, 0>, 1 }\n",
      ZR_ESCENE, "a b_spline sphere_sweep needs at least 4 spheres, not 3",
      NULL);
  bad(f, "sphere_sweep { linear_spline 2, <0, 0, 0>, 1, <1, 0, 0> }\n",
      ZR_ESCENE, "the sphere_sweep has only 1 of the 2 spheres it announced "
                 "(the last has no radius)", NULL);
  bad(f, "sphere_sweep { linear_spline 2, 0, 1, x, 1, y, 1 }\n", ZR_ESCENE,
      "the sphere_sweep has more spheres than the 2 it announced", NULL);
}

/* ---- bicubic_patch ---- */

#define MANUAL_PATCH                                                       \
  "  <0, 0, 2>, <1, 0, 0>, <2, 0, 0>, <3, 0, -2>,\n"                      \
  "  <0, 1, 0>, <1, 1, 0>, <2, 1, 0>, <3, 1, 0>,\n"                       \
  "  <0, 2, 0>, <1, 2, 0>, <2, 2, 0>, <3, 2, 0>,\n"                       \
  "  <0, 3, 2>, <1, 3, 0>, <2, 3, 0>, <3, 3, -2>\n"

/* A patch whose control net is a flat grid is the square it spans. */
static void test_surfaces_patch_flat(void **state) {
  fixture *f = *state;
  const zr_object *o = only(
      f, "bicubic_patch { type 1 u_steps 2 v_steps 2\n"
         "  <0,0,0> <1,0,0> <2,0,0> <3,0,0> <0,1,0> <1,1,0> <2,1,0> <3,1,0>\n"
         "  <0,2,0> <1,2,0> <2,2,0> <3,2,0> <0,3,0> <1,3,0> <2,3,0> <3,3,0>\n"
         "  rotate x * -90 }\n");
  assert_int_equal(o->kind, ZR_OBJ_MESH);
  assert_int_equal(o->u.mesh.data->n_faces, 32);
  zr_hit h[2];
  /* Rotated into the x-z plane: (x, y, 0) goes to (x, 0, -y). */
  assert_int_equal(cross(o, zr_v3(1.3, 5, -2.1), zr_v3(0, -1, 0), 0.0, h),
                   1);
  assert_near(h[0].t, 5.0, 1e-12);
  assert_near(fabs(h[0].normal.y), 1.0, 1e-12);
  assert_int_equal(cross(o, zr_v3(3.5, 5, 1), zr_v3(0, -1, 0), 0.0, h), 0);
  assert_false(zr__inside(o, zr_v3(1, 0, 1)));
}

/* The Bezier point and normal of the manual's patch at (u, v), for the
   expected values. */
static void manual_value(double u, double v, zr_vec3 *p, zr_vec3 *n) {
  static const double z[4][4] = {
      {2, 0, 0, -2}, {0, 0, 0, 0}, {0, 0, 0, 0}, {2, 0, 0, -2}};
  double bu[4] = {(1 - u) * (1 - u) * (1 - u), 3 * u * (1 - u) * (1 - u),
                  3 * u * u * (1 - u), u * u * u};
  double bv[4] = {(1 - v) * (1 - v) * (1 - v), 3 * v * (1 - v) * (1 - v),
                  3 * v * v * (1 - v), v * v * v};
  /* Row i is y = i, column j is x = j: x = 3 v, y = 3 u. */
  double zz = 0, zu = 0, zv = 0, h = 1e-6;
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 4; j++)
      zz += z[i][j] * bu[i] * bv[j];
  for (int s = -1; s <= 1; s += 2) {
    double uu = u + s * h, vv = v + s * h;
    double au[4] = {(1 - uu) * (1 - uu) * (1 - uu),
                    3 * uu * (1 - uu) * (1 - uu), 3 * uu * uu * (1 - uu),
                    uu * uu * uu};
    double av[4] = {(1 - vv) * (1 - vv) * (1 - vv),
                    3 * vv * (1 - vv) * (1 - vv), 3 * vv * vv * (1 - vv),
                    vv * vv * vv};
    for (int i = 0; i < 4; i++)
      for (int j = 0; j < 4; j++) {
        zu += s * z[i][j] * au[i] * bv[j] / (2 * h);
        zv += s * z[i][j] * bu[i] * av[j] / (2 * h);
      }
  }
  *p = zr_v3(3 * v, 3 * u, zz);
  /* Tangents (0, 3, zu) and (3, 0, zv); their cross product. */
  *n = zr_v3_norm(zr_v3(3 * zv, 3 * zu, -9));
}

/* The manual's patch: at a corner of the pieces the crossing is the
   Bezier point and the normal the exact one; the number of pieces is
   the manual's 2^u_steps * 2^v_steps, two triangles each (u_steps 3
   v_steps 3: "128 smooth triangles"), unless flatness stops the
   splitting. */
static void test_surfaces_patch_manual(void **state) {
  fixture *f = *state;
  const zr_object *o =
      only(f, "bicubic_patch { type 0 u_steps 3 v_steps 3\n" MANUAL_PATCH
              "}\n");
  assert_int_equal(o->u.mesh.data->n_faces, 128);
  zr_vec3 p, n;
  manual_value(0.375, 0.625, &p, &n);
  zr_hit h[2];
  zr_vec3 org = zr_v3_madd(p, n, -4.0);
  /* The patch curls back: the ray may meet it again further on. */
  assert_true(cross(o, org, n, 0.0, h) >= 1);
  assert_near(h[0].t, 4.0, 1e-9);
  double along = fabs(zr_v3_dot(h[0].normal, n));
  assert_near(along, 1.0, 1e-6);
  o = only(f, "bicubic_patch { type 1 u_steps 3 v_steps 1\n" MANUAL_PATCH
              "}\n");
  assert_int_equal(o->u.mesh.data->n_faces, 32);
  /* The patch's size (its control points' box diagonal) is sqrt 34 and
     the control points furthest from its corners' plane, P5, P8, P9
     and P12, are 1.2 from it: flatness 20 * 1.2 / sqrt 34 = 4.116
     (the tolerance is flatness / 20 of the size). */
  o = only(f, "bicubic_patch { type 1 flatness 4.12 u_steps 3 v_steps 3\n"
              MANUAL_PATCH "}\n");
  assert_int_equal(o->u.mesh.data->n_faces, 2);
  o = only(f, "bicubic_patch { type 1 flatness 4.11 u_steps 3 v_steps 3\n"
              MANUAL_PATCH "}\n");
  assert_true(o->u.mesh.data->n_faces > 2);
}

/* POV-Ray 3.7's flatness is relative (measured: the manual's patch
   with its control points times 10 renders the same at each flatness),
   so the same patch ten times larger is cut into the same pieces. */
static void test_surfaces_patch_flatness_is_relative(void **state) {
  fixture *f = *state;
  const zr_object *o = only(
      f, "bicubic_patch { type 1 flatness 0.1 u_steps 8 v_steps 8\n"
         MANUAL_PATCH "}\n");
  size_t small = o->u.mesh.data->n_faces;
  /* More than one piece, fewer than the 2^16 u_steps 8 v_steps 8
     would make: flatness decided. */
  assert_true(small > 2 && small < 2 * 65536);
  o = only(f, "bicubic_patch { type 1 flatness 0.1 u_steps 8 v_steps 8\n"
              "  <0, 0, 20>, <10, 0, 0>, <20, 0, 0>, <30, 0, -20>,\n"
              "  <0, 10, 0>, <10, 10, 0>, <20, 10, 0>, <30, 10, 0>,\n"
              "  <0, 20, 0>, <10, 20, 0>, <20, 20, 0>, <30, 20, 0>,\n"
              "  <0, 30, 20>, <10, 30, 0>, <20, 30, 0>, <30, 30, -20> }\n");
  assert_int_equal(o->u.mesh.data->n_faces, small);
}

/* One bilinear piece (u_steps 0, v_steps 0: the manual's minimum of
   one piece) whose corner at control point 16 is raised by 2.  The
   piece is cut along the diagonal from point 1 to point 16, as POV-Ray
   3.7 cuts it (its renders of uniform subdivisions are ours to the
   pixel only so; see piece() in lib/sdl/build_surface.c): a ray just
   below that diagonal meets the triangle (P1, P4, P16), z = 2 y / 3,
   and one beyond it (P1, P16, P13), z = 2 x / 3. */
static void test_surfaces_patch_diagonal(void **state) {
  fixture *f = *state;
  const zr_object *o = only(
      f, "bicubic_patch { type 1 u_steps 0 v_steps 0\n"
         "  <0,0,0> <1,0,0> <2,0,0> <3,0,0>\n"
         "  <0,1,0> <1,1,0.222222222222> <2,1,0.444444444444> "
         "<3,1,0.666666666667>\n"
         "  <0,2,0> <1,2,0.444444444444> <2,2,0.888888888889> "
         "<3,2,1.333333333333>\n"
         "  <0,3,0> <1,3,0.666666666667> <2,3,1.333333333333> <3,3,2> }\n");
  assert_int_equal(o->u.mesh.data->n_faces, 2);
  zr_hit h[2];
  assert_int_equal(cross(o, zr_v3(1.5, 1.49, 5), zr_v3(0, 0, -1), 0.0, h),
                   1);
  assert_near(h[0].t, 5.0 - 2.0 * 1.49 / 3.0, 1e-9);
  assert_int_equal(cross(o, zr_v3(0.5, 2.5, 5), zr_v3(0, 0, -1), 0.0, h),
                   1);
  assert_near(h[0].t, 5.0 - 1.0 / 3.0, 1e-9);
}

/* A patch whose first row of control points is one point: the edge
   u = 0 collapses to a tip, where the tangent along v vanishes and the
   patch has no normal.  There POV-Ray 3.7 shades with <1, 0, 0>
   (measured: see patch_value in lib/sdl/build_surface.c), not with the
   flat patch's own <0, 0, +-1>. */
static void test_surfaces_patch_collapsed_edge(void **state) {
  fixture *f = *state;
  const zr_object *o = only(
      f, "bicubic_patch { type 1 u_steps 2 v_steps 2\n"
         "  <0,0,0> <0,0,0> <0,0,0> <0,0,0>\n"
         "  <-1,1,0> <-0.3,1,0> <0.3,1,0> <1,1,0>\n"
         "  <-2,2,0> <-0.7,2,0> <0.7,2,0> <2,2,0>\n"
         "  <-3,3,0> <-1,3,0> <1,3,0> <3,3,0> }\n");
  const struct zr_mesh *m = o->u.mesh.data;
  int tips = 0;
  for (size_t k = 0; k < m->n_vertices; k++) {
    if (zr_v3_len(m->vertices[k]) > 1e-12)
      continue;
    tips++;
    assert_vec(m->normals[k], 1, 0, 0, 0.0);
  }
  assert_true(tips >= 1);
}

static void test_surfaces_patch_bad_input(void **state) {
  fixture *f = *state;
  bad(f, "bicubic_patch { u_steps 3\n" MANUAL_PATCH "}\n", ZR_ESCENE,
      "the bicubic_patch has no type (type 0 or type 1)", NULL);
  bad(f, "bicubic_patch { type 1 <0,0,0> <1,0,0> }\n", ZR_ESCENE,
      "a bicubic_patch needs 16 control points, not 2", NULL);
  bad(f, "bicubic_patch { type 1\n" MANUAL_PATCH " <1, 1, 1> }\n",
      ZR_ESCENE, "a bicubic_patch has 16 control points, not more", NULL);
  bad(f, "bicubic_patch { type 1 u_steps 11\n" MANUAL_PATCH "}\n",
      ZR_ESCENE, "u_steps must be from 0 to 10, not 11", NULL);
  bad(f, "bicubic_patch { type -1\n" MANUAL_PATCH "}\n", ZR_ESCENE,
      "Undefined bicubic patch type -1 (type 0 or 1)", NULL);
  bad(f, "bicubic_patch { type 1\n" MANUAL_PATCH " flatness 0.1 }\n",
      ZR_ESYNTAX, "a bicubic_patch's type, flatness, u_steps, v_steps and "
                  "uv_vectors come before its points",
      "t.pov:6:11: error: a bicubic_patch's type, flatness, u_steps, "
      "v_steps and uv_vectors come before its points\n"
      "    6 |  flatness 0.1 }\n"
      "      |           ^~~\n");
  good(f, "bicubic_patch { type 3 uv_vectors <0,0>,<1,0>,<1,1>,<0,1>\n"
          MANUAL_PATCH "}\n");
  assert_int_equal(f->diag.warnings, 1);
  assert_non_null(strstr(f->diag.warning,
                         "Patch type no longer supported. Using type 1."));
}

/* ---- julia_fractal ---- */

/* With p = 0 the quaternion and the hypercomplex square and cube keep
   the points of the unit ball (|h| < 1) and let the others escape, the
   bisection stops within 1e-7 of the radius and reports the inside
   end; 2e-7 covers it.  The hypercomplex set is where both complex
   parts (obj_julia.c, bicomplex) are within 1; on the x axis they are
   |x|, and escape past the radius 4 takes longer there (1e-5). */
static void test_surfaces_julia_unit_ball(void **state) {
  fixture *f = *state;
  const char *const kinds[3] = {"quaternion sqr", "quaternion cube",
                                "hypercomplex sqr"};
  for (int k = 0; k < 3; k++) {
    char text[128];
    snprintf(text, sizeof text,
             "julia_fractal { <0, 0, 0, 0> %s max_iteration 20 }\n",
             kinds[k]);
    const zr_object *o = only(f, text);
    assert_int_equal(o->kind, ZR_OBJ_JULIA);
    double eps = k == 2 ? 1e-5 : 2e-7;
    zr_hit h[2];
    assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0.0, h), 2);
    assert_near(h[0].t, 4.0, eps);
    assert_near(h[1].t, 6.0, eps);
    assert_vec(h[0].normal, -1, 0, 0, 1e-6);
    assert_vec(h[1].normal, 1, 0, 0, 1e-6);
    /* The nearest crossing alone, as the tracer asks for it, with and
       without its normal: the same t to the last bit (the march's
       points do not depend on what is asked), then the exit alone
       from just past the entry. */
    zr_ray ray = {zr_v3(-5, 0, 0), zr_v3(1, 0, 0)};
    zr_hit g[2];
    assert_int_equal(zr__intersect_first(o, &ray, 0.0, INFINITY, false, g),
                     1);
    assert_true(g[0].t == h[0].t);
    assert_int_equal(zr__intersect_first(o, &ray, 0.0, INFINITY, true, g),
                     1);
    assert_true(g[0].t == h[0].t);
    assert_vec(g[0].normal, -1, 0, 0, 1e-6);
    assert_int_equal(
        zr__intersect_first(o, &ray, h[0].t + 1e-3, INFINITY, true, g), 1);
    assert_true(g[0].t == h[1].t);
    assert_vec(g[0].normal, 1, 0, 0, 1e-6);
    assert_true(zr__inside(o, zr_v3(0.5, 0.2, 0.1)));
    assert_false(zr__inside(o, zr_v3(0.9, 0.9, 0)));
  }
}

/* slice <0, 0, 1, 1>, 0 maps (x, y, z) to (x, y, z, -z): on the z axis
   |h| = sqrt(2) |z|, so the unit ball's surface is at z = -1 / sqrt(2).
   A transform moves the fractal as any object. */
static void test_surfaces_julia_slice_and_transform(void **state) {
  fixture *f = *state;
  const zr_object *o =
      only(f, "julia_fractal { <0, 0, 0, 0> slice <0, 0, 1, 1>, 0 "
              "precision 50 scale 2 translate <1, 0, 0> }\n");
  zr_hit h[2];
  assert_int_equal(cross(o, zr_v3(1, 0, -5), zr_v3(0, 0, 1), 0.0, h), 2);
  assert_near(h[0].t, 5.0 - sqrt(2.0), 1e-6);
  assert_vec(h[0].normal, 0, 0, -1, 1e-6);
  assert_true(zr__inside(o, zr_v3(2.9, 0, 0)));
  assert_false(zr__inside(o, zr_v3(1, 0, 1.5)));
  zr_vec3 lo, hi;
  assert_true(zr__object_bounds(o, &lo, &hi));
  assert_true(lo.x <= -1.0 && hi.x >= 3.0);
}

/* Hypercomplex 1/h with p = 0 swaps |h| and 1/|h| on the x axis, so
   the points escape beyond the radius 4 or within 1/4 of the origin:
   the ray meets the hole's edges at x = -1/4 and 1/4 (it starts inside,
   at the bounding sphere, where POV-Ray reports no crossing either). */
static void test_surfaces_julia_hypercomplex_functions(void **state) {
  fixture *f = *state;
  const zr_object *o = only(
      f, "julia_fractal { <0, 0, 0, 0> hypercomplex reciprocal "
         "max_iteration 6 precision 100 }\n");
  zr_hit h[2];
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0.0, h), 2);
  assert_near(h[0].t, 4.75, 1e-6);
  assert_near(h[1].t, 5.25, 1e-6);
  assert_true(zr__inside(o, zr_v3(1, 0, 0)));
  assert_false(zr__inside(o, zr_v3(0.2, 0, 0)));
  const char *const functions[] = {"exp", "ln", "sin", "asin", "cos",
                                   "acos", "tan", "atan", "sinh", "asinh",
                                   "cosh", "acosh", "tanh", "atanh",
                                   "pwr(2, 0.5)"};
  for (size_t k = 0; k < sizeof functions / sizeof functions[0]; k++) {
    char text[128];
    snprintf(text, sizeof text,
             "julia_fractal { <0.2, 0, 0, 0> %s hypercomplex }\n",
             functions[k]);
    o = only(f, text);
    assert_int_equal(o->u.julia.data->function,
                     ZR_JULIA_EXP + (zr_julia_function)k);
  }
  assert_near(o->u.julia.data->exponent[0], 2.0, 0.0);
  assert_near(o->u.julia.data->exponent[1], 0.5, 0.0);
}

/* The escape radius R = min(1 + |p|, 2) for quaternions, as measured
   (bench/julia_probe.sh, q2_p0.5 and q2_p1.5): with max_iteration 2 the
   object is |h^2 + p| <= R, so on the x axis x^2 + p = R and on the y
   axis y^2 - p = R.  Bisection stops within 1e-7 of the radius: 2e-7. */
static void test_surfaces_julia_escape_radius(void **state) {
  fixture *f = *state;
  const zr_object *o = only(
      f, "julia_fractal { <0.5, 0, 0, 0> max_iteration 2 precision 100 }\n");
  zr_hit h[2];
  assert_true(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0.0, h) >= 1);
  assert_near(h[0].t, 5.0 - 1.0, 2e-7);
  assert_true(cross(o, zr_v3(0, -5, 0), zr_v3(0, 1, 0), 0.0, h) >= 1);
  assert_near(h[0].t, 5.0 - sqrt(2.0), 2e-7);
  o = only(f, "julia_fractal { <1.5, 0, 0, 0> max_iteration 2 "
              "precision 100 }\n");
  assert_true(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0.0, h) >= 1);
  assert_near(h[0].t, 5.0 - sqrt(0.5), 2e-7);
  assert_true(cross(o, zr_v3(0, -5, 0), zr_v3(0, 1, 0), 0.0, h) >= 1);
  assert_near(h[0].t, 5.0 - sqrt(3.5), 2e-7);
  /* One iteration keeps the whole ball, which fills the bounding
     sphere: POV-Ray shows no surface (julia_probe.sh, q1_*). */
  o = only(f, "julia_fractal { <0.5, 0, 0, 0> max_iteration 1 }\n");
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0.0, h), 0);
  assert_true(zr__inside(o, zr_v3(1.4, 0, 0)));
  assert_false(zr__inside(o, zr_v3(1.6, 0, 0)));
}

/* The hypercomplex algebra: ij = ji = k and kk = +1 (see obj_julia.c),
   escape radius 4, max_iteration 2, p = 0.  In the y-z plane
   h = yi + zj squares to -(y^2 + z^2) + 2yz k, so on the diagonal
   y = z the surface is at 8 y^4 = 16 (non-commuting quaternions would
   give 4 y^4 = 16).  At w = 0.5, h = x + 0.5k squares to x^2 + 0.25 +
   xk, so (x^2 + 0.25)^2 + x^2 = 16, x^2 = (sqrt(66) - 1.5) / 2 (kk = -1
   would give (x^2 - 0.25)^2 + x^2 = 16); POV-Ray: x = -1.819895
   (julia_probe.sh, h2_w05). */
static void test_surfaces_julia_hypercomplex_algebra(void **state) {
  fixture *f = *state;
  const zr_object *o = only(
      f, "julia_fractal { <0, 0, 0, 0> hypercomplex max_iteration 2 "
         "precision 100 }\n");
  zr_hit h[2];
  zr_vec3 d = zr_v3(0, 1 / sqrt(2.0), 1 / sqrt(2.0));
  assert_true(cross(o, zr_v3_scale(d, -5), d, 0.0, h) >= 1);
  assert_near(h[0].t, 5.0 - sqrt(2.0) * pow(2.0, 0.25), 1e-6);
  o = only(f, "julia_fractal { <0, 0, 0, 0> hypercomplex max_iteration 2 "
              "precision 100 slice <0, 0, 0, 1>, 0.5 }\n");
  assert_true(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0.0, h) >= 1);
  double x = sqrt((sqrt(66.0) - 1.5) / 2.0);
  assert_near(x, 1.819895, 1e-6);
  assert_near(h[0].t, 5.0 - x, 1e-6);
}

static void test_surfaces_julia_bad_input(void **state) {
  fixture *f = *state;
  bad(f, "julia_fractal { <0, 0, 0, 0> sin max_iteration 9 }\n",
      ZR_ESCENE, "Illegal function: quaternion only supports sqr and cube",
      "t.pov:1:30: error: Illegal function: quaternion only supports sqr "
      "and cube\n"
      "    1 | julia_fractal { <0, 0, 0, 0> sin max_iteration 9 }\n"
      "      |                              ^~~\n");
  bad(f, "julia_fractal { <0, 0, 0, 0> slice <1, 0, 0, 0>, 0 }\n",
      ZR_ESCENE, "the slice's normal must not be zero, nor its fourth "
                 "component", NULL);
  bad(f, "julia_fractal { <0, 0, 0, 0> max_iteration 0 }\n", ZR_ESCENE,
      "max_iteration must be from 1 to 1000000, not 0", NULL);
}

#define TEST(fn) cmocka_unit_test_setup_teardown(fn, setup, teardown)

int main(void) {
  const struct CMUnitTest tests[] = {
      TEST(test_surfaces_sweep_capsule),
      TEST(test_surfaces_sweep_cone),
      TEST(test_surfaces_sweep_cubic_splines_on_a_line),
      TEST(test_surfaces_sweep_curved_piece),
      TEST(test_surfaces_sweep_bad_input),
      TEST(test_surfaces_patch_flat),
      TEST(test_surfaces_patch_manual),
      TEST(test_surfaces_patch_diagonal),
      TEST(test_surfaces_patch_flatness_is_relative),
      TEST(test_surfaces_patch_collapsed_edge),
      TEST(test_surfaces_patch_bad_input),
      TEST(test_surfaces_julia_unit_ball),
      TEST(test_surfaces_julia_slice_and_transform),
      TEST(test_surfaces_julia_hypercomplex_functions),
      TEST(test_surfaces_julia_escape_radius),
      TEST(test_surfaces_julia_hypercomplex_algebra),
      TEST(test_surfaces_julia_bad_input),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
