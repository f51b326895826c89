/*
 * obj_torus.c - the torus (POV-Ray 3.7 reference, "Torus"): the ring of
 * major radius R about the y axis, in the x-z plane, with a round cross
 * section of minor radius r.
 *
 * Its points satisfy the quartic
 *   f(p) = (|p|^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + z^2) = 0,
 * negative inside the rim.  A ray p = o + s d with |d| = 1 turns f into a
 * quartic in s whose coefficients follow from expanding the square
 * (below).  Before solving, the ray is clipped to the torus's bounding
 * box and its origin moved to where it enters, so s stays of the order
 * of the torus's size: the coefficients are then well scaled, and the
 * roots come from lib/trace/roots.c, which isolates them by derivatives
 * and is exact to a few ulps even for grazing rays (POV-Ray's `sturm`
 * asks for that; zRcube always does it).  The normal is the gradient
 *   grad f / 4 = (|p|^2 + R^2 - r^2) p - 2 R^2 (x, 0, z).
 */
#include "trace/obj_shapes.h"

#include <math.h>

#include "trace/shape.h"

#include "trace/roots.h"

bool zr__ray_box_span(zr_vec3 lo, zr_vec3 hi, zr_vec3 org, zr_vec3 dir,
                      double *s0, double *s1) {
  double a = -INFINITY, b = INFINITY;
  for (int axis = 0; axis < 3; axis++) {
    double o = zr_v3_get(org, axis), d = zr_v3_get(dir, axis);
    double l = zr_v3_get(lo, axis), h = zr_v3_get(hi, axis);
    if (d == 0.0) {
      if (o < l || o > h)
        return false;
      continue;
    }
    double t0 = (l - o) / d, t1 = (h - o) / d;
    if (t0 > t1) {
      double tt = t0;
      t0 = t1;
      t1 = tt;
    }
    /* Comparisons, not fmax and fmin: those are calls into libm, and
       this runs for every CSG child a ray passes (a NaN, which fmax
       would skip, leaves a and b alone here as well). */
    a = t0 > a ? t0 : a;
    b = t1 < b ? t1 : b;
  }
  *s0 = a;
  *s1 = b;
  return a < b;
}

void zr__torus_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  double r = fabs(o->u.torus.minor), big = fabs(o->u.torus.major) + r;
  *lo = zr_v3(-big, -r, -big);
  *hi = zr_v3(big, r, big);
}

static double torus_value(const zr_object *o, zr_vec3 p) {
  double rr = o->u.torus.major * o->u.torus.major;
  double k = zr_v3_dot(p, p) + rr - o->u.torus.minor * o->u.torus.minor;
  return k * k - 4.0 * rr * (p.x * p.x + p.z * p.z);
}

bool zr__torus_inside(const zr_object *o, zr_vec3 p) {
  return torus_value(o, p) < 0.0;
}

/*
 * Whether the ray q + s d, 0 <= s <= span (its part in the torus's box,
 * d a unit vector), stays clear of the ring: every point of the torus
 * lies at a distance rho from the y axis with |R| - |r| <= rho <=
 * |R| + |r|, and rho^2 along the ray is a parabola in s, so its least
 * value on the span is at the vertex or an end and its greatest at an
 * end.  A span wholly beyond the outer radius or wholly within the hole
 * has no root, and the quartic is not solved: many rays that cross a
 * thin torus's box pass through its hole or beside its rim (the corpus'
 * truchet.pov, 16,000 tori: the root finder's samples fell by a fifth).
 * The radii are widened by a millionth, far beyond the roots' rounding,
 * so no crossing the solver would find is lost.
 */
static bool misses_ring(const zr_object *o, zr_vec3 q, zr_vec3 d,
                        double span) {
  double big = fabs(o->u.torus.major), small = fabs(o->u.torus.minor);
  double outer = (big + small) * (1.0 + 1e-6);
  double e = d.x * d.x + d.z * d.z, f = q.x * d.x + q.z * d.z;
  double g0 = q.x * q.x + q.z * q.z;
  double g1 = g0 + span * (2.0 * f + span * e); /* rho^2 at the far end */
  double at = e > 0.0 ? -f / e : 0.0;           /* the parabola's vertex */
  at = at < 0.0 ? 0.0 : at > span ? span : at;
  double least = g0 + at * (2.0 * f + at * e);
  if (least > outer * outer)
    return true;
  double hole = (big - small) * (1.0 - 1e-6);
  return hole > 0.0 && g0 < hole * hole && g1 < hole * hole;
}

