/*
 * test_intersect.c - ray/primitive intersections and inside tests against
 * hand-computed hits: every primitive, transformed and not, from outside
 * and inside, tangent rays and misses, and secondary rays leaving a
 * surface at scales from 1e-3 to 1e5.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "core/transform.h"
#include "scene/scene.h"
#include "trace/intersect.h"
#include "trace/shape.h"
#include "test_util.h"

/* Hits here are roots of low-degree polynomials with small integer or
   simple irrational coefficients: 1e-12 covers double rounding. */
#define EPS 1e-12

static zr_ray ray(double ox, double oy, double oz, double dx, double dy,
                  double dz) {
  zr_ray r = {zr_v3(ox, oy, oz), zr_v3(dx, dy, dz)};
  return r;
}

static zr_object sphere(double x, double y, double z, double r) {
  zr_object o;
  memset(&o, 0, sizeof o);
  o.kind = ZR_OBJ_SPHERE;
  o.u.sphere.centre = zr_v3(x, y, z);
  o.u.sphere.radius = r;
  return o;
}

static int hits(const zr_object *o, zr_ray r, zr_hit h[2]) {
  return zr__intersect(o, &r, 0.0, INFINITY, h);
}

static void test_intersect_sphere_outside_and_inside(void **state) {
  (void)state;
  zr_object s = sphere(0, 0, 0, 1);
  zr_hit h[2];
  assert_int_equal(hits(&s, ray(0, 0, -5, 0, 0, 1), h), 2);
  assert_near(h[0].t, 4.0, EPS);
  assert_near(h[1].t, 6.0, EPS);
  assert_vec(h[0].normal, 0, 0, -1, EPS);
  assert_vec(h[1].normal, 0, 0, 1, EPS);
  assert_ptr_equal(h[0].object, &s);
  /* From the centre only the exit is ahead; its normal still points out. */
  assert_int_equal(hits(&s, ray(0, 0, 0, 0, 1, 0), h), 1);
  assert_near(h[0].t, 1.0, EPS);
  assert_vec(h[0].normal, 0, 1, 0, EPS);
  assert_true(zr__inside(&s, zr_v3(0.5, 0.5, 0.5)));
  assert_false(zr__inside(&s, zr_v3(0.6, 0.6, 0.6)));
}

static void test_intersect_sphere_tangent_and_miss(void **state) {
  (void)state;
  zr_object s = sphere(0, 0, 0, 1);
  zr_hit h[2];
  /* Exactly tangent: a double root is a graze, not a crossing. */
  assert_int_equal(hits(&s, ray(1, 0, -5, 0, 0, 1), h), 0);
  assert_int_equal(hits(&s, ray(1.0001, 0, -5, 0, 0, 1), h), 0);
  assert_int_equal(hits(&s, ray(0, 0, -5, 0, 0, -1), h), 0); /* behind */
  /* tmax clips: only the near crossing lies before t = 5. */
  zr_ray r = ray(0, 0, -5, 0, 0, 1);
  assert_int_equal(zr__intersect(&s, &r, 0.0, 5.0, h), 1);
}

static void test_intersect_sphere_transformed_keeps_world_t(void **state) {
  (void)state;
  zr_object s = sphere(0, 0, 0, 1);
  zr_transform t;
  zr__transform_identity(&t);
  zr__transform_scale(&t, zr_v3(2, 2, 2));
  zr__transform_translate(&t, zr_v3(1, 0, 0));
  s.transform = &t;
  zr_hit h[2];
  /* A direction of length 2: t is in units of it, so the surface at
     z = -2 is reached at t = (10 - 2) / 2. */
  assert_int_equal(hits(&s, ray(1, 0, -10, 0, 0, 2), h), 2);
  assert_near(h[0].t, 4.0, EPS);
  assert_near(h[1].t, 6.0, EPS);
  assert_vec(h[0].normal, 0, 0, -1, EPS);
  assert_true(zr__inside(&s, zr_v3(2.9, 0, 0)));
  assert_false(zr__inside(&s, zr_v3(-1.1, 0, 0)));
}

