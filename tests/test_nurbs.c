/*
 * test_nurbs.c - rational B-splines and the exact parametric surfaces
 * built on them (lib/radiosity/nurbs.c, surface.c).
 *
 * Every surface is checked against its implicit equation and gradient at
 * many (u,v) samples, edges and poles included, and its area element is
 * integrated against the analytic area, with and without transforms.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "core/context.h"
#include "core/transform.h"
#include "radiosity/nurbs.h"
#include "radiosity/quadrature.h"
#include "radiosity/surface.h"

/* Points and normals: exact conics evaluated in double precision lie on
   their surface to ~1e-15 relative; 1e-9 is the brief's bound. */
#define GEOM_EPS 1e-9
/* Areas by Gauss quadrature on knot-aligned cells: the brief's 1e-6. */
#define AREA_EPS 1e-6
/* The sample grid, edges included, so poles, seams and apexes count. */
#define GRID 41

static void assert_abs(double got, double want, double tol) {
  if (!(fabs(got - want) <= tol))
    fail_msg("got %.15g, want %.15g (tolerance %g)", got, want, tol);
}

static void assert_vec_close(zr_vec3 a, zr_vec3 b, double tol) {
  if (!(zr_v3_len(zr_v3_sub(a, b)) <= tol))
    fail_msg("got <%.15g, %.15g, %.15g>, want <%.15g, %.15g, %.15g>", a.x,
             a.y, a.z, b.x, b.y, b.z);
}

/* Area with 8 x 8 cells (multiples of the 4 x 2 knot spans) of an
   8-point rule: each cell's integrand is a smooth rational function. */
static double area(const zr__surface *s) {
  zr__gauss_rule g;
  assert_int_equal(zr__gauss_rule_init(&g, 8), ZR_OK);
  return zr__surface_area(s, 0, 1, 0, 1, 8, &g);
}

/* A transform with rotation, non-uniform scale and translation. */
static void skew_transform(zr_transform *t, zr_vec3 scale) {
  zr__transform_identity(t);
  zr__transform_rotate(t, zr_v3(10, 20, 30));
  zr__transform_scale(t, scale);
  zr__transform_rotate(t, zr_v3(-35, 5, 60));
  zr__transform_translate(t, zr_v3(1, -2, 3));
}

/* ---- basis functions ---- */

static void test_nurbs_basis_partition_and_derivative(void **state) {
  (void)state;
  const double knots[] = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
  for (int k = 0; k <= 200; k++) {
    double t = k / 200.0;
    int span = zr__nurbs_find_span(9, 2, knots, t);
    assert_true(knots[span] <= t && (t < knots[span + 1] || t == 1.0));
    double n[3], dn[3];
    zr__nurbs_basis(span, t, 2, knots, n, dn);
    /* Partition of unity and its derivative, exact up to rounding. */
    assert_abs(n[0] + n[1] + n[2], 1.0, 1e-15);
    assert_abs(dn[0] + dn[1] + dn[2], 0.0, 1e-12);
    for (int j = 0; j < 3; j++)
      assert_true(n[j] >= 0.0);
    /* The derivative against a central difference inside the span:
       the error of the difference is h^2 N''' / 6 = 0 for quadratics,
       so only rounding (1e-16 / h = 1e-10) remains. */
    double h = 1e-6;
    if (t - h > knots[span] && t + h < knots[span + 1]) {
      double np[3], nm[3], d[3];
      zr__nurbs_basis(span, t + h, 2, knots, np, d);
      zr__nurbs_basis(span, t - h, 2, knots, nm, d);
      for (int j = 0; j < 3; j++)
        assert_abs(dn[j], (np[j] - nm[j]) / (2 * h), 1e-8);
    }
  }
}

