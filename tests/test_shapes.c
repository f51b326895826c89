/*
 * test_shapes.c - the torus, the polygon and the superellipsoid, from
 * scene text through the parser to the tracer's crossings, normals,
 * inside tests and bounds (lib/trace/obj_torus.c, obj_polygon.c,
 * obj_superellipsoid.c, obj_prism.c, obj_lathe.c, obj_blob.c,
 * obj_sor.c, obj_julia.c, lib/sdl/build_shape.c), and the polynomial
 * root finder they share (lib/trace/roots.c).
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
#include "scene/shapes.h"
#include "trace/intersect.h"
#include "trace/obj_shapes.h"
#include "trace/obj_sweep.h"
#include "trace/roots.h"
#include "zrcube.h"
#include "parse_fixture.h"
#include "test_util.h"

/* The coefficients (c[i] of x^i) of the monic polynomial with these
   roots. */
static void from_roots(const double *r, int n, double *c) {
  c[0] = 1.0;
  for (int i = 1; i <= n; i++)
    c[i] = 0.0;
  for (int k = 0; k < n; k++) {
    for (int i = k + 1; i > 0; i--)
      c[i] = c[i - 1] - r[k] * c[i];
    c[0] = -r[k] * c[0];
  }
}

/* Simple roots 1e-3 apart: a root's error is about the rounding of p
   (1e-15 relative to its terms) over |p'| there (about 2e-3 here), so
   1e-10 leaves a wide margin. */
static void test_shapes_roots_clustered_quartic(void **state) {
  (void)state;
  double r[4] = {1.0, 1.001, 2.0, 3.0}, c[5], out[4];
  from_roots(r, 4, c);
  assert_int_equal(zr__poly_roots(c, 4, -10.0, 10.0, out), 4);
  for (int i = 0; i < 4; i++)
    assert_near(out[i], r[i], 1e-10);
  /* Only the interval's roots. */
  assert_int_equal(zr__poly_roots(c, 4, 1.0005, 2.5, out), 2);
  assert_near(out[0], 1.001, 1e-10);
  assert_near(out[1], 2.0, 1e-10);
}

/* A ray that passes near a surface without touching it gives a
   polynomial with a close pair of complex roots: no crossing.  A triple
   root changes sign and is one. */
static void test_shapes_roots_multiplicity(void **state) {
  (void)state;
  /* ((x - 1)^2 + 1e-6) (x - 2) (x - 3). */
  double r[2] = {2.0, 3.0}, c[7], out[6], q[3];
  from_roots(r, 2, q);
  double near[3] = {1.0 + 1e-6, -2.0, 1.0};
  for (int i = 0; i <= 4; i++)
    c[i] = 0.0;
  for (int i = 0; i <= 2; i++)
    for (int j = 0; j <= 2; j++)
      c[i + j] += near[i] * q[j];
  assert_int_equal(zr__poly_roots(c, 4, -10.0, 10.0, out), 2);
  assert_near(out[0], 2.0, 1e-12);
  assert_near(out[1], 3.0, 1e-12);
  double t[3] = {0.5, 0.5, 0.5};
  from_roots(t, 3, c);
  assert_int_equal(zr__poly_roots(c, 3, -1.0, 1.0, out), 1);
  /* A triple root is found to the cube root of the rounding. */
  assert_near(out[0], 0.5, 1e-5);
  double six[6] = {-2.5, -1.0, 0.25, 0.5, 4.0, 7.0};
  from_roots(six, 6, c);
  assert_int_equal(zr__poly_roots(c, 6, -3.0, 8.0, out), 6);
  for (int i = 0; i < 6; i++)
    assert_near(out[i], six[i], 1e-9);
  /* No real roots: x^4 + 1. */
  double none[5] = {1, 0, 0, 0, 1};
  assert_int_equal(zr__poly_roots(none, 4, -10.0, 10.0, out), 0);
}

/* Roots near 1 searched over an interval nine orders wider (a poly's
   bound on its roots when its leading coefficient is small), a root far
   out, and roots of both signs: the refinement splits such intervals
   on the logarithmic scale and stops where the value is within its own
   rounding, which for these simple roots is within 1e-12 relative. */
static void test_shapes_roots_wide_interval(void **state) {
  (void)state;
  double r[4] = {-3.5, 0.25, 1.5, 2e7}, c[5], out[4];
  from_roots(r, 4, c);
  assert_int_equal(zr__poly_roots(c, 4, -1e9, 1e9, out), 4);
  for (int i = 0; i < 4; i++)
    assert_near(out[i] / r[i], 1.0, 1e-12);
  /* The same roots near a start at 1e-6, as a shadow ray's. */
  double s[3] = {0.03, 0.5, 0.97}, d[4];
  from_roots(s, 3, d);
  for (int i = 0; i <= 3; i++)
    d[i] *= 1e-9; /* scale changes no root */
  assert_int_equal(zr__poly_roots(d, 3, 1e-6, 1e6, out), 3);
  for (int i = 0; i < 3; i++)
    assert_near(out[i], s[i], 1e-12);
}

/* A small generator of test numbers (no library rand: its sequence is
   the C library's). */
static double next_unit(uint64_t *state) {
  *state = *state * 6364136223846793005u + 1442695040888963407u;
  return (double)(*state >> 11) / 9007199254740992.0;
}

/* The root walk (zr__root_walk) gives zr__poly_roots's roots, bit for
   bit and in order, for polynomials of every degree with roots inside,
   outside and clustered; and passing over intervals changes none of the
   roots after them. */
static void test_shapes_roots_walk_same_bits(void **state) {
  (void)state;
  uint64_t seed = 7;
  int compared = 0;
  for (int trial = 0; trial < 3000; trial++) {
    int degree = 1 + trial % ZR_POLY_MAX_DEGREE;
    double r[ZR_POLY_MAX_DEGREE], c[ZR_POLY_MAX_DEGREE + 1];
    for (int i = 0; i < degree; i++)
      r[i] = 4.0 * next_unit(&seed) - 2.0;
    if (trial % 3 == 0 && degree > 1)
      r[1] = r[0] + 1e-7 * next_unit(&seed); /* a close pair */
    from_roots(r, degree, c);
    if (trial % 5 == 0)
      c[0] += 0.5 * next_unit(&seed); /* complex pairs */
    double lo = -1.5 + next_unit(&seed), hi = lo + 3.0 * next_unit(&seed);
    double want[ZR_POLY_MAX_DEGREE], got[ZR_POLY_MAX_DEGREE];
    int n = zr__poly_roots(c, degree, lo, hi, want);
    zr__root_walk w;
    zr__root_walk_start(&w, c, degree, lo, hi);
    int k = 0;
    double a, b;
    while (zr__root_walk_next(&w, &a, &b)) {
      assert_true(k < degree);
      got[k] = zr__root_walk_root(&w);
      assert_true(got[k] >= a && got[k] <= b);
      k++;
    }
    assert_int_equal(k, n);
    for (int i = 0; i < n; i++)
      assert_memory_equal(&got[i], &want[i], sizeof got[i]);
    /* Every second interval passed over: the others' roots unchanged. */
    zr__root_walk_start(&w, c, degree, lo, hi);
    for (int i = 0; zr__root_walk_next(&w, &a, &b); i++)
      if (i % 2 == 1) {
        double x = zr__root_walk_root(&w);
        assert_memory_equal(&x, &want[i], sizeof x);
      }
    compared += n;
  }
  assert_true(compared > 4000); /* 4,421 roots */
  /* Leading zeros and no interval: as zr__poly_roots. */
  double lin[4] = {-1.0, 2.0, 0.0, 0.0}, a, b;
  zr__root_walk w;
  zr__root_walk_start(&w, lin, 3, 0.0, 1.0);
  assert_true(zr__root_walk_next(&w, &a, &b));
  assert_true(zr__root_walk_root(&w) == 0.5);
  assert_false(zr__root_walk_next(&w, &a, &b));
  zr__root_walk_start(&w, lin, 3, 1.0, 1.0);
  assert_false(zr__root_walk_next(&w, &a, &b));
}

