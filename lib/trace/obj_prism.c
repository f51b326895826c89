/*
 * obj_prism.c - the prism (POV-Ray 3.7 reference, "Prism"): closed
 * curves in the x-z plane swept along y between two heights, with
 * linear walls or, for conic_sweep, walls that shrink the curve towards
 * the apex at the origin (the curve at height y is the given one scaled
 * by y).  Overlaps of an even number of sub-prisms are holes.
 *
 * Whatever the spline, the parser (lib/sdl/build_shape.c) stores each
 * piece of curve as a cubic c(s) = (x(s), z(s)), s in [0, 1], in the
 * power basis.  A linear-sweep wall is met where the ray's shadow on the
 * x-z plane crosses the curve: with the ray's origin o and direction d,
 *   (x(s) - o.x) d.z - (z(s) - o.z) d.x = 0,
 * a cubic in s.  A conic wall holds the points y (x(s), 1, z(s)); such a
 * point is on the ray when it lies in the plane through the apex that
 * holds the ray, whose normal is m = o x d:
 *   m . (x(s), 1, z(s)) = 0,
 * again a cubic.  Each root in [0, 1] gives the point, its t and its
 * height, which must lie between the two heights.  The caps are the
 * planes y = y0 and y = y1 where the hit's (x, z) (divided by y for a
 * conic prism) is inside the curves, which the even-odd test decides by
 * counting the crossings of the curves with the line z = const to the
 * right of the point, again roots of cubics.
 *
 * Nothing in the geometry says which side of a wall is outside, since
 * sub-prisms may be written clockwise or not and may nest, so a wall's
 * normal is turned to point away from the region covered: a point a
 * hair along it must be outside.
 */
#include "trace/obj_shapes.h"

#include <math.h>

#include "trace/shape.h"

#include "trace/roots.h"

/* The value and derivative of one coordinate's cubic at s. */
static double cubic_at(const double *c, double s) {
  return ((c[3] * s + c[2]) * s + c[1]) * s + c[0];
}

static double cubic_slope(const double *c, double s) {
  return (3.0 * c[3] * s + 2.0 * c[2]) * s + c[1];
}

/* The roots of c(s) = 0 for s in [0, 1): the open interval plus s = 0
   itself, so two segments that meet count their joint once. */
static inline int segment_roots(const double *c, double *roots) {
  int n = 0;
  if (c[0] == 0.0)
    roots[n++] = 0.0;
  /* A straight piece's equation is linear: solved here as
     zr__poly_roots solves a first-degree one (same root, same open
     interval), without the call and its search for the degree, since
     linear_spline prisms are the common kind and their even-odd tests
     ask it for every piece beside the point. */
  if (c[3] == 0.0 && c[2] == 0.0) {
    if (c[1] == 0.0)
      return n;
    double s = -c[0] / c[1];
    if (s > 0.0 && s < 1.0)
      roots[n++] = s;
    return n;
  }
  return n + zr__poly_roots(c, 3, 0.0, 1.0, roots + n);
}

void zr__cubic_range(const double *c, double *lo, double *hi) {
  double v0 = c[0], v1 = c[0] + c[1] + c[2] + c[3];
  *lo = zr_min(v0, v1);
  *hi = zr_max(v0, v1);
  /* c' = c1 + 2 c2 s + 3 c3 s^2 */
  double a = 3.0 * c[3], b = 2.0 * c[2], k = c[1];
  double s[2];
  int n = 0;
  if (a != 0.0) {
    double disc = b * b - 4.0 * a * k;
    if (disc >= 0.0) {
      double q = -0.5 * (b + copysign(sqrt(disc), b));
      if (q != 0.0) {
        s[n++] = q / a;
        s[n++] = k / q;
      } else {
        s[n++] = 0.0;
      }
    }
  } else if (b != 0.0) {
    s[n++] = -k / b;
  }
  for (int i = 0; i < n; i++)
    if (s[i] > 0.0 && s[i] < 1.0) {
      double v = cubic_at(c, s[i]);
      *lo = zr_min(*lo, v);
      *hi = zr_max(*hi, v);
    }
}

