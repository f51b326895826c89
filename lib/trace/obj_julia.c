/*
 * obj_julia.c - the julia fractal (POV-Ray 3.7 reference, "Julia
 * Fractal"): the points h of 3-D space, taken into 4-D on the slice
 * plane, whose sequence h, f(h) + p, f(f(h) + p) + p, ... stays within
 * the escape radius for max_iteration steps.
 *
 * The slice: the manual's plane perpendicular to the 4-D normal n at
 * the given distance, projected to 3-D by dropping w, so (x, y, z) is
 * the 4-D point (x, y, z, w) with w = (distance - n.x x - n.y y -
 * n.z z) / n.w (hence n.w may not be 0).  The escape radius is the
 * manual's 4 for hypercomplex numbers; for quaternions POV-Ray 3.7's
 * renders measure 1 + |p|, at most 2 (with max_iteration 2,
 * p = <0.5, 0, 0, 0> reaches +-1 on the x axis and +-1.414 on the y
 * axis, where radius 4 would give +-1.87; p = 0 reaches 1, p = <3, 0,
 * 0, 0> +-0.56 across its silhouette; zRcube's renders of these match
 * to the pixel).  Since the set is defined by a
 * finite number of steps, the radius shapes the object.  The bounding
 * sphere is the escape radius: nothing beyond it is inside.
 *
 * Quaternion squares and cubes follow from q = (x, v), v = (y, z, w):
 * q^2 = (x^2 - |v|^2, 2 x v), q^3 = (x^3 - 3 x |v|^2, (3 x^2 - |v|^2) v).
 * Hypercomplex numbers, with the manual's table of products, are two
 * copies of the complex numbers: in the "duplex" form a = (x - w) +
 * i (y + z), b = (x + w) + i (y - z) they multiply part by part, so a
 * function of one (sqr, cube, reciprocal, exp, ln, the trigonometric
 * and hyperbolic functions and their inverses, pwr) is that complex
 * function of each part.  Quaternions have only sqr and cube, as the
 * manual says.  The manual's hypercomplex `cube` is h*h*h, which is
 * what zRcube computes; POV-Ray 3.7 renders it (measured, 200 x 200,
 * p = <-0.4, 0.3, 0.1, 0>, max_iteration 8) with nearly the silhouette
 * of its `sqr` (872 pixels differ) and far from a cube's (2587).
 *
 * Along a ray the tracer marches from the bounding sphere's entry by
 * the larger of a distance estimate (march_sample; the manual uses one
 * for quaternions) and the precision's step, 1 / precision, and
 * bisects each change between inside and outside down to TOLERANCE.
 * The march starts at the same place whatever the interval asked for,
 * so a crossing's t never depends on it.  The normal is the gradient of
 * |h_N|^2 over (x, y, z) at the crossing's inside end (N =
 * max_iteration), by forward differentiation of the iteration through
 * the slice, w following x, y and z.
 */
#include "trace/obj_sweep.h"

#include <complex.h>
#include <math.h>
#include <string.h>

/* C11's CMPLX, which glibc leaves out for compilers it does not know to
   have __builtin_complex (clang, as the fuzz build uses): a complex is
   an array of its two parts (C11 6.2.5). */
static double complex complex_of(double re, double im) {
  double parts[2] = {re, im};
  double complex z;
  memcpy(&z, parts, sizeof z);
  return z;
}

/* Bisection stops when the bracket is this small, relative to the
   bounding radius: far below a pixel, well above rounding. */
#define TOLERANCE 1e-7

static double julia_radius(const struct zr_julia *j) {
  if (j->algebra == ZR_JULIA_HYPERCOMPLEX)
    return 4.0;
  double r = 1.0 + sqrt(j->c[0] * j->c[0] + j->c[1] * j->c[1] +
                        j->c[2] * j->c[2] + j->c[3] * j->c[3]) +
             TOLERANCE;
  return r > 2.0 ? 2.0 : r;
}