/* Torus crossings are roots of well-scaled quartics with simple roots:
   1e-9 covers their refinement, which stops within a few ulps. */
#define TORUS_EPS 1e-9

static void test_shapes_torus_crossings_and_normals(void **state) {
  fixture *f = *state;
  const zr_object *o = only(f, "torus { 2, 0.5 sturm }\n");
  assert_int_equal(o->kind, ZR_OBJ_TORUS);
  assert_true(o->u.torus.sturm);
  zr_hit h[2];
  /* Along the x axis through the hole: rim, hole, rim. */
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0.0, h), 2);
  assert_near(h[0].t, 2.5, TORUS_EPS);
  assert_near(h[1].t, 3.5, TORUS_EPS);
  assert_vec(h[0].normal, -1, 0, 0, TORUS_EPS);
  assert_vec(h[1].normal, 1, 0, 0, TORUS_EPS);
  /* From inside the hole the next two are the far rim. */
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 4.0, h), 2);
  assert_near(h[0].t, 6.5, TORUS_EPS);
  assert_near(h[1].t, 7.5, TORUS_EPS);
  /* Down through the rim at x = 2. */
  assert_int_equal(cross(o, zr_v3(2, 5, 0), zr_v3(0, -2, 0), 0.0, h), 2);
  assert_near(h[0].t, 2.25, TORUS_EPS);
  assert_near(h[1].t, 2.75, TORUS_EPS);
  assert_vec(h[0].normal, 0, 1, 0, TORUS_EPS);
  assert_vec(h[1].normal, 0, -1, 0, TORUS_EPS);
  /* Down the axis: through the hole. */
  assert_int_equal(cross(o, zr_v3(0, 5, 0), zr_v3(0, -1, 0), 0.0, h), 0);
  assert_true(zr__inside(o, zr_v3(2, 0.4, 0)));
  assert_true(zr__inside(o, zr_v3(0, 0.2, -1.7)));
  assert_false(zr__inside(o, zr_v3(0, 0, 0)));
  assert_false(zr__inside(o, zr_v3(2, 0.6, 0)));
  zr_vec3 lo, hi;
  assert_true(zr__object_bounds(o, &lo, &hi));
  assert_vec(lo, -2.5, -0.5, -2.5, 1e-6);
  assert_vec(hi, 2.5, 0.5, 2.5, 1e-6);
}

/* A thin ring seen edge on: the roots 2e-3 apart must stay apart. */
static void test_shapes_torus_thin_and_transformed(void **state) {
  fixture *f = *state;
  const zr_object *o =
      only(f, "torus { 1, 0.001 rotate x*90 translate <0, 0, 3> }\n");
  zr_hit h[2];
  assert_int_equal(cross(o, zr_v3(-5, 0, 3), zr_v3(1, 0, 0), 0.0, h), 2);
  assert_near(h[0].t, 3.999, TORUS_EPS);
  assert_near(h[1].t, 4.001, TORUS_EPS);
  /* Rotated about x, the ring lies in the x-y plane at z = 3. */
  assert_int_equal(cross(o, zr_v3(0, 1, -5), zr_v3(0, 0, 1), 0.0, h), 2);
  assert_near(h[0].t, 8.0 - 0.001, 1e-6);
  assert_vec(h[0].normal, 0, 0, -1, 1e-6);
  assert_true(zr__inside(o, zr_v3(0, -1, 3)));
}

/* The search for the nearest surface asks a torus for its first
   crossing without a normal (zr__intersect_first), which the root walk
   gives without refining the others: the same t, bit for bit, as the
   first of all its crossings, over rays from every side, some starting
   inside the tube or the hole, some with the interval cut short. */
static void test_shapes_torus_first_same_bits(void **state) {
  fixture *f = *state;
  const zr_object *o =
      only(f, "torus { 2, 0.5 rotate <20, 0, 10> translate <0.3, 0, 0> }\n");
  uint64_t seed = 11;
  int hits = 0;
  for (int i = 0; i < 20000; i++) {
    zr_vec3 org = zr_v3(6.0 * next_unit(&seed) - 3.0,
                        2.0 * next_unit(&seed) - 1.0,
                        6.0 * next_unit(&seed) - 3.0);
    zr_vec3 dir = zr_v3(next_unit(&seed) - 0.5, 0.6 * next_unit(&seed) - 0.3,
                        next_unit(&seed) - 0.5);
    zr_ray ray = {org, dir};
    double tmax = i % 4 == 0 ? 2.0 * next_unit(&seed) : INFINITY;
    zr_hit all[ZR_MAX_CROSSINGS], first[ZR_MAX_CROSSINGS];
    int n = zr__intersect(o, &ray, 1e-6, tmax, all);
    int m = zr__intersect_first(o, &ray, 1e-6, tmax, false, first);
    assert_int_equal(m > 0, n > 0);
    if (n > 0) {
      assert_memory_equal(&first[0].t, &all[0].t, sizeof all[0].t);
      hits++;
    }
  }
  assert_true(hits > 2000);
}

static void test_shapes_torus_bad_minor(void **state) {
  fixture *f = *state;
  bad(f, "torus { 1, 0 }\n", ZR_ESCENE, "the torus's minor radius is zero",
      NULL);
  bad(f, "sphere { 0, 1 sturm }\n", ZR_ESYNTAX,
      "'sturm' is for tori and the other polynomial shapes", NULL);
}

/* The letter P of the manual: an outline and a rectangular hole. */
static void test_shapes_polygon_even_odd(void **state) {
  fixture *f = *state;
  const zr_object *o =
      only(f, "polygon { 12, <0, 0>, <0, 6>, <4, 6>, <4, 3>, <1, 3>,\n"
              "  <1,0>, <0, 0>, <1, 4>, <1, 5>, <3, 5>, <3, 4>, <1, 4>\n"
              "  translate z }\n");
  assert_int_equal(o->kind, ZR_OBJ_POLYGON);
  assert_int_equal(f->diag.warnings, 0);
  zr_hit h[2];
  zr_vec3 dz = zr_v3(0, 0, 1);
  assert_int_equal(cross(o, zr_v3(0.5, 1, -5), dz, 0.0, h), 1);
  /* A plane meets the ray at a quotient of exact numbers. */
  assert_near(h[0].t, 6.0, 1e-12);
  assert_near(fabs(h[0].normal.z), 1.0, 1e-12);
  assert_int_equal(cross(o, zr_v3(2, 4.5, -5), dz, 0.0, h), 0); /* hole */
  assert_int_equal(cross(o, zr_v3(3.5, 4.5, -5), dz, 0.0, h), 1);
  assert_int_equal(cross(o, zr_v3(2, 1.5, -5), dz, 0.0, h), 0);
  assert_int_equal(cross(o, zr_v3(-0.5, 1, -5), dz, 0.0, h), 0);
  assert_false(zr__inside(o, zr_v3(0.5, 1, 1)));
  assert_false(zr__has_inside(o));
  zr_vec3 lo, hi;
  assert_true(zr__object_bounds(o, &lo, &hi));
  assert_vec(lo, 0, 0, 1, 1e-6);
  assert_vec(hi, 4, 6, 1, 1e-6);
}

