/*
 * test_bvh.c - bounding boxes of primitives and the bounding volume
 * hierarchy: on seeded random scenes of every primitive kind, the BVH's
 * nearest hit and its list of all crossings must equal a brute-force
 * loop over the primitives.
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

#include "core/arena.h"
#include "core/transform.h"
#include "scene/scene.h"
#include "trace/prepare.h"
#include "trace/bvh.h"
#include "trace/bvh_wide.h"
#include "trace/intersect.h"
#include "trace/obj_sweep.h"

static double next_uniform(uint64_t *seed) {
  *seed = *seed * 6364136223846793005ULL + 1442695040888963407ULL;
  return (double)(*seed >> 11) * (1.0 / 9007199254740992.0);
}

static double range(uint64_t *seed, double lo, double hi) {
  return lo + (hi - lo) * next_uniform(seed);
}

static zr_vec3 random_point(uint64_t *seed, double extent) {
  return zr_v3(range(seed, -extent, extent), range(seed, -extent, extent),
               range(seed, -extent, extent));
}

/* One random primitive of a random kind near c, sometimes transformed. */
static zr_object *random_object(zr_scene *s, uint64_t *seed) {
  zr_object *o = zr__arena_alloc(&s->arena, sizeof *o);
  zr_vec3 c = random_point(seed, 20);
  double r = range(seed, 0.05, 0.8);
  o->kind = (zr_object_kind)(int)range(seed, 0, 7);
  switch (o->kind) {
  case ZR_OBJ_SPHERE:
    o->u.sphere.centre = c;
    o->u.sphere.radius = r;
    break;
  case ZR_OBJ_BOX:
    o->u.box.corner1 = c;
    o->u.box.corner2 = zr_v3_add(c, random_point(seed, 1));
    break;
  case ZR_OBJ_PLANE: /* rare unbounded ones: make it a sphere instead */
    o->kind = ZR_OBJ_SPHERE;
    o->u.sphere.centre = c;
    o->u.sphere.radius = r;
    break;
  case ZR_OBJ_TRIANGLE:
    for (int i = 0; i < 3; i++)
      o->u.triangle.p[i] = zr_v3_add(c, random_point(seed, 1));
    break;
  case ZR_OBJ_CYLINDER:
    o->u.cylinder.base = c;
    o->u.cylinder.cap = zr_v3_add(c, random_point(seed, 1.5));
    o->u.cylinder.radius = r * 0.5;
    o->u.cylinder.open = next_uniform(seed) < 0.3;
    break;
  case ZR_OBJ_CONE:
    o->u.cone.base = c;
    o->u.cone.cap = zr_v3_add(c, random_point(seed, 1.5));
    o->u.cone.base_radius = r;
    o->u.cone.cap_radius = next_uniform(seed) < 0.3 ? 0.0 : r * 0.3;
    o->u.cone.open = next_uniform(seed) < 0.3;
    break;
  case ZR_OBJ_DISC:
  default:
    o->kind = ZR_OBJ_DISC;
    o->u.disc.centre = c;
    o->u.disc.normal = zr_v3_norm(random_point(seed, 1));
    o->u.disc.radius = r;
    o->u.disc.hole_radius = r * 0.3;
    break;
  }
  if (next_uniform(seed) < 0.3) {
    zr_transform *t = zr__arena_alloc(&s->arena, sizeof *t);
    zr__transform_identity(t);
    zr__transform_translate(t, zr_v3_neg(c));
    zr__transform_scale(t, zr_v3(range(seed, 0.5, 2), range(seed, 0.5, 2),
                                 range(seed, 0.5, 2)));
    zr__transform_rotate(t, random_point(seed, 180));
    zr__transform_translate(t, c);
    o->transform = t;
  }
  return o;
}

static zr_scene *random_scene(uint64_t seed, size_t n, bool with_plane) {
  zr_scene *s = zr__scene_new();
  assert_non_null(s);
  for (size_t i = 0; i < n; i++)
    assert_int_equal(zr__scene_add_object(s, random_object(s, &seed)),
                     ZR_OK);
  if (with_plane) {
    zr_object *p = zr__arena_alloc(&s->arena, sizeof *p);
    p->kind = ZR_OBJ_PLANE;
    p->u.plane.normal = zr_v3(0, 1, 0);
    p->u.plane.distance = -21;
    assert_int_equal(zr__scene_add_object(s, p), ZR_OK);
    zr_object *inv = zr__arena_alloc(&s->arena, sizeof *inv);
    inv->kind = ZR_OBJ_SPHERE;
    inv->u.sphere.radius = 60;
    inv->inverse = true;
    assert_int_equal(zr__scene_add_object(s, inv), ZR_OK);
  }
  assert_int_equal(zr__scene_finish(s, NULL), ZR_OK);
  return s;
}

static bool brute_nearest(const zr_scene *s, const zr_ray *r, zr_hit *best) {
  bool found = false;
  double tmax = INFINITY;
  for (size_t i = 0; i < s->n_primitives; i++) {
    zr_hit h[ZR_MAX_CROSSINGS];
    if (zr__intersect(s->primitives[i], r, 0.0, tmax, h) > 0) {
      *best = h[0];
      tmax = h[0].t;
      found = true;
    }
  }
  return found;
}

static bool count_visit(const zr_hit *hit, void *user) {
  (void)hit;
  (*(size_t *)user)++;
  return true;
}

static void test_bvh_nearest_matches_brute_force(void **state) {
  (void)state;
  uint64_t seed = 2024;
  zr_scene *s = random_scene(7, 3000, true);
  zr_bvh_info info;
  zr__bvh_get_info(s->bvh, &info);
  assert_int_equal(info.bounded, 3000);
  assert_int_equal(info.unbounded, 2);
  assert_true(info.leaves > 3000 / 8);
  size_t found = 0;
  for (int i = 0; i < 4000; i++) {
    zr_ray r = {random_point(&seed, 30), random_point(&seed, 1)};
    zr_hit a, b;
    bool fa = zr__bvh_nearest(s->bvh, &r, 0.0, INFINITY, &a);
    bool fb = brute_nearest(s, &r, &b);
    assert_int_equal(fa, fb);
    if (!fa)
      continue;
    found++;
    /* The same object and the very same t: both paths call the same
       intersection code on the same ray, so no tolerance is needed. */
    assert_ptr_equal(a.object, b.object);
    assert_true(a.t == b.t);
    /* Every crossing, counted both ways. */
    size_t n_bvh = 0, n_brute = 0;
    assert_true(zr__bvh_all(s->bvh, &r, 0.0, INFINITY, count_visit, &n_bvh));
    for (size_t k = 0; k < s->n_primitives; k++) {
      zr_hit h[ZR_MAX_CROSSINGS];
      n_brute += (size_t)zr__intersect(s->primitives[k], &r, 0.0, INFINITY,
                                       h);
    }
    assert_int_equal(n_bvh, n_brute);
  }
  /* Every ray meets the plane or the inverse sphere around everything. */
  assert_int_equal(found, 4000);
  zr_scene_free(s);
}

