/*
 * obj_sweep.c - the sphere sweep (POV-Ray 3.7 reference, "Sphere
 * Sweep"): the space a ball of varying radius fills as it moves along a
 * spline through the written spheres.  Each piece of the spline moves a
 * ball of centre c(u) and radius r(u), polynomials of degree 1 (linear
 * spline) or 3 (b_spline, cubic_spline), for u in [0, 1]; a linear
 * sweep of n spheres has n - 1 pieces, the cubic ones n - 3, the first
 * and last sphere only steering the curve.  The manual names b_spline a
 * cubic b-spline that approximates the spheres and asks four spheres of
 * both cubic kinds; the textbook uniform cubic B-spline is the one, and
 * for cubic_spline the Catmull-Rom spline, the cubic that passes
 * through the inner spheres with the same four-point window, matches
 * povray's render of scenes/sphere_sweep.pov (tests/golden.sh, SSIM >=
 * 0.98 against tests/ref/sphere_sweep.png).
 *
 * The surface is the boundary of the union of the balls.  Along a unit ray
 * q + s d the ball at u is met for s in [b(u) - sqrt(H(u)),
 * b(u) + sqrt(H(u))], where b = d . (c - q) and H = b^2 - |c - q|^2 + r^2
 * is a polynomial of degree 6 in u.  Over a stretch of u where H > 0 these
 * intervals move continuously, so their union is one interval, from the
 * least entry to the greatest exit.  Those extremes are at the stretch's
 * ends or where the derivative of b -+ sqrt(H) vanishes, that is at the
 * roots of R = 4 b'^2 H - H'^2 (degree 10); the roots of H' are added
 * too, as for a ray square to a plane curve R has only double roots
 * there.  Each piece thus gives at most three intervals; the sweep's
 * crossings are the ends of their union, with the normal of the ball
 * that made each end.  Taking a minimum over extra candidates can only
 * help, so a root missed by rounding costs a little accuracy, never a
 * hole.  A point is inside when min over u of |p - c(u)|^2 - r(u)^2 is
 * negative for some piece (the minimum at the ends or a root of the
 * derivative, degree 5).
 *
 * Bounds: written in the Bernstein basis on [0, 1] a piece's centre and
 * radius are weighted averages of four control values, so every ball
 * lies in the box of the control balls.
 */
#include "trace/obj_sweep.h"

#include <math.h>

#include "trace/shape.h"
#include <stdlib.h>

#include "trace/obj_shapes.h"
#include "trace/roots.h"

/* Rows: the power-basis coefficients (u^0 .. u^3) as weights of the
   four spheres of a piece ("Sphere Sweep"'s two cubic splines): the
   uniform cubic B-spline's and Catmull-Rom's standard basis matrices
   (the latter with tension 1/2). */
static const double b_spline_matrix[4][4] = {
    {1.0 / 6.0, 4.0 / 6.0, 1.0 / 6.0, 0.0},
    {-3.0 / 6.0, 0.0, 3.0 / 6.0, 0.0},
    {3.0 / 6.0, -6.0 / 6.0, 3.0 / 6.0, 0.0},
    {-1.0 / 6.0, 3.0 / 6.0, -3.0 / 6.0, 1.0 / 6.0}};
static const double catmull_rom_matrix[4][4] = {
    {0.0, 1.0, 0.0, 0.0},
    {-0.5, 0.0, 0.5, 0.0},
    {1.0, -2.5, 2.0, -0.5},
    {-0.5, 1.5, -1.5, 0.5}};

/* Bezier control values of a cubic a0 + a1 u + a2 u^2 + a3 u^3. */
static void to_bernstein(const double a[4], double b[4]) {
  b[0] = a[0];
  b[1] = a[0] + a[1] / 3.0;
  b[2] = a[0] + 2.0 * a[1] / 3.0 + a[2] / 3.0;
  b[3] = a[0] + a[1] + a[2] + a[3];
}

static void segment_box(zr_sweep_segment *g) {
  double x[4] = {g->c[0].x, g->c[1].x, g->c[2].x, g->c[3].x};
  double y[4] = {g->c[0].y, g->c[1].y, g->c[2].y, g->c[3].y};
  double z[4] = {g->c[0].z, g->c[1].z, g->c[2].z, g->c[3].z};
  double bx[4], by[4], bz[4], br[4];
  to_bernstein(x, bx);
  to_bernstein(y, by);
  to_bernstein(z, bz);
  to_bernstein(g->r, br);
  g->lo = zr_v3(INFINITY, INFINITY, INFINITY);
  g->hi = zr_v3_neg(g->lo);
  for (int i = 0; i < 4; i++) {
    double r = fabs(br[i]);
    g->lo = zr_v3_min(g->lo, zr_v3(bx[i] - r, by[i] - r, bz[i] - r));
    g->hi = zr_v3_max(g->hi, zr_v3(bx[i] + r, by[i] + r, bz[i] + r));
  }
}

