/*
 * obj_blob.c - the blob (POV-Ray 3.7 reference, "Blob"): the surface
 * where the sum of its components' fields equals the threshold.  A
 * component of radius r and strength s adds s (1 - d^2 / r^2)^2 where
 * its distance d from the centre (sphere) or from the axis (cylinder,
 * with hemispherical ends) is below r, and nothing beyond.
 *
 * Along a ray every distance squared is a quadratic q(t), so within the
 * stretch of t where a component acts its field is a quartic.  Each
 * component gives one such piece (a sphere) or three (a cylinder: the
 * tube where the foot of the point lies between the ends, and the two
 * caps around the end points); a component with its own transform is
 * met by the ray mapped into its coordinates, which keeps q quadratic.
 * The ends of all pieces cut the ray into stretches in each of which the
 * field is one quartic, the sum of the active pieces; the crossings are
 * its roots where it equals the threshold, found by lib/trace/roots.c
 * in the stretch (so `sturm` changes nothing).  Each quartic is built
 * around the start of its stretch, so its coefficients stay of the size
 * of the field however far the ray came from.  The normal is minus the
 * field's gradient.
 */
#include "trace/obj_shapes.h"

#include <math.h>

#include "trace/shape.h"
#include <stdlib.h>

#include "trace/roots.h"

/* One piece: where the field is s (1 - q(t) / r^2)^2 along the ray,
   q(t) = q2 t^2 + q1 t + q0, for t in [t0, t1]. */
typedef struct piece {
  double t0, t1;
  double q2, q1, q0;
  double rr, strength;
} piece;

/* The most pieces a blob's ray keeps on the stack; more are heap
   allocated per ray. */
enum { STACK_PIECES = 96 };

/* The interval where q2 t^2 + q1 t + q0 < rr, false if none. */
static bool below(double q2, double q1, double q0, double rr, double *t0,
                  double *t1) {
  double c = q0 - rr;
  if (!(q2 > 0.0))
    return false;
  double disc = q1 * q1 - 4.0 * q2 * c;
  if (!(disc > 0.0))
    return false;
  double q = -0.5 * (q1 + copysign(sqrt(disc), q1));
  double r0 = q / q2, r1 = q != 0.0 ? c / q : r0;
  *t0 = fmin(r0, r1);
  *t1 = fmax(r0, r1);
  return true;
}

/* Adds the pieces of component c along org + t dir (blob space), along
   the whole line: the stretches, and so the crossings' t, must not
   depend on the interval searched, as the tracer finds a crossing again
   by its exact t over a narrower one. */
static int component_pieces(const zr_blob_component *c, zr_vec3 org,
                            zr_vec3 dir, piece *out) {
  if (c->transform) {
    org = zr__xform_point(c->transform->inv, org);
    dir = zr__xform_dir(c->transform->inv, dir);
  }
  double rr = c->radius * c->radius;
  int n = 0;
  /* |org + t dir - e|^2 for an end point e, clipped to where the
     foot's parameter s(t) = s0 + s1 t along the axis is in range. */
  zr_vec3 ends[2] = {c->a, c->b};
  int n_ends = c->cylinder ? 2 : 1;
  zr_vec3 axis = zr_v3_sub(c->b, c->a);
  double len = zr_v3_len(axis);
  bool tube = c->cylinder && len > 0.0;
  zr_vec3 w = tube ? zr_v3_scale(axis, 1.0 / len) : zr_v3(0, 0, 0);
  double s0 = zr_v3_dot(zr_v3_sub(org, c->a), w), s1 = zr_v3_dot(dir, w);
  for (int e = 0; e < n_ends; e++) {
    zr_vec3 oc = zr_v3_sub(org, ends[e]);
    piece p = {0, 0, zr_v3_dot(dir, dir), 2.0 * zr_v3_dot(oc, dir),
               zr_v3_dot(oc, oc), rr, c->strength};
    if (!below(p.q2, p.q1, p.q0, rr, &p.t0, &p.t1))
      continue;
    if (tube) {
      /* The cap beyond its end: s < 0 at a, s > len at b. */
      double edge = e == 0 ? 0.0 : len;
      bool before = e == 0;
      if (s1 == 0.0) {
        if (before ? !(s0 < edge) : !(s0 > edge))
          continue;
      } else {
        double te = (edge - s0) / s1;
        bool beyond_after = before ? s1 < 0.0 : s1 > 0.0;
        if (beyond_after)
          p.t0 = fmax(p.t0, te);
        else
          p.t1 = fmin(p.t1, te);
      }
    }
    if (p.t0 < p.t1)
      out[n++] = p;
  }
  if (tube) {
    /* The tube: |perp|^2 = |oc|^2 - s^2 with oc from a. */
    zr_vec3 oc = zr_v3_sub(org, c->a);
    piece p = {0, 0, zr_v3_dot(dir, dir) - s1 * s1,
               2.0 * (zr_v3_dot(oc, dir) - s0 * s1),
               zr_v3_dot(oc, oc) - s0 * s0, rr, c->strength};
    double t0 = -INFINITY, t1 = INFINITY;
    if (p.q2 > 1e-300 * zr_v3_dot(dir, dir)) {
      if (!below(p.q2, p.q1, p.q0, rr, &t0, &t1))
        return n;
    } else if (!(p.q0 < rr)) {
      return n; /* along the axis, outside the tube */
    }
    if (s1 == 0.0) {
      if (s0 < 0.0 || s0 > len)
        return n;
    } else {
      double ta = (0.0 - s0) / s1, tb = (len - s0) / s1;
      t0 = fmax(t0, fmin(ta, tb));
      t1 = fmin(t1, fmax(ta, tb));
    }
    p.t0 = t0;
    p.t1 = t1;
    if (p.t0 < p.t1)
      out[n++] = p;
  }
  return n;
}

