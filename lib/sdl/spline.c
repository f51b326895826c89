/*
 * spline.c - splines of the scene language (reference manual 3.3.1.11,
 * "Spline"): a list of (parameter, vector) points and four ways to pass
 * through them.
 *
 * The manual describes the interpolations in words only; the forms here
 * were fitted to povray 3.7.0's own values (tests/test_spline.c lists
 * them; its source was not consulted):
 *   linear_spline     straight segments between neighbouring points;
 *   quadratic_spline  the segment from point k to k + 1 is the parabola
 *                     through points k - 1, k and k + 1 (through 0, 1, 2
 *                     for the first segment);
 *   cubic_spline      a cubic Hermite segment from point k to k + 1 whose
 *                     tangent at each end is the mean of the slopes of
 *                     the two chords meeting there, so the first and last
 *                     points only steer the curve (valid from the second
 *                     to the next-to-last point);
 *   natural_spline    the natural cubic spline through every point (zero
 *                     second derivative at both ends).
 * Outside the valid range a spline keeps the value of the nearest valid
 * point.  Splines of one or two points are linear whatever their type;
 * a cubic spline of three points has no segment and gives its middle
 * point everywhere, as POV-Ray does.
 *
 * A point is a float or a vector of up to five components (the
 * language's longest vector, a colour with filter and transmit), and
 * povray's value has as many components as the longest point; a float
 * point counts as a 2-D vector with both components the float
 * (measured: spline { 0, 1  1, 3 } gives <2, 2> at 0.5).
 */
#include "config.h"

#include <string.h>

#include "sdl/spline.h"

zr_sdl_spline *zr__sdl_spline_new(zr_sdl_parser *p,
                                  const zr_sdl_spline *from) {
  zr_sdl_spline *s = zr__sdl_alloc(p, sizeof *s);
  if (!s)
    return NULL;
  memset(s, 0, sizeof *s);
  s->type = ZR_SPLINE_LINEAR;
  s->dim = 2;
  if (!from)
    return s;
  s->type = from->type;
  s->dim = from->dim;
  s->n = s->cap = from->n;
  if (from->n == 0)
    return s;
  s->t = zr__sdl_alloc(p, from->n * sizeof *s->t);
  s->v = zr__sdl_alloc(p, from->n * sizeof *s->v);
  if (!s->t || !s->v)
    return NULL;
  memcpy(s->t, from->t, from->n * sizeof *s->t);
  memcpy(s->v, from->v, from->n * sizeof *s->v);
  return s;
}

/* Room for one more point: the arena cannot grow a block, so a full one
   is replaced by one twice its size (the old one is lost until the scene
   is freed, at most as much again). */
static bool reserve(zr_sdl_parser *p, zr_sdl_spline *s) {
  if (s->n < s->cap)
    return true;
  size_t cap = s->cap ? 2 * s->cap : 8;
  double *t = zr__sdl_alloc(p, cap * sizeof *t);
  double(*v)[5] = zr__sdl_alloc(p, cap * sizeof *v);
  if (!t || !v)
    return false;
  if (s->n) {
    memcpy(t, s->t, s->n * sizeof *t);
    memcpy(v, s->v, s->n * sizeof *v);
  }
  s->t = t;
  s->v = v;
  s->cap = cap;
  return true;
}

