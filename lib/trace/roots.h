/*
 * roots.h - real roots of polynomials in an interval, for the shapes
 * whose ray equations are polynomials of degree above two (torus, and
 * later blob, lathe, sor, prism and poly).
 */
#ifndef ZR_TRACE_ROOTS_H
#define ZR_TRACE_ROOTS_H

#include <stdbool.h>

/* The highest degree zr__poly_roots accepts. */
#define ZR_POLY_MAX_DEGREE 8

/*
 * The real roots in (lo, hi) of c[degree] x^degree + ... + c[1] x + c[0]
 * (c[i] multiplies x^i), written ascending into roots[] (room for degree
 * entries); returns how many.  Only roots where the polynomial changes
 * sign are reported, so a ray passing close to a surface is a miss; an
 * exact double root (a ray tangent to it) is, after rounding, either no
 * root or two within rounding of each other.  degree <=
 * ZR_POLY_MAX_DEGREE.
 */
int zr__poly_roots(const double *c, int degree, double lo, double hi,
                   double *roots);

/*
 * The same roots one at a time, ascending, for a caller that wants only
 * some of them (a ray's nearest crossing in an interval): each root has
 * the same bits zr__poly_roots gives it, but neither a root the caller
 * passes over nor the roots of the derivatives beyond the last interval
 * asked for are refined.  zr__root_walk_next moves to the next interval
 * (*a, *b) of lo..hi that holds exactly one root and returns false when
 * none is left; zr__root_walk_root refines that interval's root.
 */
typedef struct zr__root_walk {
  int levels; /* the polynomial, then its derivatives to degree <= 2 */
  int degree[ZR_POLY_MAX_DEGREE];
  double c[ZR_POLY_MAX_DEGREE][ZR_POLY_MAX_DEGREE + 1];
  double a[ZR_POLY_MAX_DEGREE], fa[ZR_POLY_MAX_DEGREE]; /* each level's
                                                  end reached and value */
  bool done[ZR_POLY_MAX_DEGREE]; /* a level whose end reached hi */
  double low[2];                /* the last level's roots, closed form */
  int n_low, next_low;
  double hi;
  double at, b, fat; /* the interval found at the top, its value at at */
} zr__root_walk;

void zr__root_walk_start(zr__root_walk *w, const double *c, int degree,
                         double lo, double hi);
bool zr__root_walk_next(zr__root_walk *w, double *a, double *b);
double zr__root_walk_root(const zr__root_walk *w);

/* The polynomial's value at x (Horner's scheme). */
double zr__poly_eval(const double *c, int degree, double x);

#endif /* ZR_TRACE_ROOTS_H */
