/*
 * roots.h - real roots of polynomials in an interval, for the shapes
 * whose ray equations are polynomials of degree above two (torus, and
 * later blob, lathe, sor, prism and poly).
 */
#ifndef ZR_TRACE_ROOTS_H
#define ZR_TRACE_ROOTS_H

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

/* The polynomial's value at x (Horner's scheme). */
double zr__poly_eval(const double *c, int degree, double x);

#endif /* ZR_TRACE_ROOTS_H */
