/*
 * shaft.c - one test for all the shadow rays from a point to an area
 * light, or to a group of area lights that lie in one plane.
 *
 * An area light ("Area Lights" in the reference) is a grid of point
 * lights; the shadow rays from a surface point p to its points (jitter
 * moves each within its cell, circular squashes the grid into a disc,
 * both inside the grid's rectangle grown by half a cell) all lie in the
 * pyramid whose apex is p and whose base is that rectangle: a shaft.
 * When the shaft meets no surface that casts shadows, every one of the
 * rays would find the light unblocked, and the visibility lib/trace/
 * lights.c would average from them is known without tracing one.  The
 * shaft is tested against the scene's hierarchy (zr__bvh_region_clear):
 * a box or a primitive is cleared when one of the shaft's planes (its
 * sides and its base) leaves it wholly outside, when the two boxes are
 * apart, or, for a triangle, a plain plane or a sphere, by its own
 * shape (all the shaft on one side of the triangle's or the plane's
 * plane).  These are separating planes, so a cleared primitive is
 * exactly one no ray of the shaft can cross; the tests keep a margin
 * of 1e-9 of the scene's size, far above the rounding of a ray's own
 * intersection test and far below the surface offset rays leave from
 * (1e-8 of it, lib/trace/intersect.h), so what the shaft clears the
 * rays would not have met.  The shapes it cannot clear make its plan
 * (zr_shaft_plan): when there are at most ZR_SHAFT_LIST_MAX of them
 * and each is opaque (one solid colour, neither filter nor transmit,
 * a shape whose crossings name itself), a ray is blocked exactly when
 * it crosses one of them, so the rays test that list alone instead of
 * walking the hierarchy and shading what they meet; otherwise (a glass
 * ball, an unbounded shape other than a plain plane, a mesh) the light
 * goes back to its rays.  Either way the answers are the walk's and a
 * picture's bytes do not change (tests/test_shaft.c checks plans
 * against the walk, and renders a room with the shafts and without).
 *
 * The shadow rays stop short of the light by a millionth of their
 * length (lib/trace/shade.c: a surface through the light does not
 * shadow it, as radiosity/cornell.pov's ceiling around its lights), so
 * the base is moved toward p by half that, and a ceiling in the lights'
 * plane is cleared by its own plane.
 *
 * Groups: area lights whose rectangles lie in one plane (a panel split
 * into tiles, as radiosity/cornell.pov's nine 4 x 4 lights) share one
 * shaft over the convex hull of their rectangles, tested once for a
 * point and reused by the group's other lights from the same point
 * (zr_shadow_cache.shaft).  When the group's shaft is not clear, each
 * light's own shaft narrows the group's list with the cheaper tests
 * (radiosity/cornell.pov at 64x64: 606,694 shadow ray walks became
 * 257,390 rays, most against a short list; render CPU 0.145 -> 0.049
 * s, bench/README.md).
 */
#include "trace/shaft.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "trace/bvh.h"
#include "trace/intersect.h"

/* The largest base polygon kept (corners of a group's hull). */
enum { HULL_MAX = 32 };

/* A base polygon: convex, in order around its plane's normal n. */
typedef struct hull {
  zr_vec3 n;
  zr_vec3 pts[HULL_MAX];
  int n_pts;
  /* How far a grid point may lie outside the polygon or off its plane:
     rounding, and lights of a group a little off the first one's plane. */
  double slack;
  double extent; /* the largest coordinate magnitude of pts */
} hull;

struct zr_light_shafts {
  hull *hulls;
  size_t n_hulls;
  int32_t *group, *own; /* per light: hull indices, -1 for none */
  size_t n_lights;
};

void zr__shafts_free(struct zr_light_shafts *shafts) {
  if (!shafts)
    return;
  free(shafts->hulls);
  free(shafts->group);
  free(shafts->own);
  free(shafts);
}

/* Whether a shaft can stand for the light's shadow rays: an area light
   whose rays run to its grid points (not parallel, not a cylinder), a
   grid fixed in space (not orient) and a plain shadow walk (not
   projected_through). */