/* Adds the piece's field around t = a, as a quartic in u = t - a. */
static void add_field(const piece *p, double a, double *poly) {
  /* q(a + u) = q2 u^2 + (2 q2 a + q1) u + q(a); the field is
     s (1 - q / rr)^2 = s (k0 + k1 u + k2 u^2)^2 with k = -q / rr + 1. */
  double k2 = -p->q2 / p->rr;
  double k1 = -(2.0 * p->q2 * a + p->q1) / p->rr;
  double k0 = 1.0 - ((p->q2 * a + p->q1) * a + p->q0) / p->rr;
  double s = p->strength;
  poly[0] += s * k0 * k0;
  poly[1] += s * 2.0 * k0 * k1;
  poly[2] += s * (k1 * k1 + 2.0 * k0 * k2);
  poly[3] += s * 2.0 * k1 * k2;
  poly[4] += s * k2 * k2;
}

static int compare_double(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* Component c's field at p (blob space), and its gradient added to
   *grad when grad is not NULL. */
static double component_field(const zr_blob_component *c, zr_vec3 p,
                              zr_vec3 *grad) {
  zr_vec3 q = c->transform ? zr__xform_point(c->transform->inv, p) : p;
  zr_vec3 v = zr_v3_sub(q, c->a); /* from the nearest axis point */
  if (c->cylinder) {
    zr_vec3 axis = zr_v3_sub(c->b, c->a);
    double ll = zr_v3_dot(axis, axis);
    double s = ll > 0.0 ? zr_v3_dot(v, axis) / ll : 0.0;
    s = fmin(1.0, fmax(0.0, s));
    v = zr_v3_sub(q, zr_v3_madd(c->a, axis, s));
  }
  double rr = c->radius * c->radius, dd = zr_v3_dot(v, v);
  if (!(dd < rr))
    return 0.0;
  double k = 1.0 - dd / rr;
  if (grad) {
    /* d/dq of s k^2 is -2 s k / rr; grad q = 2 v (local). */
    zr_vec3 gl = zr_v3_scale(v, -4.0 * c->strength * k / rr);
    if (c->transform)
      gl = zr__xform_normal(c->transform->inv, gl);
    *grad = zr_v3_add(*grad, gl);
  }
  return c->strength * k * k;
}

/* The field and its gradient (blob space) at p. */
static double field(const zr_object *o, zr_vec3 p, zr_vec3 *grad) {
  double sum = 0.0;
  if (grad)
    *grad = zr_v3(0, 0, 0);
  for (size_t i = 0; i < o->u.blob.n_components; i++)
    sum += component_field(&o->u.blob.components[i], p, grad);
  return sum;
}

double zr__blob_component_density(const zr_object *o, size_t i,
                                  zr_vec3 p) {
  return component_field(&o->u.blob.components[i], p, NULL);
}

double zr__blob_density(const zr_object *o, zr_vec3 p) {
  return field(o, p, NULL);
}

bool zr__blob_inside(const zr_object *o, zr_vec3 p) {
  return field(o, p, NULL) > o->u.blob.threshold;
}

bool zr__blob_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  bool any = false;
  zr_vec3 l = zr_v3(INFINITY, INFINITY, INFINITY), h = zr_v3_neg(l);
  for (size_t i = 0; i < o->u.blob.n_components; i++) {
    const zr_blob_component *c = &o->u.blob.components[i];
    /* A component weaker than zero adds no surface of its own. */
    if (!(c->strength > 0.0))
      continue;
    double r = fabs(c->radius);
    zr_vec3 e = zr_v3(r, r, r);
    zr_vec3 cl = zr_v3_sub(c->a, e), ch = zr_v3_add(c->a, e);
    if (c->cylinder) {
      cl = zr_v3_min(cl, zr_v3_sub(c->b, e));
      ch = zr_v3_max(ch, zr_v3_add(c->b, e));
    }
    for (int k = 0; k < 8; k++) {
      zr_vec3 p = zr_v3(k & 1 ? ch.x : cl.x, k & 2 ? ch.y : cl.y,
                        k & 4 ? ch.z : cl.z);
      if (c->transform)
        p = zr__xform_point(c->transform->m, p);
      l = zr_v3_min(l, p);
      h = zr_v3_max(h, p);
    }
    any = true;
  }
  *lo = l;
  *hi = h;
  return any;
}