static void test_shapes_polygon_tilted_and_open(void **state) {
  fixture *f = *state;
  /* A square in the plane x + y = 1, left open: closed with a warning
     worded as POV-Ray's. */
  const zr_object *o =
      only(f, "polygon { 4, <1, 0, 0> <0, 1, 0> <0, 1, 1> <1, 0, 1> }\n");
  assert_int_equal(f->diag.warnings, 1);
  assert_non_null(strstr(f->diag.warning, "Polygon not closed. Closing it."));
  zr_hit h[2];
  assert_int_equal(
      cross(o, zr_v3(0, 0, 0.5), zr_v3(1, 1, 0), 0.0, h), 1);
  assert_near(h[0].t, 0.5, 1e-12);
  double s = sqrt(0.5);
  assert_near(fabs(h[0].normal.x), s, 1e-12);
  assert_near(h[0].normal.x, h[0].normal.y, 1e-12);
  assert_int_equal(
      cross(o, zr_v3(0, 0, 1.5), zr_v3(1, 1, 0), 0.0, h), 0);
}

static void test_shapes_polygon_bad_counts(void **state) {
  fixture *f = *state;
  bad(f, "polygon { 2, <0, 0>, <1, 0> }\n", ZR_ESCENE,
      "a polygon needs at least 3 points, not 2", NULL);
  bad(f, "polygon { 3, <0, 0>, <1, 0>, <0, 1>, <0, 0> }\n", ZR_ESCENE,
      "the polygon has more points than the 3 it announced", NULL);
  bad(f, "polygon { 4, <0, 0>, <1, 0>, <0, 1> }\n", ZR_ESCENE,
      "the polygon has 3 points, not the 4 it announced", NULL);
  /* Points on one line: a warning and nothing drawn, as POV-Ray
     (tests/legacy/polygon_line.pov). */
}

/* Superellipsoid crossings come from bisection down to 1e-15 relative
   of a function with slope about 1: 1e-9 is far above that error and
   far below any mistake in the shape. */
#define SE_EPS 1e-9

static void test_shapes_superellipsoid_sphere_and_box(void **state) {
  fixture *f = *state;
  /* e = n = 1 is the unit sphere. */
  const zr_object *o = only(f, "superellipsoid { <1, 1> }\n");
  assert_int_equal(o->kind, ZR_OBJ_SUPERELLIPSOID);
  zr_hit h[2];
  assert_int_equal(cross(o, zr_v3(-5, 0.6, 0), zr_v3(1, 0, 0), 0.0, h), 2);
  assert_near(h[0].t, 4.2, SE_EPS);
  assert_near(h[1].t, 5.8, SE_EPS);
  assert_vec(h[0].normal, -0.8, 0.6, 0, 1e-7);
  assert_vec(h[1].normal, 0.8, 0.6, 0, 1e-7);
  /* A rounded box: flat faces at 1, corners on the diagonal where
     3 s^(2/e) = 1 when e = n. */
  o = only(f, "superellipsoid { <0.2, 0.2> scale 2 }\n");
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0.0, h), 2);
  assert_near(h[0].t, 3.0, SE_EPS);
  assert_near(h[1].t, 7.0, SE_EPS);
  assert_vec(h[0].normal, -1, 0, 0, 1e-7);
  double corner = 2.0 * pow(3.0, -0.1);
  assert_int_equal(cross(o, zr_v3(-5, -5, -5), zr_v3(1, 1, 1), 0.0, h), 2);
  assert_near(h[0].t, 5.0 - corner, SE_EPS);
  assert_near(h[1].t, 5.0 + corner, SE_EPS);
  double k = 1.0 / sqrt(3.0);
  assert_vec(h[0].normal, -k, -k, -k, 1e-7);
  assert_true(zr__inside(o, zr_v3(1.9, 1.5, -1.5)));
  assert_false(zr__inside(o, zr_v3(1.9, 1.9, 1.9)));
  zr_vec3 lo, hi;
  assert_true(zr__object_bounds(o, &lo, &hi));
  assert_vec(hi, 2, 2, 2, 1e-6);
}

/* e, n above 2 pinch the shape into a star, which a ray can cross four
   times; a ray leaving one arm finds the next. */
static void test_shapes_superellipsoid_star(void **state) {
  fixture *f = *state;
  const zr_object *o = only(f, "superellipsoid { <3, 3> }\n");
  zr_hit h[2];
  /* Along the x axis the surface is at x = +-1 whatever e and n are. */
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0.0, h), 2);
  assert_near(h[0].t, 4.0, SE_EPS);
  assert_near(h[1].t, 6.0, SE_EPS);
  /* e = n = 3 gives |x|^(2/3) + |y|^(2/3) + |z|^(2/3) < 1, a star with
     six arms.  The line x + y = 0.8 in z = 0 passes through the +x arm
     and then the +y arm: four crossings, symmetric about x = y = 0.4,
     which it reaches at t = 5.4. */
  zr_vec3 from = zr_v3(5.8, -5, 0), along = zr_v3(-1, 1, 0);
  assert_int_equal(cross(o, from, along, 0.0, h), 2);
  double first = h[0].t, second = h[1].t;
  assert_true(second < 5.4);
  assert_int_equal(cross(o, from, along, second + 1e-9, h), 2);
  assert_near(h[0].t, 10.8 - second, SE_EPS);
  assert_near(h[1].t, 10.8 - first, SE_EPS);
}

/* Convex superellipsoids (e, n <= 2) are crossed by Newton steps that
   walk in from each end of the ray's span in the box: on a fan of rays
   across each shape, every crossing must lie on the surface, the middle
   of the two crossings inside, and a ray that finds none must have no
   point inside along it (sampled every 1/4000 of the box).  <2, 2> is
   the octahedron, whose edges have no derivative; <0.01, 0.01> is nearly
   the cube. */
static void test_shapes_superellipsoid_convex_fan(void **state) {
  fixture *f = *state;
  static const char *shapes[] = {
      "superellipsoid { <0.9, 0.9> }\n", "superellipsoid { <0.1, 0.5> }\n",
      "superellipsoid { <2, 2> }\n", "superellipsoid { <1, 0.3> }\n",
      "superellipsoid { <0.01, 0.01> }\n", "superellipsoid { <2, 0.2> }\n"};
  for (size_t k = 0; k < sizeof shapes / sizeof *shapes; k++) {
    const zr_object *o = only(f, shapes[k]);
    double e = o->u.superellipsoid.e, n = o->u.superellipsoid.n;
    int hits = 0;
    for (int i = 0; i < 41; i++)
      for (int j = 0; j < 41; j++) {
        /* From a point off the corner towards the plane x + y + z = 0
           (z a little tilted so no ray lies in a symmetry plane). */
        zr_vec3 from = zr_v3(3.1, 2.3, 2.7);
        zr_vec3 to = zr_v3(-1.25 + i / 16.0, -1.25 + j / 16.0,
                           0.3 * (i - j) / 40.0);
        zr_vec3 d = zr_v3_sub(to, from);
        zr_hit h[ZR_MAX_CROSSINGS];
        int c = cross(o, from, d, 0.0, h);
        if (c == 0) {
          for (int s = 0; s <= 8000; s++) {
            zr_vec3 p = zr_v3_madd(from, d, s / 4000.0);
            assert_true(zr__superellipsoid_value(e, n, p) > -1e-9);
          }
          continue;
        }
        assert_int_equal(c, 2);
        hits++;
        for (int m = 0; m < 2; m++)
          assert_near(zr__superellipsoid_value(
                          e, n, zr_v3_madd(from, d, h[m].t)),
                      0.0, 1e-12);
        if (h[1].t - h[0].t > 1e-9)
          assert_true(zr__superellipsoid_value(
                          e, n,
                          zr_v3_madd(from, d, 0.5 * (h[0].t + h[1].t))) <
                      0.0);
      }
    /* The fan is wider than every shape and narrower than the box. */
    assert_true(hits > 100 && hits < 41 * 41);
  }
}

