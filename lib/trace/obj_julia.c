/*
 * obj_julia.c - the julia fractal (POV-Ray 3.7 reference, "Julia
 * Fractal"): the points h of 3-D space, taken into 4-D on the slice
 * plane, whose sequence h, f(h) + p, f(f(h) + p) + p, ... stays within
 * the escape radius for max_iteration steps.
 *
 * The slice: the manual's plane perpendicular to the 4-D normal n at
 * the given distance, projected to 3-D by dropping w, so (x, y, z) is
 * the 4-D point (x, y, z, w) with w = (distance - n.x x - n.y y -
 * n.z z) / n.w (hence n.w may not be 0).
 *
 * The escape radius R (see escape_radius) and the bounding sphere: a
 * point is inside when none of h_0 ... h_(N-1) lies beyond R, so the
 * object lies in the 4-D ball |h_0| <= R, whose slice lies in the 3-D
 * ball of radius R about the origin (dropping w only shortens a
 * vector): that ball bounds the object and starts the march.  Since
 * the set is defined by a finite number of steps, R shapes the object
 * whenever max_iteration is small, so it is measured
 * (bench/julia_probe.sh).
 *
 * Quaternion squares and cubes follow from q = (x, v), v = (y, z, w):
 * q^2 = (x^2 - |v|^2, 2 x v), q^3 = (x^3 - 3 x |v|^2, (3 x^2 - |v|^2) v).
 * Hypercomplex numbers split into two complex numbers (see bicomplex
 * below), so a function of one (sqr, cube, reciprocal, exp, ln, the
 * trigonometric and hyperbolic functions and their inverses, pwr) is
 * that complex function of each part.  Quaternions have only sqr and
 * cube, as the manual says.  The manual's hypercomplex `cube` is h*h*h,
 * which is what zRcube computes; POV-Ray 3.7 draws it exactly as its
 * `sqr` (julia_probe.sh: h2_cube and h2_skew meet every ray at the same
 * point), which no stock scene uses.  For the functions other than
 * sqr and cube, POV-Ray's crossings lie on its march's steps (1 /
 * precision apart along the ray: h2_sin meets the ray from -y at
 * -2.083000 with precision 1000, the boundary being at -2.083329);
 * zRcube bisects every crossing.
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

#include "trace/shape.h"
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

/*
 * Where the object fills the bounding sphere, POV-Ray reports no
 * surface on the sphere, yet it finds the surface of an object whose
 * later iterates end exactly there.  Measured (bench/julia_probe.sh):
 * with max_iteration 1 the object is the whole ball |h_0| <= R and no
 * ray meets it (q1_*, h1_*); hypercomplex 1/h with p = 0 returns to h_0
 * every other step, and rays meet it only at |x| = 1/4, not on the
 * sphere (h6_recip0, h3_recip0); quaternion p = 0, max_iteration 2 is
 * the unit ball cut by |h_1| = |h_0|^2 <= 1, and rays meet it at 1
 * (q2_p0); where the slice is skewed the ball is met inside the sphere
 * and rays meet it there (h2_exp, h2_recip: x = -3.977436 =
 * -sqrt(16 - 0.18)).  So the march runs between the points where the
 * ray enters and leaves a sphere a little wider than R (radius
 * R (1 + BOUND_WIDEN)); at those two points the iterates may reach
 * |h|^2 = R^2 (1 + 3 BOUND_WIDEN) (ENTRY_SLACK), enough for h_0 and
 * for an iterate equal to it (|h|^2 <= R^2 (1 + 2 BOUND_WIDEN)), not
 * for h_0^2 on the unit sphere (R^2 (1 + 4 BOUND_WIDEN)); everywhere
 * else the test is |h| > R.  The one measured case this misses is an
 * object touching the sphere through a later iterate at the cut radius
 * 2: quaternion p = <2,0,0,0>, max_iteration 2 at y = -2 (q2_p2),
 * where POV-Ray finds nothing and zRcube the surface.  1e-9 is far
 * above rounding (about 1e-16) and far below a pixel.
 */
#define BOUND_WIDEN 1e-9
#define ENTRY_SLACK (1.0 + 3 * BOUND_WIDEN)