static bool covered(const zr_light *l) {
  if (!l->area || (l->size1 < 2 && l->size2 < 2))
    return false;
  if (l->parallel || l->kind == ZR_LIGHT_CYLINDER || l->orient ||
      l->projected_through || l->shadowless)
    return false;
  zr_vec3 n = zr_v3_cross(l->axis1, l->axis2);
  return zr_v3_len(n) > 0.0 && isfinite(zr_v3_len(n)) &&
         isfinite(zr_v3_len(l->location));
}

/* The half extents of the grid along axis1 and axis2, as fractions of
   the axes: half the grid, and half a cell more for jitter
   (lib/trace/lights.c, zr__area_light_point). */
static double half_extent(int size, bool jitter) {
  if (size < 2)
    return 0.0;
  return 0.5 + (jitter ? 0.5 / (size - 1) : 0.0);
}

static void light_corners(const zr_light *l, zr_vec3 c[4]) {
  double e1 = half_extent(l->size1, l->jitter);
  double e2 = half_extent(l->size2, l->jitter);
  for (int k = 0; k < 4; k++) {
    double a = k & 1 ? e1 : -e1, b = k & 2 ? e2 : -e2;
    c[k] = zr_v3_madd(zr_v3_madd(l->location, l->axis1, a), l->axis2, b);
  }
}

static zr_vec3 unit_normal(const zr_light *l) {
  return zr_v3_norm(zr_v3_cross(l->axis1, l->axis2));
}

/* Whether light b's rectangle lies in light a's plane, to rounding. */
static bool coplanar(const zr_light *a, const zr_light *b) {
  zr_vec3 na = unit_normal(a), nb = unit_normal(b);
  double scale = 1.0 + zr_v3_len(a->location) + zr_v3_len(b->location);
  return fabs(zr_v3_dot(na, nb)) > 1.0 - 1e-12 &&
         fabs(zr_v3_dot(na, zr_v3_sub(b->location, a->location))) <=
             1e-12 * scale;
}

typedef struct pt2 {
  double x, y;
} pt2;

static int cmp_pt2(const void *pa, const void *pb) {
  const pt2 *a = pa, *b = pb;
  if (a->x != b->x)
    return a->x < b->x ? -1 : 1;
  if (a->y != b->y)
    return a->y < b->y ? -1 : 1;
  return 0;
}