static void test_shapes_superellipsoid_clamped(void **state) {
  fixture *f = *state;
  const zr_object *o = only(f, "superellipsoid { <0, 1> }\n");
  assert_int_equal(f->diag.warnings, 1);
  assert_non_null(strstr(f->diag.warning,
                         "superellipsoid values below 0.001 are taken as "
                         "0.001"));
  assert_near(o->u.superellipsoid.e, 1e-3, 0.0);
  zr_hit h[2];
  assert_int_equal(cross(o, zr_v3(-5, 0.5, 0.5), zr_v3(1, 0, 0), 0.0, h),
                   2);
  /* With e -> 0 the shape is max(|x|, |y|)^2 + z^2 < 1 (for n = 1): a
     square in x, y swept round in z.  At y = z = 0.5 its face is at
     x = -sqrt(0.75); (1 + 1^2000)^0.001 - 1 = 7e-4 is the most e = 0.001
     can differ from that in F, where y = |x|, which is not the case
     here: 1e-9 holds. */
  assert_near(h[0].t, 5.0 - sqrt(0.75), SE_EPS);
}


/* The manual's frame: two nested squares, the hole between them. */
static void test_shapes_prism_linear_frame(void **state) {
  fixture *f = *state;
  const zr_object *o =
      only(f, "prism { linear_spline 0, 1, 10,\n"
              "  <0,0>, <6,0>, <6,8>, <0,8>, <0,0>,\n"
              "  <1,1>, <5,1>, <5,7>, <1,7>, <1,1> }\n");
  assert_int_equal(o->kind, ZR_OBJ_PRISM);
  assert_int_equal(o->u.prism.n_seg, 8);
  zr_hit h[2];
  /* Along x at z = 4: wall at 0, inner walls at 1 and 5, wall at 6.
     Lines meet lines at quotients of small integers: 1e-12. */
  assert_int_equal(cross(o, zr_v3(-5, 0.5, 4), zr_v3(1, 0, 0), 0.0, h), 2);
  assert_near(h[0].t, 5.0, 1e-12);
  assert_near(h[1].t, 6.0, 1e-12);
  assert_vec(h[0].normal, -1, 0, 0, 1e-12);
  assert_vec(h[1].normal, 1, 0, 0, 1e-12);
  assert_int_equal(cross(o, zr_v3(-5, 0.5, 4), zr_v3(1, 0, 0), 6.5, h), 2);
  assert_near(h[0].t, 10.0, 1e-12);
  assert_vec(h[0].normal, -1, 0, 0, 1e-12);
  assert_near(h[1].t, 11.0, 1e-12);
  /* Down through the rim: the caps; down through the hole: nothing. */
  assert_int_equal(cross(o, zr_v3(0.5, 5, 4), zr_v3(0, -1, 0), 0.0, h), 2);
  assert_near(h[0].t, 4.0, 1e-12);
  assert_vec(h[0].normal, 0, 1, 0, 1e-12);
  assert_vec(h[1].normal, 0, -1, 0, 1e-12);
  assert_int_equal(cross(o, zr_v3(3, 5, 4), zr_v3(0, -1, 0), 0.0, h), 0);
  /* Its two crossings through the rim are all it has there, so a CSG
     asks no further (interval_free); of four, the far two are not. */
  bool all = false;
  zr_ray rim = {zr_v3(-5, 0.5, 0.5), zr_v3(1, 0, 0)};
  assert_int_equal(zr__intersect_all(o, &rim, 0.0, INFINITY, false, h, &all),
                   2);
  assert_true(all);
  zr_ray hole = {zr_v3(-5, 0.5, 4), zr_v3(1, 0, 0)};
  assert_int_equal(
      zr__intersect_all(o, &hole, 0.0, INFINITY, false, h, &all), 2);
  assert_false(all);
  assert_true(zr__inside(o, zr_v3(0.5, 0.5, 4)));
  assert_false(zr__inside(o, zr_v3(3, 0.5, 4)));
  assert_false(zr__inside(o, zr_v3(0.5, 1.5, 4)));
  zr_vec3 lo, hi;
  assert_true(zr__object_bounds(o, &lo, &hi));
  assert_vec(lo, 0, 0, 0, 1e-6);
  assert_vec(hi, 6, 1, 8, 1e-6);
}

/* Bezier quarter circles' standard handle 0.5523 make a near circle;
   conic sweep scales it by y; open drops the caps. */
static void test_shapes_prism_bezier_conic_open(void **state) {
  fixture *f = *state;
  const zr_object *o =
      only(f, "prism { bezier_spline conic_sweep 0.5, 1, 16,\n"
              "  <1, 0>, <1, 0.5523>, <0.5523, 1>, <0, 1>,\n"
              "  <0, 1>, <-0.5523, 1>, <-1, 0.5523>, <-1, 0>,\n"
              "  <-1, 0>, <-1, -0.5523>, <-0.5523, -1>, <0, -1>,\n"
              "  <0, -1>, <0.5523, -1>, <1, -0.5523>, <1, 0> open }\n");
  assert_true(o->u.prism.conic && o->u.prism.open);
  zr_hit h[2];
  /* At height 0.8 the curve has radius 0.8: the walls at x = -+0.8,
     exact at the Bezier's end points (1e-12); the cone's normal leans
     down, (1, -1, 0) / sqrt 2 on the far side. */
  assert_int_equal(cross(o, zr_v3(-5, 0.8, 0), zr_v3(1, 0, 0), 0.0, h), 2);
  assert_near(h[0].t, 4.2, 1e-12);
  assert_near(h[1].t, 5.8, 1e-12);
  double k = sqrt(0.5);
  assert_vec(h[1].normal, k, -k, 0, 1e-9);
  /* Open: straight down the axis meets nothing. */
  assert_int_equal(cross(o, zr_v3(0, 5, 0), zr_v3(0, -1, 0), 0.0, h), 0);
  assert_true(zr__inside(o, zr_v3(0.5, 0.8, 0)));
  assert_false(zr__inside(o, zr_v3(0.7, 0.6, 0))); /* radius 0.6 there */
  assert_false(zr__inside(o, zr_v3(0, 0.4, 0)));    /* below the base */
}

/* The quadratic and cubic splines as measured on POV-Ray: parabolas
   through three points, Catmull-Rom pieces. */
static void test_shapes_prism_spline_forms(void **state) {
  fixture *f = *state;
  const zr_object *o =
      only(f, "prism { quadratic_spline 0, 1, 6,\n"
              "  <-1,-1>, <0,0>, <4,0>, <4,4>, <0,4>, <0,0> }\n");
  assert_int_equal(o->u.prism.n_seg, 4);
  /* The first piece: (2.5 s + 1.5 s^2, 0.5 s - 0.5 s^2). */
  const double *seg = o->u.prism.seg;
  double want[8] = {0, 2.5, 1.5, 0, 0, 0.5, -0.5, 0};
  for (int i = 0; i < 8; i++)
    assert_near(seg[i], want[i], 1e-12);
  zr_hit h[2];
  /* Down at x = 1 (s = 1/3): the wall at z = 1/9 from below. */
  assert_int_equal(cross(o, zr_v3(1, 0.5, -5), zr_v3(0, 0, 1), 0.0, h), 2);
  assert_near(h[0].t, 5.0 + 1.0 / 9.0, 1e-12);
  o = only(f, "prism { cubic_spline 0, 1, 7,\n"
              "  <0,-1>, <0,0>, <4,0>, <4,4>, <0,4>, <0,0>, <4,0> }\n");
  assert_int_equal(o->u.prism.n_seg, 4);
  /* From a = (0,0) to b = (4,0), end slopes ta = (2, 0.5) and
     tb = (2, 2): a + ta s + (3 (b - a) - 2 ta - tb) s^2
     + (2 (a - b) + ta + tb) s^3. */
  seg = o->u.prism.seg;
  double cubic[8] = {0, 2, 6, -4, 0, 0.5, -3, 2.5};
  for (int i = 0; i < 8; i++)
    assert_near(seg[i], cubic[i], 1e-12);
}