static void test_nurbs_derivatives_match_differences(void **state) {
  (void)state;
  /* The quotient rule for S_u, S_v and S_uv of a rational surface
     against central differences (error O(h^2) ~ 1e-8 for h = 1e-4). */
  zr__nurbs_profile prof;
  zr__nurbs s;
  zr__nurbs_profile_half_circle(&prof, 1.5);
  zr__nurbs_revolve(&s, &prof);
  const double uv[3][2] = {{0.1, 0.2}, {0.6, 0.3}, {0.9, 0.85}};
  double h = 1e-4;
  for (int k = 0; k < 3; k++) {
    double u = uv[k][0], v = uv[k][1];
    zr__nurbs_derivs d, a, b, c, e;
    zr__nurbs_eval(&s, u, v, &d);
    zr__nurbs_eval(&s, u + h, v, &a);
    zr__nurbs_eval(&s, u - h, v, &b);
    assert_vec_close(d.su, zr_v3_scale(zr_v3_sub(a.s, b.s), 0.5 / h), 1e-6);
    zr__nurbs_eval(&s, u, v + h, &c);
    zr__nurbs_eval(&s, u, v - h, &e);
    assert_vec_close(d.sv, zr_v3_scale(zr_v3_sub(c.s, e.s), 0.5 / h), 1e-6);
    assert_vec_close(d.suv, zr_v3_scale(zr_v3_sub(c.su, e.su), 0.5 / h),
                     1e-6);
  }
}

/* ---- spheres ---- */

/* Checks points and normals of a sphere (centre c, radius r) seen
   through transform t (NULL: none) on the sample grid. */
static void check_sphere(const zr__surface *s, zr_vec3 c, double r,
                         const zr_transform *t) {
  for (int i = 0; i < GRID; i++) {
    for (int j = 0; j < GRID; j++) {
      zr__surface_point pt;
      zr__surface_eval(s, (double)i / (GRID - 1), (double)j / (GRID - 1),
                       &pt);
      zr_vec3 q = t ? zr__xform_point(t->inv, pt.p) : pt.p;
      zr_vec3 d = zr_v3_sub(q, c);
      assert_abs(zr_v3_len(d), r, GEOM_EPS);
      /* The implicit gradient, taken to world space as a normal. */
      zr_vec3 grad = t ? zr__xform_normal(t->inv, d) : d;
      assert_vec_close(pt.n, zr_v3_norm(grad), GEOM_EPS);
      assert_true(pt.da >= 0.0);
    }
  }
}

static void test_nurbs_sphere_on_implicit_surface(void **state) {
  (void)state;
  zr__surface s;
  zr_vec3 c = zr_v3(0.5, -1, 2);
  assert_int_equal(zr__surface_sphere(&s, c, 1.7, NULL, NULL, NULL), ZR_OK);
  check_sphere(&s, c, 1.7, NULL);
  assert_abs(area(&s) / (4 * M_PI * 1.7 * 1.7), 1.0, AREA_EPS);
  /* The poles: S_u vanishes there, the normal is the limit. */
  zr__surface_point pt;
  zr__surface_eval(&s, 0.3, 0.0, &pt);
  assert_vec_close(pt.n, zr_v3(0, -1, 0), 1e-12);
  assert_abs(pt.da, 0.0, 1e-12);
  zr__surface_eval(&s, 0.8, 1.0, &pt);
  assert_vec_close(pt.n, zr_v3(0, 1, 0), 1e-12);
}

/* POV-Ray's torus about y: (sqrt(x^2 + z^2) - R)^2 + y^2 = r^2, with
   the implicit gradient as its outward normal, area 4 pi^2 R r, and
   (u, v) found again from a point (but at the seams u = 0 and v = 0,
   which are also u = 1 and v = 1). */
static void test_nurbs_torus_on_implicit_surface(void **state) {
  (void)state;
  const double big = 2.0, small = 0.5;
  zr_transform t;
  skew_transform(&t, zr_v3(1, 1, 1));
  for (int k = 0; k < 2; k++) {
    const zr_transform *xf = k ? &t : NULL;
    zr__surface s;
    assert_int_equal(zr__surface_torus(&s, big, small, xf, NULL, NULL),
                     ZR_OK);
    for (int i = 0; i < GRID; i++)
      for (int j = 0; j < GRID; j++) {
        double u = (double)i / (GRID - 1), v = (double)j / (GRID - 1);
        zr__surface_point pt;
        zr__surface_eval(&s, u, v, &pt);
        zr_vec3 q = xf ? zr__xform_point(xf->inv, pt.p) : pt.p;
        double rho = hypot(q.x, q.z);
        assert_abs(hypot(rho - big, q.y), small, GEOM_EPS);
        zr_vec3 grad = zr_v3((rho - big) * q.x / rho, q.y,
                             (rho - big) * q.z / rho);
        zr_vec3 n = xf ? zr__xform_normal(xf->inv, grad) : grad;
        assert_vec_close(pt.n, zr_v3_norm(n), GEOM_EPS);
        assert_true(pt.da > 0.0);
        if (i == 0 || i == GRID - 1 || j == 0 || j == GRID - 1)
          continue;
        double lu, lv;
        zr__surface_locate(&s, pt.p, &lu, &lv);
        assert_abs(lu, u, 1e-12);
        assert_abs(lv, v, 1e-12);
      }
    /* A rigid motion keeps the area. */
    assert_abs(area(&s) / (4 * M_PI * M_PI * big * small), 1.0, AREA_EPS);
  }
  zr_context *ctx = NULL;
  assert_int_equal(zr_context_new(&ctx), ZR_OK);
  zr__surface s;
  assert_int_equal(zr__surface_torus(&s, 1, 2, NULL, ctx, NULL), ZR_EINVAL);
  assert_string_equal(zr_context_last_error(ctx),
                      "error: torus: radiosity needs 0 < minor < major "
                      "radius (got 1, 2)\n");
  zr_context_free(ctx);
}