/* Whether piece seg crosses the line z = const (zc holds its z(s) - z)
   to the right of x an odd number of times. */
static bool piece_flips(const double *seg, const double *zc, double x) {
  double s[4];
  int n = segment_roots(zc, s);
  bool flip = false;
  for (int k = 0; k < n; k++) {
    /* A root where z(s) only touches the line does not cross it. */
    if (zc[0] == 0.0 && s[k] == 0.0 && cubic_slope(zc, 0.0) == 0.0)
      continue;
    if (cubic_at(seg, s[k]) > x)
      flip = !flip;
  }
  return flip;
}

bool zr__curves_cover(const double *pieces, const double *box,
                      size_t n_pieces, double x, double z) {
  bool in = false;
  /* A piece wholly above or below the line z, or wholly at or left of
     x, crosses nothing to the right of the point: skip its roots.  The
     boxes made with the shape are read in place (this test runs for
     every cap hit and every inside question of a CSG: the corpus'
     aug10-2.pov asks it some five million times). */
  for (size_t i = 0; i < n_pieces; i++) {
    const double *seg = pieces + 8 * i;
    double work[4];
    const double *b = box ? box + 4 * i : work;
    if (!box)
      zr__piece_box(pieces, NULL, i, work);
    if (z < b[2] || z > b[3] || b[1] <= x)
      continue;
    double zc[4] = {seg[4] - z, seg[5], seg[6], seg[7]};
    if (piece_flips(seg, zc, x))
      in = !in;
  }
  return in;
}

/* The 2-D point of the curves under (x, z) at height y. */
static bool covers_at(const zr_object *o, zr_vec3 p) {
  const double *seg = o->u.prism.seg, *box = o->u.prism.box;
  size_t n = o->u.prism.n_seg;
  if (!o->u.prism.conic)
    return zr__curves_cover(seg, box, n, p.x, p.z);
  if (p.y == 0.0)
    return false;
  return zr__curves_cover(seg, box, n, p.x / p.y, p.z / p.y);
}

bool zr__prism_inside(const zr_object *o, zr_vec3 p) {
  return p.y > o->u.prism.y0 && p.y < o->u.prism.y1 && covers_at(o, p);
}

void zr__prism_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  double y0 = o->u.prism.y0, y1 = o->u.prism.y1;
  zr_vec3 l = o->u.prism.lo, h = o->u.prism.hi;
  if (!o->u.prism.conic) {
    *lo = zr_v3(l.x, y0, l.z);
    *hi = zr_v3(h.x, y1, h.z);
    return;
  }
  /* The curve scaled by y: its extremes are at the two heights. */
  *lo = zr_v3(zr_min(l.x * y0, l.x * y1), y0, zr_min(l.z * y0, l.z * y1));
  *lo = zr_v3_min(*lo, zr_v3(zr_min(h.x * y0, h.x * y1), y0,
                             zr_min(h.z * y0, h.z * y1)));
  *hi = zr_v3(zr_max(l.x * y0, l.x * y1), y1, zr_max(l.z * y0, l.z * y1));
  *hi = zr_v3_max(*hi, zr_v3(zr_max(h.x * y0, h.x * y1), y1,
                             zr_max(h.z * y0, h.z * y1)));
}

void zr__hits_keep(zr_hit_list *l, double t, zr_vec3 n) {
  int j = l->n;
  if (j == ZR_SHAPE_MAX_CROSSINGS) {
    if (t >= l->t[j - 1])
      return;
    j--;
  } else {
    l->n++;
  }
  while (j > 0 && l->t[j - 1] > t) {
    l->t[j] = l->t[j - 1];
    l->normal[j] = l->normal[j - 1];
    j--;
  }
  l->t[j] = t;
  l->normal[j] = n;
}