bool zr__sdl_spline_add(zr_sdl_parser *p, zr_sdl_spline *s,
                        const zr_sdl_expr *t, const zr_sdl_loc *t_loc,
                        const zr_sdl_expr *v) {
  double at;
  if (!zr__sdl_want_float(p, t, t_loc, &at))
    return false;
  double value[5] = {0, 0, 0, 0, 0};
  int dim = v->dim;
  if (dim <= 1) {
    for (int k = 0; k < 5; k++)
      value[k] = v->v[0];
    dim = 2;
  } else {
    for (int k = 0; k < dim && k < 5; k++)
      value[k] = v->v[k];
  }
  if (dim > s->dim)
    s->dim = dim;
  /* The manual says a point replaces an older one of the same parameter,
     and povray 3.7.0 does so except when that parameter is the last
     point's (of two or more): then the new point is dropped (measured:
     spline { 0,<0,0,0> 1,<1,1,1> 1,<3,3,3> } is <1,1,1> at 1).  Scenes
     rendered by both must agree, so povray's rule is kept. */
  if (s->n >= 2 && s->t[s->n - 1] == at)
    return true;
  /* Keep the points sorted: find the first at or after 'at', by
     bisection, so that a long spline does not cost a pass a point. */
  size_t i = 0, end = s->n;
  while (i < end) {
    size_t mid = i + (end - i) / 2;
    if (s->t[mid] < at)
      i = mid + 1;
    else
      end = mid;
  }
  if (i < s->n && s->t[i] == at) {
    memcpy(s->v[i], value, sizeof value);
    return true;
  }
  if (!reserve(p, s))
    return false;
  memmove(s->t + i + 1, s->t + i, (s->n - i) * sizeof *s->t);
  memmove(s->v + i + 1, s->v + i, (s->n - i) * sizeof *s->v);
  s->t[i] = at;
  memcpy(s->v[i], value, sizeof value);
  s->n++;
  return true;
}

/* The natural spline's second derivatives: the tridiagonal system of
   continuous first derivatives, solved by elimination (Thomas). */
static bool natural_setup(zr_sdl_parser *p, zr_sdl_spline *s) {
  size_t n = s->n;
  s->d2 = zr__sdl_alloc(p, n * sizeof *s->d2);
  double *diag = zr__sdl_alloc(p, n * sizeof *diag);
  if (!s->d2 || !diag)
    return false;
  for (int k = 0; k < 5; k++) {
    double(*m)[5] = s->d2;
    diag[0] = 1;
    m[0][k] = 0;
    for (size_t i = 1; i + 1 < n; i++) {
      double h0 = s->t[i] - s->t[i - 1], h1 = s->t[i + 1] - s->t[i];
      double rhs = 6 * ((s->v[i + 1][k] - s->v[i][k]) / h1 -
                        (s->v[i][k] - s->v[i - 1][k]) / h0);
      /* The row above has its upper entry only when it is not the
         first, whose equation is just m[0] = 0. */
      double upper = i > 1 ? s->t[i] - s->t[i - 1] : 0;
      double f = h0 / diag[i - 1];
      diag[i] = 2 * (h0 + h1) - f * upper;
      m[i][k] = rhs - f * m[i - 1][k];
    }
    m[n - 1][k] = 0;
    for (size_t i = n - 1; i-- > 1;) {
      double h1 = s->t[i + 1] - s->t[i];
      double next = i + 2 < n ? m[i + 1][k] : 0;
      m[i][k] = (m[i][k] - h1 * next) / diag[i];
    }
  }
  return true;
}

bool zr__sdl_spline_finish(zr_sdl_parser *p, zr_sdl_spline *s,
                           const zr_sdl_loc *loc) {
  if (s->n == 0) {
    zr__sdl_error(p, ZR_ESCENE, loc, "a spline needs at least one point");
    return false;
  }
  return s->n < 3 || natural_setup(p, s);
}

/* The segment holding t: the k with t[k] <= t < t[k + 1], for t strictly
   inside [t[lo], t[hi]]. */
static size_t segment(const zr_sdl_spline *s, size_t lo, size_t hi,
                      double t) {
  while (hi - lo > 1) {
    size_t mid = lo + (hi - lo) / 2;
    if (s->t[mid] <= t)
      lo = mid;
    else
      hi = mid;
  }
  return lo;
}