bool zr__julia_prepare(struct zr_julia *j) {
  double n2 = 0.0;
  for (int k = 0; k < 4; k++)
    n2 += j->slice[k] * j->slice[k];
  if (!(n2 > 0.0) || j->slice[3] == 0.0)
    return false;
  double r = julia_radius(j);
  j->exit2 = j->algebra == ZR_JULIA_HYPERCOMPLEX ? 16.0 : r * r + TOLERANCE;
  if (j->precision < 1.0)
    j->precision = 1.0;
  return true;
}

void zr__julia_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  double r = julia_radius(o->u.julia.data);
  *lo = zr_v3(-r, -r, -r);
  *hi = zr_v3(r, r, r);
}

/* A 4-D point and the three columns of its derivative by x, y, z. */
typedef struct julia_state {
  double h[4];
  double dh[3][4];
} julia_state;

/* The 4-D point of a 3-D one, with its derivatives when asked. */
static void lift(const struct zr_julia *j, zr_vec3 p, julia_state *s,
                 bool derivs) {
  const double *n = j->slice;
  s->h[0] = p.x;
  s->h[1] = p.y;
  s->h[2] = p.z;
  s->h[3] = (j->distance - n[0] * p.x - n[1] * p.y - n[2] * p.z) / n[3];
  if (!derivs)
    return;
  for (int k = 0; k < 3; k++) {
    for (int m = 0; m < 4; m++)
      s->dh[k][m] = m == k ? 1.0 : 0.0;
    s->dh[k][3] = -n[k] / n[3];
  }
}

/* Quaternion q -> q^2 or q^3, with the derivative columns d mapped by
   the differential at q. */
static void quaternion_step(const double q[4], int power, double out[4],
                            double (*d)[4], int n_cols) {
  double x = q[0], vv = q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
  for (int k = 0; k < n_cols; k++) {
    double a = d[k][0];
    double vb = q[1] * d[k][1] + q[2] * d[k][2] + q[3] * d[k][3];
    double r, sv, sb;
    if (power == 2) {
      /* d(q^2) = q dq + dq q = (2 (x a - v.b), 2 (x b + a v)). */
      r = 2.0 * (x * a - vb);
      sv = 2.0 * a;
      sb = 2.0 * x;
    } else {
      /* d(q^3) = (3 (x^2 - |v|^2) a - 6 x v.b,
                   (6 x a - 2 v.b) v + (3 x^2 - |v|^2) b). */
      r = 3.0 * (x * x - vv) * a - 6.0 * x * vb;
      sv = 6.0 * x * a - 2.0 * vb;
      sb = 3.0 * x * x - vv;
    }
    d[k][0] = r;
    for (int m = 1; m < 4; m++)
      d[k][m] = sv * q[m] + sb * d[k][m];
  }
  if (power == 2) {
    out[0] = x * x - vv;
    for (int m = 1; m < 4; m++)
      out[m] = 2.0 * x * q[m];
  } else {
    double s = 3.0 * x * x - vv;
    out[0] = x * (x * x - 3.0 * vv);
    for (int m = 1; m < 4; m++)
      out[m] = s * q[m];
  }
}

/* The duplex form of a hypercomplex number and back. */
static void to_duplex(const double h[4], double complex *a,
                      double complex *b) {
  *a = complex_of(h[0] - h[3], h[1] + h[2]);
  *b = complex_of(h[0] + h[3], h[1] - h[2]);
}

static void from_duplex(double complex a, double complex b, double h[4]) {
  h[0] = 0.5 * (creal(a) + creal(b));
  h[1] = 0.5 * (cimag(a) + cimag(b));
  h[2] = 0.5 * (cimag(a) - cimag(b));
  h[3] = 0.5 * (creal(b) - creal(a));
}

/* The complex function of a julia_fractal on one duplex part; the
   inverse functions take C99's principal branches (ISO C 7.3.5). */