static void test_intersect_ellipsoid_normal_by_inverse_transpose(void **st) {
  (void)st;
  /* x^2/4 + y^2 + z^2 = 1: at (1, sqrt(3)/2, 0) the gradient is
     (x/4, y, z) = (1/4, sqrt(3)/2, 0). */
  zr_object s = sphere(0, 0, 0, 1);
  zr_transform t;
  zr__transform_identity(&t);
  zr__transform_scale(&t, zr_v3(2, 1, 1));
  s.transform = &t;
  zr_hit h[2];
  assert_int_equal(hits(&s, ray(1, 5, 0, 0, -1, 0), h), 2);
  assert_near(h[0].t, 5.0 - sqrt(3.0) / 2.0, EPS);
  zr_vec3 g = zr_v3_norm(zr_v3(0.25, sqrt(3.0) / 2.0, 0));
  assert_vec(h[0].normal, g.x, g.y, g.z, EPS);
}

static void test_intersect_box_faces_rotation_and_parallel(void **state) {
  (void)state;
  zr_object b;
  memset(&b, 0, sizeof b);
  b.kind = ZR_OBJ_BOX;
  b.u.box.corner1 = zr_v3(1, 1, 1); /* corners in either order */
  b.u.box.corner2 = zr_v3(-1, -1, -1);
  zr_hit h[2];
  assert_int_equal(hits(&b, ray(-5, 0.5, 0.25, 1, 0, 0), h), 2);
  assert_near(h[0].t, 4.0, EPS);
  assert_near(h[1].t, 6.0, EPS);
  assert_vec(h[0].normal, -1, 0, 0, EPS);
  assert_vec(h[1].normal, 1, 0, 0, EPS);
  /* From inside only the exit face. */
  assert_int_equal(hits(&b, ray(0, 0, 0, 0, 0, -1), h), 1);
  assert_vec(h[0].normal, 0, 0, -1, EPS);
  /* Parallel to the y faces and above them: a miss. */
  assert_int_equal(hits(&b, ray(-5, 1.5, 0, 1, 0, 0), h), 0);
  /* Rotated 45 degrees about y the box's corner points along -z. */
  zr_transform t;
  zr__transform_identity(&t);
  zr__transform_rotate(&t, zr_v3(0, 45, 0));
  b.transform = &t;
  assert_int_equal(hits(&b, ray(0, 0, -5, 0, 0, 1), h), 2);
  assert_near(h[0].t, 5.0 - sqrt(2.0), 1e-12);
  assert_true(zr__inside(&b, zr_v3(0, 0, 1.4)));
  assert_false(zr__inside(&b, zr_v3(1, 0, 1)));
}

static void test_intersect_plane_sides_and_inverse(void **state) {
  (void)state;
  zr_object p;
  memset(&p, 0, sizeof p);
  p.kind = ZR_OBJ_PLANE;
  p.u.plane.normal = zr_v3(0, 1, 0);
  p.u.plane.distance = -1;
  zr_hit h[2];
  assert_int_equal(hits(&p, ray(0, 3, 0, 0, -2, 0), h), 1);
  assert_near(h[0].t, 2.0, EPS);
  assert_vec(h[0].normal, 0, 1, 0, EPS);
  assert_int_equal(hits(&p, ray(0, 3, 0, 1, 0, 0), h), 0); /* parallel */
  assert_true(zr__inside(&p, zr_v3(0, -2, 0)));
  assert_false(zr__inside(&p, zr_v3(0, 0, 0)));
  p.inverse = true;
  assert_int_equal(hits(&p, ray(0, 3, 0, 0, -2, 0), h), 1);
  assert_vec(h[0].normal, 0, -1, 0, EPS);
  assert_false(zr__inside(&p, zr_v3(0, -2, 0)));
  assert_true(zr__inside(&p, zr_v3(0, 0, 0)));
}

