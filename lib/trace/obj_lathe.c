/*
 * obj_lathe.c - the lathe (POV-Ray 3.7 reference, "Lathe"): a curve in
 * the (r, y) plane turned about the y axis.  The parser stores the curve
 * as cubic pieces (r(s), y(s)), s in [0, 1], exactly as for a prism
 * (lib/sdl/build_shape.c).
 *
 * A point of the ray o + t d lies on the surface of a piece when its
 * height is y(s) and its distance from the axis r(s).  For a ray that is
 * not horizontal the height gives t = (y(s) - o.y) / d.y, and multiplying
 * the distance condition by d.y^2 leaves the polynomial of degree six
 *   (o.x d.y + (y(s) - o.y) d.x)^2 + (o.z d.y + (y(s) - o.y) d.z)^2
 *     - r(s)^2 d.y^2 = 0,
 * whose roots in [0, 1] lib/trace/roots.c finds (the manual's `sturm`
 * asks for care there; zRcube always takes it).  A horizontal ray keeps
 * its height: the roots of y(s) = o.y are the circles it may meet, each
 * a quadratic in t.  The normal lies in the plane of the axis and the
 * point: along the profile's normal (y'(s), -r'(s)), turned away from
 * the region the curve encloses (even-odd rule, as for the prism), since
 * the curve may run either way round.
 */
#include "trace/obj_shapes.h"

#include <math.h>

#include "trace/shape.h"

#include "trace/roots.h"

static double cubic_at(const double *c, double s) {
  return ((c[3] * s + c[2]) * s + c[1]) * s + c[0];
}

static double cubic_slope(const double *c, double s) {
  return (3.0 * c[3] * s + 2.0 * c[2]) * s + c[1];
}

void zr__lathe_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  double r = fmax(fabs(o->u.lathe.lo.x), fabs(o->u.lathe.hi.x));
  *lo = zr_v3(-r, o->u.lathe.lo.y, -r);
  *hi = zr_v3(r, o->u.lathe.hi.y, r);
}

static bool covers(const zr_object *o, zr_vec3 p) {
  return zr__curves_cover(o->u.lathe.seg, o->u.lathe.box, o->u.lathe.n_seg,
                          sqrt(p.x * p.x + p.z * p.z), p.y);
}

bool zr__lathe_inside(const zr_object *o, zr_vec3 p) { return covers(o, p); }


/* The outward normal at p on the piece seg at s. */
static zr_vec3 lathe_normal(const zr_object *o, const double *seg, double s,
                            zr_vec3 p) {
  double rho = sqrt(p.x * p.x + p.z * p.z);
  zr_vec3 e = rho > 0.0 ? zr_v3(p.x / rho, 0.0, p.z / rho) : zr_v3(1, 0, 0);
  double dr = cubic_slope(seg, s), dy = cubic_slope(seg + 4, s);
  zr_vec3 n = zr_v3(e.x * dy, -dr, e.z * dy);
  double len = zr_v3_len(n);
  if (!(len > 0.0))
    return n;
  double size = fmax(o->u.lathe.hi.y - o->u.lathe.lo.y,
                     fmax(fabs(o->u.lathe.lo.x), fabs(o->u.lathe.hi.x)));
  zr_vec3 q = zr_v3_madd(p, n, 1e-7 * fmax(size, 1e-300) / len);
  return covers(o, q) ? zr_v3_neg(n) : n;
}

/* The product of two cubics into a polynomial of degree six. */
static void multiply_add(const double *a, const double *b, double k,
                         double *out) {
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 4; j++)
      out[i + j] += k * a[i] * b[j];
}

/*
 * Whether the sextic may vanish on [0, 1]: its coefficients in the
 * Bernstein basis of degree 6 bound it there (the curve lies in their
 * convex hull), so when all have one strict sign it has no root and the
 * root search is skipped; b_k = sum over i <= k of C(k, i) / C(6, i) a_i.
 */
static bool bernstein_may_vanish(const double a[7]) {
  static const double binom[7][7] = {
      {1},          {1, 1},           {1, 2, 1},          {1, 3, 3, 1},
      {1, 4, 6, 4, 1}, {1, 5, 10, 10, 5, 1}, {1, 6, 15, 20, 15, 6, 1}};
  bool pos = false, neg = false;
  for (int k = 0; k <= 6; k++) {
    double b = 0.0;
    for (int i = 0; i <= k; i++)
      b += binom[k][i] / binom[6][i] * a[i];
    if (b >= 0.0)
      pos = true;
    if (b <= 0.0)
      neg = true;
    if (pos && neg)
      return true;
  }
  return false;
}