static void test_bvh_nearest_respects_interval(void **state) {
  (void)state;
  uint64_t seed = 99;
  zr_scene *s = random_scene(11, 500, false);
  for (int i = 0; i < 2000; i++) {
    zr_ray r = {random_point(&seed, 25), random_point(&seed, 1)};
    zr_hit a, b;
    double tmin = range(&seed, 0, 10), tmax = tmin + range(&seed, 0, 30);
    bool fa = zr__bvh_nearest(s->bvh, &r, tmin, tmax, &a);
    bool fb = false;
    double best = tmax;
    for (size_t k = 0; k < s->n_primitives; k++) {
      zr_hit h[ZR_MAX_CROSSINGS];
      if (zr__intersect(s->primitives[k], &r, tmin, best, h) > 0) {
        b = h[0];
        best = h[0].t;
        fb = true;
      }
    }
    assert_int_equal(fa, fb);
    if (fa) {
      assert_true(a.t == b.t);
      assert_true(a.t > tmin && a.t < tmax);
    }
  }
  zr_scene_free(s);
}

static bool stop_at_first(const zr_hit *hit, void *user) {
  (void)hit;
  (*(int *)user)++;
  return false;
}

static void test_bvh_all_stops_when_asked(void **state) {
  (void)state;
  zr_scene *s = random_scene(5, 200, true);
  zr_ray r = {zr_v3(0, 0, 0), zr_v3(0, -1, 0)};
  int calls = 0;
  assert_false(zr__bvh_all(s->bvh, &r, 0.0, INFINITY, stop_at_first,
                           &calls));
  assert_int_equal(calls, 1);
  zr_scene_free(s);
}

static void test_bvh_empty_and_unbounded_only(void **state) {
  (void)state;
  zr_scene *s = zr__scene_new();
  assert_int_equal(zr__scene_finish(s, NULL), ZR_OK);
  zr_ray r = {zr_v3(0, 0, 0), zr_v3(0, 0, 1)};
  zr_hit h;
  assert_false(zr__bvh_nearest(s->bvh, &r, 0.0, INFINITY, &h));
  zr_bvh_info info;
  zr__bvh_get_info(s->bvh, &info);
  assert_int_equal(info.nodes, 0);
  zr_scene_free(s);

  s = zr__scene_new();
  zr_object *p = zr__arena_alloc(&s->arena, sizeof *p);
  p->kind = ZR_OBJ_PLANE;
  p->u.plane.normal = zr_v3(0, 0, -1);
  p->u.plane.distance = -3; /* z = 3 */
  zr__scene_add_object(s, p);
  assert_int_equal(zr__scene_finish(s, NULL), ZR_OK);
  assert_true(zr__bvh_nearest(s->bvh, &r, 0.0, INFINITY, &h));
  assert_true(h.t == 3.0);
  zr__bvh_get_info(s->bvh, &info);
  assert_int_equal(info.unbounded, 1);
  assert_int_equal(info.bounded, 0);
  zr_scene_free(s);
  zr__bvh_free(NULL); /* a no-op */
}

/* Many primitives sharing one centre cannot be split by position; the
   build must still finish with bounded depth and correct answers. */
static void test_bvh_coincident_primitives(void **state) {
  (void)state;
  zr_scene *s = zr__scene_new();
  for (int i = 0; i < 1000; i++) {
    zr_object *o = zr__arena_alloc(&s->arena, sizeof *o);
    o->kind = ZR_OBJ_SPHERE;
    o->u.sphere.radius = 1.0 + i * 1e-3;
    zr__scene_add_object(s, o);
  }
  assert_int_equal(zr__scene_finish(s, NULL), ZR_OK);
  zr_bvh_info info;
  zr__bvh_get_info(s->bvh, &info);
  assert_true(info.depth < 100);
  zr_ray r = {zr_v3(0, 0, -10), zr_v3(0, 0, 1)};
  zr_hit h;
  assert_true(zr__bvh_nearest(s->bvh, &r, 0.0, INFINITY, &h));
  /* The largest sphere, radius 1.999, is met first. */
  assert_true(fabs(h.t - (10.0 - 1.999)) < 1e-12);
  zr_scene_free(s);
}

/* A grid of spheres in rows that share their centres' y and z, and a
   run of spheres with one centre: ties everywhere, for the median
   split's sort as well as the binned one. */
static zr_scene *tied_scene(void) {
  zr_scene *s = zr__scene_new();
  assert_non_null(s);
  for (int i = 0; i < 1500; i++) {
    zr_object *o = zr__arena_alloc(&s->arena, sizeof *o);
    o->kind = ZR_OBJ_SPHERE;
    o->u.sphere.centre = i < 1200 ? zr_v3(i % 40, (i / 40) % 3, 0)
                                  : zr_v3(7, 7, 7);
    o->u.sphere.radius = 0.25 + (i % 7) * 0.01;
    assert_int_equal(zr__scene_add_object(s, o), ZR_OK);
  }
  assert_int_equal(zr__scene_finish(s, NULL), ZR_OK);
  return s;
}

/* The build makes the same tree as the plain builder of session 12
   (the items' centres stored, every bin computed twice): the digests
   of its leaf order were printed by that builder (main 3feb202) for
   these scenes.  The tracer's answers depend on the order of the
   primitives in a leaf, so a faster build must keep it (the image
   bytes of bench/peers.sh and tests/golden.sh). */
static const uint64_t TIED_DIGEST = 0x50b0007861a63062u;

static void test_bvh_build_same_tree(void **state) {
  (void)state;
  static const struct {
    uint64_t seed;
    size_t n;
    bool plane;
    uint64_t digest;
  } cases[] = {
      {1, 3000, true, 0xe629781a1d3fb8b7u},
      {2, 7381, false, 0x3fe90b1def6433bcu},
      {3, 200, true, 0x8db11fb25474418cu},
  };
  enum { CASES = sizeof cases / sizeof *cases };
  uint64_t got[CASES + 1];
  for (size_t i = 0; i <= CASES; i++) {
    zr_scene *s = i < CASES ? random_scene(cases[i].seed, cases[i].n,
                                           cases[i].plane)
                            : tied_scene();
    zr_bvh_info info;
    zr__bvh_get_info(s->bvh, &info);
    got[i] = info.order_digest;
    print_message("case %zu: digest 0x%016llx\n", i,
                  (unsigned long long)got[i]);
    zr_scene_free(s);
  }
  for (size_t i = 0; i < CASES; i++)
    assert_true(got[i] == cases[i].digest);
  assert_true(got[CASES] == TIED_DIGEST);
}

/* The build's plain minimum and maximum (bvh.c, pick_min) against the
   NaN-aware ones it takes when a box holds a NaN: the same leaves in
   the same order, the same wide nodes byte for byte, on the scenes
   above (a change to either path that moves one split, or one box by
   one bit, fails here). */
static void test_bvh_build_nan_path_same(void **state) {
  (void)state;
  static const struct {
    uint64_t seed;
    size_t n;
    bool plane;
  } cases[] = {{1, 3000, true}, {2, 7381, false}, {3, 200, true},
               {5, 20000, false}, {6, 5, true}};
  enum { CASES = sizeof cases / sizeof *cases };
  for (size_t i = 0; i <= CASES; i++) {
    zr_scene *s = i < CASES ? random_scene(cases[i].seed, cases[i].n,
                                           cases[i].plane)
                            : tied_scene();
    zr_bvh_info fast, slow;
    zr__bvh_get_info(s->bvh, &fast);
    assert_int_equal(zr__bvh_build_nan_path(s, NULL), ZR_OK);
    zr__bvh_get_info(s->bvh, &slow);
    print_message("case %zu: nodes %zu digests 0x%016llx 0x%016llx\n", i,
                  fast.nodes, (unsigned long long)fast.order_digest,
                  (unsigned long long)fast.node_digest);
    assert_true(fast.nodes > 0);
    assert_true(fast.order_digest == slow.order_digest);
    assert_true(fast.node_digest == slow.node_digest);
    assert_int_equal(fast.nodes, slow.nodes);
    zr_scene_free(s);
  }
}