static double turn(pt2 o, pt2 a, pt2 b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

/* Andrew's monotone chain: the convex hull of p[0..n) counterclockwise,
   without collinear points, into out (room for 2 n + 1); its size. */
static int hull_2d(pt2 *p, int n, pt2 *out) {
  qsort(p, (size_t)n, sizeof *p, cmp_pt2);
  int k = 0;
  for (int i = 0; i < n; i++) {
    while (k >= 2 && turn(out[k - 2], out[k - 1], p[i]) <= 0.0)
      k--;
    out[k++] = p[i];
  }
  for (int i = n - 2, lo = k + 1; i >= 0; i--) {
    while (k >= lo && turn(out[k - 2], out[k - 1], p[i]) <= 0.0)
      k--;
    out[k++] = p[i];
  }
  return k > 1 ? k - 1 : k;
}

/* The hull of the rectangles of lights ids[0..n) (coplanar with the
   first); false when it has too many corners or is degenerate. */
static bool make_hull(const zr_light *lights, const size_t *ids, size_t n,
                      hull *h) {
  const zr_light *first = &lights[ids[0]];
  zr_vec3 nrm = unit_normal(first);
  zr_vec3 u = zr_v3_norm(first->axis1);
  zr_vec3 v = zr_v3_cross(nrm, u);
  zr_vec3 o = first->location;
  size_t np = 4 * n;
  pt2 *p = malloc(np * sizeof *p), *out = malloc((2 * np + 1) * sizeof *out);
  if (!p || !out) {
    free(p);
    free(out);
    return false;
  }
  double off_plane = 0.0, size = 0.0;
  for (size_t i = 0; i < n; i++) {
    const zr_light *l = &lights[ids[i]];
    zr_vec3 c[4];
    light_corners(l, c);
    for (int k = 0; k < 4; k++) {
      zr_vec3 d = zr_v3_sub(c[k], o);
      p[4 * i + (size_t)k] = (pt2){zr_v3_dot(d, u), zr_v3_dot(d, v)};
      off_plane = fmax(off_plane, fabs(zr_v3_dot(d, nrm)));
      size = fmax(size, zr_v3_len(c[k]));
    }
  }
  int k = hull_2d(p, (int)np, out);
  bool ok = k >= 3 && k <= HULL_MAX;
  if (ok) {
    h->n = nrm;
    h->n_pts = k;
    h->extent = 0.0;
    for (int i = 0; i < k; i++) {
      h->pts[i] = zr_v3_madd(zr_v3_madd(o, u, out[i].x), v, out[i].y);
      h->extent = fmax(h->extent, fmax(fabs(h->pts[i].x),
                                       fmax(fabs(h->pts[i].y),
                                            fabs(h->pts[i].z))));
    }
    h->slack = off_plane + 1e-9 * (1.0 + size);
  }
  free(p);
  free(out);
  return ok;
}

zr_status zr__shafts_build(zr_scene *scene) {
  scene->shafts = NULL;
  size_t nl = scene->n_lights, eligible = 0;
  for (size_t i = 0; i < nl; i++)
    eligible += covered(&scene->lights[i]);
  if (eligible == 0)
    return ZR_OK;
  struct zr_light_shafts *s = calloc(1, sizeof *s);
  size_t *ids = malloc(nl * sizeof *ids);
  if (s) {
    s->hulls = malloc(2 * eligible * sizeof *s->hulls);
    s->group = malloc(nl * sizeof *s->group);
    s->own = malloc(nl * sizeof *s->own);
    s->n_lights = nl;
  }
  if (!s || !ids || !s->hulls || !s->group || !s->own) {
    zr__shafts_free(s);
    free(ids);
    return ZR_ENOMEM;
  }
  for (size_t i = 0; i < nl; i++)
    s->group[i] = s->own[i] = -1;
  for (size_t i = 0; i < nl; i++) {
    const zr_light *l = &scene->lights[i];
    if (!covered(l) || !make_hull(scene->lights, &i, 1, &s->hulls[s->n_hulls]))
      continue;
    s->own[i] = (int32_t)s->n_hulls++;
  }
  /* Groups: each light not yet in one gathers the later lights in its
     plane. */
  for (size_t i = 0; i < nl; i++) {
    if (s->own[i] < 0 || s->group[i] >= 0)
      continue;
    size_t n = 0;
    ids[n++] = i;
    for (size_t j = i + 1; j < nl; j++)
      if (s->own[j] >= 0 && s->group[j] < 0 &&
          coplanar(&scene->lights[i], &scene->lights[j]))
        ids[n++] = j;
    int32_t g = s->own[i];
    if (n > 1 && make_hull(scene->lights, ids, n, &s->hulls[s->n_hulls]))
      g = (int32_t)s->n_hulls++;
    for (size_t k = 0; k < n; k++)
      s->group[ids[k]] = n > 1 ? g : s->own[ids[k]];
  }
  free(ids);
  scene->shafts = s;
  return ZR_OK;
}

/* The shaft from one point: its planes (outward normals, points x
   inside having dot(m, x) <= d), its box, and its corners. */
typedef struct shaft {
  zr_vec3 m[HULL_MAX + 1];
  double d[HULL_MAX + 1];
  int n_planes;
  zr_vec3 corner[HULL_MAX + 1]; /* the apex, then the base */
  int n_corners;
  double lo[3], hi[3];
  double eps; /* the margin every test keeps */
  bool thorough; /* try the edges' axes too (edges_apart) */
} shaft;

/* fmin and fmax without their NaN rules, which keep GCC from inlining
   them: every value here is finite. */
static inline double lesser(double a, double b) { return a < b ? a : b; }
static inline double greater(double a, double b) { return a > b ? a : b; }

static double axis_of(zr_vec3 p, int a) {
  return a == 0 ? p.x : a == 1 ? p.y : p.z;
}

/* The shaft from apex to h's polygon; false when the apex lies so near
   the polygon's plane that the pyramid is too flat to orient. */
static bool make_shaft(const hull *h, zr_vec3 apex, shaft *s) {
  double ext = greater(h->extent, greater(fabs(apex.x),
                                    greater(fabs(apex.y), fabs(apex.z))));
  s->eps = 1e-9 * (1.0 + ext) + h->slack;
  s->thorough = true;
  double height = zr_v3_dot(h->n, zr_v3_sub(apex, h->pts[0]));
  if (!(fabs(height) > 1e-6 * (1.0 + ext)))
    return false;
  /* The rays end a millionth short of the light: the base moves toward
     the apex by less than that (2^-21 of the way), so it still holds
     their ends. */
  const double f = 1.0 - 0x1p-21;
  int k = h->n_pts;
  s->corner[0] = apex;
  zr_vec3 centre = zr_v3(0, 0, 0);
  for (int i = 0; i < k; i++) {
    s->corner[i + 1] =
        zr_v3_madd(apex, zr_v3_sub(h->pts[i], apex), f);
    centre = zr_v3_add(centre, s->corner[i + 1]);
  }
  s->n_corners = k + 1;
  centre = zr_v3_scale(centre, 1.0 / k);
  for (int i = 0; i < k; i++) {
    zr_vec3 a = s->corner[i + 1], b = s->corner[(i + 1) % k + 1];
    zr_vec3 m = zr_v3_cross(zr_v3_sub(a, apex), zr_v3_sub(b, a));
    double len = zr_v3_len(m);
    if (!(len > 0.0) || !isfinite(len))
      return false;
    m = zr_v3_scale(m, 1.0 / len);
    if (zr_v3_dot(m, zr_v3_sub(centre, apex)) > 0.0)
      m = zr_v3_neg(m);
    s->m[i] = m;
    s->d[i] = zr_v3_dot(m, apex);
  }
  /* The base: the apex inside. */
  zr_vec3 out = height > 0.0 ? zr_v3_neg(h->n) : h->n;
  double d = -INFINITY;
  for (int i = 0; i < k; i++)
    d = greater(d, zr_v3_dot(out, s->corner[i + 1]));
  s->m[k] = out;
  s->d[k] = d;
  s->n_planes = k + 1;
  for (int a = 0; a < 3; a++) {
    s->lo[a] = s->hi[a] = axis_of(apex, a);
    for (int i = 1; i <= k; i++) {
      s->lo[a] = lesser(s->lo[a], axis_of(s->corner[i], a));
      s->hi[a] = greater(s->hi[a], axis_of(s->corner[i], a));
    }
  }
  return true;
}

/* Whether a box may meet the shaft: not when the boxes are apart or a
   plane of the shaft leaves the box outside. */
static bool box_meets(const double lo[3], const double hi[3], void *user) {
  const shaft *s = user;
  for (int a = 0; a < 3; a++)
    if (lo[a] > s->hi[a] + s->eps || hi[a] < s->lo[a] - s->eps)
      return false;
  for (int i = 0; i < s->n_planes; i++) {
    zr_vec3 m = s->m[i];
    double near = (m.x > 0.0 ? m.x * lo[0] : m.x * hi[0]) +
                  (m.y > 0.0 ? m.y * lo[1] : m.y * hi[1]) +
                  (m.z > 0.0 ? m.z * lo[2] : m.z * hi[2]);
    if (near > s->d[i] + s->eps)
      return false;
  }
  return true;
}

/* Whether the shaft lies wholly on one side of the plane dot(n, x) =
   dist, n of unit length. */
static bool beside_plane(const shaft *s, zr_vec3 n, double dist) {
  int above = 0, below = 0;
  for (int i = 0; i < s->n_corners; i++) {
    double h = zr_v3_dot(n, s->corner[i]) - dist;
    above += h > s->eps;
    below += h < -s->eps;
  }
  return above == s->n_corners || below == s->n_corners;
}

/* The last separating axes between two convex shapes: the cross
   products of an edge of the triangle p and a side edge of the shaft
   (apex to a corner; the base's edges, out at the light, seldom tell
   the two apart).  A pyramid beside a block's edge is most often told
   apart from its faces only so. */
static bool edges_apart(const shaft *s, const zr_vec3 p[3]) {
  int k = s->n_corners - 1;
  for (int te = 0; te < 3; te++) {
    zr_vec3 e = zr_v3_sub(p[(te + 1) % 3], p[te]);
    for (int se = 0; se < k; se++) {
      zr_vec3 f = zr_v3_sub(s->corner[se + 1], s->corner[0]);
      zr_vec3 a = zr_v3_cross(e, f);
      double len = zr_v3_len(a);
      if (!(len > 0.0) || !isfinite(len))
        continue;
      double t0 = zr_v3_dot(a, p[0]), t1 = zr_v3_dot(a, p[1]),
             t2 = zr_v3_dot(a, p[2]);
      double tlo = lesser(t0, lesser(t1, t2)), thi = greater(t0, greater(t1, t2));
      double slo = INFINITY, shi = -INFINITY;
      for (int i = 0; i < s->n_corners; i++) {
        double x = zr_v3_dot(a, s->corner[i]);
        slo = lesser(slo, x);
        shi = greater(shi, x);
      }
      double gap = s->eps * len;
      if (tlo > shi + gap || thi < slo - gap)
        return true;
    }
  }
  return false;
}

static bool triangle_clear(const shaft *s, const zr_object *o) {
  const zr_vec3 *p = o->u.triangle.p;
  double lo[3], hi[3];
  for (int a = 0; a < 3; a++) {
    lo[a] = lesser(axis_of(p[0], a), lesser(axis_of(p[1], a), axis_of(p[2], a)));
    hi[a] = greater(axis_of(p[0], a), greater(axis_of(p[1], a), axis_of(p[2], a)));
    if (lo[a] > s->hi[a] + s->eps || hi[a] < s->lo[a] - s->eps)
      return true;
  }
  for (int i = 0; i < s->n_planes; i++)
    if (zr_v3_dot(s->m[i], p[0]) > s->d[i] + s->eps &&
        zr_v3_dot(s->m[i], p[1]) > s->d[i] + s->eps &&
        zr_v3_dot(s->m[i], p[2]) > s->d[i] + s->eps)
      return true;
  zr_vec3 n = zr_v3_cross(zr_v3_sub(p[1], p[0]), zr_v3_sub(p[2], p[0]));
  double len = zr_v3_len(n);
  if (!(len > 0.0) || !isfinite(len))
    return false;
  n = zr_v3_scale(n, 1.0 / len);
  if (beside_plane(s, n, zr_v3_dot(n, p[0])))
    return true;
  return s->thorough && edges_apart(s, p);
}

static bool sphere_clear(const shaft *s, zr_vec3 c, double r) {
  for (int i = 0; i < s->n_planes; i++)
    if (zr_v3_dot(s->m[i], c) > s->d[i] + r + s->eps)
      return true;
  double lo[3] = {c.x - r, c.y - r, c.z - r};
  double hi[3] = {c.x + r, c.y + r, c.z + r};
  return !box_meets(lo, hi, (void *)s);
}

/* Whether no shadow ray of the shaft can cross o. */
static bool prim_clear(const zr_object *o, void *user) {
  const shaft *s = user;
  /* The shadow walk passes no_shadow objects by (lib/trace/shade.c). */
  if (o->no_shadow)
    return true;
  if (!o->transform && !o->clip) {
    if (o->kind == ZR_OBJ_TRIANGLE)
      return triangle_clear(s, o);
    if (o->kind == ZR_OBJ_PLANE)
      return beside_plane(s, o->u.plane.normal, o->u.plane.distance);
    if (o->kind == ZR_OBJ_SPHERE)
      return sphere_clear(s, o->u.sphere.centre, o->u.sphere.radius);
  }
  zr_vec3 lo, hi;
  if (!zr__primitive_bounds(o, &lo, &hi))
    return false;
  double l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z};
  return !box_meets(l, h, (void *)s);
}