static void test_nurbs_sphere_transformed(void **state) {
  (void)state;
  zr__surface s;
  zr_transform t;
  zr_vec3 c = zr_v3(0.2, 0.1, -0.3);
  skew_transform(&t, zr_v3(2, 0.5, 1.25));
  assert_int_equal(zr__surface_sphere(&s, c, 0.8, &t, NULL, NULL), ZR_OK);
  check_sphere(&s, c, 0.8, &t);
  /* A prolate spheroid (semi-axes a, a, b > a) has the closed-form area
     2 pi a^2 (1 + b / (a e) asin e), e^2 = 1 - a^2 / b^2. */
  zr_transform sp;
  zr__transform_identity(&sp);
  zr__transform_scale(&sp, zr_v3(1, 2, 1));
  zr__transform_rotate(&sp, zr_v3(30, 40, 50));
  zr__transform_translate(&sp, zr_v3(-5, 4, 3));
  assert_int_equal(zr__surface_sphere(&s, zr_v3(0, 0, 0), 1.5, &sp, NULL,
                                      NULL),
                   ZR_OK);
  double a = 1.5, b = 3.0, e = sqrt(1 - a * a / (b * b));
  double want = 2 * M_PI * a * a * (1 + b / (a * e) * asin(e));
  assert_abs(area(&s) / want, 1.0, AREA_EPS);
}

static void test_nurbs_mirror_keeps_normals_outward(void **state) {
  (void)state;
  zr__surface s;
  zr_transform t;
  zr__transform_identity(&t);
  zr__transform_scale(&t, zr_v3(-1, 1, 1));
  assert_int_equal(zr__surface_sphere(&s, zr_v3(0, 0, 0), 1.0, &t, NULL,
                                      NULL),
                   ZR_OK);
  assert_true(s.orient == -1.0);
  check_sphere(&s, zr_v3(0, 0, 0), 1.0, &t);
}

/* ---- cylinders and cones ---- */

/*
 * A cone side from base (radius rb) to cap (radius rc) in object space:
 * the implicit function f = dist(q, axis) - r(t) with r linear in the
 * axial coordinate t, whose gradient is the radial unit vector minus
 * (rc - rb) / L times the axis.  A cylinder is rb == rc.
 */
static void check_cone(const zr__surface *s, zr_vec3 base, double rb,
                       zr_vec3 cap, double rc, const zr_transform *t) {
  zr_vec3 d = zr_v3_sub(cap, base);
  double len = zr_v3_len(d);
  zr_vec3 axis = zr_v3_scale(d, 1 / len);
  for (int i = 0; i < GRID; i++) {
    for (int j = 0; j < GRID; j++) {
      double u = (double)i / (GRID - 1), v = (double)j / (GRID - 1);
      zr__surface_point pt;
      zr__surface_eval(s, u, v, &pt);
      zr_vec3 q = zr_v3_sub(t ? zr__xform_point(t->inv, pt.p) : pt.p, base);
      double along = zr_v3_dot(q, axis);
      zr_vec3 radial = zr_v3_madd(q, axis, -along);
      assert_abs(along, v * len, GEOM_EPS);
      assert_abs(zr_v3_len(radial), rb + (rc - rb) * along / len, GEOM_EPS);
      if (zr_v3_len(radial) < 1e-6)
        continue; /* the apex: the gradient's radial part is undefined */
      zr_vec3 grad = zr_v3_madd(zr_v3_norm(radial), axis, -(rc - rb) / len);
      zr_vec3 n = t ? zr__xform_normal(t->inv, grad) : grad;
      assert_vec_close(pt.n, zr_v3_norm(n), GEOM_EPS);
    }
  }
}