static void assert_box(const zr_object *o, zr_vec3 lo, zr_vec3 hi,
                       double tol) {
  zr_vec3 l, h;
  assert_true(zr__object_bounds(o, &l, &h));
  assert_true(fabs(l.x - lo.x) <= tol && fabs(l.y - lo.y) <= tol &&
              fabs(l.z - lo.z) <= tol);
  assert_true(fabs(h.x - hi.x) <= tol && fabs(h.y - hi.y) <= tol &&
              fabs(h.z - hi.z) <= tol);
}

/* Boxes are exact up to the 1e-9 relative padding bounds.c adds. */
static void test_bvh_object_bounds(void **state) {
  (void)state;
  const double tol = 1e-8;
  zr_object o;
  memset(&o, 0, sizeof o);
  o.kind = ZR_OBJ_SPHERE;
  o.u.sphere.centre = zr_v3(1, 2, 3);
  o.u.sphere.radius = 2;
  assert_box(&o, zr_v3(-1, 0, 1), zr_v3(3, 4, 5), tol);
  /* A cylinder along y: a circle of radius 0.5 in x and z. */
  memset(&o, 0, sizeof o);
  o.kind = ZR_OBJ_CYLINDER;
  o.u.cylinder.base = zr_v3(0, 0, 0);
  o.u.cylinder.cap = zr_v3(0, 2, 0);
  o.u.cylinder.radius = 0.5;
  assert_box(&o, zr_v3(-0.5, 0, -0.5), zr_v3(0.5, 2, 0.5), tol);
  /* A cone leaning at 45 degrees in x-y, radius 1 at the base only. */
  memset(&o, 0, sizeof o);
  o.kind = ZR_OBJ_CONE;
  o.u.cone.cap = zr_v3(1, 1, 0);
  o.u.cone.base_radius = 1;
  double s = sqrt(0.5);
  assert_box(&o, zr_v3(-s, -s, -1), zr_v3(1, 1, 1), tol);
  /* A unit box scaled by 2 in x and turned 90 degrees about z. */
  zr_transform t;
  zr__transform_identity(&t);
  zr__transform_scale(&t, zr_v3(2, 1, 1));
  zr__transform_rotate(&t, zr_v3(0, 0, 90));
  memset(&o, 0, sizeof o);
  o.kind = ZR_OBJ_BOX;
  o.u.box.corner1 = zr_v3(0, 0, 0);
  o.u.box.corner2 = zr_v3(1, 1, 1);
  o.transform = &t;
  assert_box(&o, zr_v3(-1, 0, 0), zr_v3(0, 2, 1), tol);
  /* Unbounded: planes and anything inverse. */
  zr_vec3 l, h;
  o.inverse = true;
  assert_false(zr__object_bounds(&o, &l, &h));
  memset(&o, 0, sizeof o);
  o.kind = ZR_OBJ_PLANE;
  o.u.plane.normal = zr_v3(0, 1, 0);
  assert_false(zr__object_bounds(&o, &l, &h));
}

/*
 * The tracer's boxes are floats tested in float (bvh.c's slab_entries)
 * with a margin that makes the test conservative: it must never skip a
 * box the exact test would open.  Tiny spheres (radius 1e-4) far from
 * the origin (1e4), met by grazing rays from near and from far, by rays
 * parallel to the axes (direction components exactly 0) and by rays
 * that start on a sphere's box: every nearest hit and every count of
 * crossings must equal the brute-force loop's.  Without the margin,
 * float rounding of a far origin (a unit in the last place of 1e4 is
 * 1e-3, ten radii) loses hits here.
 */
static void test_bvh_float_boxes_never_miss(void **state) {
  (void)state;
  zr_scene *s = zr__scene_new();
  assert_non_null(s);
  const zr_vec3 base = zr_v3(1e4, -1e4, 5e3);
  const double step = 1e-3, radius = 1e-4;
  enum { NX = 16, NY = 16, NZ = 4 };
  size_t n = 0;
  for (int i = 0; i < NX; i++)
    for (int j = 0; j < NY; j++)
      for (int k = 0; k < NZ; k++) {
        zr_object *o = zr__arena_alloc(&s->arena, sizeof *o);
        o->kind = ZR_OBJ_SPHERE;
        o->u.sphere.centre = zr_v3_add(
            base, zr_v3(i * step, j * step, k * step + (i + j) * 1e-5));
        o->u.sphere.radius = radius * (1.0 + 0.01 * (i % 3));
        n++;
        assert_int_equal(zr__scene_add_object(s, o), ZR_OK);
      }
  assert_int_equal(zr__scene_finish(s, NULL), ZR_OK);
  uint64_t seed = 99;
  size_t hits = 0;
  for (int i = 0; i < 8000; i++) {
    const zr_object *target = s->primitives[(size_t)(next_uniform(&seed) *
                                                     (double)n) % n];
    zr_vec3 c = target->u.sphere.centre;
    double r = target->u.sphere.radius;
    zr_ray ray;
    int kind = i % 4;
    if (kind == 0) {
      /* From the origin, 1.4e4 away (a float's step there is 1e-3, ten
         radii), through the centre. */
      ray = (zr_ray){zr_v3(0, 0, 0), c};
    } else if (kind == 3) {
      /* From 50 away, just inside the rim (the sphere's own quadratic
         loses a rim hit from much farther). */
      zr_vec3 from = zr_v3_add(c, random_point(&seed, 50));
      zr_vec3 d = zr_v3_norm(zr_v3_sub(c, from));
      zr_vec3 side = zr_v3_norm(zr_v3_cross(d, random_point(&seed, 1)));
      zr_vec3 aim = zr_v3_madd(c, side, r * (1.0 - 1e-6));
      ray = (zr_ray){from, zr_v3_sub(aim, from)};
    } else if (kind == 1) {
      /* Along an axis, the other two coordinates just inside the rim. */
      int axis = (int)(next_uniform(&seed) * 3) % 3;
      double off = r * (1.0 - 1e-6) * (next_uniform(&seed) < 0.5 ? -1 : 1);
      zr_vec3 o = c, d = zr_v3(0, 0, 0);
      if (axis == 0) {
        o.x -= 1.0, o.y += off, d.x = 1.0;
      } else if (axis == 1) {
        o.y += 1.0, o.z += off, d.y = -1.0;
      } else {
        o.z -= 0.5, o.x += off, d.z = 3.0;
      }
      ray = (zr_ray){o, d};
    } else {
      /* From a corner of the sphere's box, through its centre. */
      zr_vec3 o = zr_v3_add(c, zr_v3(r, -r, r));
      ray = (zr_ray){o, zr_v3_sub(c, o)};
    }
    zr_hit a, b;
    bool fa = zr__bvh_nearest(s->bvh, &ray, 0.0, INFINITY, &a);
    bool fb = brute_nearest(s, &ray, &b);
    assert_int_equal(fa, fb);
    if (fa) {
      hits++;
      assert_ptr_equal(a.object, b.object);
      assert_true(a.t == b.t);
    }
    size_t n_bvh = 0, n_brute = 0;
    assert_true(zr__bvh_all(s->bvh, &ray, 0.0, INFINITY, count_visit,
                            &n_bvh));
    for (size_t k = 0; k < s->n_primitives; k++) {
      zr_hit h[ZR_MAX_CROSSINGS];
      n_brute += (size_t)zr__intersect(s->primitives[k], &ray, 0.0,
                                       INFINITY, h);
    }
    assert_int_equal(n_bvh, n_brute);
  }
  /* Every ray was aimed at a sphere, but from 1.4e4 away the sphere's
     quadratic (c = |oc|^2 - r^2 loses r^2 = 1e-8 against 2e8) decides
     about half of them at random, the same way in both loops: 5,506 of
     the 8,000 meet one. */
  assert_true(hits > 5000);
  zr_scene_free(s);
}

