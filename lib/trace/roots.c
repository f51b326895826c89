/*
 * roots.c - real roots of a polynomial in a bounded interval.
 *
 * Closed forms for cubics and quartics (Cardano, Ferrari) lose most of
 * their digits when the roots are clustered or the coefficients differ
 * in size, which is exactly the case of a ray grazing a thin torus; the
 * POV-Ray manual warns about it and offers a slower Sturm solver
 * ("Torus": sturm).  zRcube uses one method that is reliable on its own,
 * so `sturm` is accepted and changes nothing: isolation by derivatives.
 *
 * Between two consecutive real roots of p' the polynomial p is
 * monotonic, so it has at most one root there, and exactly one when its
 * values at the two ends have opposite signs.  The roots of p' are found
 * the same way from p'', down to a quadratic solved in closed form.  Each
 * bracketed root is then refined by Newton's method kept inside its
 * bracket (a step that would leave it, or that is not at most half the
 * step before it, is replaced by a split of the bracket: see split()),
 * which converges quadratically near the root and can never wander to
 * another one; it stops where the value is within its own rounding
 * error of zero (the polynomial's digits tell no more).  The interval must be finite: callers clip the ray to the shape's
 * bounding box first, which also keeps the coefficients well scaled.
 */
#include "trace/roots.h"

#include <math.h>
#include <stdbool.h>

double zr__poly_eval(const double *c, int degree, double x) {
  double v = c[degree];
  for (int i = degree - 1; i >= 0; i--)
    v = v * x + c[i];
  return v;
}

/* The value and derivative at x together, and in *noise a bound on
   the value's rounding error: Horner's scheme on |c_i| at |x| times
   2 degree units of rounding (the classical bound is about degree
   of them; twice that is margin). */
static double eval_with_slope(const double *c, int degree, double x,
                              double *slope, double *noise) {
  double v = c[degree], d = 0.0, e = fabs(c[degree]), ax = fabs(x);
  for (int i = degree - 1; i >= 0; i--) {
    d = d * x + v;
    v = v * x + c[i];
    e = e * ax + fabs(c[i]);
  }
  *slope = d;
  *noise = 2.0 * degree * 2.2e-16 * e;
  return v;
}

/* The point that splits (a, b) when Newton's step is refused: the
   midpoint, unless the ends differ by orders of magnitude (a ray's
   roots are bounded by the size of its coefficients, 1e3 or more when
   the roots are near 1), where halving would take a step for every
   factor of two: then zero when the ends have opposite signs, else the
   geometric mean (of |a|, |b| and 1e-3, our floor below which halving
   is fast enough), which halves the number of digits between them. */
static double split(double a, double b) {
  if (a < 0.0 && b > 0.0)
    return 0.0;
  double small = fmin(fabs(a), fabs(b)), large = fmax(fabs(a), fabs(b));
  if (large > 64.0 * small && large > 64e-3) {
    double g = sqrt(fmax(small, 1e-3) * large);
    return a < 0.0 ? -g : g;
  }
  return 0.5 * (a + b);
}

/* The root in (a, b) of a polynomial whose values at a and b have
   opposite signs (fa is the value at a). */
static double refine(const double *c, int degree, double a, double b,
                     double fa) {
  /* The size of the last Newton step; infinite after a split. */
  double x = split(a, b), last = INFINITY;
  for (int iter = 0; iter < 200; iter++) {
    double slope, noise, fx = eval_with_slope(c, degree, x, &slope, &noise);
    /* A value within its own rounding error of zero: x is the root as
       nearly as the polynomial's digits tell it. */
    if (fabs(fx) <= noise)
      return x;
    /* Keep the bracket: the end whose value has fx's sign moves. */
    if ((fx < 0.0) == (fa < 0.0)) {
      a = x;
      fa = fx;
    } else {
      b = x;
    }
    double width = b - a;
    if (width <= 4.0 * 2.2e-16 * fmax(fabs(a), fabs(b)) ||
        width < 1e-300)
      break;
    double next = slope != 0.0 ? x - fx / slope : a;
    /* Newton's step is taken while it stays in the bracket and, after
       the first, is at most half the step before it (near a simple root
       the steps shrink quadratically): far from a root of a polynomial
       of degree n it shrinks x by only (n - 1) / n a step, and near a
       double root it halves the distance, where a split (of digits, when
       the ends are far apart) does better.  No rule on the bracket's
       width: Newton's steps often close in on a root from one side,
       leaving the other end where it was. */
    double step = fabs(next - x);
    /* A Newton step within rounding of x: converged (next may even be
       x itself, on the end of the bracket). */
    if (step <= 2.2e-16 * fabs(x))
      return x;
    if (next > a && next < b && step <= 0.5 * last) {
      last = step;
    } else {
      next = split(a, b);
      last = INFINITY;
    }
    x = next;
  }
  return x;
}

/* The root of c[1] x + c[0] in (lo, hi), if it has one there. */
static int line_root(const double *c, double lo, double hi, double *roots) {
  if (c[1] == 0.0)
    return 0;
  double x = -c[0] / c[1];
  if (!(x > lo && x < hi))
    return 0;
  roots[0] = x;
  return 1;
}

/* Roots of a x^2 + b x + c in (lo, hi) with a sign change. */
static int quadratic_roots(const double *c, double lo, double hi,
                           double *roots) {
  double a = c[2], b = c[1], k = c[0];
  int n = 0;
  if (a == 0.0)
    return line_root(c, lo, hi, roots);
  double disc = b * b - 4.0 * a * k;
  if (!(disc > 0.0))
    return 0;
  double q = -0.5 * (b + copysign(sqrt(disc), b));
  double r0 = q / a, r1 = q != 0.0 ? k / q : r0;
  double x0 = fmin(r0, r1), x1 = fmax(r0, r1);
  if (x0 > lo && x0 < hi)
    roots[n++] = x0;
  if (x1 > lo && x1 < hi && x1 > x0)
    roots[n++] = x1;
  return n;
}