/* How far a point beside a wall is moved off it to ask which side is
   covered, as a share of the curves' size. */
#define BESIDE 1e-7

static double curves_size(const zr_object *o) {
  return zr_max(zr_v3_max_comp(zr_v3_sub(o->u.prism.hi, o->u.prism.lo)),
                1e-300);
}

/* Whether a point a hair from p along the wall normal n is covered:
   then n points into the region. */
static bool faces_in(const zr_object *o, zr_vec3 p, zr_vec3 n, double len) {
  zr_vec3 q = zr_v3_madd(p, n, BESIDE * curves_size(o) / len);
  return covers_at(o, q);
}

/*
 * The part of a straight piece whose side zr__prism_wall_sides vouches
 * for: s in (SIDE_END, 1 - SIDE_END).  Nearer its ends, where the next
 * piece comes within a hair, the side is asked at the hit as before.
 */
#define SIDE_END 1e-3

/* The distance from point p to the segment a-b (2-D). */
static double point_segment_distance(const double p[2], const double a[2],
                                     const double b[2]) {
  double ab[2] = {b[0] - a[0], b[1] - a[1]};
  double ap[2] = {p[0] - a[0], p[1] - a[1]};
  double ll = ab[0] * ab[0] + ab[1] * ab[1];
  double u = ll > 0.0 ? (ap[0] * ab[0] + ap[1] * ab[1]) / ll : 0.0;
  u = u < 0.0 ? 0.0 : u > 1.0 ? 1.0 : u;
  return hypot(ap[0] - u * ab[0], ap[1] - u * ab[1]);
}

/* The distance between segments a-b and c-d (2-D): 0 when they cross. */
static double segment_distance(const double a[2], const double b[2],
                               const double c[2], const double d[2]) {
  double ab[2] = {b[0] - a[0], b[1] - a[1]};
  double cd[2] = {d[0] - c[0], d[1] - c[1]};
  double o1 = ab[0] * (c[1] - a[1]) - ab[1] * (c[0] - a[0]);
  double o2 = ab[0] * (d[1] - a[1]) - ab[1] * (d[0] - a[0]);
  double o3 = cd[0] * (a[1] - c[1]) - cd[1] * (a[0] - c[0]);
  double o4 = cd[0] * (b[1] - c[1]) - cd[1] * (b[0] - c[0]);
  if (((o1 < 0.0 && o2 > 0.0) || (o1 > 0.0 && o2 < 0.0)) &&
      ((o3 < 0.0 && o4 > 0.0) || (o3 > 0.0 && o4 < 0.0)))
    return 0.0;
  double m = point_segment_distance(a, c, d);
  m = zr_min(m, point_segment_distance(b, c, d));
  m = zr_min(m, point_segment_distance(c, a, b));
  return zr_min(m, point_segment_distance(d, a, b));
}

/*
 * Which way each wall of a linear_spline prism faces, worked out once
 * rather than for every hit (outward() asks zr__curves_cover, a test of
 * every piece, at each wall crossing: the corpus' aug10-2.pov spent a
 * fifth of its time there).  A point beside a straight piece is covered
 * or not all along it as long as no curve comes between, since the
 * even-odd count changes only across a curve.  So a piece whose middle
 * part (SIDE_END from its ends) stays well clear (100 hairs) of every
 * other piece gets the side that outward() finds beside it:
 * side[i] = 1 when its normal (z', -x') points out, -1 when it points
 * in; 0 for the others (a piece that another crosses or nearly
 * touches, a piece next to a very sharp corner, a point), and for
 * every piece of curves with a curved piece or so far from the origin
 * that a hair is lost in rounding.  For up to 4096 pieces: the pairs
 * are tested once, when the prism is made.
 */