/* The walks' own crossings of one primitive (plain spheres from their
   leaf records or the fast path, others through the table) are
   zr__intersect_t's, t for t; and the walk over a scene of spheres, plain
   and transformed, visits each crossing the primitives give alone. */
static bool sum_visit(const zr_hit *hit, void *user) {
  double *sum = user;
  sum[0] += hit->t;
  sum[1] += 1.0;
  return true;
}

static void test_bvh_crossings_match_intersect(void **state) {
  (void)state;
  uint64_t seed = 77;
  zr_scene *s = random_scene(13, 800, true);
  for (int i = 0; i < 1500; i++) {
    zr_ray r = {random_point(&seed, 25), random_point(&seed, 1)};
    double brute[2] = {0.0, 0.0};
    for (size_t k = 0; k < s->n_primitives; k++) {
      zr_hit a[ZR_MAX_CROSSINGS], b[ZR_MAX_CROSSINGS];
      int na = zr__bvh_crossings_t(s->primitives[k], &r, 0.0, INFINITY, a);
      int nb = zr__intersect_t(s->primitives[k], &r, 0.0, INFINITY, b);
      assert_int_equal(na, nb);
      for (int j = 0; j < na; j++) {
        assert_true(a[j].t == b[j].t);
        assert_ptr_equal(a[j].object, b[j].object);
      }
      /* Unbounded ones are walked first, then the leaves: summed in
         another order, so compared below within rounding. */
      for (int j = 0; j < na; j++)
        brute[0] += a[j].t;
      brute[1] += na;
    }
    double walk[2] = {0.0, 0.0};
    assert_true(zr__bvh_all(s->bvh, &r, 0.0, INFINITY, sum_visit, walk));
    assert_true(walk[1] == brute[1]);
    assert_true(fabs(walk[0] - brute[0]) <= 1e-9 * (1.0 + fabs(brute[0])));
  }
  zr_scene_free(s);
}

/*
 * The leaves test plain spheres from their leaf records (bvh.c
 * sphere_t, inlined in both walks) rather than through obj_sphere.c:
 * the two must reject and accept the same spheres.  Rays that graze a
 * sphere, passing at its radius give or take a few units in the last
 * place (where the discriminant's sign is decided by rounding), must
 * find the crossings zr__intersect finds alone, t for t, through both
 * walks.  (A two-spheres-at-once SSE2 prefilter of the discriminant was
 * tried against this test in session 9 and dropped: no time saved.)
 */
static void test_bvh_grazing_spheres(void **state) {
  (void)state;
  uint64_t seed = 4242;
  zr_scene *s = zr__scene_new();
  assert_non_null(s);
  enum { N = 700 };
  for (int i = 0; i < N; i++) {
    zr_object *o = zr__arena_alloc(&s->arena, sizeof *o);
    o->kind = ZR_OBJ_SPHERE;
    o->u.sphere.centre = random_point(&seed, 10);
    o->u.sphere.radius = range(&seed, 0.05, 0.6);
    assert_int_equal(zr__scene_add_object(s, o), ZR_OK);
  }
  assert_int_equal(zr__scene_finish(s, NULL), ZR_OK);
  size_t hits = 0, misses = 0;
  for (int i = 0; i < 6000; i++) {
    const zr_object *target = s->primitives[i % N];
    zr_vec3 c = target->u.sphere.centre;
    double r = target->u.sphere.radius;
    zr_vec3 d = zr_v3_norm(random_point(&seed, 1));
    /* u: a unit vector across d; the ray passes c at r (1 + e). */
    zr_vec3 u = zr_v3_norm(zr_v3_cross(d, random_point(&seed, 1)));
    double e = (double)((int)range(&seed, -8, 9)) * 0x1p-52;
    zr_vec3 o = zr_v3_madd(zr_v3_madd(c, u, r * (1.0 + e)), d,
                           -range(&seed, 2, 30));
    zr_ray ray = {o, zr_v3_scale(d, range(&seed, 0.5, 2))};
    zr_hit h[ZR_MAX_CROSSINGS];
    int alone = zr__intersect(target, &ray, 0.0, INFINITY, h);
    if (alone > 0)
      hits++;
    else
      misses++;
    zr_hit a, b;
    bool fa = zr__bvh_nearest(s->bvh, &ray, 0.0, INFINITY, &a);
    bool fb = brute_nearest(s, &ray, &b);
    assert_int_equal(fa, fb);
    if (fa) {
      assert_ptr_equal(a.object, b.object);
      assert_true(a.t == b.t);
    }
    double walk[2] = {0.0, 0.0}, brute = 0.0;
    assert_true(zr__bvh_all(s->bvh, &ray, 0.0, INFINITY, sum_visit, walk));
    for (size_t k = 0; k < s->n_primitives; k++)
      brute += (double)zr__intersect(s->primitives[k], &ray, 0.0, INFINITY,
                                     h);
    assert_true(walk[1] == brute);
  }
  /* The rays sit on the boundary: both answers occur often. */
  assert_true(hits > 600 && misses > 600);
  zr_scene_free(s);
}

/* A random double for the slab ray's tests: ordinary magnitudes, tiny
   and huge ones, zeros of both signs, infinities and NaNs. */
static double slab_component(uint64_t *seed) {
  double u = next_uniform(seed), m = range(seed, -1, 1);
  if (u < 0.05)
    return next_uniform(seed) < 0.5 ? 0.0 : -0.0;
  if (u < 0.10)
    return m * 1e-31; /* below the reciprocal's 1e-30 cut */
  if (u < 0.15)
    return m * 1e-30 * range(seed, 0.5, 2); /* about the cut */
  if (u < 0.20)
    return m * 1e39; /* beyond float: an infinity when rounded */
  if (u < 0.23)
    return next_uniform(seed) < 0.5 ? INFINITY : -INFINITY;
  if (u < 0.25)
    return NAN;
  if (u < 0.35)
    return m * 0x1p-149 * range(seed, 1, 8); /* float's subnormals */
  return m * pow(10.0, range(seed, -8, 8));
}

/* Whether two floats have the same bits (a NaN equals its own bits). */
static bool same_float_bits(float a, float b) {
  uint32_t x, y;
  memcpy(&x, &a, sizeof x);
  memcpy(&y, &b, sizeof y);
  return x == y;
}

/*
 * The SSE slab ray (zr__make_slab_ray, three axes at once) against its
 * plain C definition, field by field and bit for bit, on rays whose
 * components cover every case the definition tells apart: a direction
 * of 0, below and about the 1e-30 cut, beyond float's range, infinite,
 * NaN, subnormal in float, and ordinary ones.  Any difference in a
 * rounding, a sign copy or a lane would move the boxes the walks open.
 */