static void piece_crossings(const zr_object *o, const double *seg,
                            zr_vec3 org, zr_vec3 dir, double tmin,
                            double tmax, zr_hit_list *l) {
  const double *r = seg, *y = seg + 4;
  double s[8];
  int n;
  if (dir.y != 0.0) {
    double a[4], b[4], poly[7] = {0};
    for (int k = 0; k < 4; k++) {
      a[k] = y[k] * dir.x;
      b[k] = y[k] * dir.z;
    }
    a[0] += org.x * dir.y - org.y * dir.x;
    b[0] += org.z * dir.y - org.y * dir.z;
    multiply_add(a, a, 1.0, poly);
    multiply_add(b, b, 1.0, poly);
    multiply_add(r, r, -dir.y * dir.y, poly);
    if (!bernstein_may_vanish(poly))
      return;
    n = zr__poly_roots(poly, 6, 0.0, 1.0, s);
    for (int k = 0; k < n; k++) {
      double t = (cubic_at(y, s[k]) - org.y) / dir.y;
      if (!(t > tmin && t < tmax))
        continue;
      zr_vec3 p = zr_v3_madd(org, dir, t);
      zr__hits_keep(l, t, lathe_normal(o, seg, s[k], p));
    }
    return;
  }
  /* Horizontal: the circles at the ray's height. */
  double h[4] = {y[0] - org.y, y[1], y[2], y[3]};
  n = zr__poly_roots(h, 3, 0.0, 1.0, s);
  double a = dir.x * dir.x + dir.z * dir.z;
  if (!(a > 0.0))
    return;
  for (int k = 0; k < n; k++) {
    double rad = cubic_at(r, s[k]);
    double b = 2.0 * (org.x * dir.x + org.z * dir.z);
    double c = org.x * org.x + org.z * org.z - rad * rad;
    double disc = b * b - 4.0 * a * c;
    if (!(disc > 0.0))
      continue;
    double q = -0.5 * (b + copysign(sqrt(disc), b));
    double ts[2] = {q / a, q != 0.0 ? c / q : q / a};
    for (int i = 0; i < 2; i++) {
      if (!(ts[i] > tmin && ts[i] < tmax))
        continue;
      zr_vec3 p = zr_v3_madd(org, dir, ts[i]);
      zr__hits_keep(l, ts[i], lathe_normal(o, seg, s[k], p));
    }
  }
}

/*
 * Whether the ray can meet the surface one segment turns: it must pass
 * through the slab of the segment's heights at a distance from the y
 * axis within the segment's radii (pad widens both).  Skipping the
 * others leaves the crossings as they were and spares most of the
 * degree-six solves (a chess piece has a dozen segments, and a ray near
 * its foot meets one or two).
 */
static bool piece_may_cross(const zr_object *o, size_t i, zr_vec3 org,
                            zr_vec3 dir, double pad) {
  double b[4];
  zr__piece_box(o->u.lathe.seg, o->u.lathe.box, i, b);
  double rlo = b[0], rhi = b[1], ylo = b[2] - pad, yhi = b[3] + pad;
  double rmax = fmax(fabs(rlo), fabs(rhi)) + pad;
  double rmin = (rlo > 0.0 || rhi < 0.0) ? fmin(fabs(rlo), fabs(rhi)) - pad
                                         : 0.0;
  double t0 = -INFINITY, t1 = INFINITY;
  if (dir.y != 0.0) {
    double a = (ylo - org.y) / dir.y, b = (yhi - org.y) / dir.y;
    t0 = fmin(a, b);
    t1 = fmax(a, b);
  } else if (org.y < ylo || org.y > yhi) {
    return false;
  }
  /* d(t) = |(org + t dir) across the axis|^2 = A t^2 + B t + C. */
  double A = dir.x * dir.x + dir.z * dir.z;
  double B = 2.0 * (org.x * dir.x + org.z * dir.z);
  double C = org.x * org.x + org.z * org.z;
  if (!(A > 0.0))
    return C <= rmax * rmax && C >= (rmin > 0.0 ? rmin * rmin : 0.0);
  if (!isfinite(t0) || !isfinite(t1))
    return true;
  double tv = fmin(fmax(-B / (2.0 * A), t0), t1);
  double dmin = (A * tv + B) * tv + C;
  if (dmin > rmax * rmax)
    return false;
  if (rmin > 0.0) {
    double d0 = (A * t0 + B) * t0 + C, d1 = (A * t1 + B) * t1 + C;
    if (fmax(d0, d1) < rmin * rmin)
      return false;
  }
  return true;
}

int zr__lathe_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                        double tmin, double tmax, double t[4],
                        zr_vec3 normal[4]) {
  zr_vec3 lo, hi;
  zr__lathe_bounds(o, &lo, &hi);
  double s0, s1, pad = 1e-9 * fmax(1.0, zr_v3_max_comp(zr_v3_max(
                                              zr_v3_neg(lo), hi)));
  if (!zr__ray_box_span(zr_v3_sub(lo, zr_v3(pad, pad, pad)),
                        zr_v3_add(hi, zr_v3(pad, pad, pad)), org, dir, &s0,
                        &s1))
    return 0;
  if (!(fmax(tmin, s0) < fmin(tmax, s1)))
    return 0;
  zr_hit_list l = {0, {0}, {{0, 0, 0}}};
  for (size_t i = 0; i < o->u.lathe.n_seg; i++)
    if (piece_may_cross(o, i, org, dir, pad))
      piece_crossings(o, o->u.lathe.seg + 8 * i, org, dir, tmin, tmax, &l);
  for (int i = 0; i < l.n; i++) {
    t[i] = l.t[i];
    normal[i] = l.normal[i];
  }
  return l.n;
}

static bool lathe_box(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  zr__lathe_bounds(o, lo, hi);
  return o->u.lathe.n_seg > 0;
}

/* The operations the tracer calls through (lib/trace/shape.h). */
const zr_shape_ops zr__shape_lathe = {
    .name = "a lathe",
    .search = zr__lathe_crossings,
    .inside = zr__lathe_inside,
    .bounds = lathe_box,
};