void zr__prism_wall_sides(const zr_object *o, signed char *side) {
  size_t n = o->u.prism.n_seg;
  const double *seg = o->u.prism.seg;
  for (size_t i = 0; i < n; i++)
    side[i] = 0;
  double size = curves_size(o), hair = BESIDE * size;
  double far = zr_max(zr_v3_max_comp(zr_v3_max(zr_v3_neg(o->u.prism.lo),
                                               o->u.prism.hi)),
                      0.0);
  if (!(far * 1e-12 < hair) || n > 4096)
    return;
  for (size_t i = 0; i < n; i++) {
    const double *c = seg + 8 * i;
    if (c[2] != 0.0 || c[3] != 0.0 || c[6] != 0.0 || c[7] != 0.0)
      return; /* a curved piece: the tests below are for straight ones */
  }
  double clear = 100.0 * hair;
  for (size_t i = 0; i < n; i++) {
    const double *x = seg + 8 * i, *z = x + 4;
    double a[2] = {x[0], z[0]}, b[2] = {x[0] + x[1], z[0] + z[1]};
    double len = hypot(x[1], z[1]);
    if (!(len > clear))
      continue;
    double a1[2] = {a[0] + SIDE_END * x[1], a[1] + SIDE_END * z[1]};
    double b1[2] = {b[0] - SIDE_END * x[1], b[1] - SIDE_END * z[1]};
    bool near = false;
    for (size_t j = 0; j < n && !near; j++) {
      if (j == i)
        continue;
      const double *xj = seg + 8 * j, *zj = xj + 4;
      double c[2] = {xj[0], zj[0]}, d[2] = {xj[0] + xj[1], zj[0] + zj[1]};
      /* Boxes farther apart than clear: no need for the distance. */
      if (zr_min(c[0], d[0]) > zr_max(a[0], b[0]) + clear ||
          zr_max(c[0], d[0]) < zr_min(a[0], b[0]) - clear ||
          zr_min(c[1], d[1]) > zr_max(a[1], b[1]) + clear ||
          zr_max(c[1], d[1]) < zr_min(a[1], b[1]) - clear)
        continue;
      near = !(segment_distance(a1, b1, c, d) > clear);
    }
    if (near)
      continue;
    /* outward()'s question, with the same normal, at three points of
       the piece, which must agree: the even-odd count is unreliable on
       the line through a vertex or along a piece (the middle of the
       side of a square lies at the height of a crossing square's
       edge), and such a line rarely passes through all three. */
    static const double at[3] = {0.5, 0.3819660112501051,
                                 0.6180339887498949};
    zr_vec3 nrm = zr_v3(z[1], 0.0, -x[1]);
    int in = 0;
    for (int k = 0; k < 3; k++)
      in += faces_in(o, zr_v3(a[0] + at[k] * x[1], 0.0, a[1] + at[k] * z[1]),
                     nrm, len);
    side[i] = in == 3 ? -1 : in == 0 ? 1 : 0;
  }
}

/* Turns the normal n of piece i's wall at p (its parameter s) away from
   the covered region. */
static zr_vec3 outward(const zr_object *o, size_t i, double s, zr_vec3 p,
                       zr_vec3 n) {
  const signed char *side = o->u.prism.side;
  if (side && side[i] != 0 && !o->u.prism.conic && s > SIDE_END &&
      s < 1.0 - SIDE_END)
    return side[i] > 0 ? n : zr_v3_neg(n);
  double len = zr_v3_len(n);
  if (!(len > 0.0))
    return n;
  return faces_in(o, p, n, len) ? zr_v3_neg(n) : n;
}

/*
 * Whether the part of a ray from tmin to tmax, seen from above (in the
 * x-z plane), meets the box b of a piece widened by pad: a wall point
 * of the piece lies in that box, so a ray that misses it has no
 * crossing there with t in (tmin, tmax), and the cubic is not solved
 * (a prism of many pieces is met by a ray at two or three of them).
 * Only for a straight prism: a conic one's pieces are scaled by y.
 */