static void test_nurbs_cylinder_on_implicit_surface(void **state) {
  (void)state;
  zr__surface s;
  zr_vec3 b = zr_v3(1, 2, 3), c = zr_v3(-1, 4, 2);
  assert_int_equal(zr__surface_cylinder(&s, b, c, 0.6, NULL, NULL, NULL),
                   ZR_OK);
  check_cone(&s, b, 0.6, c, 0.6, NULL);
  assert_abs(area(&s) / (2 * M_PI * 0.6 * 3.0), 1.0, AREA_EPS);
  /* Along the y axis, under a rotation, a uniform scale 2.5 and a
     translation: the area grows by 2.5^2. */
  zr_transform t;
  zr__transform_identity(&t);
  zr__transform_rotate(&t, zr_v3(15, 25, 35));
  zr__transform_scale(&t, zr_v3(2.5, 2.5, 2.5));
  zr__transform_translate(&t, zr_v3(3, 0, -1));
  assert_int_equal(zr__surface_cylinder(&s, zr_v3(0, 0, 0), zr_v3(0, 1, 0),
                                        1.0, &t, NULL, NULL),
                   ZR_OK);
  check_cone(&s, zr_v3(0, 0, 0), 1, zr_v3(0, 1, 0), 1, &t);
  assert_abs(area(&s) / (2 * M_PI * 6.25), 1.0, AREA_EPS);
  /* A non-uniform, sheared frame: points and normals still exact. */
  skew_transform(&t, zr_v3(0.5, 3, 1));
  assert_int_equal(zr__surface_cylinder(&s, b, c, 0.6, &t, NULL, NULL),
                   ZR_OK);
  check_cone(&s, b, 0.6, c, 0.6, &t);
}

static void test_nurbs_cone_on_implicit_surface(void **state) {
  (void)state;
  zr__surface s;
  zr_vec3 b = zr_v3(0, -1, 0), c = zr_v3(2, 1, 1);
  double len = 3.0, rb = 1.2, rc = 0.4;
  assert_int_equal(zr__surface_cone(&s, b, rb, c, rc, NULL, NULL, NULL),
                   ZR_OK);
  check_cone(&s, b, rb, c, rc, NULL);
  double slant = sqrt(len * len + (rb - rc) * (rb - rc));
  assert_abs(area(&s) / (M_PI * (rb + rc) * slant), 1.0, AREA_EPS);
  /* With an apex, transformed. */
  zr_transform t;
  skew_transform(&t, zr_v3(1.5, 0.7, 2));
  assert_int_equal(zr__surface_cone(&s, b, rb, c, 0.0, &t, NULL, NULL),
                   ZR_OK);
  check_cone(&s, b, rb, c, 0.0, &t);
  zr__transform_identity(&t);
  zr__transform_rotate(&t, zr_v3(0, 0, 90));
  zr__transform_scale(&t, zr_v3(0.5, 0.5, 0.5));
  assert_int_equal(zr__surface_cone(&s, b, rb, c, 0.0, &t, NULL, NULL),
                   ZR_OK);
  slant = sqrt(len * len + rb * rb);
  assert_abs(area(&s) / (0.25 * M_PI * rb * slant), 1.0, AREA_EPS);
  /* The normal at the apex is the limit along its u line. */
  zr__surface_point apex, near;
  zr__surface_eval(&s, 0.3, 1.0, &apex);
  zr__surface_eval(&s, 0.3, 1.0 - 1e-7, &near);
  assert_vec_close(apex.n, near.n, 1e-6);
}

/* ---- planar surfaces ---- */

