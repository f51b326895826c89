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
 * bracket (a step that would leave it is replaced by bisection), which
 * converges quadratically near the root and can never wander to another
 * one.  The interval must be finite: callers clip the ray to the shape's
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

/* The value and derivative at x together. */
static double eval_with_slope(const double *c, int degree, double x,
                              double *slope) {
  double v = c[degree], d = 0.0;
  for (int i = degree - 1; i >= 0; i--) {
    d = d * x + v;
    v = v * x + c[i];
  }
  *slope = d;
  return v;
}

/* The root in (a, b) of a polynomial whose values at a and b have
   opposite signs (fa is the value at a). */
static double refine(const double *c, int degree, double a, double b,
                     double fa) {
  double x = 0.5 * (a + b);
  for (int iter = 0; iter < 200; iter++) {
    double slope, fx = eval_with_slope(c, degree, x, &slope);
    if (fx == 0.0)
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
    if (!(next > a && next < b))
      next = 0.5 * (a + b);
    /* Newton's step is accepted only while it converges fast; a step
       that barely moves is finished by bisection's guaranteed halving. */
    if (fabs(next - x) > 0.5 * width)
      next = 0.5 * (a + b);
    x = next;
  }
  return x;
}

/* Roots of a x^2 + b x + c in (lo, hi) with a sign change. */
static int quadratic_roots(const double *c, double lo, double hi,
                           double *roots) {
  double a = c[2], b = c[1], k = c[0];
  int n = 0;
  if (a == 0.0) {
    if (b != 0.0) {
      double x = -k / b;
      if (x > lo && x < hi)
        roots[n++] = x;
    }
    return n;
  }
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

int zr__poly_roots(const double *c, int degree, double lo, double hi,
                   double *roots) {
  while (degree > 0 && c[degree] == 0.0)
    degree--;
  if (degree <= 0 || !(lo < hi))
    return 0;
  if (degree == 1) {
    double x = -c[0] / c[1];
    if (!(x > lo && x < hi))
      return 0;
    roots[0] = x;
    return 1;
  }
  if (degree == 2)
    return quadratic_roots(c, lo, hi, roots);
  /* The ends of the monotonic pieces: lo, the roots of p', hi. */
  double deriv[ZR_POLY_MAX_DEGREE];
  for (int i = 1; i <= degree; i++)
    deriv[i - 1] = i * c[i];
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