static void quadratic(const zr_sdl_spline *s, size_t k, double t,
                      double out[5]) {
  size_t j = k < 1 ? 1 : k;
  double t0 = s->t[j - 1], t1 = s->t[j], t2 = s->t[j + 1];
  double l0 = (t - t1) * (t - t2) / ((t0 - t1) * (t0 - t2));
  double l1 = (t - t0) * (t - t2) / ((t1 - t0) * (t1 - t2));
  double l2 = (t - t0) * (t - t1) / ((t2 - t0) * (t2 - t1));
  for (int c = 0; c < 5; c++)
    out[c] = l0 * s->v[j - 1][c] + l1 * s->v[j][c] + l2 * s->v[j + 1][c];
}

static void cubic(const zr_sdl_spline *s, size_t k, double t,
                  double out[5]) {
  double dt = s->t[k + 1] - s->t[k];
  double before = s->t[k] - s->t[k - 1], after = s->t[k + 2] - s->t[k + 1];
  double u = (t - s->t[k]) / dt, u2 = u * u, u3 = u2 * u;
  double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u;
  double h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
  for (int c = 0; c < 5; c++) {
    double chord = (s->v[k + 1][c] - s->v[k][c]) / dt;
    double m0 = (chord + (s->v[k][c] - s->v[k - 1][c]) / before) / 2 * dt;
    double m1 = ((s->v[k + 2][c] - s->v[k + 1][c]) / after + chord) / 2 * dt;
    out[c] = h00 * s->v[k][c] + h10 * m0 + h01 * s->v[k + 1][c] + h11 * m1;
  }
}

static void natural(const zr_sdl_spline *s, size_t k, double t,
                    double out[5]) {
  double h = s->t[k + 1] - s->t[k];
  double a = s->t[k + 1] - t, b = t - s->t[k];
  for (int c = 0; c < 5; c++) {
    double m0 = s->d2[k][c], m1 = s->d2[k + 1][c];
    out[c] = m0 * a * a * a / (6 * h) + m1 * b * b * b / (6 * h) +
             (s->v[k][c] / h - m0 * h / 6) * a +
             (s->v[k + 1][c] / h - m1 * h / 6) * b;
  }
}

void zr__sdl_spline_eval(const zr_sdl_spline *s, int type, double t,
                         double out[5]) {
  if (type < 0)
    type = (int)s->type;
  size_t n = s->n;
  if (n < 3)
    type = ZR_SPLINE_LINEAR;
  if (type == ZR_SPLINE_CUBIC && n == 3) {
    memcpy(out, s->v[1], 5 * sizeof *out);
    return;
  }
  size_t lo = 0, hi = n - 1;
  if (type == ZR_SPLINE_CUBIC) {
    lo = 1;
    hi = n - 2;
  }
  /* The negated test also sends a NaN parameter to the first point. */
  if (!(t > s->t[lo])) {
    memcpy(out, s->v[lo], 5 * sizeof *out);
    return;
  }
  if (t >= s->t[hi]) {
    memcpy(out, s->v[hi], 5 * sizeof *out);
    return;
  }
  size_t k = segment(s, lo, hi, t);
  switch (type) {
  case ZR_SPLINE_QUADRATIC:
    quadratic(s, k, t, out);
    return;
  case ZR_SPLINE_CUBIC:
    cubic(s, k, t, out);
    return;
  case ZR_SPLINE_NATURAL:
    natural(s, k, t, out);
    return;
  default: {
    double u = (t - s->t[k]) / (s->t[k + 1] - s->t[k]);
    for (int c = 0; c < 5; c++)
      out[c] = s->v[k][c] + u * (s->v[k + 1][c] - s->v[k][c]);
    return;
  }
  }
}

zr_sdl_expr zr__sdl_spline_value(const zr_sdl_spline *s, int type,
                                 double t) {
  zr_sdl_expr e;
  memset(&e, 0, sizeof e);
  e.dim = s->dim;
  zr__sdl_spline_eval(s, type, t, e.v);
  return e;
}