static void test_intersect_triangle_inside_edges_and_miss(void **state) {
  (void)state;
  zr_object t;
  memset(&t, 0, sizeof t);
  t.kind = ZR_OBJ_TRIANGLE;
  t.u.triangle.p[0] = zr_v3(0, 0, 0);
  t.u.triangle.p[1] = zr_v3(1, 0, 0);
  t.u.triangle.p[2] = zr_v3(0, 1, 0);
  zr_hit h[2];
  assert_int_equal(hits(&t, ray(0.25, 0.25, -2, 0, 0, 1), h), 1);
  assert_near(h[0].t, 2.0, EPS);
  assert_vec(h[0].normal, 0, 0, 1, EPS); /* (p1 - p0) x (p2 - p0) */
  assert_int_equal(hits(&t, ray(0.6, 0.6, -2, 0, 0, 1), h), 0);
  assert_int_equal(hits(&t, ray(-0.1, 0.5, -2, 0, 0, 1), h), 0);
  assert_int_equal(hits(&t, ray(0.5, 0.5, -2, 1, 0, 0), h), 0);
  assert_false(zr__inside(&t, zr_v3(0.25, 0.25, 0)));
}

static zr_object cylinder(bool open) {
  zr_object c;
  memset(&c, 0, sizeof c);
  c.kind = ZR_OBJ_CYLINDER;
  c.u.cylinder.base = zr_v3(0, 0, 0);
  c.u.cylinder.cap = zr_v3(0, 2, 0);
  c.u.cylinder.radius = 0.5;
  c.u.cylinder.open = open;
  return c;
}

static void test_intersect_cylinder_capped_and_open(void **state) {
  (void)state;
  zr_object c = cylinder(false);
  zr_hit h[2];
  /* Across the side. */
  assert_int_equal(hits(&c, ray(-3, 1, 0, 1, 0, 0), h), 2);
  assert_near(h[0].t, 2.5, EPS);
  assert_near(h[1].t, 3.5, EPS);
  assert_vec(h[0].normal, -1, 0, 0, EPS);
  /* Along the axis through both caps. */
  assert_int_equal(hits(&c, ray(0.1, -1, 0, 0, 1, 0), h), 2);
  assert_near(h[0].t, 1.0, EPS);
  assert_near(h[1].t, 3.0, EPS);
  assert_vec(h[0].normal, 0, -1, 0, EPS);
  assert_vec(h[1].normal, 0, 1, 0, EPS);
  /* In through the bottom cap, out through the side at y = 1. */
  assert_int_equal(hits(&c, ray(0, -1, 0, 0.25, 1, 0), h), 2);
  assert_vec(h[0].normal, 0, -1, 0, EPS);
  assert_near(h[1].t, 2.0, EPS);
  assert_vec(h[1].normal, 1, 0, 0, EPS);
  /* Above the cap, past the end: a miss. */
  assert_int_equal(hits(&c, ray(-3, 2.5, 0, 1, 0, 0), h), 0);
  /* Open: the axis ray meets no surface, the slanted one only the side,
     seen from within. */
  zr_object o = cylinder(true);
  assert_int_equal(hits(&o, ray(0.1, -1, 0, 0, 1, 0), h), 0);
  assert_int_equal(hits(&o, ray(0, -1, 0, 0.25, 1, 0), h), 1);
  assert_near(h[0].t, 2.0, EPS);
  assert_vec(h[0].normal, 1, 0, 0, EPS);
  assert_true(zr__inside(&c, zr_v3(0.4, 1.9, 0)));
  assert_false(zr__inside(&c, zr_v3(0.4, 2.1, 0)));
  assert_false(zr__inside(&c, zr_v3(0.6, 1, 0)));
}

/* zr__intersect_all says when a part of a CSG object need not be asked
   again beyond its last crossing (lib/trace/csg.c): a sphere's two are
   all it has; a torus, whose list depends on the interval and may hold
   four, is always asked again, and gives its far two then. */