int zr__blob_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                       double tmin, double tmax, double t[4],
                       zr_vec3 normal[4]) {
  size_t room = 3 * o->u.blob.n_components;
  piece stack_pieces[STACK_PIECES];
  double stack_cuts[2 * STACK_PIECES];
  piece *pieces = stack_pieces;
  double *cuts = stack_cuts;
  if (room > STACK_PIECES) {
    pieces = malloc(room * sizeof *pieces);
    cuts = malloc(2 * room * sizeof *cuts);
    if (!pieces || !cuts) {
      free(pieces);
      free(cuts);
      return 0; /* out of memory: the ray misses */
    }
  }
  size_t n = 0;
  for (size_t i = 0; i < o->u.blob.n_components; i++)
    n += (size_t)component_pieces(&o->u.blob.components[i], org, dir,
                                  pieces + n);
  size_t n_cuts = 0;
  for (size_t i = 0; i < n; i++) {
    cuts[n_cuts++] = pieces[i].t0;
    cuts[n_cuts++] = pieces[i].t1;
  }
  qsort(cuts, n_cuts, sizeof *cuts, compare_double);
  int found = 0;
  for (size_t k = 0; k + 1 < n_cuts && found < ZR_SHAPE_MAX_CROSSINGS;
       k++) {
    double a = cuts[k], b = cuts[k + 1];
    if (!(b > a) || b <= tmin || a >= tmax)
      continue;
    double poly[5] = {-o->u.blob.threshold, 0, 0, 0, 0};
    double mid = 0.5 * (a + b);
    bool active = false;
    for (size_t i = 0; i < n; i++)
      if (pieces[i].t0 <= mid && mid <= pieces[i].t1) {
        add_field(&pieces[i], a, poly);
        active = true;
      }
    if (!active)
      continue;
    double u[4];
    /* The stretch's start belongs to it, so a crossing exactly on a
       cut is not lost between two stretches. */
    int m = 0;
    if (poly[0] == 0.0 && k > 0)
      u[m++] = 0.0;
    m += zr__poly_roots(poly, 4, 0.0, b - a, u + m);
    for (int i = 0; i < m && found < ZR_SHAPE_MAX_CROSSINGS; i++) {
      double th = a + u[i];
      if (!(th > tmin && th < tmax))
        continue;
      zr_vec3 g;
      field(o, zr_v3_madd(org, dir, th), &g);
      t[found] = th;
      normal[found] = zr_v3_neg(g);
      found++;
    }
  }
  if (pieces != stack_pieces) {
    free(pieces);
    free(cuts);
  }
  return found;
}

/* The operations the tracer calls through (lib/trace/shape.h). */
const zr_shape_ops zr__shape_blob = {
    .name = "a blob",
    .search = zr__blob_crossings,
    .inside = zr__blob_inside,
    .bounds = zr__blob_bounds,
};