/*
 * Whether o stops every shadow ray that crosses it, whatever the
 * point: the shadow walk (lib/trace/shade.c, shadow_visit) ends at any
 * crossing of an object that casts shadows and has one solid colour
 * with neither filter nor transmit.  Only shapes whose crossings name
 * the object itself (not a CSG part, not a mesh's textured copy).
 */
static bool stops_light(const zr_object *o) {
  if (!zr__simple_kind(o->kind))
    return false;
  const zr_texture *tx = o->texture;
  if (o->solid || o->no_shadow || !tx || tx->over || tx->map || !tx->pigment)
    return false;
  const zr_pigment *pg = tx->pigment;
  return pg->kind == ZR_PIGMENT_SOLID && pg->colour.f == 0.0 &&
         pg->colour.t == 0.0;
}

/* A shaft and the primitives it could not clear. */
typedef struct gather {
  shaft s;
  zr_shaft_plan *plan;
} gather;

static bool gather_prim(const zr_object *o, void *user) {
  gather *g = user;
  if (prim_clear(o, &g->s))
    return true;
  if (g->plan->n >= ZR_SHAFT_LIST_MAX || !stops_light(o))
    return false;
  g->plan->objects[g->plan->n++] = o;
  return true;
}

static bool gather_meets(const double lo[3], const double hi[3],
                         void *user) {
  return box_meets(lo, hi, &((gather *)user)->s);
}

