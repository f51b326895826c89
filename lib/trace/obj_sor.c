/*
 * obj_sor.c - the surface of revolution (POV-Ray 3.7 reference, "Surface
 * of Revolution"): x^2 + z^2 = f(y), with f a cubic on each segment
 * between two consecutive points of the curve, closed by flat caps at
 * its lowest and highest points unless `open`.
 *
 * The manual gives f's coefficients (the parser computes them, lib/sdl/
 * build_shape.c); here they are kept in the segment's own variable
 * u = (y - h0) / (h1 - h0), which stays in [0, 1].  Along a ray u is
 * linear in t, so x^2 + z^2 - f is a cubic in t on each segment, as the
 * manual promises, and its roots in the stretch of t where the ray is
 * within the segment's heights are the crossings (lib/trace/roots.c; the
 * Sturm solver POV-Ray offers is not needed).  A ray at constant height
 * meets one circle: a quadratic.  The normal is the gradient of
 * x^2 + z^2 - f(y), which points out of the solid.
 */
#include "trace/obj_shapes.h"

#include <math.h>

#include "trace/shape.h"

#include "trace/roots.h"

void zr__sor_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  double r = o->u.sor.rmax;
  const double *first = o->u.sor.seg;
  const double *last = o->u.sor.seg + 6 * (o->u.sor.n_seg - 1);
  *lo = zr_v3(-r, first[0], -r);
  *hi = zr_v3(r, last[1], r);
}

/* f and its slope df/dy on a segment at height y. */
static double profile(const double *seg, double y, double *slope) {
  double dh = seg[1] - seg[0], u = (y - seg[0]) / dh;
  const double *c = seg + 2;
  if (slope)
    *slope = ((3.0 * c[3] * u + 2.0 * c[2]) * u + c[1]) / dh;
  return ((c[3] * u + c[2]) * u + c[1]) * u + c[0];
}

/* The segment holding height y, NULL when outside the curve. */
static const double *segment_at(const zr_object *o, double y) {
  for (size_t i = 0; i < o->u.sor.n_seg; i++) {
    const double *seg = o->u.sor.seg + 6 * i;
    if (y >= seg[0] && y <= seg[1])
      return seg;
  }
  return NULL;
}

bool zr__sor_inside(const zr_object *o, zr_vec3 p) {
  const double *seg = segment_at(o, p.y);
  return seg && p.x * p.x + p.z * p.z < profile(seg, p.y, NULL);
}


static void wall_hit(const double *seg, zr_vec3 org, zr_vec3 dir, double t,
                     double tmin, double tmax, zr_hit_list *l) {
  if (!(t > tmin && t < tmax))
    return;
  zr_vec3 p = zr_v3_madd(org, dir, t);
  double slope;
  profile(seg, fmin(seg[1], fmax(seg[0], p.y)), &slope);
  zr__hits_keep(l, t, zr_v3(2.0 * p.x, -slope, 2.0 * p.z));
}

static void segment_crossings(const double *seg, zr_vec3 org, zr_vec3 dir,
                              double tmin, double tmax, zr_hit_list *l) {
  double a = dir.x * dir.x + dir.z * dir.z;
  double b = 2.0 * (org.x * dir.x + org.z * dir.z);
  double k = org.x * org.x + org.z * org.z;
  double dh = seg[1] - seg[0];
  const double *c = seg + 2;
  if (dir.y == 0.0) {
    if (org.y < seg[0] || org.y > seg[1])
      return;
    double poly[3] = {k - profile(seg, org.y, NULL), b, a}, r[2];
    int n = zr__poly_roots(poly, 2, -INFINITY, INFINITY, r);
    for (int i = 0; i < n; i++)
      wall_hit(seg, org, dir, r[i], tmin, tmax, l);
    return;
  }
  /* u = u0 + u1 t; f = c0 + c1 u + c2 u^2 + c3 u^3 in t. */
  double u0 = (org.y - seg[0]) / dh, u1 = dir.y / dh;
  double poly[4] = {k, b, a, 0.0};
  double pw[4] = {1.0, 0.0, 0.0, 0.0}; /* (u0 + u1 t)^i */
  for (int i = 0; i <= 3; i++) {
    for (int j = 0; j <= 3; j++)
      poly[j] -= c[i] * pw[j];
    for (int j = 3; j > 0; j--)
      pw[j] = pw[j] * u0 + pw[j - 1] * u1;
    pw[0] *= u0;
  }
  double t0 = (seg[0] - org.y) / dir.y, t1 = (seg[1] - org.y) / dir.y;
  double r[3];
  int n = zr__poly_roots(poly, 3, fmin(t0, t1), fmax(t0, t1), r);
  for (int i = 0; i < n; i++)
    wall_hit(seg, org, dir, r[i], tmin, tmax, l);
}

int zr__sor_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                      double tmin, double tmax, double t[4],
                      zr_vec3 normal[4]) {
  zr_vec3 lo, hi;
  zr__sor_bounds(o, &lo, &hi);
  double s0, s1, pad = 1e-9 * fmax(1.0, zr_v3_max_comp(zr_v3_max(
                                              zr_v3_neg(lo), hi)));
  if (!zr__ray_box_span(zr_v3_sub(lo, zr_v3(pad, pad, pad)),
                        zr_v3_add(hi, zr_v3(pad, pad, pad)), org, dir, &s0,
                        &s1) ||
      !(fmax(tmin, s0) < fmin(tmax, s1)))
    return 0;
  zr_hit_list l = {0, {0}, {{0, 0, 0}}};
  for (size_t i = 0; i < o->u.sor.n_seg; i++)
    segment_crossings(o->u.sor.seg + 6 * i, org, dir, tmin, tmax, &l);
  if (!o->u.sor.open && dir.y != 0.0) {
    const double *first = o->u.sor.seg;
    const double *last = o->u.sor.seg + 6 * (o->u.sor.n_seg - 1);
    double h[2] = {first[0], last[1]};
    double rr[2] = {profile(first, first[0], NULL),
                    profile(last, last[1], NULL)};
    for (int i = 0; i < 2; i++) {
      double tc = (h[i] - org.y) / dir.y;
      if (!(tc > tmin && tc < tmax))
        continue;
      zr_vec3 p = zr_v3_madd(org, dir, tc);
      if (p.x * p.x + p.z * p.z <= rr[i])
        zr__hits_keep(&l, tc, zr_v3(0.0, i == 0 ? -1.0 : 1.0, 0.0));
    }
  }
  for (int i = 0; i < l.n; i++) {
    t[i] = l.t[i];
    normal[i] = l.normal[i];
  }
  return l.n;
}

static bool sor_box(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  zr__sor_bounds(o, lo, hi);
  return true;
}

/* The operations the tracer calls through (lib/trace/shape.h). */
const zr_shape_ops zr__shape_sor = {
    .name = "a sor",
    .search = zr__sor_crossings,
    .inside = zr__sor_inside,
    .bounds = sor_box,
};