static void test_bvh_slab_ray_matches_scalar(void **state) {
  (void)state;
  uint64_t seed = 31337;
  for (int i = 0; i < 200000; i++) {
    zr_ray ray = {zr_v3(slab_component(&seed), slab_component(&seed),
                        slab_component(&seed)),
                  zr_v3(slab_component(&seed), slab_component(&seed),
                        slab_component(&seed))};
    zr_slab_ray fast, plain;
    memset(&fast, 0, sizeof fast);
    memset(&plain, 0, sizeof plain);
    zr__make_slab_ray(&ray, &fast);
    zr__make_slab_ray_scalar(&ray, &plain);
    for (int a = 0; a < 3; a++) {
      assert_true(same_float_bits(fast.org[a], plain.org[a]));
      assert_true(same_float_bits(fast.inv[a], plain.inv[a]));
      assert_true(same_float_bits(fast.org_pad[a], plain.org_pad[a]));
      assert_true(same_float_bits(fast.ext_pad[a], plain.ext_pad[a]));
#ifdef __SSE2__
      float f[4], g[4];
      const __m128 *rows[4][2] = {{&fast.org4[a], &plain.org4[a]},
                                  {&fast.inv4[a], &plain.inv4[a]},
                                  {&fast.org_pad4[a], &plain.org_pad4[a]},
                                  {&fast.ext_pad4[a], &plain.ext_pad4[a]}};
      for (int r = 0; r < 4; r++) {
        _mm_storeu_ps(f, *rows[r][0]);
        _mm_storeu_ps(g, *rows[r][1]);
        for (int l = 0; l < 4; l++)
          assert_true(same_float_bits(f[l], g[l]));
      }
#endif
    }
  }
}

/*
 * bvh.c's plain plane (plane_t, the walks' own test of an unbounded
 * plane) skips the division when the ray leaves the plane behind (the
 * quotient's signs differ and tmin >= 0).  Its crossings must stay
 * zr__intersect_t's, t for t, for rays from both sides, toward and away
 * from the plane, nearly parallel, from on the plane, and for tmin of
 * 0, -0, negative and positive.
 */
static void test_bvh_plane_crossings_match_intersect(void **state) {
  (void)state;
  uint64_t seed = 5150;
  zr_scene *s = zr__scene_new();
  assert_non_null(s);
  zr_object *p = zr__arena_alloc(&s->arena, sizeof *p);
  p->kind = ZR_OBJ_PLANE;
  p->u.plane.normal = zr_v3_norm(zr_v3(0.3, 1, -0.2));
  p->u.plane.distance = 0.75;
  assert_int_equal(zr__scene_add_object(s, p), ZR_OK);
  assert_int_equal(zr__scene_finish(s, NULL), ZR_OK);
  const double tmins[] = {0.0, -0.0, -1.0, 1e-9, 0.5, 3.0};
  size_t found = 0, behind = 0;
  for (int i = 0; i < 60000; i++) {
    zr_vec3 o = random_point(&seed, 5);
    if (i % 7 == 0) /* on the plane, give or take rounding */
      o = zr_v3_madd(o, p->u.plane.normal,
                     p->u.plane.distance - zr_v3_dot(o, p->u.plane.normal));
    zr_vec3 d = random_point(&seed, 1);
    if (i % 5 == 0) /* nearly parallel */
      d = zr_v3_madd(d, p->u.plane.normal,
                     -zr_v3_dot(d, p->u.plane.normal) *
                         (1.0 - range(&seed, -1e-9, 1e-9)));
    zr_ray ray = {o, d};
    double tmin = tmins[i % 6];
    double tmax = i % 3 ? INFINITY : range(&seed, 0, 10);
    zr_hit a[ZR_MAX_CROSSINGS], b[ZR_MAX_CROSSINGS];
    int na = zr__bvh_crossings_t(p, &ray, tmin, tmax, a);
    int nb = zr__intersect_t(p, &ray, tmin, tmax, b);
    assert_int_equal(na, nb);
    for (int k = 0; k < na; k++)
      assert_true(a[k].t == b[k].t);
    found += (size_t)na;
    double num = p->u.plane.distance - zr_v3_dot(p->u.plane.normal, o);
    behind += num * zr_v3_dot(p->u.plane.normal, d) < 0.0;
    /* The walk of the whole hierarchy sees the same. */
    size_t walked = 0;
    assert_true(zr__bvh_all(s->bvh, &ray, tmin, tmax, count_visit, &walked));
    assert_int_equal(walked, (size_t)nb);
    /* So does the nearest search, which tests the plane in place. */
    zr_hit near;
    bool hit = zr__bvh_nearest(s->bvh, &ray, tmin, tmax, &near);
    assert_int_equal(hit, nb > 0);
    if (hit)
      assert_true(near.t == b[0].t && near.object == p);
  }
  /* Both answers, and the skipped division, occur often. */
  assert_true(found > 10000 && behind > 10000);
  zr_scene_free(s);
}

/*
 * The walks' sphere test (bvh.c sphere_t) returns nothing at once for a
 * ray going away from a sphere it starts outside of when tmin >= 0.
 * Rays leaving a sphere's surface, as secondary rays do (from just
 * outside, just inside and on it, outward, inward and along it), and
 * rays from far away toward and away from it, with tmin 0, -0,
 * negative and positive, must find zr__intersect_t's crossings, t for
 * t, through zr__bvh_crossings_t and through a walk of a hierarchy.
 */
static void test_bvh_sphere_leaving_rays(void **state) {
  (void)state;
  uint64_t seed = 8086;
  zr_scene *s = zr__scene_new();
  assert_non_null(s);
  enum { N = 64 };
  for (int i = 0; i < N; i++) {
    zr_object *o = zr__arena_alloc(&s->arena, sizeof *o);
    o->kind = ZR_OBJ_SPHERE;
    o->u.sphere.centre = random_point(&seed, 30);
    o->u.sphere.radius = range(&seed, 0.01, 3);
    assert_int_equal(zr__scene_add_object(s, o), ZR_OK);
  }
  assert_int_equal(zr__scene_finish(s, NULL), ZR_OK);
  const double tmins[] = {0.0, -0.0, -2.0, 1e-12, 0.3};
  size_t found = 0, away = 0;
  for (int i = 0; i < 60000; i++) {
    const zr_object *o = s->primitives[i % N];
    zr_vec3 c = o->u.sphere.centre;
    double r = o->u.sphere.radius;
    zr_vec3 n = zr_v3_norm(random_point(&seed, 1));
    double at = r;
    switch (i % 4) {
    case 0: at = r * (1.0 + 1e-9); break;  /* just outside */
    case 1: at = r * (1.0 - 1e-9); break;  /* just inside */
    case 2: at = r; break;                 /* on it, as rounded */
    default: at = r * range(&seed, 1.5, 20); break; /* far */
    }
    zr_vec3 from = zr_v3_madd(c, n, at);
    zr_vec3 d = random_point(&seed, 1);
    if (i % 3 == 0) /* along the surface */
      d = zr_v3_madd(d, n, -zr_v3_dot(d, n));
    zr_ray ray = {from, zr_v3_scale(d, range(&seed, 0.1, 10))};
    double tmin = tmins[i % 5];
    zr_hit a[ZR_MAX_CROSSINGS], b[ZR_MAX_CROSSINGS];
    int na = zr__bvh_crossings_t(o, &ray, tmin, INFINITY, a);
    int nb = zr__intersect_t(o, &ray, tmin, INFINITY, b);
    assert_int_equal(na, nb);
    for (int k = 0; k < na; k++)
      assert_true(a[k].t == b[k].t);
    found += (size_t)na;
    away += zr_v3_dot(ray.dir, zr_v3_sub(from, c)) > 0.0;
    size_t walked = 0, brute = 0;
    assert_true(zr__bvh_all(s->bvh, &ray, tmin, INFINITY, count_visit,
                            &walked));
    for (size_t k = 0; k < s->n_primitives; k++)
      brute += (size_t)zr__intersect_t(s->primitives[k], &ray, tmin,
                                       INFINITY, b);
    assert_int_equal(walked, brute);
  }
  assert_true(found > 10000 && away > 20000);
  zr_scene_free(s);
}