/* A uniform number in [0, 1) from a 64-bit LCG (Knuth's MMIX). */
static double lcg_uniform(uint64_t *seed) {
  *seed = *seed * 6364136223846793005ULL + 1442695040888963407ULL;
  return (double)(*seed >> 11) * 0x1p-53;
}

/* The walls' sides worked out once (zr__prism_wall_sides) give the same
   crossings and normals, bit for bit, as the per-hit test beside the
   wall, which a copy without them falls back on: rays from all around
   at prisms with holes, crossing and touching sub-prisms, sharp spikes
   and a zero-length piece.  The ones with straight pieces clear of the
   others must have their sides known (else the fast path is never
   taken), and pieces that others cross must not. */
static void test_shapes_prism_wall_sides(void **state) {
  fixture *f = *state;
  static const struct {
    const char *text;
    int known_min, unknown_min; /* pieces of each kind, at least */
  } cases[] = {
      /* The corpus' aug10-2.pov hexagon, and a frame (hole inside). */
      {"prism { linear_sweep linear_spline 0, 1, 7, <3,5>, <-3,5>,\n"
       "  <-5,0>, <-3,-5>, <3,-5>, <5,0>, <3,5> rotate 90*x }\n",
       6, 0},
      {"prism { linear_spline -1, 2, 10, <0,0>, <0,8>, <6,8>, <6,0>,\n"
       "  <0,0>, <1,1>, <5,1>, <5,7>, <1,7>, <1,1> }\n",
       8, 0},
      /* Two squares overlapping (their crossing walls change side
         halfway), a triangle touching one at a corner. */
      {"prism { linear_spline 0, 1, 14, <0,0>, <4,0>, <4,4>, <0,4>,\n"
       "  <0,0>, <2,2>, <6,2>, <6,6>, <2,6>, <2,2>, <4,4>, <8,3>,\n"
       "  <8,5>, <4,4> }\n",
       0, 6},
      /* A star of needle-sharp spikes, and a repeated point. */
      {"prism { linear_spline 0, 0.5, 9, <0,0>, <10,0>, <0,0.01>,\n"
       "  <-10,0.6>, <0,1>, <0,1>, <-0.2,0.5>, <-10,-0.3>, <0,0> }\n",
       2, 2},
  };
  uint64_t seed = 12345;
  for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
    const zr_object *o = only(f, cases[c].text);
    assert_int_equal(o->kind, ZR_OBJ_PRISM);
    const signed char *side = o->u.prism.side;
    assert_non_null(side);
    int known = 0, unknown = 0;
    for (size_t i = 0; i < o->u.prism.n_seg; i++)
      side[i] ? known++ : unknown++;
    assert_true(known >= cases[c].known_min);
    assert_true(unknown >= cases[c].unknown_min);
    zr_object plain;
    memcpy(&plain, o, zr__object_size(o->kind));
    plain.u.prism.side = NULL;
    zr_vec3 lo, hi;
    assert_true(zr__object_bounds(o, &lo, &hi));
    zr_vec3 mid = zr_v3_scale(zr_v3_add(lo, hi), 0.5);
    double r = zr_v3_len(zr_v3_sub(hi, lo));
    int crossings = 0;
    for (int k = 0; k < 4000; k++) {
      /* From a sphere around the prism towards a point in its box. */
      double u = 2.0 * lcg_uniform(&seed) - 1.0;
      double a = 2.0 * M_PI * lcg_uniform(&seed), w = sqrt(1.0 - u * u);
      zr_vec3 from = zr_v3_madd(mid, zr_v3(w * cos(a), u, w * sin(a)), r);
      zr_vec3 to = zr_v3(lo.x + (hi.x - lo.x) * lcg_uniform(&seed),
                         lo.y + (hi.y - lo.y) * lcg_uniform(&seed),
                         lo.z + (hi.z - lo.z) * lcg_uniform(&seed));
      zr_vec3 d = zr_v3_sub(to, from);
      for (double tmin = 0.0; tmin < 2.0; tmin += 0.5) {
        zr_hit fast[ZR_MAX_CROSSINGS], slow[ZR_MAX_CROSSINGS];
        int n = cross(o, from, d, tmin, fast);
        assert_int_equal(cross(&plain, from, d, tmin, slow), n);
        for (int i = 0; i < n; i++) {
          assert_memory_equal(&fast[i].t, &slow[i].t, sizeof fast[i].t);
          assert_memory_equal(&fast[i].normal, &slow[i].normal,
                              sizeof fast[i].normal);
          crossings++;
        }
      }
    }
    assert_true(crossings > 1000);
  }
}

/* Whether (x, z) is inside the closed polygon of n corners pt (x, z
   pairs) by the even-odd rule, written out plainly for the test. */
static bool polygon_holds(const double *pt, int n, double x, double z) {
  bool in = false;
  for (int i = 0, j = n - 1; i < n; j = i++) {
    double xi = pt[2 * i], zi = pt[2 * i + 1];
    double xj = pt[2 * j], zj = pt[2 * j + 1];
    if ((zi > z) != (zj > z) && x < xi + (z - zi) * (xj - xi) / (zj - zi))
      in = !in;
  }
  return in;
}

/* The corpus' aug10-2.pov frame (a hexagon with a hexagonal hole) met
   by rays near the sweep, as down its tunnel (walls passed over are
   turned down by a box test of the ray's short stroke seen from
   above, and straight pieces' even-odd roots are solved inline), and
   by rays across it: the crossings are the walls' and the caps'
   worked out here with plain line algebra (random rays: no corner
   is ever hit exactly; 1e-9 covers the solve's rounding), and inside
   is the even-odd rule. */
static void test_shapes_prism_along_sweep(void **state) {
  fixture *f = *state;
  static const double outer[12] = {3, 5, -3, 5, -5, 0, -3, -5, 3, -5, 5, 0};
  static const double inner[12] = {2.4, 4,  -2.4, 4,  -4, 0,
                                   -2.4, -4, 2.4, -4, 4,  0};
  const zr_object *o =
      only(f, "prism { linear_sweep linear_spline 0, 1, 14,\n"
              "  <3,5>, <-3,5>, <-5,0>, <-3,-5>, <3,-5>, <5,0>, <3,5>,\n"
              "  <2.4,4>, <-2.4,4>, <-4,0>, <-2.4,-4>, <2.4,-4>, <4,0>,\n"
              "  <2.4,4> }\n");
  assert_int_equal(o->kind, ZR_OBJ_PRISM);
  const double *poly[2] = {outer, inner};
  uint64_t seed = 777;
  int walls = 0, caps = 0, through = 0;
  for (int k = 0; k < 20000; k++) {
    /* From below or above, tilted by up to 0.3 (k < 15000) or up to
       3 (across the walls). */
    double tilt = k < 15000 ? 0.3 : 3.0;
    double up = lcg_uniform(&seed) < 0.5 ? 1.0 : -1.0;
    zr_vec3 org = zr_v3(12.0 * lcg_uniform(&seed) - 6.0,
                        up > 0 ? -1.0 - lcg_uniform(&seed)
                               : 2.0 + lcg_uniform(&seed),
                        12.0 * lcg_uniform(&seed) - 6.0);
    zr_vec3 dir = zr_v3(tilt * (2.0 * lcg_uniform(&seed) - 1.0), up,
                        tilt * (2.0 * lcg_uniform(&seed) - 1.0));
    double want[32];
    int n_want = 0;
    for (int c = 0; c < 2; c++)
      for (int i = 0; i < 6; i++) {
        const double *a = poly[c] + 2 * i, *b = poly[c] + 2 * ((i + 1) % 6);
        /* org + t dir = a + u (b - a) in x and z. */
        double ex = b[0] - a[0], ez = b[1] - a[1];
        double det = dir.x * -ez + ex * dir.z;
        if (det == 0.0)
          continue;
        double rx = a[0] - org.x, rz = a[1] - org.z;
        double t = (rx * -ez + ex * rz) / det;
        double u = (dir.x * rz - dir.z * rx) / det;
        double y = org.y + t * dir.y;
        if (u >= 0.0 && u < 1.0 && t > 0.0 && y >= 0.0 && y <= 1.0)
          want[n_want++] = t;
      }
    int n_wall = n_want;
    for (int h = 0; h < 2; h++) {
      double t = ((double)h - org.y) / dir.y;
      double x = org.x + t * dir.x, z = org.z + t * dir.z;
      if (t > 0.0 && polygon_holds(outer, 6, x, z) !=
                         polygon_holds(inner, 6, x, z))
        want[n_want++] = t;
    }
    for (int i = 1; i < n_want; i++)
      for (int j = i; j > 0 && want[j - 1] > want[j]; j--) {
        double keep = want[j];
        want[j] = want[j - 1];
        want[j - 1] = keep;
      }
    double t[ZR_SHAPE_MAX_CROSSINGS];
    zr_vec3 nrm[ZR_SHAPE_MAX_CROSSINGS];
    int n = zr__prism_crossings(o, org, dir, 0.0, INFINITY, t, nrm);
    int m = n_want < ZR_SHAPE_MAX_CROSSINGS ? n_want
                                            : ZR_SHAPE_MAX_CROSSINGS;
    assert_int_equal(n, m);
    for (int i = 0; i < n; i++)
      assert_near(t[i], want[i], 1e-9);
    walls += n_wall > 0;
    caps += n_want > n_wall;
    through += n_want == 0 && fabs(org.x) < 2.0 && fabs(org.z) < 2.0;
    /* Inside: a point of the ray at the height of the frame. */
    double ty = (0.5 - org.y) / dir.y;
    zr_vec3 p = zr_v3_madd(org, dir, ty);
    assert_int_equal(zr__inside(o, p),
                     polygon_holds(outer, 6, p.x, p.z) !=
                         polygon_holds(inner, 6, p.x, p.z));
  }
  /* All three kinds of ray are met, many times. */
  assert_true(walls > 1000 && caps > 1000 && through > 100);
}