static void test_nurbs_disc_and_annulus(void **state) {
  (void)state;
  zr__surface s;
  zr_vec3 c = zr_v3(1, 1, 1), n = zr_v3_norm(zr_v3(1, 2, -2));
  const double holes[2] = {0.0, 0.75};
  for (int k = 0; k < 2; k++) {
    double hole = holes[k];
    assert_int_equal(zr__surface_disc(&s, c, n, 2.0, hole, NULL, NULL, NULL),
                     ZR_OK);
    for (int i = 0; i < GRID; i++) {
      for (int j = 0; j < GRID; j++) {
        double v = (double)j / (GRID - 1);
        zr__surface_point pt;
        zr__surface_eval(&s, (double)i / (GRID - 1), v, &pt);
        zr_vec3 d = zr_v3_sub(pt.p, c);
        assert_abs(zr_v3_dot(d, n), 0.0, GEOM_EPS);
        /* v runs from the rim (v = 0) in to the hole, linearly. */
        assert_abs(zr_v3_len(d), 2.0 + (hole - 2.0) * v, GEOM_EPS);
        assert_vec_close(pt.n, n, 1e-15);
      }
    }
    assert_abs(area(&s) / (M_PI * (4.0 - hole * hole)), 1.0, AREA_EPS);
  }
  /* Transformed: a disc in y = 0 scaled by 3 in x and z is an ellipse
     of area 9 pi r^2, still facing +y. */
  zr_transform t;
  zr__transform_identity(&t);
  zr__transform_scale(&t, zr_v3(3, 1, 3));
  zr__transform_translate(&t, zr_v3(0, 5, 0));
  assert_int_equal(zr__surface_disc(&s, zr_v3(0, 0, 0), zr_v3(0, 1, 0), 1.0,
                                    0.5, &t, NULL, NULL),
                   ZR_OK);
  assert_abs(area(&s) / (9 * M_PI * 0.75), 1.0, AREA_EPS);
  zr__surface_point pt;
  zr__surface_eval(&s, 0.4, 0.6, &pt);
  assert_vec_close(pt.n, zr_v3(0, 1, 0), 1e-15);
  assert_abs(pt.p.y, 5.0, 1e-15);
}

static void test_nurbs_planar_patches(void **state) {
  (void)state;
  zr__surface s;
  zr__gauss_rule g;
  assert_int_equal(zr__gauss_rule_init(&g, 2), ZR_OK);
  /* A triangle: the collapsed square's area element is linear in u, so
     a 2-point rule integrates it exactly. */
  zr_vec3 a = zr_v3(0, 0, 0), b = zr_v3(2, 0, 0), c = zr_v3(0, 0, 3);
  assert_int_equal(zr__surface_triangle(&s, a, b, c, NULL, NULL, NULL),
                   ZR_OK);
  assert_abs(zr__surface_area(&s, 0, 1, 0, 1, 1, &g), 3.0, 1e-14);
  assert_vec_close(s.plane_normal, zr_v3(0, -1, 0), 1e-15);
  zr__surface_point pt;
  zr__surface_eval(&s, 0.0, 0.7, &pt);
  assert_vec_close(pt.p, a, 0);
  zr__surface_eval(&s, 1.0, 0.5, &pt);
  assert_vec_close(pt.p, zr_v3(1, 0, 1.5), 1e-15);
  /* A sub-rectangle of the triangle is a straight-edged quadrilateral;
     at u0 = 0 it collapses to the triangle p0, S(u1,v0), S(u1,v1). */
  zr_vec3 poly[8];
  assert_int_equal(zr__surface_patch_polygon(&s, 0, 0.5, 0, 1, 4, poly, 8),
                   3);
  assert_int_equal(zr__surface_patch_polygon(&s, 0.5, 1, 0.25, 0.5, 4, poly,
                                             8),
                   4);
  /* Box faces: areas and outward normals, under a rotation. */
  zr__surface faces[6];
  zr_transform t;
  zr__transform_identity(&t);
  zr__transform_rotate(&t, zr_v3(0, 90, 0));
  assert_int_equal(zr__surface_box_faces(faces, zr_v3(1, 1, 1),
                                         zr_v3(-1, 0, 0.5), &t, NULL, NULL),
                   ZR_OK);
  zr_vec3 centre = zr__xform_point(t.m, zr_v3(0, 0.5, 0.75));
  const double areas[6] = {0.5, 0.5, 1.0, 1.0, 2.0, 2.0};
  for (int f = 0; f < 6; f++) {
    assert_abs(zr__surface_area(&faces[f], 0, 1, 0, 1, 1, &g), areas[f],
               1e-14);
    zr__surface_eval(&faces[f], 0.5, 0.5, &pt);
    zr_vec3 out = zr_v3_sub(pt.p, centre);
    assert_vec_close(pt.n, zr_v3_norm(out), 1e-15);
  }
}