/* The plan of hull h's shaft from apex, by a walk of the hierarchy. */
static void hull_plan(const zr_scene *scene, const hull *h, zr_vec3 apex,
                      zr_shaft_plan *plan) {
  gather g;
  g.plan = plan;
  plan->n = 0;
  if (!make_shaft(h, apex, &g.s) ||
      !zr__bvh_region_clear(scene->bvh, gather_meets, gather_prim, &g))
    plan->n = -1;
}

static bool same_point(zr_vec3 a, zr_vec3 b) {
  return memcmp(&a, &b, sizeof a) == 0;
}

/* hull_plan, remembered in the thread's shadow cache. */
static void hull_plan_kept(const zr_tracer *tr, uint32_t index,
                           zr_vec3 apex, zr_shaft_plan *plan) {
  const struct zr_light_shafts *ls = tr->scene->shafts;
  zr_shadow_cache *c = tr->shadow_cache;
  if (c)
    for (int i = 0; i < ZR_SHAFT_SLOTS; i++)
      if (c->shaft[i].hull == index + 1 &&
          same_point(c->shaft[i].apex, apex)) {
        *plan = c->shaft[i].plan;
        return;
      }
  hull_plan(tr->scene, &ls->hulls[index], apex, plan);
  if (c) {
    struct zr_shaft_memo *m = &c->shaft[c->shaft_next++ % ZR_SHAFT_SLOTS];
    m->hull = index + 1;
    m->apex = apex;
    m->plan = *plan;
  }
}