/* The quaternion orbit kept in locals (obj_julia.c quaternion_orbit)
   decides inside as the loop over arrays it replaced, written out here
   in the same arithmetic: sqr and cube, at points all over the
   bounding ball and beyond (default slice: w = 0). */
static void test_shapes_julia_quaternion_orbit(void **state) {
  fixture *f = *state;
  static const char *const texts[] = {
      "julia_fractal { <-0.083, 0, -0.83, -0.025> quaternion sqr\n"
      "  max_iteration 8 precision 15 }\n",
      "julia_fractal { <-0.2, 0.4, 0.1, 0.3> quaternion cube\n"
      "  max_iteration 12 }\n",
  };
  uint64_t seed = 99;
  for (int c = 0; c < 2; c++) {
    const zr_object *o = only(f, texts[c]);
    assert_int_equal(o->kind, ZR_OBJ_JULIA);
    const struct zr_julia *j = o->u.julia.data;
    int power = c == 0 ? 2 : 3, in_count = 0;
    for (int k = 0; k < 20000; k++) {
      double h[4] = {0.0, 0.0, 0.0, 0.0};
      for (int m = 0; m < 3; m++)
        h[m] = 2.4 * (2.0 * lcg_uniform(&seed) - 1.0);
      zr_vec3 p = zr_v3(h[0], h[1], h[2]);
      int i = 0;
      for (; i < j->max_iteration; i++) {
        double n2 = h[0] * h[0] + h[1] * h[1] + h[2] * h[2] + h[3] * h[3];
        if (n2 > j->escape * j->escape)
          break;
        double next[4], x = h[0], vv = n2 - h[0] * h[0];
        if (power == 2) {
          next[0] = x * x - vv;
          for (int m = 1; m < 4; m++)
            next[m] = 2.0 * x * h[m];
        } else {
          double sv = 3.0 * x * x - vv;
          next[0] = x * (x * x - 3.0 * vv);
          for (int m = 1; m < 4; m++)
            next[m] = sv * h[m];
        }
        for (int m = 0; m < 4; m++)
          h[m] = next[m] + j->c[m];
      }
      bool in = i == j->max_iteration;
      in_count += in;
      assert_int_equal(zr__inside(o, p), in);
    }
    /* Both kinds of point are met. */
    assert_true(in_count > 100 && in_count < 19900);
  }
}

/* The bisection's three orbits at once (obj_julia.c,
   zr__julia_points_inside) say inside where zr__julia_inside does, for
   each algebra with sqr and cube, three points whose orbits escape at
   different steps (or never), on a skewed slice too; the other
   functions are left to one orbit at a time. */
static void test_shapes_julia_points_inside(void **state) {
  fixture *f = *state;
  static const char *const texts[] = {
      "julia_fractal { <-0.083, 0, -0.83, -0.025> quaternion sqr\n"
      "  max_iteration 8 }\n",
      "julia_fractal { <-0.2, 0.4, 0.1, 0.3> quaternion cube\n"
      "  max_iteration 12 }\n",
      "julia_fractal { <0.2, 0.1, 0.59, -0.2> hypercomplex sqr\n"
      "  max_iteration 7 slice <0.1, 0.2, 0.3, 1>, 0.2 }\n",
      "julia_fractal { <0.1, 0.2, 0.0, -0.1> hypercomplex cube\n"
      "  max_iteration 8 }\n",
  };
  /* Each a box about its object (the hypercomplex ones are small). */
  static const double scale[4] = {0.5, 0.5, 0.3, 0.3};
  uint64_t seed = 4242;
  for (int c = 0; c < 4; c++) {
    const zr_object *o = only(f, texts[c]);
    const struct zr_julia *j = o->u.julia.data;
    int in_count = 0, mixed = 0;
    for (int k = 0; k < 6000; k++) {
      zr_vec3 p[3];
      for (int l = 0; l < 3; l++)
        p[l] = zr_v3(4.4 * (2.0 * lcg_uniform(&seed) - 1.0),
                     4.4 * (2.0 * lcg_uniform(&seed) - 1.0),
                     4.4 * (2.0 * lcg_uniform(&seed) - 1.0));
      for (int l = 0; l < 3; l++)
        p[l] = zr_v3_scale(p[l], scale[c]);
      bool in[3];
      assert_true(zr__julia_points_inside(j, p, in));
      for (int l = 0; l < 3; l++) {
        assert_int_equal(in[l], zr__julia_inside(o, p[l]));
        in_count += in[l];
      }
      mixed += in[0] != in[1] || in[1] != in[2];
    }
    assert_true(in_count > 100 && in_count < 17900);
    assert_true(mixed > 100);
  }
  const zr_object *o = only(f, "julia_fractal { <0.2, 0, 0, 0> hypercomplex "
                               "sin max_iteration 6 }\n");
  zr_vec3 p[3] = {zr_v3(0, 0, 0), zr_v3(1, 0, 0), zr_v3(0, 1, 0)};
  bool in[3] = {false, false, false};
  assert_false(zr__julia_points_inside(o->u.julia.data, p, in));
}

/* The march with its orbits iterated two and three together (the next
   sample with the one a step ahead, the bisection's middle and quarter
   points) finds the crossings and normals of the march that takes
   them one at a time, bit for bit: rays from all sides through each
   algebra with sqr and cube, and a function without lanes. */