void zr__sweep_build(struct zr_sphere_sweep *s) {
  size_t n = s->n_spheres;
  bool linear = s->spline == ZR_SWEEP_LINEAR;
  s->n_segments = linear ? n - 1 : n - 3;
  const double(*m)[4] =
      s->spline == ZR_SWEEP_B_SPLINE ? b_spline_matrix : catmull_rom_matrix;
  s->lo = zr_v3(INFINITY, INFINITY, INFINITY);
  s->hi = zr_v3_neg(s->lo);
  for (size_t i = 0; i < s->n_segments; i++) {
    zr_sweep_segment *g = &s->segments[i];
    for (int k = 0; k < 4; k++) {
      g->c[k] = zr_v3(0, 0, 0);
      g->r[k] = 0.0;
    }
    if (linear) {
      g->c[0] = s->centres[i];
      g->c[1] = zr_v3_sub(s->centres[i + 1], s->centres[i]);
      g->r[0] = s->radii[i];
      g->r[1] = s->radii[i + 1] - s->radii[i];
    } else {
      for (int k = 0; k < 4; k++)
        for (int j = 0; j < 4; j++) {
          g->c[k] = zr_v3_madd(g->c[k], s->centres[i + j], m[k][j]);
          g->r[k] += m[k][j] * s->radii[i + j];
        }
    }
    segment_box(g);
    s->lo = zr_v3_min(s->lo, g->lo);
    s->hi = zr_v3_max(s->hi, g->hi);
  }
}

void zr__sweep_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  *lo = o->u.sweep.data->lo;
  *hi = o->u.sweep.data->hi;
}

/* ---- polynomials in u ---- */

/* The highest degree met here: R = 4 b'^2 H - H'^2. */
#define MAX_DEGREE 10

static void poly_mul(const double *a, int da, const double *b, int db,
                     double *out) {
  for (int i = 0; i <= da + db; i++)
    out[i] = 0.0;
  for (int i = 0; i <= da; i++)
    for (int j = 0; j <= db; j++)
      out[i + j] += a[i] * b[j];
}

static void poly_deriv(const double *a, int da, double *out) {
  for (int i = 1; i <= da; i++)
    out[i - 1] = i * a[i];
  if (da == 0)
    out[0] = 0.0;
}

/* The root in (a, b) of p, whose values at a and b have opposite
   signs (fa at a): bisection, which is enough for u in [0, 1]. */
static double bisect(const double *c, int degree, double a, double b,
                     double fa) {
  for (int i = 0; i < 64 && b - a > 1e-15; i++) {
    double m = 0.5 * (a + b), fm = zr__poly_eval(c, degree, m);
    if (fm == 0.0)
      return m;
    if ((fm < 0.0) == (fa < 0.0)) {
      a = m;
      fa = fm;
    } else {
      b = m;
    }
  }
  return 0.5 * (a + b);
}

/* The sign-changing roots in (lo, hi), ascending, of a polynomial of
   degree up to MAX_DEGREE: lib/trace/roots.c up to its degree, above
   it the same isolation between the roots of the derivative. */
static int roots_any(const double *c, int degree, double lo, double hi,
                     double *roots) {
  while (degree > 0 && c[degree] == 0.0)
    degree--;
  if (degree <= ZR_POLY_MAX_DEGREE)
    return degree > 0 ? zr__poly_roots(c, degree, lo, hi, roots) : 0;
  double d[MAX_DEGREE], ends[MAX_DEGREE + 1];
  poly_deriv(c, degree, d);
  ends[0] = lo;
  int n_ends = 1 + roots_any(d, degree - 1, lo, hi, ends + 1);
  ends[n_ends++] = hi;
  int n = 0;
  double fa = zr__poly_eval(c, degree, ends[0]);
  for (int i = 0; i + 1 < n_ends; i++) {
    double fb = zr__poly_eval(c, degree, ends[i + 1]);
    if ((fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0))
      roots[n++] = bisect(c, degree, ends[i], ends[i + 1], fa);
    fa = fb;
  }
  return n;
}

/* ---- crossings ---- */

/* One end of a piece's interval along the ray: where, and which ball. */
typedef struct sweep_end {
  double s, u;
  const zr_sweep_segment *seg;
} sweep_end;

typedef struct sweep_interval {
  sweep_end in, out;
} sweep_interval;