static void test_nurbs_plane_in_box(void **state) {
  (void)state;
  zr__surface s;
  zr__gauss_rule g;
  bool more = true;
  assert_int_equal(zr__gauss_rule_init(&g, 1), ZR_OK);
  /* A floor in the bounds x in [-1, 2], z in [0, 3]: exactly 3 x 3. */
  assert_int_equal(zr__surface_plane_in_box(&s, zr_v3(0, 1, 0), 0.0,
                                            zr_v3(-1, -1, 0), zr_v3(2, 1, 3),
                                            NULL, &more, NULL, NULL),
                   ZR_OK);
  assert_false(more);
  assert_abs(zr__surface_area(&s, 0, 1, 0, 1, 1, &g), 9.0, 1e-14);
  assert_vec_close(s.plane_normal, zr_v3(0, 1, 0), 0);
  zr__surface_point pt;
  zr__surface_eval(&s, 0, 0, &pt);
  assert_vec_close(pt.p, zr_v3(-1, 0, 0), 1e-15);
  zr__surface_eval(&s, 1, 1, &pt);
  assert_vec_close(pt.p, zr_v3(2, 0, 3), 1e-15);
  /* POV-Ray's plane { -y, -1 } is y = 1 facing down. */
  assert_int_equal(zr__surface_plane_in_box(&s, zr_v3(0, -1, 0), -1.0,
                                            zr_v3(-1, -1, -1),
                                            zr_v3(1, 2, 1), NULL, &more,
                                            NULL, NULL),
                   ZR_OK);
  assert_vec_close(s.plane_normal, zr_v3(0, -1, 0), 0);
  zr__surface_eval(&s, 0.3, 0.3, &pt);
  assert_abs(pt.p.y, 1.0, 1e-15);
  /* Moved up by 0.5 and turned 90 degrees about x: z = 0.5, facing +z,
     still exact although the rotation leaves 6e-17 in the normal. */
  zr_transform t;
  zr__transform_identity(&t);
  zr__transform_translate(&t, zr_v3(0, 0.5, 0));
  zr__transform_rotate(&t, zr_v3(90, 0, 0));
  assert_int_equal(zr__surface_plane_in_box(&s, zr_v3(0, 1, 0), 0.0,
                                            zr_v3(-1, -1, -1),
                                            zr_v3(1, 1, 1), &t, &more, NULL,
                                            NULL),
                   ZR_OK);
  assert_false(more);
  assert_vec_close(s.plane_normal, zr_v3(0, 0, 1), 0);
  assert_abs(zr__surface_area(&s, 0, 1, 0, 1, 1, &g), 4.0, 1e-14);
  zr__surface_eval(&s, 0.7, 0.2, &pt);
  assert_abs(pt.p.z, 0.5, 1e-15);
  /* A tilted plane x + y = 0: its section of the cube, a 2 sqrt2 x 2
     rectangle, lies inside the parallelogram, which says it covers
     more. */
  assert_int_equal(zr__surface_plane_in_box(&s, zr_v3(1, 1, 0), 0.0,
                                            zr_v3(-1, -1, -1),
                                            zr_v3(1, 1, 1), NULL, &more,
                                            NULL, NULL),
                   ZR_OK);
  assert_true(more);
  assert_vec_close(s.plane_normal, zr_v3(M_SQRT1_2, M_SQRT1_2, 0), 1e-15);
  const zr_vec3 corners[4] = {
      {1, -1, 1}, {1, -1, -1}, {-1, 1, 1}, {-1, 1, -1}};
  for (int k = 0; k < 4; k++) {
    double u, v;
    zr__surface_locate(&s, corners[k], &u, &v);
    zr__surface_eval(&s, u, v, &pt);
    assert_vec_close(pt.p, corners[k], 1e-12);
  }
  assert_true(zr__surface_area(&s, 0, 1, 0, 1, 1, &g) >=
              4 * M_SQRT2 - 1e-12);
  /* Outside the bounds. */
  zr_context *ctx;
  assert_int_equal(zr_context_new(&ctx), ZR_OK);
  assert_int_equal(zr__surface_plane_in_box(&s, zr_v3(0, 1, 0), 5.0,
                                            zr_v3(-1, -1, -1),
                                            zr_v3(1, 1, 1), NULL, NULL, ctx,
                                            NULL),
                   ZR_EINVAL);
  assert_string_equal(zr_context_last_error(ctx),
                      "error: plane does not cross the scene's bounds\n");
  zr_context_free(ctx);
}