static void test_shapes_julia_march_lanes(void **state) {
  fixture *f = *state;
  static const char *const texts[] = {
      "julia_fractal { <0.02, -0.02, 0.8, 0> quaternion sqr\n"
      "  max_iteration 10 precision 20 }\n",
      "julia_fractal { <-0.2, 0.4, 0.1, 0.3> quaternion cube\n"
      "  max_iteration 12 precision 30 }\n",
      "julia_fractal { <0.2, 0.1, 0.59, -0.2> hypercomplex sqr\n"
      "  max_iteration 7 precision 20 }\n",
      "julia_fractal { <-0.54, 0.57, 0.0, -0.37> hypercomplex cube\n"
      "  max_iteration 8 precision 20 }\n",
      "julia_fractal { <0.2, 0.1, 0, 0> hypercomplex exp\n"
      "  max_iteration 6 precision 10 }\n",
  };
  uint64_t seed = 77;
  for (int c = 0; c < 5; c++) {
    const zr_object *o = only(f, texts[c]);
    int crossings = 0, several = 0;
    for (int k = 0; k < 400; k++) {
      zr_vec3 from = zr_v3(2.0 * lcg_uniform(&seed) - 1.0,
                           2.0 * lcg_uniform(&seed) - 1.0,
                           2.0 * lcg_uniform(&seed) - 1.0);
      from = zr_v3_scale(zr_v3_norm(from), 5.0);
      zr_vec3 to = zr_v3(0.8 * (2.0 * lcg_uniform(&seed) - 1.0),
                         0.8 * (2.0 * lcg_uniform(&seed) - 1.0),
                         0.8 * (2.0 * lcg_uniform(&seed) - 1.0));
      zr_vec3 dir = zr_v3_scale(zr_v3_sub(to, from), 0.5);
      double ta[4], tb[4];
      zr_vec3 na[4], nb[4];
      int a = zr__julia_crossings(o, from, dir, 0.0, INFINITY, ta, na);
      int b = zr__julia_crossings_plain(o, from, dir, 0.0, INFINITY, tb, nb);
      assert_int_equal(a, b);
      for (int i = 0; i < a; i++) {
        assert_true(ta[i] == tb[i]);
        assert_true(na[i].x == nb[i].x && na[i].y == nb[i].y &&
                    na[i].z == nb[i].z);
      }
      crossings += a;
      several += a > 2;
    }
    assert_true(crossings > 100);
    if (c < 4)
      assert_true(several > 5);
  }
}

static void test_shapes_prism_bad_input(void **state) {
  fixture *f = *state;
  bad(f, "prism { 0, 1, 2, <0, 0>, <1, 0> }\n", ZR_ESCENE,
      "this prism needs at least 3 points, not 2", NULL);
  bad(f, "prism { 0, 1, 3, <0, 0, 0>, <1, 0, 0>, <0, 0, 1> }\n", ZR_ESCENE,
      "a prism's points are 2-D vectors <x, z>", NULL);
  bad(f, "prism { bezier_spline 0, 1, 5, <0,0>, <1,0>, <1,1>, <0,1>,\n"
         "  <0,0> }\n",
      ZR_ESCENE, "a bezier_spline prism needs 4 points a piece, not 5 "
                 "points", NULL);
  bad(f, "prism { cubic_spline 0, 1, 5, <0,0>, <1,0>, <1,1>, <0,1>,\n"
         "  <0,0> }\n",
      ZR_ESCENE, "a sub-prism of this spline is not closed: its first "
                 "curve point must come again", NULL);
  good(f, "prism { 0, 1, 3, <0, 0>, <1, 0>, <0, 1> }\n");
  assert_int_equal(f->diag.warnings, 1);
  assert_non_null(
      strstr(f->diag.warning, "Linear prism not closed. Closing it."));
}

/* The manual's thick tube: radii 2 and 3, height 5. */
static void test_shapes_lathe_tube(void **state) {
  fixture *f = *state;
  const zr_object *o =
      only(f, "lathe { linear_spline 5, <2, 0>, <3, 0>, <3, 5>, <2, 5>,\n"
              "  <2, 0> }\n");
  assert_int_equal(o->kind, ZR_OBJ_LATHE);
  assert_int_equal(o->u.lathe.n_seg, 4);
  zr_hit h[2];
  /* A slanted ray, so the degree-six equation is used: across the
     wall at x = -3 and -2 on its way.  Roots of a polynomial with small
     integer coefficients: 1e-9. */
  zr_vec3 d = zr_v3(1, 0.1, 0);
  assert_int_equal(cross(o, zr_v3(-5, 1, 0), d, 0.0, h), 2);
  assert_near(h[0].t, 2.0, 1e-9);
  assert_near(h[1].t, 3.0, 1e-9);
  assert_vec(h[0].normal, -1, 0, 0, 1e-9);
  assert_vec(h[1].normal, 1, 0, 0, 1e-9);
  assert_int_equal(cross(o, zr_v3(-5, 1, 0), d, 3.5, h), 2);
  assert_near(h[0].t, 7.0, 1e-9);
  assert_vec(h[0].normal, -1, 0, 0, 1e-9);
  assert_near(h[1].t, 8.0, 1e-9);
  /* Horizontal: the circles at the ray's height. */
  assert_int_equal(cross(o, zr_v3(0, 2, -5), zr_v3(0, 0, 1), 0.0, h), 2);
  assert_near(h[0].t, 2.0, 1e-12);
  assert_near(h[1].t, 3.0, 1e-12);
  assert_vec(h[0].normal, 0, 0, -1, 1e-9);
  /* Down into the wall from above: the top ring. */
  assert_int_equal(cross(o, zr_v3(0, 9, 2.5), zr_v3(0, -1, 0), 0.0, h), 2);
  assert_near(h[0].t, 4.0, 1e-9);
  assert_vec(h[0].normal, 0, 1, 0, 1e-9);
  assert_near(h[1].t, 9.0, 1e-9);
  assert_true(zr__inside(o, zr_v3(0, 1, 2.5)));
  assert_true(zr__inside(o, zr_v3(-1.8, 4, 1.8)));
  assert_false(zr__inside(o, zr_v3(0, 1, 1.5)));
  assert_false(zr__inside(o, zr_v3(0, 6, 2.5)));
  zr_vec3 lo, hi;
  assert_true(zr__object_bounds(o, &lo, &hi));
  assert_vec(lo, -3, 0, -3, 1e-6);
  assert_vec(hi, 3, 5, 3, 1e-6);
}

static void test_shapes_lathe_bad_input(void **state) {
  fixture *f = *state;
  bad(f, "lathe { cubic_spline 3, <0, 0>, <1, 0>, <1, 1> }\n", ZR_ESCENE,
      "this lathe needs at least 4 points, not 3", NULL);
  bad(f, "lathe { conic_sweep 3, <0, 0>, <1, 0>, <1, 1> }\n", ZR_ESYNTAX,
      "a lathe takes a spline type, not a sweep", NULL);
  bad(f, "lathe { 2, <0, 0>, <1, 0>, <1, 1> }\n", ZR_ESCENE,
      "the lathe has more points than the 2 it announced", NULL);
  bad(f, "lathe { 2, <0, 0, 0>, <1, 0, 0> }\n", ZR_ESCENE,
      "a lathe's points are 2-D vectors <r, y>", NULL);
}

/* One sphere component: the surface is the sphere where
   s (1 - d^2 / r^2)^2 = threshold. */