/* The order a walk takes entries in: pops the stack until empty, with
   first (when given) searched before anything on the stack. */
static int walk_order(const zr_wide_entry *first, const zr_wide_entry *stack,
                      int sp, uint32_t out[ZR_WIDE_WIDTH]) {
  int n = 0;
  if (first)
    out[n++] = first->child;
  while (sp > 0)
    out[n++] = stack[--sp].child;
  return n;
}

/*
 * The walks search the first child met at once rather than pushing it
 * (zr__wide_next_in_order, zr__wide_next_nearest_first): they must take
 * the same children in the same order as pushing all of them did, so
 * the crossings a shadow walk visits, and the nearest a search keeps on
 * equal t, do not change.  Every mask of four children, with entry
 * distances that tie and that do not.
 */
static void test_bvh_next_child_keeps_order(void **state) {
  (void)state;
  static const float dists[3][ZR_WIDE_WIDTH] = {
      {0.5f, 0.25f, 2.0f, 1.0f}, {1.0f, 1.0f, 1.0f, 1.0f},
      {3.0f, 0.5f, 0.5f, -1.0f}};
  zr_wide_node w;
  memset(&w, 0, sizeof w);
  for (int c = 0; c < ZR_WIDE_WIDTH; c++) {
    w.child[c] = 10u + (uint32_t)c;
    w.count[c] = (uint16_t)c;
  }
  for (int d = 0; d < 3; d++)
    for (unsigned mask = 1; mask < 16; mask++) {
      for (int nearest = 0; nearest < 2; nearest++) {
        zr_wide_entry a[8], b[8], next;
        int sa = nearest ? zr__wide_push_nearest_first(&w, mask, dists[d],
                                                       a, 0, 8)
                         : zr__wide_push_in_order(&w, mask, dists[d], a, 0,
                                                  8);
        int sb = nearest ? zr__wide_next_nearest_first(&w, mask, dists[d],
                                                       b, 0, 8, &next)
                         : zr__wide_next_in_order(&w, mask, dists[d], b, 0,
                                                  8, &next);
        uint32_t oa[ZR_WIDE_WIDTH], ob[ZR_WIDE_WIDTH];
        int na = walk_order(NULL, a, sa, oa);
        int nb = walk_order(&next, b, sb, ob);
        assert_int_equal(na, nb);
        assert_int_equal(sb, sa - 1);
        for (int k = 0; k < na; k++)
          assert_int_equal(oa[k], ob[k]);
        assert_int_equal(next.count, next.child - 10u);
      }
    }
}

/* Stops a crossing walk at its first crossing, noting that there was one
   (zr__rad_occluded's question before zr__bvh_occluded). */
static bool note_first(const zr_hit *hit, void *user) {
  (void)hit;
  *(bool *)user = true;
  return false;
}

static bool walk_occluded(const struct zr_bvh *bvh, const zr_ray *r,
                          double tmin, double tmax) {
  bool blocked = false;
  zr__bvh_all(bvh, r, tmin, tmax, note_first, &blocked);
  return blocked;
}

/* A scene of every kind zr__bvh_occluded tests by itself (triangles,
   polygons, boxes, planes, spheres; plain and transformed) and of kinds
   it leaves to the crossing walk (clipped, CSG, cylinder, disc, mesh),
   in SDL so the parser builds them as a scene would. */
static char *mixed_scene_text(uint64_t seed) {
  size_t cap = 1 << 16, n = 0;
  char *t = malloc(cap);
  assert_non_null(t);
#define PUT(...) \
  n += (size_t)snprintf(t + n, cap - n, __VA_ARGS__); \
  assert_true(n < cap)
  PUT("#version 3.7;\n");
  /* A closed room of triangles, as the Cornell box is made. */
  PUT("union { triangle { <0,0,0>, <10,0,0>, <10,0,10> }\n"
      " triangle { <0,0,0>, <10,0,10>, <0,0,10> }\n"
      " triangle { <0,10,0>, <10,10,10>, <10,10,0> }\n"
      " triangle { <0,10,0>, <0,10,10>, <10,10,10> }\n"
      " triangle { <0,0,10>, <10,0,10>, <10,10,10> }\n"
      " triangle { <0,0,10>, <10,10,10>, <0,10,10> } }\n");
  for (int i = 0; i < 40; i++) {
    zr_vec3 c = zr_v3(range(&seed, 1, 9), range(&seed, 1, 9),
                      range(&seed, 1, 9));
    zr_vec3 a = zr_v3_add(c, random_point(&seed, 1.5));
    zr_vec3 b = zr_v3_add(c, random_point(&seed, 1.5));
    zr_vec3 d = zr_v3_add(c, random_point(&seed, 1.5));
    double r = range(&seed, 0.2, 0.8);
    switch (i % 10) {
    case 0:
    case 1:
    case 2:
      PUT("triangle { <%.17g,%.17g,%.17g>, <%.17g,%.17g,%.17g>, "
          "<%.17g,%.17g,%.17g>%s }\n",
          a.x, a.y, a.z, b.x, b.y, b.z, d.x, d.y, d.z,
          i % 10 == 2 ? " rotate <10,20,30> translate <0.5,0,0>" : "");
      break;
    case 3:
      PUT("box { <%.17g,%.17g,%.17g>, <%.17g,%.17g,%.17g>%s }\n", a.x, a.y,
          a.z, b.x, b.y, b.z, i % 20 == 3 ? "" : " rotate <30,40,50>");
      break;
    case 4:
      PUT("polygon { 5, <0,0>, <%.17g,0>, <%.17g,%.17g>, <0,%.17g>, "
          "<0,0> rotate <%.17g,%.17g,0> translate <%.17g,%.17g,%.17g> }\n",
          r * 2, r * 2, r * 3, r, range(&seed, 0, 90), range(&seed, 0, 90),
          c.x, c.y, c.z);
      break;
    case 5:
      PUT("sphere { <%.17g,%.17g,%.17g>, %.17g%s }\n", c.x, c.y, c.z, r,
          i % 20 == 5 ? "" : " scale <1,1.5,0.7> translate <0.1,0,0>");
      break;
    case 6:
      PUT("sphere { <%.17g,%.17g,%.17g>, %.17g clipped_by { box { "
          "<%.17g,%.17g,%.17g>, <%.17g,%.17g,%.17g> } } }\n",
          c.x, c.y, c.z, r, c.x - 1, c.y - 1, c.z, c.x + 1, c.y + 1,
          c.z + 1);
      break;
    case 7:
      PUT("intersection { sphere { <%.17g,%.17g,%.17g>, %.17g } box { "
          "<%.17g,%.17g,%.17g>, <%.17g,%.17g,%.17g> } }\n",
          c.x, c.y, c.z, r, c.x - r, c.y - r, c.z - r / 2, c.x + r,
          c.y + r / 2, c.z + r);
      break;
    case 8:
      PUT("cylinder { <%.17g,%.17g,%.17g>, <%.17g,%.17g,%.17g>, %.17g }\n"
          "disc { <%.17g,%.17g,%.17g>, <%.17g,%.17g,%.17g>, %.17g }\n",
          a.x, a.y, a.z, b.x, b.y, b.z, r / 3, d.x, d.y, d.z, c.x - d.x,
          c.y - d.y, c.z - d.z, r);
      break;
    default:
      PUT("mesh { triangle { <%.17g,%.17g,%.17g>, <%.17g,%.17g,%.17g>, "
          "<%.17g,%.17g,%.17g> } triangle { <%.17g,%.17g,%.17g>, "
          "<%.17g,%.17g,%.17g>, <%.17g,%.17g,%.17g> } }\n",
          a.x, a.y, a.z, b.x, b.y, b.z, d.x, d.y, d.z, a.x, a.y, a.z, d.x,
          d.y, d.z, c.x, c.y, c.z);
      break;
    }
  }
  /* Unbounded ones: a tilted plane through the room and one below it. */
  PUT("plane { <1,1,0.5>, 9 }\nplane { y, -0.5 }\n");
#undef PUT
  return t;
}