void zr__shaft_plan(const zr_tracer *tracer, const zr_light *light,
                    zr_vec3 lit_from, bool own, zr_shaft_plan *plan) {
  plan->n = -1;
  const zr_scene *scene = tracer->scene;
  const struct zr_light_shafts *ls = scene->shafts;
  if (!ls)
    return;
  uintptr_t at = (uintptr_t)light, first = (uintptr_t)scene->lights;
  if (at < first || (at - first) % sizeof *light != 0)
    return;
  size_t i = (at - first) / sizeof *light;
  if (i >= ls->n_lights || ls->own[i] < 0)
    return;
  int32_t g = ls->group[i], o = ls->own[i];
  /* A ray to the centre alone costs less than a shaft test that no
     other light will reuse. */
  if (!own && (g == o || !tracer->shadow_cache))
    return;
  if (g != o) {
    hull_plan_kept(tracer, (uint32_t)g, lit_from, plan);
    if (plan->n == 0 || !own)
      return;
  }
  if (plan->n < 0) {
    hull_plan(scene, &ls->hulls[o], lit_from, plan);
    return;
  }
  /* The group's blockers that the light's own shaft does not clear. */
  shaft s;
  if (!make_shaft(&ls->hulls[o], lit_from, &s))
    return;
  /* Four rays against a short list cost less than the edges' axes. */
  s.thorough = false;
  int n = 0;
  for (int k = 0; k < plan->n; k++)
    if (!prim_clear(plan->objects[k], &s))
      plan->objects[n++] = plan->objects[k];
  plan->n = n;
}

bool zr__shaft_blocks(const zr_tracer *tracer, const zr_shaft_plan *plan,
                      zr_vec3 lit_from, zr_vec3 target) {
  /* The shadow walk's ray and interval (zr__shadow_transmission). */
  zr_ray ray = {lit_from, zr_v3_sub(target, lit_from)};
  tracer->stats->shadow_rays++;
  zr_hit h[ZR_MAX_CROSSINGS];
  for (int k = 0; k < plan->n; k++)
    if (zr__bvh_crossings_t(plan->objects[k], &ray, 0.0, 1.0 - 1e-6, h) > 0)
      return true;
  return false;
}
