/*
 * obj_julia.c - the julia fractal (POV-Ray 3.7 reference, "Julia
 * Fractal"): the points h of 3-D space, taken into 4-D on the slice
 * plane, whose sequence h, f(h) + p, f(f(h) + p) + p, ... stays within
 * the escape radius for max_iteration steps.
 *
 * The slice: a 3-D point (x, y, z) is the 4-D point (x, y, z, w) with
 * w = (distance - n.x x - n.y y - n.z z) / n.w, as POV-Ray maps it.  The
 * escape test and the bounding sphere are POV-Ray's (source
 * core/shape/fractal.cpp): for quaternions the radius is 1 + |p|, at
 * most 2, and a point escapes when |h|^2 exceeds that radius squared;
 * hypercomplex numbers use radius 4.  Since the set is defined by a
 * finite number of steps, these radii shape the object and must match.
 *
 * Quaternion squares and cubes follow from q = (x, v), v = (y, z, w):
 * q^2 = (x^2 - |v|^2, 2 x v), q^3 = (x^3 - 3 x |v|^2, (3 x^2 - |v|^2) v).
 * Hypercomplex numbers multiply componentwise in their "duplex" form,
 * the complex pair a = (x - w) + i (y + z), b = (x + w) + i (y - z), so
 * a function of one (sqr, cube, reciprocal, exp, ln, the trigonometric
 * and hyperbolic functions and their inverses, pwr) is that complex
 * function of each part, as POV-Ray computes it.  Quaternions have only
 * sqr and cube (the parser refuses the others, as POV-Ray does).
 * (POV-Ray 3.7's hypercomplex `cube` iterates the square, a slip in its
 * source; zRcube computes the cube the keyword asks for.)
 *
 * Along a ray the tracer marches from the bounding sphere's entry, by
 * the larger of POV-Ray's distance estimate (march_sample) and the
 * precision's step (1 / precision, as POV-Ray's "precision" is), and
 * bisects each change between inside and outside down to POV-Ray's
 * tolerance.  The estimates are POV-Ray's rather than rigorous bounds
 * so that the same specks of a dusty set appear.  The march starts at
 * the same place whatever the interval asked for, so a crossing's t
 * never depends on it.  The normal is the gradient of |h_N|^2 over
 * (x, y, z) at the crossing's inside end (N = max_iteration), by
 * forward differentiation of the iteration, which is how POV-Ray
 * shades it (for the hypercomplex functions other than sqr and cube
 * with POV-Ray's stand-in factors, see hypercomplex_step); POV-Ray
 * leaves out how w follows x, y and z on a tilted slice, zRcube does
 * not.
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
   bounding radius (POV-Ray's Fractal_Tolerance is 1e-7 units). */
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

/* The complex function of a julia_fractal on one duplex part, with the
   inverse functions on the branches of POV-Ray's formulas (source
   core/math/hypercomplex.cpp): asin z = -i ln(i z + sqrt(1 - z^2)),
   acos z = -i ln(z + sqrt(z^2 - 1)), and so on. */
static double complex part_function(const struct zr_julia *j,
                                    double complex z) {
  const double complex i = I;
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
    return -i * clog(i * z + csqrt(1.0 - z * z));
  case ZR_JULIA_COS:
    return ccos(z);
  case ZR_JULIA_ACOS:
    return -i * clog(z + csqrt(z * z - 1.0));
  case ZR_JULIA_TAN:
    return ctan(z);
  case ZR_JULIA_ATAN:
    return 0.5 * i * clog((1.0 - i * z) / (1.0 + i * z));
  case ZR_JULIA_SINH:
    return csinh(z);
  case ZR_JULIA_ASINH:
    return clog(z + csqrt(z * z + 1.0));
  case ZR_JULIA_COSH:
    return ccosh(z);
  case ZR_JULIA_ACOSH:
    return clog(z + csqrt(z * z - 1.0));
  case ZR_JULIA_TANH:
    return ctanh(z);
  case ZR_JULIA_ATANH:
    return 0.5 * clog((1.0 + z) / (1.0 - z));
  case ZR_JULIA_PWR:
    if (z == 0.0)
      return 0.0;
    return cexp(complex_of(j->exponent[0], j->exponent[1]) * clog(z));
  }
  return z * z;
}

/*
 * Hypercomplex h -> f(h), part by part in duplex form, with the
 * derivative columns multiplied by the parts' factors: the derivative
 * for sqr and cube; for the other functions POV-Ray's own factors,
 * which its normals and steps are made of ("up to a constant", its
 * source says): h at the first step, then f(h), or -1/h^2 for
 * reciprocal.  step is the step's number from 0.
 */
