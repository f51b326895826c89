/*
 * quadrature.h - Gauss-Legendre rules on [0, 1] for the radiosity code.
 *
 * Form factors between patches and the areas of curved surfaces are
 * integrals of smooth functions over (u,v) rectangles, where an n-point
 * Gauss-Legendre rule is exact for polynomials of degree 2n - 1 and
 * converges geometrically for analytic integrands.  A rule is computed
 * once by its user and then only read, so any number of threads may share
 * it (there is no cached global table).
 */
#ifndef ZR_RADIOSITY_QUADRATURE_H
#define ZR_RADIOSITY_QUADRATURE_H

#include "zrcube.h"

/* The largest rule offered; 64 points resolve any integrand we meet. */
#define ZR__GAUSS_MAX 64

typedef struct zr__gauss_rule {
  int n;                    /* number of points, 1..ZR__GAUSS_MAX */
  double x[ZR__GAUSS_MAX];  /* nodes in (0, 1), increasing */
  double w[ZR__GAUSS_MAX];  /* weights, summing to 1 */
} zr__gauss_rule;

/*
 * Fills rule with the n-point Gauss-Legendre rule on [0, 1].  Returns
 * ZR_EINVAL (rule untouched) when n is outside 1..ZR__GAUSS_MAX.
 */
zr_status zr__gauss_rule_init(zr__gauss_rule *rule, int n);

#endif /* ZR_RADIOSITY_QUADRATURE_H */