static bool piece_may_cross(const double b[4], zr_vec3 org, zr_vec3 dir,
                            double tmin, double tmax, double pad) {
  double lo[2] = {b[0] - pad, b[2] - pad}, hi[2] = {b[1] + pad, b[3] + pad};
  double o2[2] = {org.x, org.z}, d2[2] = {dir.x, dir.z};
  for (int k = 0; k < 2; k++) {
    if (d2[k] == 0.0) {
      if (o2[k] < lo[k] || o2[k] > hi[k])
        return false;
      continue;
    }
    double a = (lo[k] - o2[k]) / d2[k], c = (hi[k] - o2[k]) / d2[k];
    tmin = zr_max(tmin, zr_min(a, c));
    tmax = zr_min(tmax, zr_max(a, c));
  }
  return tmin <= tmax;
}

/*
 * The box, in the x-z plane, of the part of a ray from tmin to tmax,
 * widened by pad and by a margin for the rounding of its ends: xlo,
 * xhi, zlo, zhi.  A piece whose widened box misses it is a piece that
 * piece_may_cross() turns down (a point of the ray in (tmin, tmax)
 * inside the piece's widened box lies in both boxes), found with four
 * comparisons rather than four divisions: a ray along the sweep, as
 * down the tunnel of hexagonal frames of the corpus' aug10-2.pov, is a
 * short stroke seen from above, beside most pieces.  False when the
 * ends are not finite: then every piece is asked.
 */
static bool stroke_box(zr_vec3 org, zr_vec3 dir, double tmin, double tmax,
                       double pad, double out[4]) {
  double a[2] = {org.x + tmin * dir.x, org.z + tmin * dir.z};
  double b[2] = {org.x + tmax * dir.x, org.z + tmax * dir.z};
  if (!(isfinite(a[0]) && isfinite(a[1]) && isfinite(b[0]) &&
        isfinite(b[1])))
    return false;
  /* The ends carry a rounding error of a few ulps of the largest of
     the terms that made them; 1e-12 of it is a wide margin. */
  double big = zr_max(zr_max(fabs(org.x), fabs(org.z)),
                      zr_max(zr_max(fabs(a[0]), fabs(a[1])),
                             zr_max(fabs(b[0]), fabs(b[1]))));
  double w = 2.0 * pad + 1e-12 * big;
  for (int k = 0; k < 2; k++) {
    out[2 * k] = zr_min(a[k], b[k]) - w;
    out[2 * k + 1] = zr_max(a[k], b[k]) + w;
  }
  return true;
}

static bool boxes_meet(const double b[4], const double c[4]) {
  return b[0] <= c[1] && b[1] >= c[0] && b[2] <= c[3] && b[3] >= c[2];
}