/*
 * The escape radius R: a point escapes once an iterate has |h| > R.
 *
 * Hypercomplex numbers: the manual's "hypersphere of radius 4"; measured
 * (julia_probe.sh, h2_p0: with p = 0 and max_iteration 2, h_1 = h_0^2
 * reaches 4 where rays meet the object, at |h_0| = 2; h2_p0.5, h2_p2,
 * h2_p5 agree).
 *
 * Quaternions: R = 1 + |p|, but no more than 2.  Why 1 + |p| is an
 * escape radius (|q^2| = |q|^2 for quaternions): if |q| = r > 1 + |p|
 * then |q^2 + p| >= r^2 - |p| = r + (r (r - 1) - |p|) and
 * r (r - 1) - |p| > (1 + |p|) |p| - |p| = |p|^2 >= 0, and that gain
 * grows with r, so the iterates grow without bound: past R a point
 * never comes back.  That POV-Ray 3.7 uses this R, and cuts it at 2,
 * is measured (julia_probe.sh: with max_iteration 2 the object is
 * |h_0^2 + p| <= R; p = <0.5,0,0,0> meets the rays at x = -1 and
 * y = -1.414214, R = 1.5; p = <1,0,0,0> at x = -1 and y = -1.732051,
 * R = 2; p = <2,0,0,0> on the diagonal at 1.154701 = 2 / sqrt(3),
 * R = 2, not 3; q2_p1.5 and q2_pi15 give R = 2 for |p| = 1.5; p = 0
 * gives R = 1, the unit ball).  The cut at 2 keeps R an escape radius
 * only while |p| <= 2 (r (r - 1) >= |p| at r = 2), so for a larger p
 * some points beyond R would come back: they are outside all the same.
 */
static double escape_radius(const struct zr_julia *j) {
  if (j->algebra == ZR_JULIA_HYPERCOMPLEX)
    return 4.0;
  double p = sqrt(j->c[0] * j->c[0] + j->c[1] * j->c[1] +
                  j->c[2] * j->c[2] + j->c[3] * j->c[3]);
  return fmin(1.0 + p, 2.0);
}

bool zr__julia_prepare(struct zr_julia *j) {
  double n2 = 0.0;
  for (int k = 0; k < 4; k++)
    n2 += j->slice[k] * j->slice[k];
  if (!(n2 > 0.0) || j->slice[3] == 0.0)
    return false;
  j->escape = escape_radius(j);
  if (j->precision < 1.0)
    j->precision = 1.0;
  return true;
}

void zr__julia_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  double r = ((const struct zr_julia *)o->u.julia.data)->escape *
             (1.0 + BOUND_WIDEN);
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

/*
 * Hypercomplex numbers as pairs of complex numbers.  The manual's table
 * gives ij = ji = k, jk = kj = -i, ki = ik = -j and ii = jj = -1; it
 * also lists kk = -1, but commuting i and j give kk = (ij)(ij) = ii jj =
 * +1, and POV-Ray agrees (julia_probe.sh, h2_w05: at w = 0.5, h_0 = x +
 * 0.5k, and rays meet the object where (x^2 + 0.25)^2 + x^2 = 16, x =
 * 1.819895, as kk = +1 gives; kk = -1 would give 1.946).  So with
 * kk = 1 the elements e = (1 + k) / 2 and f = (1 - k) / 2 satisfy
 * e e = e, f f = f, e f = 0, e + f = 1 and k e = e, k f = -f.  Writing
 * j = -ik (from ik = -j), h = x + yi + zj + wk = A + B k with
 * A = x + iy and B = w - iz, complex numbers in 1 and i, hence
 *   h = (A + B) e + (A - B) f,
 * and products, sums and so power series act on the two parts
 * separately: f(h) = f(A + B) e + f(A - B) f.  Back: A = (P + M) / 2,
 * B = (P - M) / 2 for P = A + B, M = A - B; and |h|^2 = |A|^2 + |B|^2 =
 * (|P|^2 + |M|^2) / 2.  tests/test_julia.c checks the table.
 */
typedef struct bicomplex {
  double complex along_e; /* P = A + B */
  double complex along_f; /* M = A - B */
} bicomplex;