/* The most intervals one piece gives: H (degree 6) is positive on at
   most three stretches of [0, 1]. */
#define PIECE_INTERVALS 3
#define STACK_INTERVALS 96

/* The polynomials b, H of a piece along the ray q + s d, |d| = 1. */
typedef struct piece_polys {
  double b[4], h[7];
} piece_polys;

static void piece_along(const zr_sweep_segment *g, zr_vec3 q, zr_vec3 d,
                        piece_polys *pp) {
  zr_vec3 c[4] = {zr_v3_sub(g->c[0], q), g->c[1], g->c[2], g->c[3]};
  for (int k = 0; k < 4; k++)
    pp->b[k] = zr_v3_dot(d, c[k]);
  for (int k = 0; k <= 6; k++)
    pp->h[k] = 0.0;
  for (int j = 0; j < 4; j++)
    for (int k = 0; k < 4; k++)
      pp->h[j + k] += pp->b[j] * pp->b[k] - zr_v3_dot(c[j], c[k]) +
                      g->r[j] * g->r[k];
}

/* The entry (sign -1) or exit (+1) of the ball at u. */
static double ball_end(const piece_polys *pp, double u, double sign) {
  double h = zr__poly_eval(pp->h, 6, u);
  return zr__poly_eval(pp->b, 3, u) + sign * sqrt(fmax(h, 0.0));
}

static int compare_double(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* The piece's intervals along the ray into out[]; returns how many. */
static int piece_intervals(const zr_sweep_segment *g, zr_vec3 q, zr_vec3 d,
                           sweep_interval *out) {
  piece_polys pp;
  piece_along(g, q, d, &pp);
  /* The stretches of u in [0, 1] where H > 0. */
  double cuts[8];
  int n_cuts = 0;
  cuts[n_cuts++] = 0.0;
  n_cuts += roots_any(pp.h, 6, 0.0, 1.0, cuts + n_cuts);
  cuts[n_cuts++] = 1.0;
  /* Candidates for the extremes: roots of R and of H', and a few
     samples, which may only improve a minimum. */
  double cand[2 * MAX_DEGREE + 16];
  int n_cand = 0;
  double db[3], dh[6], db2[5], r1[11], r2[11];
  poly_deriv(pp.b, 3, db);
  poly_deriv(pp.h, 6, dh);
  poly_mul(db, 2, db, 2, db2);
  poly_mul(db2, 4, pp.h, 6, r1);
  poly_mul(dh, 5, dh, 5, r2);
  for (int k = 0; k <= 10; k++)
    r1[k] = 4.0 * r1[k] - r2[k];
  n_cand += roots_any(r1, 10, 0.0, 1.0, cand + n_cand);
  n_cand += roots_any(dh, 5, 0.0, 1.0, cand + n_cand);
  for (int k = 1; k < 8; k++)
    cand[n_cand++] = k / 8.0;
  qsort(cand, (size_t)n_cand, sizeof *cand, compare_double);
  int n = 0;
  for (int i = 0; i + 1 < n_cuts && n < PIECE_INTERVALS; i++) {
    double a = cuts[i], b = cuts[i + 1];
    if (!(zr__poly_eval(pp.h, 6, 0.5 * (a + b)) > 0.0))
      continue;
    sweep_interval iv;
    iv.in.seg = iv.out.seg = g;
    iv.in.u = a;
    iv.in.s = ball_end(&pp, a, -1.0);
    iv.out.u = a;
    iv.out.s = ball_end(&pp, a, 1.0);
    /* The stretch's other end, then the candidates inside it. */
    for (int k = -1; k < n_cand; k++) {
      double u = k < 0 ? b : cand[k];
      if (u < a || u > b)
        continue;
      double si = ball_end(&pp, u, -1.0), so = ball_end(&pp, u, 1.0);
      if (si < iv.in.s) {
        iv.in.s = si;
        iv.in.u = u;
      }
      if (so > iv.out.s) {
        iv.out.s = so;
        iv.out.u = u;
      }
    }
    out[n++] = iv;
  }
  return n;
}

static int compare_interval(const void *a, const void *b) {
  const sweep_interval *x = a, *y = b;
  return (x->in.s > y->in.s) - (x->in.s < y->in.s);
}

/* The outward normal at q + s d of the ball at u (object space). */
static zr_vec3 end_normal(const sweep_end *e, zr_vec3 q, zr_vec3 d) {
  const zr_sweep_segment *g = e->seg;
  double u = e->u;
  zr_vec3 c = zr_v3_madd(
      zr_v3_madd(zr_v3_madd(g->c[0], g->c[1], u), g->c[2], u * u), g->c[3],
      u * u * u);
  return zr_v3_sub(zr_v3_madd(q, d, e->s), c);
}

int zr__sweep_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                        double tmin, double tmax, double t[4],
                        zr_vec3 normal[4]) {
  const struct zr_sphere_sweep *sw = o->u.sweep.data;
  double len = zr_v3_len(dir);
  if (!(len > 0.0) || !isfinite(len) || sw->n_segments == 0)
    return 0;
  zr_vec3 d = zr_v3_scale(dir, 1.0 / len);
  double size = zr_v3_max_comp(zr_v3_sub(sw->hi, sw->lo));
  zr_vec3 pad = zr_v3(1e-9 * size, 1e-9 * size, 1e-9 * size);
  double s0, s1;
  if (!zr__ray_box_span(zr_v3_sub(sw->lo, pad), zr_v3_add(sw->hi, pad), org,
                        d, &s0, &s1))
    return 0;
  /* The whole span is searched whatever the interval, so a crossing's t
     does not depend on it (the tracer finds crossings again by t). */
  if (!(fmax(s0, tmin * len) < fmin(s1, tmax * len)))
    return 0;
  zr_vec3 q = zr_v3_madd(org, d, s0);
  size_t room = PIECE_INTERVALS * sw->n_segments;
  sweep_interval stack_iv[STACK_INTERVALS];
  sweep_interval *iv = stack_iv;
  if (room > STACK_INTERVALS) {
    iv = malloc(room * sizeof *iv);
    if (!iv)
      return 0; /* out of memory: the ray misses */
  }
  size_t n = 0;
  for (size_t i = 0; i < sw->n_segments; i++) {
    const zr_sweep_segment *g = &sw->segments[i];
    double a, b;
    if (!zr__ray_box_span(zr_v3_sub(g->lo, pad), zr_v3_add(g->hi, pad), q, d,
                          &a, &b))
      continue;
    n += (size_t)piece_intervals(g, q, d, iv + n);
  }
  qsort(iv, n, sizeof *iv, compare_interval);
  /* The union: each run of overlapping intervals gives one entry and
     one exit. */
  int found = 0;
  size_t i = 0;
  while (i < n && found < ZR_SHAPE_MAX_CROSSINGS) {
    sweep_end in = iv[i].in, out = iv[i].out;
    for (i++; i < n && iv[i].in.s <= out.s; i++)
      if (iv[i].out.s > out.s)
        out = iv[i].out;
    const sweep_end *ends[2] = {&in, &out};
    for (int k = 0; k < 2 && found < ZR_SHAPE_MAX_CROSSINGS; k++) {
      double ti = (s0 + ends[k]->s) / len;
      if (!(ti > tmin && ti < tmax))
        continue;
      t[found] = ti;
      normal[found] = end_normal(ends[k], q, d);
      found++;
    }
  }
  if (iv != stack_iv)
    free(iv);
  return found;
}