static void test_intersect_all_tells_when_complete(void **state) {
  (void)state;
  zr_object s = sphere(0, 0, 0, 1);
  zr_ray r = ray(0, 0, -5, 0, 0, 1);
  zr_hit h[2];
  bool all = false;
  assert_int_equal(zr__intersect_all(&s, &r, 0.0, INFINITY, false, h, &all),
                   2);
  assert_true(all);
  assert_near(h[1].t, 6.0, EPS);
  assert_int_equal(zr__intersect_all(&s, &r, 6.0, INFINITY, false, h, &all),
                   0);
  zr_object t;
  memset(&t, 0, sizeof t);
  t.kind = ZR_OBJ_TORUS;
  t.u.torus.major = 2.0;
  t.u.torus.minor = 0.5;
  zr_ray across = ray(-5, 0, 0, 1, 0, 0);
  all = true;
  assert_int_equal(
      zr__intersect_all(&t, &across, 0.0, INFINITY, false, h, &all), 2);
  assert_false(all);
  assert_near(h[1].t, 3.5, 1e-9);
  assert_int_equal(
      zr__intersect_all(&t, &across, h[1].t, INFINITY, false, h, &all), 2);
  assert_near(h[0].t, 6.5, 1e-9);
  assert_near(h[1].t, 7.5, 1e-9);
}

/* A small deterministic generator for the randomised checks below. */
static double uniform(uint64_t *seed) {
  *seed = *seed * 6364136223846793005ULL + 1442695040888963407ULL;
  return (double)(*seed >> 11) * (1.0 / 9007199254740992.0);
}

/*
 * The parser measures a cylinder's and a cone's axis once
 * (zr__axis_measure); an object made by hand, with height 0, has the
 * tracer measure it for each ray by the same operations.  Both must give
 * the same crossings and normals to the bit, and the same inside tests:
 * renders are byte for byte those of the per-ray frame.
 */
static void test_intersect_axis_measured_once_same_bits(void **state) {
  (void)state;
  uint64_t seed = 7;
  for (int n = 0; n < 2000; n++) {
    zr_object a;
    memset(&a, 0, sizeof a);
    bool cone = n % 2 == 1;
    a.kind = cone ? ZR_OBJ_CONE : ZR_OBJ_CYLINDER;
    zr_vec3 base = zr_v3(uniform(&seed) - 0.5, uniform(&seed) - 0.5,
                         uniform(&seed) - 0.5);
    zr_vec3 cap = zr_v3(3 * uniform(&seed) - 1.5, 3 * uniform(&seed) - 1.5,
                        3 * uniform(&seed) - 1.5);
    if (cone) {
      a.u.cone.base = base;
      a.u.cone.cap = cap;
      a.u.cone.base_radius = uniform(&seed);
      a.u.cone.cap_radius = n % 6 == 1 ? 0.0 : uniform(&seed);
      a.u.cone.open = n % 5 == 0;
    } else {
      a.u.cylinder.base = base;
      a.u.cylinder.cap = cap;
      a.u.cylinder.radius = uniform(&seed);
      a.u.cylinder.open = n % 5 == 0;
    }
    zr_object b = a;
    if (cone)
      b.u.cone.height = zr__axis_measure(base, cap, &b.u.cone.axis);
    else
      b.u.cylinder.height =
          zr__axis_measure(base, cap, &b.u.cylinder.axis);
    zr_ray r = ray(4 * uniform(&seed) - 2, 4 * uniform(&seed) - 2,
                   4 * uniform(&seed) - 2, uniform(&seed) - 0.5,
                   uniform(&seed) - 0.5, uniform(&seed) - 0.5);
    zr_hit ha[2], hb[2];
    int na = zr__intersect(&a, &r, 0.0, INFINITY, ha);
    int nb = zr__intersect(&b, &r, 0.0, INFINITY, hb);
    assert_int_equal(na, nb);
    for (int k = 0; k < na; k++) {
      assert_memory_equal(&ha[k].t, &hb[k].t, sizeof ha[k].t);
      assert_memory_equal(&ha[k].normal, &hb[k].normal,
                          sizeof ha[k].normal);
    }
    assert_int_equal(zr__inside(&a, r.origin), zr__inside(&b, r.origin));
  }
}