static double complex part_function(const struct zr_julia *j,
                                    double complex z) {
  switch (j->function) {
  case ZR_JULIA_SQR:
    return z * z;
  case ZR_JULIA_CUBE:
    return z * z * z;
  case ZR_JULIA_RECIPROCAL:
    return z != 0.0 ? 1.0 / z : 0.0;
  case ZR_JULIA_EXP:
    return cexp(z);
  case ZR_JULIA_LN:
    return clog(z);
  case ZR_JULIA_SIN:
    return csin(z);
  case ZR_JULIA_ASIN:
    return casin(z);
  case ZR_JULIA_COS:
    return ccos(z);
  case ZR_JULIA_ACOS:
    return cacos(z);
  case ZR_JULIA_TAN:
    return ctan(z);
  case ZR_JULIA_ATAN:
    return catan(z);
  case ZR_JULIA_SINH:
    return csinh(z);
  case ZR_JULIA_ASINH:
    return casinh(z);
  case ZR_JULIA_COSH:
    return ccosh(z);
  case ZR_JULIA_ACOSH:
    return cacosh(z);
  case ZR_JULIA_TANH:
    return ctanh(z);
  case ZR_JULIA_ATANH:
    return catanh(z);
  case ZR_JULIA_PWR:
    if (z == 0.0)
      return 0.0;
    return cexp(complex_of(j->exponent[0], j->exponent[1]) * clog(z));
  }
  return z * z;
}

/* The derivative of part_function at z, where it has the value fz. */
static double complex part_derivative(const struct zr_julia *j,
                                      double complex z, double complex fz) {
  switch (j->function) {
  case ZR_JULIA_SQR:
    return 2.0 * z;
  case ZR_JULIA_CUBE:
    return 3.0 * z * z;
  case ZR_JULIA_RECIPROCAL:
    return -fz * fz;
  case ZR_JULIA_EXP:
    return fz;
  case ZR_JULIA_LN:
    return z != 0.0 ? 1.0 / z : 0.0;
  case ZR_JULIA_SIN:
    return ccos(z);
  case ZR_JULIA_ASIN:
    return 1.0 / csqrt(1.0 - z * z);
  case ZR_JULIA_COS:
    return -csin(z);
  case ZR_JULIA_ACOS:
    return -1.0 / csqrt(1.0 - z * z);
  case ZR_JULIA_TAN:
    return 1.0 + fz * fz;
  case ZR_JULIA_ATAN:
    return 1.0 / (1.0 + z * z);
  case ZR_JULIA_SINH:
    return ccosh(z);
  case ZR_JULIA_ASINH:
    return 1.0 / csqrt(z * z + 1.0);
  case ZR_JULIA_COSH:
    return csinh(z);
  case ZR_JULIA_ACOSH:
    return 1.0 / (csqrt(z - 1.0) * csqrt(z + 1.0));
  case ZR_JULIA_TANH:
    return 1.0 - fz * fz;
  case ZR_JULIA_ATANH:
    return 1.0 / (1.0 - z * z);
  case ZR_JULIA_PWR:
    return z != 0.0 ? complex_of(j->exponent[0], j->exponent[1]) * fz / z
                    : 0.0;
  }
  return 2.0 * z;
}

/* Hypercomplex h -> f(h), part by part in duplex form, with the
   derivative columns multiplied part by part by f' (the duplex form
   makes the algebra two copies of the complex numbers, so f acts on
   each copy as a holomorphic function).  Returns how much the step
   stretches small distances at most, max(|f'(a)|, |f'(b)|), as the
   duplex form is an isometry up to the factor sqrt(2); 0 when neither
   the columns nor the factor are asked for (want_stretch false). */
static double hypercomplex_step(const struct zr_julia *j,
                                const double h[4], double out[4],
                                double (*d)[4], int n_cols,
                                bool want_stretch) {
  double complex a, b;
  to_duplex(h, &a, &b);
  double complex fa = part_function(j, a), fb = part_function(j, b);
  from_duplex(fa, fb, out);
  if (!n_cols && !want_stretch)
    return 0.0;
  double complex ka = part_derivative(j, a, fa);
  double complex kb = part_derivative(j, b, fb);
  for (int k = 0; k < n_cols; k++) {
    double complex da, db;
    to_duplex(d[k], &da, &db);
    from_duplex(ka * da, kb * db, d[k]);
  }
  return fmax(cabs(ka), cabs(kb));
}

