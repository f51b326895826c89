/*
 * quadrature.c - Gauss-Legendre nodes and weights.
 *
 * The nodes of the n-point rule on [-1, 1] are the roots of the Legendre
 * polynomial P_n.  Each is found by Newton's method from the classical
 * first guess cos(pi (i - 1/4) / (n + 1/2)) (Abramowitz & Stegun 22.16),
 * which lies close enough to the i-th root that the iteration converges
 * to it, and not to a neighbour, for every n we offer.  P_n and its
 * derivative come from the three-term recurrence
 *   (k + 1) P_{k+1} = (2k + 1) x P_k - k P_{k-1},
 *   P_n'(x) = n (x P_n - P_{n-1}) / (x^2 - 1),
 * and the weight is 2 / ((1 - x^2) P_n'(x)^2) (Abramowitz & Stegun 25.4.29).
 * The rule is then mapped to [0, 1], halving the weights, because every
 * user integrates over unit parameter rectangles.
 */
#include "radiosity/quadrature.h"

#include <math.h>

/* P_n(x) in *p and P_n'(x) in *dp, for |x| < 1. */
static void legendre(int n, double x, double *p, double *dp) {
  double p0 = 1.0, p1 = x;
  for (int k = 1; k < n; k++) {
    double p2 = ((2.0 * k + 1.0) * x * p1 - k * p0) / (k + 1.0);
    p0 = p1;
    p1 = p2;
  }
  *p = n == 0 ? 1.0 : p1;
  *dp = n * (x * p1 - p0) / (x * x - 1.0);
}

/* The i-th root (0-based, decreasing in x) of P_n and its weight. */
static void legendre_root(int n, int i, double *root, double *weight) {
  double x = cos(M_PI * (i + 0.75) / (n + 0.5));
  double p, dp;
  /* Newton converges quadratically from this guess; 100 steps is a bound
     that is never reached, kept so a bad case cannot loop forever. */
  for (int it = 0; it < 100; it++) {
    legendre(n, x, &p, &dp);
    double dx = p / dp;
    x -= dx;
    if (fabs(dx) <= 1e-16)
      break;
  }
  legendre(n, x, &p, &dp);
  *root = x;
  *weight = 2.0 / ((1.0 - x * x) * dp * dp);
}

zr_status zr__gauss_rule_init(zr__gauss_rule *rule, int n) {
  if (n < 1 || n > ZR__GAUSS_MAX)
    return ZR_EINVAL;
  if (n == 1) {
    rule->n = 1;
    rule->x[0] = 0.5;
    rule->w[0] = 1.0;
    return ZR_OK;
  }
  rule->n = n;
  for (int i = 0; i < n; i++) {
    double x, w;
    legendre_root(n, i, &x, &w);
    /* Roots come in decreasing x, so 0.5 (1 - x) increases with i. */
    rule->x[i] = 0.5 * (1.0 - x);
    rule->w[i] = 0.5 * w;
  }
  return ZR_OK;
}