static void test_shapes_blob_sphere_and_cylinder(void **state) {
  fixture *f = *state;
  const zr_object *o =
      only(f, "blob { threshold 0.25 sphere { <0, 0, 0>, 2, strength 1 }\n"
              "  cylinder { <5, 0, 0>, <5, 4, 0>, 1, 1 } }\n");
  assert_int_equal(o->kind, ZR_OBJ_BLOB);
  assert_int_equal(o->u.blob.n_components, 2);
  /* (1 - d^2 / 4)^2 = 1/4: d^2 = 2.  Quartic roots of a well-scaled
     field: 1e-9. */
  double d = sqrt(2.0);
  zr_hit h[2];
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0.0, h), 2);
  assert_near(h[0].t, 5.0 - d, 1e-9);
  assert_near(h[1].t, 5.0 + d, 1e-9);
  assert_vec(h[0].normal, -1, 0, 0, 1e-9);
  /* The cylinder: radius sqrt(1/2) about its axis, round ends. */
  double c = sqrt(0.5);
  assert_int_equal(cross(o, zr_v3(5, 2, -5), zr_v3(0, 0, 1), 0.0, h), 2);
  assert_near(h[0].t, 5.0 - c, 1e-9);
  assert_vec(h[0].normal, 0, 0, -1, 1e-9);
  assert_int_equal(cross(o, zr_v3(5, 9, 0), zr_v3(0, -1, 0), 0.0, h), 2);
  assert_near(h[0].t, 5.0 - c, 1e-9);
  assert_vec(h[0].normal, 0, 1, 0, 1e-9);
  assert_near(h[1].t, 9.0 + c, 1e-9);
  assert_true(zr__inside(o, zr_v3(1, 0, 0)));
  assert_false(zr__inside(o, zr_v3(1.5, 0, 0)));
  assert_near(zr__blob_density(o, zr_v3(0, 0, 0)), 1.0, 1e-15);
  zr_vec3 lo, hi;
  assert_true(zr__object_bounds(o, &lo, &hi));
  assert_vec(lo, -2, -2, -2, 1e-6);
  assert_vec(hi, 6, 5, 2, 1e-6);
}

/* Two spheres melt into one surface; a negative one dents it; a ray
   leaving through the middle finds the far side, wherever it starts. */
static void test_shapes_blob_fields_add(void **state) {
  fixture *f = *state;
  const zr_object *o =
      only(f, "blob { threshold 0.5\n"
              "  sphere { <-0.5, 0, 0>, 1, 1 }\n"
              "  sphere { 0, 1, 1 scale <1, 1, 1> translate x * 0.5 }\n"
              "  component -1, 0.5, <0, 0, -0.7> }\n");
  zr_hit h[2];
  /* At the middle both add (1 - 0.25)^2 = 0.5625 each. */
  assert_true(zr__inside(o, zr_v3(0, 0, 0)));
  assert_near(zr__blob_density(o, zr_v3(0, 0, 0)), 1.125, 1e-12);
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0.0, h), 2);
  double first = h[0].t, second = h[1].t;
  assert_near(first + second, 10.0, 1e-9); /* symmetric */
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 5.0, h), 1);
  assert_near(h[0].t, second, 0.0); /* the same t, bit for bit */
  /* The dent: along z the surface is nearer the centre at -z. */
  assert_int_equal(cross(o, zr_v3(0, 0, -5), zr_v3(0, 0, 1), 0.0, h), 2);
  assert_true(5.0 - h[0].t < h[1].t - 5.0);
  bad(f, "blob { sphere { 0, 1, 1 no_shadow } }\n", ZR_ESYNTAX,
      "a blob component takes a texture, pigment, normal, finish and "
      "transformations only", NULL);
  bad(f, "blob { threshold 0 sphere { 0, 1, 1 } }\n", ZR_ESCENE,
      "a blob's threshold must be positive", NULL);
}

/* Points on a line r = 1 + y / 2 give r^2 = (1 + y/2)^2 exactly: the
   manual's slopes are then the true ones and the cubic is exact. */
static void test_shapes_sor_cone(void **state) {
  fixture *f = *state;
  const zr_object *o =
      only(f, "sor { 5, <0.5, -1>, <1, 0>, <1.5, 1>, <2, 2>, <2.5, 3> }\n");
  assert_int_equal(o->kind, ZR_OBJ_SOR);
  assert_int_equal(o->u.sor.n_seg, 2);
  zr_hit h[2];
  /* At y = 0.5 the radius is 1.25.  Cubic roots: 1e-9. */
  assert_int_equal(cross(o, zr_v3(-5, 0.5, 0), zr_v3(1, 0, 0), 0.0, h), 2);
  assert_near(h[0].t, 5.0 - 1.25, 1e-9);
  assert_near(h[1].t, 5.0 + 1.25, 1e-9);
  /* The normal of the cone r = 1 + y / 2: (1, -1/2, 0) normalised. */
  double k = 1.0 / sqrt(1.25);
  assert_vec(h[1].normal, k, -0.5 * k, 0, 1e-9);
  /* A slanted ray, through the cubic in t. */
  assert_int_equal(cross(o, zr_v3(-5, 1.5, 1), zr_v3(1, 0.01, 0), 0.0, h),
                   2);
  zr_vec3 p = zr_v3_madd(zr_v3(-5, 1.5, 1), zr_v3(1, 0.01, 0), h[0].t);
  double r = 1.0 + p.y / 2.0;
  assert_near(p.x * p.x + p.z * p.z, r * r, 1e-9);
  /* Down the axis: the caps at y = 2 (radius 2) and y = 0. */
  assert_int_equal(cross(o, zr_v3(0.5, 5, 0), zr_v3(0, -1, 0), 0.0, h), 2);
  assert_near(h[0].t, 3.0, 1e-12);
  assert_vec(h[0].normal, 0, 1, 0, 1e-12);
  assert_near(h[1].t, 5.0, 1e-12);
  assert_vec(h[1].normal, 0, -1, 0, 1e-12);
  assert_true(zr__inside(o, zr_v3(1.2, 1, 0)));
  assert_false(zr__inside(o, zr_v3(1.6, 1, 0)));
  assert_false(zr__inside(o, zr_v3(0, 2.5, 0)));
  zr_vec3 lo, hi;
  assert_true(zr__object_bounds(o, &lo, &hi));
  assert_vec(lo, -2, 0, -2, 1e-6);
  assert_vec(hi, 2, 2, 2, 1e-6);
  o = only(f, "sor { 5, <0.5, -1>, <1, 0>, <1.5, 1>, <2, 2>, <2.5, 3>\n"
              "  open }\n");
  assert_int_equal(cross(o, zr_v3(0.5, 5, 0), zr_v3(0, -1, 0), 0.0, h), 0);
  bad(f, "sor { 4, <1, 0>, <1, 1>, <1, 0.5>, <1, 2> }\n", ZR_ESCENE,
      "the heights of a sor's points must increase", NULL);
  bad(f, "sor { 3, <1, 0>, <1, 1>, <1, 2> }\n", ZR_ESCENE,
      "a sor needs at least 4 points, not 3", NULL);
}

#define TEST(fn) cmocka_unit_test_setup_teardown(fn, setup, teardown)

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_shapes_roots_clustered_quartic),
      cmocka_unit_test(test_shapes_roots_multiplicity),
      cmocka_unit_test(test_shapes_roots_wide_interval),
      cmocka_unit_test(test_shapes_roots_walk_same_bits),
      TEST(test_shapes_torus_crossings_and_normals),
      TEST(test_shapes_torus_thin_and_transformed),
      TEST(test_shapes_torus_first_same_bits),
      TEST(test_shapes_torus_bad_minor),
      TEST(test_shapes_polygon_even_odd),
      TEST(test_shapes_polygon_tilted_and_open),
      TEST(test_shapes_polygon_bad_counts),
      TEST(test_shapes_superellipsoid_sphere_and_box),
      TEST(test_shapes_superellipsoid_star),
      TEST(test_shapes_superellipsoid_convex_fan),
      TEST(test_shapes_superellipsoid_clamped),
      TEST(test_shapes_prism_linear_frame),
      TEST(test_shapes_prism_bezier_conic_open),
      TEST(test_shapes_prism_spline_forms),
      TEST(test_shapes_prism_wall_sides),
      TEST(test_shapes_prism_along_sweep),
      TEST(test_shapes_julia_quaternion_orbit),
      TEST(test_shapes_julia_points_inside),
      TEST(test_shapes_julia_march_lanes),
      TEST(test_shapes_prism_bad_input),
      TEST(test_shapes_lathe_tube),
      TEST(test_shapes_lathe_bad_input),
      TEST(test_shapes_blob_sphere_and_cylinder),
      TEST(test_shapes_blob_fields_add),
      TEST(test_shapes_sor_cone),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