static void wall_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                           double tmin, double tmax, double pad,
                           zr_hit_list *l) {
  zr_vec3 m = zr_v3_cross(org, dir);
  double dd = zr_v3_dot(dir, dir);
  double stroke[4];
  bool stroked = !o->u.prism.conic &&
                 stroke_box(org, dir, tmin, tmax, pad, stroke);
  for (size_t i = 0; i < o->u.prism.n_seg; i++) {
    const double *x = o->u.prism.seg + 8 * i, *z = x + 4;
    if (!o->u.prism.conic) {
      double b[4];
      zr__piece_box(o->u.prism.seg, o->u.prism.box, i, b);
      if (stroked && !boxes_meet(b, stroke))
        continue;
      if (!piece_may_cross(b, org, dir, tmin, tmax, pad))
        continue;
    }
    double c[4];
    for (int k = 0; k < 4; k++)
      c[k] = o->u.prism.conic ? m.x * x[k] + m.z * z[k]
                              : x[k] * dir.z - z[k] * dir.x;
    if (o->u.prism.conic)
      c[0] += m.y;
    else
      c[0] += org.z * dir.x - org.x * dir.z;
    double s[4];
    int n = segment_roots(c, s);
    for (int k = 0; k < n; k++) {
      double cx = cubic_at(x, s[k]), cz = cubic_at(z, s[k]);
      double tx = cubic_slope(x, s[k]), tz = cubic_slope(z, s[k]);
      double t;
      zr_vec3 nrm;
      if (!o->u.prism.conic) {
        double dxz = dir.x * dir.x + dir.z * dir.z;
        if (!(dxz > 0.0))
          continue;
        t = ((cx - org.x) * dir.x + (cz - org.z) * dir.z) / dxz;
        nrm = zr_v3(tz, 0.0, -tx);
      } else {
        /* org + t dir = y q with q = (cx, 1, cz): y from the cross
           products with dir, then t along it. */
        zr_vec3 q = zr_v3(cx, 1.0, cz), qd = zr_v3_cross(q, dir);
        double qq = zr_v3_dot(qd, qd);
        if (!(qq > 0.0))
          continue;
        double y = zr_v3_dot(m, qd) / qq;
        t = zr_v3_dot(zr_v3_sub(zr_v3_scale(q, y), org), dir) / dd;
        /* The wall's tangents y (x', 0, z') and (x, 1, z). */
        nrm = zr_v3_cross(zr_v3(tx, 0.0, tz), q);
      }
      if (!(t > tmin && t < tmax))
        continue;
      zr_vec3 p = zr_v3_madd(org, dir, t);
      if (p.y < o->u.prism.y0 || p.y > o->u.prism.y1)
        continue;
      zr__hits_keep(l, t, outward(o, i, s[k], p, nrm));
    }
  }
}

static void cap_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                          double tmin, double tmax, zr_hit_list *l) {
  if (o->u.prism.open || dir.y == 0.0)
    return;
  double h[2] = {o->u.prism.y0, o->u.prism.y1};
  for (int i = 0; i < 2; i++) {
    double t = (h[i] - org.y) / dir.y;
    if (!(t > tmin && t < tmax))
      continue;
    zr_vec3 p = zr_v3_madd(org, dir, t);
    p.y = h[i];
    if (covers_at(o, p))
      zr__hits_keep(l, t, zr_v3(0.0, i == 0 ? -1.0 : 1.0, 0.0));
  }
}

int zr__prism_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                        double tmin, double tmax, double t[4],
                        zr_vec3 normal[4]) {
  zr_vec3 lo, hi;
  zr__prism_bounds(o, &lo, &hi);
  double s0, s1, pad = 1e-9 * zr_max(1.0, zr_v3_max_comp(zr_v3_max(
                                              zr_v3_neg(lo), hi)));
  if (!zr__ray_box_span(zr_v3_sub(lo, zr_v3(pad, pad, pad)),
                        zr_v3_add(hi, zr_v3(pad, pad, pad)), org, dir, &s0,
                        &s1))
    return 0;
  tmin = zr_max(tmin, s0 - pad);
  tmax = zr_min(tmax, s1 + pad);
  if (!(tmin < tmax))
    return 0;
  /* Only the first l.n entries are ever read: no need to clear them. */
  zr_hit_list l;
  l.n = 0;
  wall_crossings(o, org, dir, tmin, tmax, pad, &l);
  cap_crossings(o, org, dir, tmin, tmax, &l);
  for (int i = 0; i < l.n; i++) {
    t[i] = l.t[i];
    normal[i] = l.normal[i];
  }
  return l.n;
}

static bool prism_box(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  zr__prism_bounds(o, lo, hi);
  return o->u.prism.n_seg > 0;
}

/* The operations the tracer calls through (lib/trace/shape.h). */
const zr_shape_ops zr__shape_prism = {
    .name = "a prism",
    .search = zr__prism_crossings,
    .inside = zr__prism_inside,
    .bounds = prism_box,
    /* Its pieces' roots do not depend on the interval, which only
       filters them: the crossings in (tmin, tmax) given at once (at
       most two) are all there are, for a CSG's second asking. */
    .interval_free = true,
};