static void test_nurbs_patch_polygon_of_curved_patch(void **state) {
  (void)state;
  /* A sphere patch's polygon is inscribed: its points are on the
     sphere, four edges of segs points each. */
  zr__surface s;
  assert_int_equal(zr__surface_sphere(&s, zr_v3(0, 0, 0), 2.0, NULL, NULL,
                                      NULL),
                   ZR_OK);
  zr_vec3 poly[32];
  size_t n = zr__surface_patch_polygon(&s, 0.1, 0.3, 0.4, 0.6, 5, poly, 32);
  assert_int_equal(n, 20);
  for (size_t k = 0; k < n; k++)
    assert_abs(zr_v3_len(poly[k]), 2.0, GEOM_EPS);
  /* A patch touching the pole loses its collapsed edge. */
  n = zr__surface_patch_polygon(&s, 0.1, 0.3, 0.0, 0.2, 5, poly, 32);
  assert_int_equal(n, 15);
  /* The output is capped at max. */
  assert_int_equal(zr__surface_patch_polygon(&s, 0, 1, 0, 1, 50, poly, 32),
                   32);
}

/* ---- locating hits ---- */

/* eval then locate gives back (u,v) where u is defined, and the point
   always; 1e-12 relative to the surface's size is rounding only. */
static void check_round_trip(const zr__surface *s, double size) {
  for (int i = 0; i < GRID; i++) {
    for (int j = 0; j < GRID; j++) {
      double u = (double)i / (GRID - 1), v = (double)j / (GRID - 1);
      zr__surface_point pt, back;
      double lu, lv;
      zr__surface_eval(s, u, v, &pt);
      zr__surface_locate(s, pt.p, &lu, &lv);
      zr__surface_eval(s, lu, lv, &back);
      assert_vec_close(back.p, pt.p, 1e-12 * size);
      bool u_defined = pt.da > 1e-9 * size * size;
      if (u_defined && i > 0 && i < GRID - 1)
        assert_abs(lu, u, 1e-12);
      if (s->kind != ZR__SURFACE_TRIANGLE || u > 0.0)
        assert_abs(lv, v, 1e-12);
    }
  }
}

static void test_nurbs_locate_round_trip(void **state) {
  (void)state;
  zr_transform t;
  skew_transform(&t, zr_v3(2, 0.5, 1.25));
  for (int k = 0; k < 2; k++) {
    const zr_transform *xf = k ? &t : NULL;
    zr__surface s, faces[6];
    assert_int_equal(zr__surface_sphere(&s, zr_v3(1, 2, 3), 1.5, xf, NULL,
                                        NULL),
                     ZR_OK);
    check_round_trip(&s, 4);
    assert_int_equal(zr__surface_cylinder(&s, zr_v3(1, 2, 3), zr_v3(0, 0, 1),
                                          0.5, xf, NULL, NULL),
                     ZR_OK);
    check_round_trip(&s, 4);
    assert_int_equal(zr__surface_cone(&s, zr_v3(1, 2, 3), 1.0,
                                      zr_v3(0, 0, 1), 0.0, xf, NULL, NULL),
                     ZR_OK);
    check_round_trip(&s, 4);
    assert_int_equal(zr__surface_disc(&s, zr_v3(1, 2, 3), zr_v3(1, 1, 0),
                                      2.0, 0.5, xf, NULL, NULL),
                     ZR_OK);
    check_round_trip(&s, 4);
    assert_int_equal(zr__surface_triangle(&s, zr_v3(1, 2, 3),
                                          zr_v3(0, 0, 1), zr_v3(2, -1, 0),
                                          xf, NULL, NULL),
                     ZR_OK);
    check_round_trip(&s, 4);
    assert_int_equal(zr__surface_box_faces(faces, zr_v3(1, 2, 3),
                                           zr_v3(0, 0, 1), xf, NULL, NULL),
                     ZR_OK);
    for (int f = 0; f < 6; f++)
      check_round_trip(&faces[f], 4);
  }
  /* Off the surface, a point maps to the parameters of a nearby one:
     above a sphere point, along its normal, the same (u,v). */
  zr__surface s;
  assert_int_equal(zr__surface_sphere(&s, zr_v3(0, 0, 0), 1.0, NULL, NULL,
                                      NULL),
                   ZR_OK);
  zr__surface_point pt;
  double u, v;
  zr__surface_eval(&s, 0.3, 0.6, &pt);
  zr__surface_locate(&s, zr_v3_madd(pt.p, pt.n, 1e-3), &u, &v);
  assert_abs(u, 0.3, 1e-12);
  assert_abs(v, 0.6, 1e-12);
}