/* Only the direction of the derivative's columns matters (they make a
   normal), and over many steps of a cube they leave the range of
   doubles: they are kept near 1 by a common power of two. */
static void rescale(double (*dh)[4]) {
  double big = 0.0;
  for (int k = 0; k < 3; k++)
    for (int m = 0; m < 4; m++)
      big = fmax(big, fabs(dh[k][m]));
  if (!(big > 0.0) || !isfinite(big) || (big > 0x1p-64 && big < 0x1p64))
    return;
  int e;
  frexp(big, &e);
  for (int k = 0; k < 3; k++)
    for (int m = 0; m < 4; m++)
      dh[k][m] = ldexp(dh[k][m], -e);
}

/* Whether the distance estimate applies: the iteration is a
   polynomial (Hart, Sandin and Kauffman's estimate comes from the
   Green's function of a polynomial Julia set).  The manual names the
   estimate for quaternions; hypercomplex sqr and cube are polynomials
   in each duplex part, so it holds for them as well. */
static bool has_estimate(const struct zr_julia *j) {
  return j->function == ZR_JULIA_SQR || j->function == ZR_JULIA_CUBE;
}

/*
 * Iterates from s (with the derivative columns when n_cols is 3, kept
 * in range by rescale when asked); true when the point stays inside.
 * A point is inside when none of h_0 ... h_(N-1) lies beyond the
 * escape radius, N = max_iteration (the manual's sequence; h_N itself
 * is not tested, as POV-Ray's renders of p = <0.5, 0, 0, 0> with
 * max_iteration 2 show: their edge on the x axis is where h_1, not h_2,
 * reaches the radius).  For a point that escapes, s holds the first
 * iterate beyond the radius and *stretch, when not NULL, a bound on how
 * much the iteration up to it stretches small distances: the product
 * over the steps of each step's bound (quaternions: |d(q^n)| is at most
 * n |q|^(n-1) |dq|, since |a b| = |a| |b|; hypercomplex numbers: see
 * hypercomplex_step).
 */
static bool iterate(const struct zr_julia *j, julia_state *s, int n_cols,
                    bool keep_in_range, double *stretch) {
  int power = j->function == ZR_JULIA_CUBE ? 3 : 2;
  bool quaternion = j->algebra == ZR_JULIA_QUATERNION;
  if (stretch)
    *stretch = 1.0;
  for (int i = 0; i < j->max_iteration; i++) {
    double n2 = s->h[0] * s->h[0] + s->h[1] * s->h[1] +
                s->h[2] * s->h[2] + s->h[3] * s->h[3];
    if (n2 > j->exit2)
      return false;
    double next[4], k;
    if (quaternion) {
      quaternion_step(s->h, power, next, s->dh, n_cols);
      k = power * (power == 2 ? sqrt(n2) : n2);
    } else {
      k = hypercomplex_step(j, s->h, next, s->dh, n_cols, stretch != NULL);
    }
    if (stretch)
      *stretch *= k;
    for (int m = 0; m < 4; m++)
      s->h[m] = next[m] + j->c[m];
    if (n_cols && keep_in_range)
      rescale(s->dh);
  }
  return true;
}

static bool point_inside(const struct zr_julia *j, zr_vec3 p) {
  julia_state s;
  lift(j, p, &s, false);
  return iterate(j, &s, 0, false, NULL);
}

/*
 * A point of the march: whether it is inside, and in *dist how far the
 * march may step from it, 0 when no estimate applies.  For a point
 * that escapes a polynomial iteration, Hart, Sandin and Kauffman's
 * estimate ("Ray tracing deterministic 3-D fractals", SIGGRAPH 1989)
 * of the distance to the set: |h| ln |h| / (2 |h'|), with |h'| bounded
 * above by iterate's stretch, which only shortens the estimate.  Like
 * the manual's, it is not a proven bound in four dimensions, so the
 * march still checks every point it steps to.
 */