/* A point on some surface: where a random ray from inside the room
   first meets one (the ends of radiosity's visibility rays lie on
   surfaces, moved off them by a tiny eps or not at all). */
static zr_vec3 surface_point(const zr_scene *s, uint64_t *seed) {
  for (;;) {
    zr_ray r = {zr_v3(range(seed, 0.5, 9.5), range(seed, 0.5, 9.5),
                      range(seed, 0.5, 9.5)),
                random_point(seed, 1)};
    zr_hit h;
    if (zr__bvh_nearest(s->bvh, &r, 0.0, INFINITY, &h))
      return zr_v3_madd(r.origin, r.dir, h.t);
  }
}

/*
 * zr__bvh_occluded must answer exactly what the crossing walk answers
 * (zr__bvh_all stopped at the first crossing), for every segment: between
 * surface points (exactly on the surfaces, or 1e-9 and 1e-6 off them:
 * the interval's ends then decide), in the plane of a triangle (grazing,
 * det 0 or a rounding), along the axes and at random, with and without
 * a hint carried from segment to segment.  Both answers must occur
 * often, so a predicate that always says yes or no fails.
 */
static void test_bvh_occluded_matches_walk(void **state) {
  (void)state;
  zr_context *ctx = NULL;
  assert_int_equal(zr_context_new(&ctx), ZR_OK);
  char *text = mixed_scene_text(17);
  zr_scene *s = NULL;
  assert_int_equal(
      zr_scene_parse_string(ctx, "<mixed>", text, strlen(text), &s), ZR_OK);
  free(text);
  zr_bvh_info info;
  zr__bvh_get_info(s->bvh, &info);
  assert_true(info.bounded > 40);
  assert_int_equal(info.unbounded, 2);
  uint64_t seed = 5;
  zr_bvh_hint hint = {0};
  size_t blocked = 0, open = 0;
  for (int i = 0; i < 60000; i++) {
    zr_vec3 a, b;
    int kind = i % 6;
    if (kind <= 2) {
      /* Surface to surface, offset along the segment by 0, 1e-9 or
         1e-6 of its length. */
      a = surface_point(s, &seed);
      b = surface_point(s, &seed);
      double off = kind == 0 ? 0.0 : kind == 1 ? 1e-9 : 1e-6;
      zr_vec3 d = zr_v3_sub(b, a);
      a = zr_v3_madd(a, d, off);
      b = zr_v3_madd(b, d, -off);
    } else if (kind == 3) {
      /* In the plane of a primitive triangle (grazing). */
      const zr_object *o =
          s->primitives[(size_t)(next_uniform(&seed) *
                                 (double)s->n_primitives) %
                        s->n_primitives];
      if (o->kind != ZR_OBJ_TRIANGLE)
        continue;
      const zr_vec3 *p = o->u.triangle.p;
      double u0 = range(&seed, -0.5, 1.5), v0 = range(&seed, -0.5, 1.5);
      double u1 = range(&seed, -0.5, 1.5), v1 = range(&seed, -0.5, 1.5);
      a = zr_v3_madd(zr_v3_madd(p[0], zr_v3_sub(p[1], p[0]), u0),
                     zr_v3_sub(p[2], p[0]), v0);
      b = zr_v3_madd(zr_v3_madd(p[0], zr_v3_sub(p[1], p[0]), u1),
                     zr_v3_sub(p[2], p[0]), v1);
    } else if (kind == 4) {
      /* Along an axis from a surface point. */
      a = surface_point(s, &seed);
      b = a;
      int axis = i % 3;
      double len = range(&seed, -6, 6);
      if (axis == 0)
        b.x += len;
      else if (axis == 1)
        b.y += len;
      else
        b.z += len;
    } else {
      a = zr_v3_add(zr_v3(5, 5, 5), random_point(&seed, 7));
      b = zr_v3_add(zr_v3(5, 5, 5), random_point(&seed, 7));
    }
    zr_ray r = {a, zr_v3_sub(b, a)};
    const double ends[3][2] = {{1e-9, 1.0 - 1e-9}, {0.0, 1.0},
                               {0.25, 0.5}};
    for (int e = 0; e < 3; e++) {
      bool want = walk_occluded(s->bvh, &r, ends[e][0], ends[e][1]);
      assert_int_equal(
          zr__bvh_occluded(s->bvh, &r, ends[e][0], ends[e][1], NULL), want);
      assert_int_equal(
          zr__bvh_occluded(s->bvh, &r, ends[e][0], ends[e][1], &hint),
          want);
      if (e == 0) {
        blocked += want;
        open += !want;
      }
    }
  }
  assert_true(blocked > 10000);
  assert_true(open > 10000);
  /* No scene, no hierarchy: nothing is in the way. */
  zr_ray r = {zr_v3(0, 0, 0), zr_v3(1, 1, 1)};
  assert_false(zr__bvh_occluded(NULL, &r, 0.0, 1.0, &hint));
  zr_scene_free(s);
  zr_context_free(ctx);
}


/* julia_fractals, whose march the search for the nearest surface asks
   for its normal at once and shadow walks ask for four crossings at a
   time (lib/trace/bvh.c, normal_at_once and visit_march): glass-like
   quaternions (rays cross them several times), a hypercomplex cube,
   transformed, one inverse (unbounded). */
static zr_object *julia_object(zr_scene *s, const double c[4],
                               zr_julia_algebra algebra,
                               zr_julia_function function, int iterations,
                               zr_vec3 at, double turn, bool inverse) {
  zr_object *o = zr__arena_alloc(&s->arena, sizeof *o);
  struct zr_julia *j = zr__arena_alloc(&s->arena, sizeof *j);
  memcpy(j->c, c, sizeof j->c);
  j->algebra = algebra;
  j->function = function;
  j->max_iteration = iterations;
  j->precision = 20.0;
  j->slice[3] = 1.0;
  assert_true(zr__julia_prepare(j));
  o->kind = ZR_OBJ_JULIA;
  o->u.julia.data = j;
  o->inverse = inverse;
  zr_transform *t = zr__arena_alloc(&s->arena, sizeof *t);
  zr__transform_identity(t);
  zr__transform_rotate(t, zr_v3(turn, 2 * turn, -turn));
  zr__transform_translate(t, at);
  o->transform = t;
  return o;
}