/* ---- bad input ---- */

static void expect_error(zr_context *ctx, zr_status st, const char *text) {
  assert_int_equal(st, ZR_EINVAL);
  assert_string_equal(zr_context_last_error(ctx), text);
}

static void test_nurbs_bad_input_messages(void **state) {
  (void)state;
  zr_context *ctx;
  assert_int_equal(zr_context_new(&ctx), ZR_OK);
  zr__surface s, faces[6];
  zr_vec3 o = zr_v3(0, 0, 0), y = zr_v3(0, 1, 0);
  expect_error(ctx, zr__surface_sphere(&s, o, 0.0, NULL, ctx, NULL),
               "error: sphere radius must be positive and finite (got 0)\n");
  expect_error(ctx, zr__surface_sphere(&s, o, NAN, NULL, ctx, NULL),
               "error: sphere radius must be positive and finite "
               "(got nan)\n");
  expect_error(ctx, zr__surface_cylinder(&s, y, y, 1.0, NULL, ctx, NULL),
               "error: cylinder base and cap points coincide\n");
  expect_error(ctx, zr__surface_cylinder(&s, o, y, -1.0, NULL, ctx, NULL),
               "error: cylinder radius must be positive and finite "
               "(got -1)\n");
  expect_error(ctx, zr__surface_cone(&s, o, 0.0, y, 0.0, NULL, ctx, NULL),
               "error: cone radii must be finite, not negative and not "
               "both zero (got 0 and 0)\n");
  expect_error(ctx, zr__surface_disc(&s, o, y, 1.0, 1.0, NULL, ctx, NULL),
               "error: disc hole radius 1 must be in [0, radius 1)\n");
  expect_error(ctx, zr__surface_disc(&s, o, o, 1.0, 0.0, NULL, ctx, NULL),
               "error: disc normal is the zero vector\n");
  expect_error(ctx,
               zr__surface_triangle(&s, o, y, zr_v3(0, 2, 0), NULL, ctx,
                                    NULL),
               "error: triangle has zero area (collinear vertices)\n");
  expect_error(ctx,
               zr__surface_box_faces(faces, o, zr_v3(1, 0, 1), NULL, ctx,
                                     NULL),
               "error: box has zero thickness (corners <0, 0, 0> and "
               "<1, 0, 1>)\n");
  expect_error(ctx,
               zr__surface_parallelogram(&s, o, y, zr_v3(0, INFINITY, 0),
                                         NULL, ctx, NULL),
               "error: parallelogram: non-finite corner or edge\n");
  /* A transform that flattens everything. */
  zr_transform flat;
  zr__transform_identity(&flat);
  zr__transform_scale(&flat, zr_v3(1, 0, 1));
  expect_error(ctx, zr__surface_sphere(&s, o, 1.0, &flat, ctx, NULL),
               "error: radiosity surface: singular or non-finite "
               "transform\n");
  /* The place of the object, when given, leads the message. */
  zr_diag_place where = {"scene.pov", 7, 3, NULL, 0, 0, NULL, 0, 0};
  expect_error(ctx, zr__surface_sphere(&s, o, -2.0, NULL, ctx, &where),
               "scene.pov:7:3: error: sphere radius must be positive and "
               "finite (got -2)\n");
  zr_context_free(ctx);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_nurbs_basis_partition_and_derivative),
      cmocka_unit_test(test_nurbs_derivatives_match_differences),
      cmocka_unit_test(test_nurbs_sphere_on_implicit_surface),
      cmocka_unit_test(test_nurbs_sphere_transformed),
      cmocka_unit_test(test_nurbs_torus_on_implicit_surface),
      cmocka_unit_test(test_nurbs_mirror_keeps_normals_outward),
      cmocka_unit_test(test_nurbs_cylinder_on_implicit_surface),
      cmocka_unit_test(test_nurbs_cone_on_implicit_surface),
      cmocka_unit_test(test_nurbs_disc_and_annulus),
      cmocka_unit_test(test_nurbs_planar_patches),
      cmocka_unit_test(test_nurbs_plane_in_box),
      cmocka_unit_test(test_nurbs_patch_polygon_of_curved_patch),
      cmocka_unit_test(test_nurbs_locate_round_trip),
      cmocka_unit_test(test_nurbs_bad_input_messages),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