/*
 * A torus skips its quartic for a ray whose part in the torus's box
 * stays beyond the rim or within the hole (obj_torus.c, misses_ring).
 * No crossing may be lost to it: for rays aimed near the rim and the
 * hole's edge, every sign change of the torus's function along the ray
 * (sampled 4,000 times) must be a crossing it reports.
 */
static void test_intersect_torus_ring_test_loses_nothing(void **state) {
  (void)state;
  zr_object t;
  memset(&t, 0, sizeof t);
  t.kind = ZR_OBJ_TORUS;
  t.u.torus.major = 0.5;
  t.u.torus.minor = 0.04;
  uint64_t seed = 11;
  int crossed = 0;
  for (int n = 0; n < 3000; n++) {
    /* A target point at a distance from the axis between 0.4 and 0.6
       (about the hole's edge 0.46 and the rim 0.54) and a height within
       the tube, and a ray through it from any direction. */
    double ang = 6.283185307179586 * uniform(&seed);
    double rho = 0.4 + 0.2 * uniform(&seed);
    zr_vec3 aim = zr_v3(rho * cos(ang), 0.08 * uniform(&seed) - 0.04,
                        rho * sin(ang));
    zr_vec3 d = zr_v3(uniform(&seed) - 0.5, uniform(&seed) - 0.5,
                      uniform(&seed) - 0.5);
    if (n % 3 == 0)
      d.y *= 0.01; /* nearly level: long spans within the box */
    zr_ray r = {zr_v3_madd(aim, d, -4.0), d};
    zr_hit h[2];
    int got = zr__intersect(&t, &r, 0.0, INFINITY, h);
    int changes = 0;
    double prev = 0.0;
    for (int k = 0; k <= 4000; k++) {
      zr_vec3 p = zr_v3_madd(r.origin, d, 8.0 * k / 4000.0);
      double rr = 0.25, q = zr_v3_dot(p, p) + rr - 0.04 * 0.04;
      double f = q * q - 4.0 * rr * (p.x * p.x + p.z * p.z);
      if (k > 0 && (f < 0.0) != (prev < 0.0))
        changes++;
      prev = f;
    }
    if (changes > 0) {
      crossed++;
      assert_true(got > 0);
    }
  }
  assert_true(crossed > 300); /* the rays do meet the torus */
}

static void test_intersect_cone_apex_frustum_and_open(void **state) {
  (void)state;
  zr_object k;
  memset(&k, 0, sizeof k);
  k.kind = ZR_OBJ_CONE;
  k.u.cone.base = zr_v3(0, 0, 0);
  k.u.cone.base_radius = 1;
  k.u.cone.cap = zr_v3(0, 1, 0);
  k.u.cone.cap_radius = 0; /* a pointed cone */
  zr_hit h[2];
  /* At height 0.5 the radius is 0.5 and the side slopes at 45 degrees. */
  assert_int_equal(hits(&k, ray(-3, 0.5, 0, 1, 0, 0), h), 2);
  assert_near(h[0].t, 2.5, EPS);
  assert_near(h[1].t, 3.5, EPS);
  double s = sqrt(0.5);
  assert_vec(h[0].normal, -s, s, 0, EPS);
  assert_vec(h[1].normal, s, s, 0, EPS);
  /* Up from below: the base disc, then the side. */
  assert_int_equal(hits(&k, ray(0.25, -1, 0, 0, 1, 0), h), 2);
  assert_near(h[0].t, 1.0, EPS);
  assert_vec(h[0].normal, 0, -1, 0, EPS);
  assert_near(h[1].t, 1.75, EPS);
  /* The mirror nappe above the apex is not part of the cone. */
  assert_int_equal(hits(&k, ray(-3, 1.5, 0, 1, 0, 0), h), 0);
  /* A frustum with both caps, and the same one open. */
  k.u.cone.cap_radius = 0.5;
  assert_int_equal(hits(&k, ray(0.1, 2, 0, 0, -1, 0), h), 2);
  assert_near(h[0].t, 1.0, EPS);
  assert_vec(h[0].normal, 0, 1, 0, EPS);
  assert_near(h[1].t, 2.0, EPS);
  k.u.cone.open = true;
  assert_int_equal(hits(&k, ray(0.1, 2, 0, 0, -1, 0), h), 0);
  assert_true(zr__inside(&k, zr_v3(0.7, 0.5, 0)));
  assert_false(zr__inside(&k, zr_v3(0.8, 0.5, 0)));
}