/* The roots in (lo, hi) of a polynomial of degree 2 or less, in closed
   form. */
static int low_roots(const double *c, int degree, double lo, double hi,
                     double *roots) {
  if (degree == 2)
    return quadratic_roots(c, lo, hi, roots);
  if (degree == 1)
    return line_root(c, lo, hi, roots);
  return 0;
}

/* d = c', of degree - 1. */
static void derivative(const double *c, int degree, double *d) {
  for (int i = 1; i <= degree; i++)
    d[i - 1] = i * c[i];
}

int zr__poly_roots(const double *c, int degree, double lo, double hi,
                   double *roots) {
  while (degree > 0 && c[degree] == 0.0)
    degree--;
  if (degree <= 0 || !(lo < hi))
    return 0;
  if (degree <= 2)
    return low_roots(c, degree, lo, hi, roots);
  /* The ends of the monotonic pieces: lo, the roots of p', hi. */
  double deriv[ZR_POLY_MAX_DEGREE];
  derivative(c, degree, deriv);
  double ends[ZR_POLY_MAX_DEGREE + 1];
  ends[0] = lo;
  int n_ends = 1 + zr__poly_roots(deriv, degree - 1, lo, hi, ends + 1);
  ends[n_ends++] = hi;
  int n = 0;
  double fa = zr__poly_eval(c, degree, ends[0]);
  for (int i = 0; i + 1 < n_ends; i++) {
    double fb = zr__poly_eval(c, degree, ends[i + 1]);
    if ((fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0))
      roots[n++] = refine(c, degree, ends[i], ends[i + 1], fa);
    fa = fb;
  }
  return n;
}

/* ---- one root at a time ------------------------------------------ */

/*
 * The walk keeps, for the polynomial and each derivative down to degree
 * 2 (a level each), the end of the monotonic pieces it has reached; a
 * level's next end is the next root of the level below, found only when
 * asked for.  The values and refinements are zr__poly_roots's, in its
 * order, so every root has its bits.
 */
void zr__root_walk_start(zr__root_walk *w, const double *c, int degree,
                         double lo, double hi) {
  w->levels = 0;
  w->n_low = w->next_low = 0;
  w->hi = hi;
  while (degree > 0 && c[degree] == 0.0)
    degree--;
  if (degree <= 0 || !(lo < hi))
    return;
  const double *from = c;
  for (int k = 0; k < ZR_POLY_MAX_DEGREE; k++) {
    double *ck = w->c[k];
    if (k == 0) {
      for (int i = 0; i <= degree; i++)
        ck[i] = from[i];
    } else {
      /* The derivative of the level above (zr__poly_roots's deriv). */
      derivative(from, degree, ck);
      degree--;
      while (degree > 0 && ck[degree] == 0.0)
        degree--;
    }
    w->degree[k] = degree;
    w->levels = k + 1;
    w->a[k] = lo;
    w->done[k] = false;
    if (degree <= 2) {
      /* The last level: its roots in closed form, as zr__poly_roots
         takes a line or a quadratic. */
      w->n_low = low_roots(ck, degree, lo, hi, w->low);
      break;
    }
    w->fa[k] = zr__poly_eval(ck, degree, lo);
    from = ck;
  }
}

static bool level_interval(zr__root_walk *w, int k, double *a, double *b,
                          double *fa);

/* Level k's next root; false when it has no more. */
static bool level_root(zr__root_walk *w, int k, double *x) {
  if (k == w->levels - 1) {
    if (w->next_low >= w->n_low)
      return false;
    *x = w->low[w->next_low++];
    return true;
  }
  double a, b, fa;
  if (!level_interval(w, k, &a, &b, &fa))
    return false;
  *x = refine(w->c[k], w->degree[k], a, b, fa);
  return true;
}

/* Level k's next monotonic piece whose ends' values have opposite
   signs (k above the last level). */
static bool level_interval(zr__root_walk *w, int k, double *a, double *b,
                          double *fa) {
  while (!w->done[k]) {
    double e;
    if (!level_root(w, k + 1, &e)) {
      e = w->hi;
      w->done[k] = true;
    }
    double fe = zr__poly_eval(w->c[k], w->degree[k], e);
    double a0 = w->a[k], f0 = w->fa[k];
    w->a[k] = e;
    w->fa[k] = fe;
    if ((f0 < 0.0 && fe > 0.0) || (f0 > 0.0 && fe < 0.0)) {
      *a = a0;
      *b = e;
      *fa = f0;
      return true;
    }
  }
  return false;
}

bool zr__root_walk_next(zr__root_walk *w, double *a, double *b) {
  if (w->levels == 0)
    return false;
  if (w->levels == 1) {
    /* A line or a quadratic: each root is its own interval. */
    double x;
    if (!level_root(w, 0, &x))
      return false;
    *a = *b = w->at = w->b = x;
    return true;
  }
  if (!level_interval(w, 0, &w->at, &w->b, &w->fat))
    return false;
  *a = w->at;
  *b = w->b;
  return true;
}

double zr__root_walk_root(const zr__root_walk *w) {
  if (w->levels == 1)
    return w->at;
  return refine(w->c[0], w->degree[0], w->at, w->b, w->fat);
}