/*
 * The crossings in (tmin, tmax), nearest first: at most max_found of
 * them, with their normals when normal is not NULL.  The quartic's roots
 * are walked in order (zr__root_walk, the bits zr__poly_roots gives
 * them): a root that lies before tmin or beyond tmax, or past the ones
 * wanted, is not refined, nor are the derivative's roots beyond the last
 * one taken.  A search for the nearest surface wants one crossing and no
 * normal; half the quartic's refinements went to the second crossing of
 * a ray that met the torus (radiosity2.pov: 119,000 of 136,000 solves
 * had two roots).  With normals, every crossing in the interval is
 * given, as the tracer's second asking (bvh.c's nearest, which picks the
 * one nearest the t it found) has always had them.
 */
static int torus_search(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                        double tmin, double tmax, int max_found,
                        double t[4], zr_vec3 *normal) {
  double len = zr_v3_len(dir);
  if (!(len > 0.0) || !isfinite(len))
    return 0;
  zr_vec3 d = zr_v3_scale(dir, 1.0 / len);
  zr_vec3 lo, hi;
  zr__torus_bounds(o, &lo, &hi);
  /* A hair of padding so a ray along a face of the box still counts. */
  double pad = 1e-9 * hi.x;
  lo = zr_v3_sub(lo, zr_v3(pad, pad, pad));
  hi = zr_v3_add(hi, zr_v3(pad, pad, pad));
  double s0, s1;
  if (!zr__ray_box_span(lo, hi, org, d, &s0, &s1))
    return 0;
  /* The whole span in the box is searched whatever the interval, so a
     crossing's t does not depend on it: the tracer finds a crossing
     again by its exact t over a narrower interval. */
  if (!(fmax(s0, tmin * len) < fmin(s1, tmax * len)))
    return 0;
  zr_vec3 q = zr_v3_madd(org, d, s0); /* the new origin */
  if (misses_ring(o, q, d, s1 - s0))
    return 0;
  double rr = o->u.torus.major * o->u.torus.major;
  double b = 2.0 * zr_v3_dot(q, d);
  double c = zr_v3_dot(q, q) + rr - o->u.torus.minor * o->u.torus.minor;
  double e = d.x * d.x + d.z * d.z;
  double f = 2.0 * (q.x * d.x + q.z * d.z);
  double g = q.x * q.x + q.z * q.z;
  double coef[5] = {c * c - 4.0 * rr * g, 2.0 * b * c - 4.0 * rr * f,
                    b * b + 2.0 * c - 4.0 * rr * e, 2.0 * b, 1.0};
  if (normal)
    max_found = 4;
  zr__root_walk walk;
  zr__root_walk_start(&walk, coef, 4, 0.0, s1 - s0);
  int kept = 0;
  double at, end;
  while (kept < max_found && zr__root_walk_next(&walk, &at, &end)) {
    /* The root lies in (at, end), and t grows with it, rounding
       included: the whole piece before tmin is passed over, and the
       pieces from tmax on are not searched. */
    if ((s0 + end) / len <= tmin)
      continue;
    if ((s0 + at) / len >= tmax)
      break;
    double si = zr__root_walk_root(&walk);
    double ti = (s0 + si) / len;
    if (!(ti > tmin && ti < tmax))
      continue;
    if (normal) {
      zr_vec3 p = zr_v3_madd(q, d, si);
      double k =
          zr_v3_dot(p, p) + rr - o->u.torus.minor * o->u.torus.minor;
      normal[kept] = zr_v3_sub(zr_v3_scale(p, k),
                               zr_v3(2.0 * rr * p.x, 0.0, 2.0 * rr * p.z));
    }
    t[kept++] = ti;
  }
  return kept;
}

int zr__torus_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                        double tmin, double tmax, double t[4],
                        zr_vec3 normal[4]) {
  return torus_search(o, org, dir, tmin, tmax, 4, t, normal);
}

static bool torus_box(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  zr__torus_bounds(o, lo, hi);
  return true;
}

#define UV_PI 3.14159265358979323846

/* u about the y axis from -x, v about the tube from its inner equator
   (POV-Ray 3.7's torus; povray renders of uv_mapping gradient x and
   gradient y on a torus agree). */
static void torus_uv(const zr_object *o, zr_vec3 p, double *u, double *v) {
  *u = 1.0 - (atan2(p.z, p.x) + UV_PI) / (2.0 * UV_PI);
  double x = sqrt(p.x * p.x + p.z * p.z) - o->u.torus.major;
  *v = (atan2(p.y, x) + UV_PI) / (2.0 * UV_PI);
}

/* The operations the tracer calls through (lib/trace/shape.h). */
const zr_shape_ops zr__shape_torus = {
    .name = "a torus",
    .search = zr__torus_crossings,
    .search_upto = torus_search, /* what intersect.c calls */
    .inside = zr__torus_inside,
    .bounds = torus_box,
    .uv = torus_uv,
};