static void test_intersect_disc_with_hole(void **state) {
  (void)state;
  zr_object d;
  memset(&d, 0, sizeof d);
  d.kind = ZR_OBJ_DISC;
  d.u.disc.centre = zr_v3(0, 0, 1);
  d.u.disc.normal = zr_v3(0, 0, -1);
  d.u.disc.radius = 1;
  d.u.disc.hole_radius = 0.5;
  zr_hit h[2];
  assert_int_equal(hits(&d, ray(0.75, 0, -1, 0, 0, 1), h), 1);
  assert_near(h[0].t, 2.0, EPS);
  assert_vec(h[0].normal, 0, 0, -1, EPS);
  assert_int_equal(hits(&d, ray(0.25, 0, -1, 0, 0, 1), h), 0); /* hole */
  assert_int_equal(hits(&d, ray(1.25, 0, -1, 0, 0, 1), h), 0); /* outside */
  /* A disc's inside is its plane's: opposite the normal. */
  assert_true(zr__inside(&d, zr_v3(5, 5, 2)));
  assert_false(zr__inside(&d, zr_v3(0, 0, 0)));
}

static void test_intersect_inverse_sphere_flips_normal(void **state) {
  (void)state;
  zr_object s = sphere(0, 0, 0, 1);
  s.inverse = true;
  zr_hit h[2];
  assert_int_equal(hits(&s, ray(0, 0, -5, 0, 0, 1), h), 2);
  assert_vec(h[0].normal, 0, 0, 1, EPS);
  assert_false(zr__inside(&s, zr_v3(0, 0, 0)));
  assert_true(zr__inside(&s, zr_v3(0, 0, 2)));
}

/* A small deterministic generator for the robustness test. */
static double next_uniform(uint64_t *seed) {
  *seed = *seed * 6364136223846793005ULL + 1442695040888963407ULL;
  return (double)(*seed >> 11) * (1.0 / 9007199254740992.0);
}

/*
 * A secondary ray leaving a surface point, moved off by
 * zr__surface_offset() along the normal, must not find the surface it
 * leaves, whatever the scale of the scene (POV-Ray scenes range from
 * 1e-3 to 1e5 units) and whatever the direction into the half space.
 * And a ray sent back through the surface must find it exactly once.
 */
static void test_intersect_no_self_hit_across_scales(void **state) {
  (void)state;
  const double scales[] = {1e-3, 1.0, 1e5};
  uint64_t seed = 12345;
  for (int si = 0; si < 3; si++) {
    double k = scales[si];
    zr_object s = sphere(3 * k, -2 * k, 7 * k, 0.9 * k);
    zr_transform t;
    zr__transform_identity(&t);
    zr__transform_scale(&t, zr_v3(1.0, 0.3, 2.0));
    zr__transform_rotate(&t, zr_v3(20, 30, 40));
    s.transform = &t;
    for (int i = 0; i < 2000; i++) {
      zr_vec3 from = zr_v3(k * (next_uniform(&seed) * 40 - 20),
                           k * (next_uniform(&seed) * 40 - 20), -60 * k);
      zr_vec3 target = zr__xform_point(t.m, s.u.sphere.centre);
      zr_ray r = {from, zr_v3_sub(target, from)};
      zr_hit h[2];
      if (zr__intersect(&s, &r, 0.0, INFINITY, h) == 0)
        continue;
      zr_vec3 p = zr_v3_madd(r.origin, r.dir, h[0].t);
      zr_vec3 n = h[0].normal;
      zr_vec3 d = zr_v3_norm(zr_v3(next_uniform(&seed) - 0.5,
                                   next_uniform(&seed) - 0.5,
                                   next_uniform(&seed) - 0.5));
      if (zr_v3_dot(d, n) < 0)
        d = zr_v3_neg(d);
      zr_ray out = {zr_v3_madd(p, n, zr__surface_offset(p)), d};
      assert_int_equal(zr__intersect(&s, &out, 0.0, INFINITY, h), 0);
      zr_ray in = {zr_v3_madd(p, n, -zr__surface_offset(p)),
                   zr_v3_neg(d)};
      assert_int_equal(zr__intersect(&s, &in, 0.0, INFINITY, h), 1);
    }
  }
}