/* The crossings visit_leaf found before visit_march: rounds of the
   nearest two, each asked beyond the last (the march from the
   bounding sphere's entry every time). */
static size_t julia_rounds(const zr_object *o, const zr_ray *r, double tmin,
                           double *t, size_t room) {
  size_t n = 0;
  for (int round = 0; round < 256; round++) {
    zr_hit h[ZR_MAX_CROSSINGS];
    int k = zr__intersect_t(o, r, tmin, INFINITY, h);
    for (int i = 0; i < k; i++) {
      assert_true(n < room);
      t[n++] = h[i].t;
    }
    if (k < ZR_MAX_CROSSINGS)
      break;
    tmin = h[k - 1].t + 1e-7 * (1.0 + fabs(h[k - 1].t));
  }
  return n;
}

typedef struct t_list {
  size_t n;
  double t[512];
  const zr_object *object[512];
} t_list;

static bool list_visit(const zr_hit *hit, void *user) {
  t_list *l = user;
  assert_true(l->n < 512);
  assert_true(hit->normal.x == 0 && hit->normal.y == 0 &&
              hit->normal.z == 0);
  l->t[l->n] = hit->t;
  l->object[l->n++] = hit->object;
  return true;
}

static void test_bvh_julia_same_as_asking_again(void **state) {
  (void)state;
  zr_scene *s = zr__scene_new();
  const double glass[4] = {0.02, -0.02, 0.8, 0}, cube[4] = {-0.54, 0.57,
                                                            0.0, -0.37};
  const double swirl[4] = {-0.083, 0.0, -0.83, -0.025};
  zr_object *objects[4] = {
      julia_object(s, glass, ZR_JULIA_QUATERNION, ZR_JULIA_SQR, 10,
                   zr_v3(0, 0, 0), 40, false),
      julia_object(s, cube, ZR_JULIA_HYPERCOMPLEX, ZR_JULIA_CUBE, 8,
                   zr_v3(3.5, 0.5, 0), 25, false),
      julia_object(s, swirl, ZR_JULIA_QUATERNION, ZR_JULIA_SQR, 6,
                   zr_v3(-3, 1, 1), 70, false),
      julia_object(s, glass, ZR_JULIA_QUATERNION, ZR_JULIA_SQR, 10,
                   zr_v3(0, 0, 0), 10, true)};
  /* The inverse one as its own scene: it is met by every ray. */
  for (int i = 0; i < 3; i++)
    assert_int_equal(zr__scene_add_object(s, objects[i]), ZR_OK);
  assert_int_equal(zr__scene_finish(s, NULL), ZR_OK);
  zr_scene *inv = zr__scene_new();
  assert_int_equal(zr__scene_add_object(inv, objects[3]), ZR_OK);
  assert_int_equal(zr__scene_finish(inv, NULL), ZR_OK);
  uint64_t seed = 1989;
  size_t hits = 0, long_walks = 0;
  for (int i = 0; i < 600; i++) {
    const zr_scene *sc = i % 6 == 5 ? inv : s;
    int aim = i % 3;
    zr_vec3 centre = aim == 0 ? zr_v3(0, 0, 0)
                     : aim == 1 ? zr_v3(3.5, 0.5, 0)
                                : zr_v3(-3, 1, 1);
    zr_vec3 from = zr_v3_add(centre, zr_v3_scale(zr_v3_norm(
                                         random_point(&seed, 1)), 6.0));
    zr_vec3 to = zr_v3_add(centre, random_point(&seed, 0.8));
    zr_ray r = {from, zr_v3_sub(to, from)};
    /* The nearest crossing and its normal, as the search asked for it
       before: the winner intersected again from just before its t. */
    zr_hit a;
    bool fa = zr__bvh_nearest(sc->bvh, &r, 0.0, INFINITY, &a);
    zr_hit b = {0};
    bool fb = false;
    double best = INFINITY;
    for (size_t k = 0; k < sc->n_primitives; k++) {
      zr_hit h[ZR_MAX_CROSSINGS];
      if (zr__intersect_t(sc->primitives[k], &r, 0.0, best, h) > 0) {
        b = h[0];
        best = h[0].t;
        fb = true;
      }
    }
    assert_int_equal(fa, fb);
    if (fa) {
      hits++;
      assert_ptr_equal(a.object, b.object);
      assert_true(a.t == b.t);
      zr_hit h[ZR_MAX_CROSSINGS];
      double from_t = b.t - 1e-9 * fmax(1.0, fabs(b.t));
      assert_int_equal(
          zr__intersect_first(b.object, &r, from_t, INFINITY, true, h), 1);
      assert_true(h[0].t == a.t);
      assert_true(a.normal.x == h[0].normal.x &&
                  a.normal.y == h[0].normal.y &&
                  a.normal.z == h[0].normal.z);
    }
    /* Every crossing a shadow walk visits, in the walk's order, from a
       start that is sometimes on the way (tmin > 0). */
    double tmin = i % 4 == 3 ? range(&seed, 0.0, 1.0) : 0.0;
    t_list walk = {0};
    assert_true(zr__bvh_all(sc->bvh, &r, tmin, INFINITY, list_visit, &walk));
    size_t at = 0;
    for (size_t k = 0; k < sc->n_primitives; k++) {
      double t[512];
      size_t n = julia_rounds(sc->primitives[k], &r, tmin, t, 512);
      /* The walk visits a leaf's crossings together, the leaves in
         the tree's order: find this object's run. */
      size_t first = 0;
      while (first < walk.n && walk.object[first] != sc->primitives[k])
        first++;
      for (size_t m = 0; m < n; m++) {
        assert_true(first + m < walk.n);
        assert_ptr_equal(walk.object[first + m], sc->primitives[k]);
        assert_true(walk.t[first + m] == t[m]);
      }
      at += n;
      if (n > 4)
        long_walks++;
    }
    assert_int_equal(at, walk.n);
  }
  /* The rays meet the fractals often, and cross some more than four
     times (so that visit_march marches again). */
  assert_true(hits > 300);
  assert_true(long_walks > 10);
  zr_scene_free(s);
  zr_scene_free(inv);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_bvh_nearest_matches_brute_force),
      cmocka_unit_test(test_bvh_nearest_respects_interval),
      cmocka_unit_test(test_bvh_all_stops_when_asked),
      cmocka_unit_test(test_bvh_empty_and_unbounded_only),
      cmocka_unit_test(test_bvh_coincident_primitives),
      cmocka_unit_test(test_bvh_object_bounds),
      cmocka_unit_test(test_bvh_float_boxes_never_miss),
      cmocka_unit_test(test_bvh_crossings_match_intersect),
      cmocka_unit_test(test_bvh_next_child_keeps_order),
      cmocka_unit_test(test_bvh_grazing_spheres),
      cmocka_unit_test(test_bvh_occluded_matches_walk),
      cmocka_unit_test(test_bvh_build_same_tree),
      cmocka_unit_test(test_bvh_build_nan_path_same),
      cmocka_unit_test(test_bvh_slab_ray_matches_scalar),
      cmocka_unit_test(test_bvh_plane_crossings_match_intersect),
      cmocka_unit_test(test_bvh_sphere_leaving_rays),
      cmocka_unit_test(test_bvh_julia_same_as_asking_again),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