/* Whether some ball of the piece holds p. */
static bool piece_inside(const zr_sweep_segment *g, zr_vec3 p) {
  if (p.x < g->lo.x || p.y < g->lo.y || p.z < g->lo.z || p.x > g->hi.x ||
      p.y > g->hi.y || p.z > g->hi.z)
    return false;
  zr_vec3 c[4] = {zr_v3_sub(g->c[0], p), g->c[1], g->c[2], g->c[3]};
  double f[7] = {0}, df[6], u[6];
  for (int j = 0; j < 4; j++)
    for (int k = 0; k < 4; k++)
      f[j + k] += zr_v3_dot(c[j], c[k]) - g->r[j] * g->r[k];
  if (f[0] < 0.0 || zr__poly_eval(f, 6, 1.0) < 0.0)
    return true;
  poly_deriv(f, 6, df);
  int m = roots_any(df, 5, 0.0, 1.0, u);
  for (int i = 0; i < m; i++)
    if (zr__poly_eval(f, 6, u[i]) < 0.0)
      return true;
  return false;
}

bool zr__sweep_inside(const zr_object *o, zr_vec3 p) {
  const struct zr_sphere_sweep *sw = o->u.sweep.data;
  for (size_t i = 0; i < sw->n_segments; i++)
    if (piece_inside(&sw->segments[i], p))
      return true;
  return false;
}

static bool sweep_box(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  zr__sweep_bounds(o, lo, hi);
  return o->u.sweep.data->n_segments > 0;
}

/* The operations the tracer calls through (lib/trace/shape.h). */
const zr_shape_ops zr__shape_sphere_sweep = {
    .name = "a sphere_sweep",
    .search = zr__sweep_crossings,
    .inside = zr__sweep_inside,
    .bounds = sweep_box,
};