static bicomplex split(const double h[4]) {
  double complex a = complex_of(h[0], h[1]);  /* x + iy */
  double complex b = complex_of(h[3], -h[2]); /* w - iz */
  return (bicomplex){a + b, a - b};
}

static void join(bicomplex s, double h[4]) {
  double complex a = 0.5 * (s.along_e + s.along_f);
  double complex b = 0.5 * (s.along_e - s.along_f);
  h[0] = creal(a);
  h[1] = cimag(a);
  h[2] = -cimag(b);
  h[3] = creal(b);
}

/* The complex function of a julia_fractal on one part (bicomplex); the
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

/* Hypercomplex h -> f(h), part by part (bicomplex above), with the
   derivative columns multiplied part by part by f' (each part is a
   complex number on which f acts as a holomorphic function).  Returns
   how much the step stretches small distances at most, the larger of
   |f'| on the two parts (|h|^2 is the mean of the parts' |.|^2);
   0 when neither the columns nor the factor are asked for
   (want_stretch false). */
static double hypercomplex_step(const struct zr_julia *j,
                                const double h[4], double out[4],
                                double (*d)[4], int n_cols,
                                bool want_stretch) {
  bicomplex s = split(h);
  bicomplex fs = {part_function(j, s.along_e),
                  part_function(j, s.along_f)};
  join(fs, out);
  if (!n_cols && !want_stretch)
    return 0.0;
  double complex ke = part_derivative(j, s.along_e, fs.along_e);
  double complex kf = part_derivative(j, s.along_f, fs.along_f);
  for (int k = 0; k < n_cols; k++) {
    bicomplex ds = split(d[k]);
    join((bicomplex){ke * ds.along_e, kf * ds.along_f}, d[k]);
  }
  return fmax(cabs(ke), cabs(kf));
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
   in each part (bicomplex), so it holds for them as well. */
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
                    bool keep_in_range, double *stretch, double slack) {
  double limit2 = j->escape * j->escape * slack;
  int power = j->function == ZR_JULIA_CUBE ? 3 : 2;
  bool quaternion = j->algebra == ZR_JULIA_QUATERNION;
  if (stretch)
    *stretch = 1.0;
  for (int i = 0; i < j->max_iteration; i++) {
    double n2 = s->h[0] * s->h[0] + s->h[1] * s->h[1] +
                s->h[2] * s->h[2] + s->h[3] * s->h[3];
    if (n2 > limit2)
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
  return iterate(j, &s, 0, false, NULL, 1.0);
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
                         double *dist, double slack) {
  julia_state s;
  double stretch;
  bool estimate = has_estimate(j);
  lift(j, p, &s, false);
  *dist = 0.0;
  if (iterate(j, &s, 0, false, estimate ? &stretch : NULL, slack))
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
  iterate(j, &s, 3, true, NULL, 1.0);
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
  double r = j->escape * (1.0 + BOUND_WIDEN);
  /* The bounding sphere about the origin (see ENTRY_SLACK). */
  double b = zr_v3_dot(org, d), c = zr_v3_dot(org, org) - r * r;
  double disc = b * b - c;
  if (!(disc > 0.0))
    return 0;
  double root = sqrt(disc);
  /* The march starts a few tolerances from the ray's origin, so a ray
     leaving the surface does not find it again. */
  double step = 1.0 / j->precision, tol = TOLERANCE * r;
  double s_far = -b + root, s = fmax(-b - root, 3.0 * tol);
  double s_end = fmin(s_far, tmax * len);
  if (!(s < s_end))
    return 0;
  double dist;
  bool in = march_sample(j, zr_v3_madd(org, d, s), &dist, ENTRY_SLACK);
  int found = 0;
  while (s < s_end && found < 4) {
    double ds = fmax(dist, step);
    double s_next = fmin(s + ds, s_end), dist_next;
    bool in_next = march_sample(j, zr_v3_madd(org, d, s_next), &dist_next,
                                s_next == s_far ? ENTRY_SLACK : 1.0);
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

static bool julia_box(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  zr__julia_bounds(o, lo, hi);
  return true;
}

/* The operations the tracer calls through (lib/trace/shape.h). */
const zr_shape_ops zr__shape_julia = {
    .name = "a julia_fractal",
    .search = zr__julia_crossings,
    .inside = zr__julia_inside,
    .bounds = julia_box,
};