/* The table of shape operations (lib/trace/shape.h): every kind has an
   entry with a name; every kind that is not CSG has exactly one form of
   crossings, and the flags agree with what the tracer expects of the
   kinds with no inside or a flat one. */
static void test_intersect_shape_table_complete(void **state) {
  (void)state;
  for (int k = ZR_OBJ_SPHERE; k <= ZR_OBJ_PARAMETRIC; k++) {
    const zr_shape_ops *ops = zr__shape((zr_object_kind)k);
    assert_non_null(ops);
    assert_non_null(ops->name);
    if (zr__is_csg((zr_object_kind)k)) {
      assert_null(ops->search);
      assert_null(ops->crossings);
      assert_non_null(ops->inside);
      continue;
    }
    assert_true((ops->search != NULL) != (ops->crossings != NULL));
  }
  assert_string_equal(zr__shape(ZR_OBJ_SPHERE)->name, "a sphere");
  assert_string_equal(zr__shape(ZR_OBJ_INTERSECTION)->name,
                      "an intersection or difference");
  assert_null(zr__shape(ZR_OBJ_TRIANGLE)->inside);
  assert_null(zr__shape(ZR_OBJ_POLYGON)->inside);
  assert_null(zr__shape(ZR_OBJ_PARAMETRIC)->inside);
  assert_true(zr__shape(ZR_OBJ_DISC)->flat);
  assert_null(zr__shape(ZR_OBJ_PLANE)->bounds);
  assert_null(zr__shape(ZR_OBJ_QUADRIC)->bounds);
  assert_null(zr__shape(ZR_OBJ_POLY)->bounds);
  assert_true(zr__shape(ZR_OBJ_MESH)->uv_from_hit);
  /* A disc has an inside test (its plane's) but encloses no volume. */
  zr_object disc;
  memset(&disc, 0, sizeof disc);
  disc.kind = ZR_OBJ_DISC;
  disc.u.disc.normal = zr_v3(0, 1, 0);
  disc.u.disc.radius = 1;
  assert_false(zr__has_inside(&disc));
  assert_true(zr__inside(&disc, zr_v3(5, -1, 0)));
  zr_object ball;
  memset(&ball, 0, sizeof ball);
  ball.kind = ZR_OBJ_SPHERE;
  ball.u.sphere.radius = 1;
  assert_true(zr__has_inside(&ball));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_intersect_sphere_outside_and_inside),
      cmocka_unit_test(test_intersect_shape_table_complete),
      cmocka_unit_test(test_intersect_sphere_tangent_and_miss),
      cmocka_unit_test(test_intersect_sphere_transformed_keeps_world_t),
      cmocka_unit_test(test_intersect_ellipsoid_normal_by_inverse_transpose),
      cmocka_unit_test(test_intersect_box_faces_rotation_and_parallel),
      cmocka_unit_test(test_intersect_plane_sides_and_inverse),
      cmocka_unit_test(test_intersect_triangle_inside_edges_and_miss),
      cmocka_unit_test(test_intersect_cylinder_capped_and_open),
      cmocka_unit_test(test_intersect_cone_apex_frustum_and_open),
      cmocka_unit_test(test_intersect_axis_measured_once_same_bits),
      cmocka_unit_test(test_intersect_torus_ring_test_loses_nothing),
      cmocka_unit_test(test_intersect_all_tells_when_complete),
      cmocka_unit_test(test_intersect_disc_with_hole),
      cmocka_unit_test(test_intersect_inverse_sphere_flips_normal),
      cmocka_unit_test(test_intersect_no_self_hit_across_scales),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