static void hypercomplex_step(const struct zr_julia *j, const double h[4],
                              int step, double out[4], double (*d)[4],
                              int n_cols) {
  double complex a, b;
  to_duplex(h, &a, &b);
  double complex fa = part_function(j, a), fb = part_function(j, b);
  double complex ka, kb;
  if (j->function == ZR_JULIA_SQR) {
    ka = 2.0 * a;
    kb = 2.0 * b;
  } else if (j->function == ZR_JULIA_CUBE) {
    ka = 3.0 * a * a;
    kb = 3.0 * b * b;
  } else if (step == 0) {
    ka = a;
    kb = b;
  } else if (j->function == ZR_JULIA_RECIPROCAL) {
    ka = -fa * fa;
    kb = -fb * fb;
  } else {
    ka = fa;
    kb = fb;
  }
  for (int k = 0; k < n_cols; k++) {
    double complex da, db;
    to_duplex(d[k], &da, &db);
    from_duplex(ka * da, kb * db, d[k]);
  }
  from_duplex(fa, fb, out);
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

/*
 * Iterates from s (with the derivative columns when n_cols is 3, kept
 * in range by rescale when asked); true when the point stays inside.
 * For a point that escapes, *escape is the step at which it was seen
 * beyond the radius (s then holds that iterate) and *norms the product
 * of the norms of the iterates before it; *escape is -1 otherwise.
 */
static bool iterate(const struct zr_julia *j, julia_state *s, int n_cols,
                    bool keep_in_range, int *escape, double *norms) {
  int power = j->function == ZR_JULIA_CUBE ? 3 : 2;
  *escape = -1;
  *norms = 1.0;
  for (int i = 0; i < j->max_iteration; i++) {
    double n2 = s->h[0] * s->h[0] + s->h[1] * s->h[1] +
                s->h[2] * s->h[2] + s->h[3] * s->h[3];
    if (n2 > j->exit2) {
      *escape = i;
      return false;
    }
    *norms *= sqrt(n2);
    double next[4];
    if (j->algebra == ZR_JULIA_QUATERNION)
      quaternion_step(s->h, power, next, s->dh, n_cols);
    else
      hypercomplex_step(j, s->h, i, next, s->dh, n_cols);
    for (int m = 0; m < 4; m++)
      s->h[m] = next[m] + j->c[m];
    if (n_cols && keep_in_range)
      rescale(s->dh);
  }
  /* POV-Ray tests before each step only, so a point that escapes at
     the last one is still inside. */
  return true;
}

static bool point_inside(const struct zr_julia *j, zr_vec3 p) {
  julia_state s;
  int escape;
  double norms;
  lift(j, p, &s, false);
  return iterate(j, &s, 0, false, &escape, &norms);
}

/*
 * A point of the march along the unit direction d: whether it is
 * inside, and in *dist how far the march may step from it, POV-Ray's
 * estimates (core/math/quaternion.cpp, hypercomplex.cpp) so the same
 * thin parts are found or stepped over: for quaternions |h| ln|h|^2
 * over power^(i+1) times the product of the norms of the iterates up to
 * the escaped one, the i-th; for hypercomplex numbers the step to where
 * |h|^2 would vanish along the gradient of |h|^2 / 2 at the escape,
 * used only between 1 and 30 times the precision's step.  0 when none
 * applies.
 */
static bool march_sample(const struct zr_julia *j, zr_vec3 p, zr_vec3 d,
                         double *dist) {
  julia_state s;
  int escape;
  double norms, step = 1.0 / j->precision;
  bool hyper = j->algebra == ZR_JULIA_HYPERCOMPLEX;
  lift(j, p, &s, hyper);
  *dist = 0.0;
  if (iterate(j, &s, hyper ? 3 : 0, false, &escape, &norms))
    return true;
  double n2 = s.h[0] * s.h[0] + s.h[1] * s.h[1] + s.h[2] * s.h[2] +
              s.h[3] * s.h[3];
  if (!hyper) {
    double power = j->function == ZR_JULIA_CUBE ? 3.0 : 2.0;
    /* POV-Ray's product runs over the escaped iterate too. */
    double den = pow(power, escape + 1) * norms * sqrt(n2);
    if (den > 0.0 && n2 > 1.0)
      *dist = sqrt(n2) * log(n2) / den;
    return false;
  }
  double slope = 0.0;
  zr_vec3 dd = d;
  double dc[3] = {dd.x, dd.y, dd.z};
  for (int k = 0; k < 3; k++)
    for (int m = 0; m < 4; m++)
      slope += dc[k] * s.h[m] * s.dh[k][m];
  if (slope < -TOLERANCE) {
    slope *= -2.0;
    if (n2 > step * slope && n2 < 30.0 * step * slope)
      *dist = n2 / slope;
  }
  return false;
}

bool zr__julia_inside(const zr_object *o, zr_vec3 p) {
  return point_inside(o->u.julia.data, p);
}

/* The gradient of |h_N|^2 by (x, y, z): outward. */
static zr_vec3 julia_normal(const struct zr_julia *j, zr_vec3 p) {
  julia_state s;
  int escape;
  double norms;
  lift(j, p, &s, true);
  iterate(j, &s, 3, true, &escape, &norms);
  double g[3];
  for (int k = 0; k < 3; k++) {
    g[k] = 0.0;
    for (int m = 0; m < 4; m++)
      g[k] += s.h[m] * s.dh[k][m];
  }
  /* h_N may be tiny too: scaled, the normal survives normalising. */
  double big = fmax(fabs(g[0]), fmax(fabs(g[1]), fabs(g[2])));
  if (big > 0.0 && isfinite(big))
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
  /* The march starts a few tolerances from the origin, as POV-Ray's
     does, so a ray leaving the surface does not find it again. */
  double step = 1.0 / j->precision, tol = TOLERANCE * r;
  double s_end = -b + root, s = fmax(-b - root, 3.0 * tol);
  s_end = fmin(s_end, tmax * len);
  if (!(s < s_end))
    return 0;
  double dist;
  bool in = march_sample(j, zr_v3_madd(org, d, s), d, &dist);
  int found = 0;
  while (s < s_end && found < 4) {
    double ds = fmax(dist, step);
    double s_next = fmin(s + ds, s_end), dist_next;
    bool in_next = march_sample(j, zr_v3_madd(org, d, s_next), d,
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
      /* The crossing is the bracket's inside end, as in POV-Ray: its
         normal then comes from all max_iteration steps. */
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