static bool march_sample(const struct zr_julia *j, zr_vec3 p,
                         double *dist) {
  julia_state s;
  double stretch;
  bool estimate = has_estimate(j);
  lift(j, p, &s, false);
  *dist = 0.0;
  if (iterate(j, &s, 0, false, estimate ? &stretch : NULL))
    return true;
  if (!estimate)
    return false;
  double n = sqrt(s.h[0] * s.h[0] + s.h[1] * s.h[1] + s.h[2] * s.h[2] +
                  s.h[3] * s.h[3]);
  if (n > 1.0 && stretch > 0.0 && isfinite(stretch))
    *dist = n * log(n) / (2.0 * stretch);
  return false;
}

bool zr__julia_inside(const zr_object *o, zr_vec3 p) {
  return point_inside(o->u.julia.data, p);
}

/* The gradient of |h_N|^2 by (x, y, z): outward. */
static zr_vec3 julia_normal(const struct zr_julia *j, zr_vec3 p) {
  julia_state s;
  lift(j, p, &s, true);
  iterate(j, &s, 3, true, NULL);
  double g[3];
  for (int k = 0; k < 3; k++) {
    g[k] = 0.0;
    for (int m = 0; m < 4; m++)
      g[k] += s.h[m] * s.dh[k][m];
  }
  /* h_N may be tiny too: scaled, the normal survives normalising. */
  double big = fmax(fabs(g[0]), fmax(fabs(g[1]), fabs(g[2])));
  /* At a pole or branch point of the function the gradient is lost;
     the direction from the centre is the best guess left. */
  if (!(big > 0.0) || !isfinite(big))
    return zr_v3_dot(p, p) > 0.0 ? p : zr_v3(0, 1, 0);
  for (int k = 0; k < 3; k++)
    g[k] /= big;
  return zr_v3(g[0], g[1], g[2]);
}

int zr__julia_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                        double tmin, double tmax, double t[4],
                        zr_vec3 normal[4]) {
  const struct zr_julia *j = o->u.julia.data;
  double len = zr_v3_len(dir);
  if (!(len > 0.0) || !isfinite(len))
    return 0;
  zr_vec3 d = zr_v3_scale(dir, 1.0 / len);
  double r = julia_radius(j);
  /* The bounding sphere about the origin. */
  double b = zr_v3_dot(org, d), c = zr_v3_dot(org, org) - r * r;
  double disc = b * b - c;
  if (!(disc > 0.0))
    return 0;
  double root = sqrt(disc);
  /* The march starts a few tolerances from the ray's origin, so a ray
     leaving the surface does not find it again. */
  double step = 1.0 / j->precision, tol = TOLERANCE * r;
  double s_end = -b + root, s = fmax(-b - root, 3.0 * tol);
  s_end = fmin(s_end, tmax * len);
  if (!(s < s_end))
    return 0;
  double dist;
  bool in = march_sample(j, zr_v3_madd(org, d, s), &dist);
  int found = 0;
  while (s < s_end && found < 4) {
    double ds = fmax(dist, step);
    double s_next = fmin(s + ds, s_end), dist_next;
    bool in_next = march_sample(j, zr_v3_madd(org, d, s_next),
                                &dist_next);
    if (in_next != in) {
      /* Bisect [s, s_next] down to the tolerance. */
      double a = s, e = s_next;
      while (e - a > tol) {
        double m = 0.5 * (a + e);
        if (point_inside(j, zr_v3_madd(org, d, m)) == in)
          a = m;
        else
          e = m;
      }
      /* The crossing is the bracket's inside end: its normal then
         comes from all max_iteration steps. */
      double sh = in ? a : e, th = sh / len;
      if (th > tmin && th < tmax) {
        t[found] = th;
        normal[found] = julia_normal(j, zr_v3_madd(org, d, sh));
        found++;
      }
    }
    s = s_next;
    dist = dist_next;
    in = in_next;
  }
  return found;
}
