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

/* Quaternion q -> q^2 or q^3 (see the top), vv being |v|^2 of q =
   (x, v) as the caller has it. */
static inline void quaternion_power(const double q[4], double vv,
                                    int power, double out[4]) {
  double x = q[0];
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
  quaternion_power(q, vv, power, out);
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

/* Whether distance bounds apply: the iteration is a polynomial (Hart,
   Sandin and Kauffman's estimate comes from the Green's function of a
   polynomial Julia set, and the bounds below from the difference of
   two powers).  The manual names the estimate for quaternions;
   hypercomplex sqr and cube are polynomials in each part (bicomplex),
   so it holds for them as well. */
static bool has_estimate(const struct zr_julia *j) {
  return j->function == ZR_JULIA_SQR || j->function == ZR_JULIA_CUBE;
}

/* The normal's iteration: from s with the three derivative columns,
   kept in range by rescale, through all max_iteration steps unless an
   iterate escapes (the test of orbit_escape below, without slack). */
static void iterate_with_derivatives(const struct zr_julia *j,
                                     julia_state *s) {
  double limit2 = j->escape * j->escape;
  int power = j->function == ZR_JULIA_CUBE ? 3 : 2;
  bool quaternion = j->algebra == ZR_JULIA_QUATERNION;
  for (int i = 0; i < j->max_iteration; i++) {
    double n2 = s->h[0] * s->h[0] + s->h[1] * s->h[1] +
                s->h[2] * s->h[2] + s->h[3] * s->h[3];
    if (n2 > limit2)
      return;
    double next[4];
    if (quaternion)
      quaternion_step(s->h, power, next, s->dh, 3);
    else
      hypercomplex_step(j, s->h, next, s->dh, 3, false);
    for (int m = 0; m < 4; m++)
      s->h[m] = next[m] + j->c[m];
    rescale(s->dh);
  }
}

/* The longest orbit whose radii a march sample keeps for the distance
   bounds (max_iteration is 20 by default); a longer one steps by Hart,
   Sandin and Kauffman's estimate alone outside, and by the precision's
   step inside. */
#define ORBIT_MAX 64

/*
 * The radii of an orbit h_0, h_1, ..., as the distance bounds need
 * them.  The growth radius A_i bounds how much the step from h_i
 * stretches a perturbation: for quaternions A_i = |h_i|, and a
 * perturbation e of h_i becomes at most (A_i + e)^n - A_i^n after
 * q -> q^n + p (n = 2, 3), because a^2 - b^2 = a (a - b) + (a - b) b
 * and a^3 - b^3 = a^2 (a - b) + a (a - b) b + (a - b) b^2 in any
 * algebra, and |a b| = |a| |b| for quaternions.  For hypercomplex
 * numbers the same holds of each complex part (bicomplex) when A_i is
 * the larger of the parts' moduli and e bounds both parts'
 * perturbations (then |dh| <= e, since |h|^2 is the mean of the
 * parts' |.|^2).
 */
typedef struct orbit {
  int n;                     /* radii recorded, of h_0 ... h_(n-1) */
  double radius[ORBIT_MAX];  /* |h_i| */
  double growth[ORBIT_MAX];  /* A_i */
  double growth2_product;    /* the product of A_i^2 over the steps */
} orbit;

/* The hypercomplex square or cube of h (power 2 or 3) by its complex
   parts in real arithmetic, with the larger part's modulus squared. */
static void bicomplex_power(const double h[4], int power, double out[4],
                            double *growth2) {
  /* P = A + B, M = A - B for A = x + iy, B = w - iz (bicomplex). */
  double pr = h[0] + h[3], pi = h[1] - h[2];
  double mr = h[0] - h[3], mi = h[1] + h[2];
  double p2 = pr * pr + pi * pi, m2 = mr * mr + mi * mi;
  *growth2 = fmax(p2, m2);
  double fpr, fpi, fmr, fmi;
  if (power == 2) {
    fpr = pr * pr - pi * pi;
    fpi = 2.0 * pr * pi;
    fmr = mr * mr - mi * mi;
    fmi = 2.0 * mr * mi;
  } else {
    fpr = pr * (pr * pr - 3.0 * pi * pi);
    fpi = pi * (3.0 * pr * pr - pi * pi);
    fmr = mr * (mr * mr - 3.0 * mi * mi);
    fmi = mi * (3.0 * mr * mr - mi * mi);
  }
  /* Back: A = (P + M) / 2, B = (P - M) / 2 (join). */
  out[0] = 0.5 * (fpr + fmr);
  out[1] = 0.5 * (fpi + fmi);
  out[2] = -0.5 * (fpi - fmi);
  out[3] = 0.5 * (fpr - fmr);
}

/*
 * Iterates h_0 = h to the first iterate beyond the escape radius
 * (scaled by sqrt(slack); see ENTRY_SLACK) and returns its index, or
 * max_iteration when none of h_0 ... h_(N-1) lies beyond (the point is
 * inside: the manual's sequence; h_N itself is not tested, as
 * POV-Ray's renders of p = <0.5, 0, 0, 0> with max_iteration 2 show:
 * their edge on the x axis is where h_1, not h_2, reaches the radius).
 * h ends as the last iterate computed.  When rec is given (sqr and
 * cube only), it receives the orbit's radii up to ORBIT_MAX and the
 * product of the growth radii over the steps taken.
 */
/*
 * orbit_escape's loop for quaternions, the iterate in locals rather
 * than in h[] and next[] (which the compiler kept in memory, every
 * step storing and loading them): the same arithmetic in the same
 * order, so the same orbit bit for bit.  Inline, so that each of its
 * two callers gets a copy with rec known to be NULL or not.
 */
static inline int quaternion_orbit(const struct zr_julia *j, double h[4],
                                   double limit2, int power, orbit *rec) {
  double h0 = h[0], h1 = h[1], h2 = h[2], h3 = h[3];
  const double c0 = j->c[0], c1 = j->c[1], c2 = j->c[2], c3 = j->c[3];
  int i = 0;
  for (; i < j->max_iteration; i++) {
    double n2 = h0 * h0 + h1 * h1 + h2 * h2 + h3 * h3;
    if (n2 > limit2)
      break;
    double vv = n2 - h0 * h0, n0, s;
    if (power == 2) {
      n0 = h0 * h0 - vv;
      s = 2.0 * h0;
    } else {
      n0 = h0 * (h0 * h0 - 3.0 * vv);
      s = 3.0 * h0 * h0 - vv;
    }
    if (rec) {
      double r = sqrt(n2); /* |h|, and its growth radius (see orbit) */
      if (i < ORBIT_MAX) {
        rec->radius[i] = r;
        rec->growth[i] = r;
        rec->n = i + 1;
      }
      rec->growth2_product *= n2;
    }
    h0 = n0 + c0;
    h1 = s * h1 + c1;
    h2 = s * h2 + c2;
    h3 = s * h3 + c3;
  }
  h[0] = h0;
  h[1] = h1;
  h[2] = h2;
  h[3] = h3;
  return i;
}

static int orbit_escape(const struct zr_julia *j, double h[4],
                        double slack, orbit *rec) {
  double limit2 = j->escape * j->escape * slack;
  int power = j->function == ZR_JULIA_CUBE ? 3 : 2;
  bool quaternion = j->algebra == ZR_JULIA_QUATERNION;
  if (quaternion) {
    if (rec) {
      rec->n = 0;
      rec->growth2_product = 1.0;
      return quaternion_orbit(j, h, limit2, power, rec);
    }
    return quaternion_orbit(j, h, limit2, power, NULL);
  }
  bool polynomial = has_estimate(j);
  const double *c = j->c;
  if (rec) {
    rec->n = 0;
    rec->growth2_product = 1.0;
  }
  int i = 0;
  for (; i < j->max_iteration; i++) {
    double n2 = h[0] * h[0] + h[1] * h[1] + h[2] * h[2] + h[3] * h[3];
    if (n2 > limit2)
      return i;
    double next[4], growth2 = n2;
    if (quaternion) {
      quaternion_power(h, n2 - h[0] * h[0], power, next);
    } else if (polynomial) {
      bicomplex_power(h, power, next, &growth2);
    } else {
      hypercomplex_step(j, h, next, NULL, 0, false);
    }
    if (rec) {
      if (i < ORBIT_MAX) {
        rec->radius[i] = sqrt(n2);
        rec->growth[i] = sqrt(growth2);
        rec->n = i + 1;
      }
      rec->growth2_product *= growth2;
    }
    for (int m = 0; m < 4; m++)
      h[m] = next[m] + c[m];
  }
  return i;
}

static bool point_inside(const struct zr_julia *j, zr_vec3 p) {
  julia_state s;
  lift(j, p, &s, false);
  return orbit_escape(j, s.h, 1.0, NULL) == j->max_iteration;
}

/*
 * point_inside for three points at once, in[k] for p[k], where the
 * iteration is a polynomial (quaternions, hypercomplex sqr and cube;
 * elsewhere it returns false and leaves in[] alone):
 * the three orbits advance together, each with orbit_escape's
 * operations in its order (so each lane's iterates are its own orbit's
 * bits), and a lane is inside when none of its first max_iteration
 * iterates lies beyond the radius.  An orbit is a chain of dependent
 * multiplications, each waiting for the one before; three independent
 * chains fill the time one leaves idle, so the bisection below tests
 * two levels (the middle and both quarter points) for little more than
 * the time of one.  A lane that has escaped runs on (its values are
 * never read) until every lane has.
 */
#define LANES 3

static bool lockstep_inside(const struct zr_julia *j) {
  return j->algebra == ZR_JULIA_QUATERNION || has_estimate(j);
}

/* One lane's step: quaternion_orbit's, or orbit_escape's with
   bicomplex_power's arithmetic, on the locals of lane L (h0L ... h3L),
   clearing inL once an iterate lies beyond the radius. */
#define QUATERNION_LANE(L)                                                   \
  do {                                                                       \
    double n2 = h0##L * h0##L + h1##L * h1##L + h2##L * h2##L +             \
                h3##L * h3##L;                                               \
    in##L = in##L && !(n2 > limit2);                                         \
    double vv = n2 - h0##L * h0##L, n0, sc;                                  \
    if (power == 2) {                                                        \
      n0 = h0##L * h0##L - vv;                                               \
      sc = 2.0 * h0##L;                                                      \
    } else {                                                                 \
      n0 = h0##L * (h0##L * h0##L - 3.0 * vv);                               \
      sc = 3.0 * h0##L * h0##L - vv;                                         \
    }                                                                        \
    h0##L = n0 + c0;                                                         \
    h1##L = sc * h1##L + c1;                                                 \
    h2##L = sc * h2##L + c2;                                                 \
    h3##L = sc * h3##L + c3;                                                 \
  } while (0)

#define BICOMPLEX_LANE(L)                                                    \
  do {                                                                       \
    double n2 = h0##L * h0##L + h1##L * h1##L + h2##L * h2##L +             \
                h3##L * h3##L;                                               \
    in##L = in##L && !(n2 > limit2);                                         \
    double pr = h0##L + h3##L, pi = h1##L - h2##L;                           \
    double mr = h0##L - h3##L, mi = h1##L + h2##L;                           \
    double fpr, fpi, fmr, fmi;                                               \
    if (power == 2) {                                                        \
      fpr = pr * pr - pi * pi;                                               \
      fpi = 2.0 * pr * pi;                                                   \
      fmr = mr * mr - mi * mi;                                               \
      fmi = 2.0 * mr * mi;                                                   \
    } else {                                                                 \
      fpr = pr * (pr * pr - 3.0 * pi * pi);                                  \
      fpi = pi * (3.0 * pr * pr - pi * pi);                                  \
      fmr = mr * (mr * mr - 3.0 * mi * mi);                                  \
      fmi = mi * (3.0 * mr * mr - mi * mi);                                  \
    }                                                                        \
    h0##L = 0.5 * (fpr + fmr) + c0;                                          \
    h1##L = 0.5 * (fpi + fmi) + c1;                                          \
    h2##L = -0.5 * (fpi - fmi) + c2;                                         \
    h3##L = 0.5 * (fpr - fmr) + c3;                                          \
  } while (0)

/* The three lanes' iteration for one algebra and power, with the
   iterates in locals: in arrays, with bicomplex_power called a lane,
   the compiler kept them in memory and objects/fractal2.pov took as
   long as with one orbit at a time (1.13 against 1.12 CPU s); so
   written, 0.92 against 1.07 (best of five, interleaved). */
static inline __attribute__((always_inline)) void
lanes_inside(const struct zr_julia *j, const double (*h)[4], bool quaternion,
             int power, bool in[LANES]) {
  double h0a = h[0][0], h1a = h[0][1], h2a = h[0][2], h3a = h[0][3];
  double h0b = h[1][0], h1b = h[1][1], h2b = h[1][2], h3b = h[1][3];
  double h0c = h[2][0], h1c = h[2][1], h2c = h[2][2], h3c = h[2][3];
  const double c0 = j->c[0], c1 = j->c[1], c2 = j->c[2], c3 = j->c[3];
  double limit2 = j->escape * j->escape * 1.0; /* orbit_escape's, slack 1 */
  bool ina = true, inb = true, inc = true;
  for (int i = 0; i < j->max_iteration && (ina || inb || inc); i++) {
    if (quaternion) {
      QUATERNION_LANE(a);
      QUATERNION_LANE(b);
      QUATERNION_LANE(c);
    } else {
      BICOMPLEX_LANE(a);
      BICOMPLEX_LANE(b);
      BICOMPLEX_LANE(c);
    }
  }
  in[0] = ina;
  in[1] = inb;
  in[2] = inc;
}

bool zr__julia_points_inside(const struct zr_julia *j, const zr_vec3 p[3],
                             bool in[3]) {
  if (!lockstep_inside(j))
    return false;
  double h[LANES][4];
  for (int k = 0; k < LANES; k++) {
    julia_state s;
    lift(j, p[k], &s, false);
    memcpy(h[k], s.h, sizeof h[k]);
  }
  bool cube = j->function == ZR_JULIA_CUBE;
  if (j->algebra == ZR_JULIA_QUATERNION) {
    if (cube)
      lanes_inside(j, h, true, 3, in);
    else
      lanes_inside(j, h, true, 2, in);
  } else if (cube) {
    lanes_inside(j, h, false, 3, in);
  } else {
    lanes_inside(j, h, false, 2, in);
  }
  return true;
}

/* The largest perturbation e of an iterate of growth radius a whose
   image, at most (a + e)^n - a^n (see orbit), stays within y. */
static double allowed_before(int power, double a, double y) {
  if (!(y > 0.0))
    return 0.0;
  if (power == 2)
    return y / (sqrt(a * a + y) + a);
  double x = cbrt(a * a * a + y);
  return y / (x * x + x * a + a * a);
}

/* What one march needs besides the fractal. */
typedef struct march_frame {
  const struct zr_julia *j;
  int power;
  bool estimate; /* has_estimate */
  /* How far h_0 moves, at most, per unit of 3-D distance, times sqrt(2)
     for hypercomplex numbers (a part moves up to sqrt(2) |dh|): the
     slice's w follows x, y, z by -n.xyz / n.w. */
  double lift_gain;
} march_frame;

static march_frame frame_of(const struct zr_julia *j) {
  const double *n = j->slice;
  double gain = sqrt(1.0 + (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) /
                               (n[3] * n[3]));
  if (j->algebra == ZR_JULIA_HYPERCOMPLEX)
    gain *= sqrt(2.0);
  return (march_frame){j, j->function == ZR_JULIA_CUBE ? 3 : 2,
                       has_estimate(j), gain};
}

/*
 * A lower bound on the distance from an inside point to the outside,
 * from its orbit (all max_iteration radii recorded): every point p'
 * closer than it has |h_i(p')| <= R for i < N, so it is inside too.
 * Perturbations grow at most as orbit says, so b_i, the largest
 * perturbation of h_i that keeps h_i ... h_(N-1) within R, is
 * min(R - |h_i|, allowed_before(A_i, b_(i+1))) with b_(N-1) =
 * R - |h_(N-1)|, and b_0 / lift_gain bounds the distance.
 */
static double inside_bound(const march_frame *f, const orbit *o) {
  double r = f->j->escape, b = INFINITY;
  for (int i = o->n - 1; i >= 0; i--) {
    if (i < o->n - 1)
      b = allowed_before(f->power, o->growth[i], b);
    b = fmin(b, r - o->radius[i]);
    if (!(b > 0.0))
      return 0.0;
  }
  /* Nine tenths of it: a step of the whole bound may land on the
     surface itself (a ray through the centre of the ball that
     max_iteration 1 keeps does), where rounding tells outside from
     inside by chance. */
  return 0.9 * b / f->lift_gain;
}

/*
 * A march point: whether it is inside, and in *dist how far the march
 * may step from it, 0 when no bound or estimate applies.  Inside, the
 * proven bound of inside_bound.  Outside, for a point escaping a
 * polynomial iteration, Hart, Sandin and Kauffman's estimate ("Ray
 * tracing deterministic 3-D fractals", SIGGRAPH 1989) of the distance
 * to the set: |h| ln |h| / (2 |h'|), with |h'| bounded above by the
 * product over the steps of n A_i^(n-1) (orbit), which only shortens
 * the estimate.  Like the manual's, it is not a proven bound in four
 * dimensions, so the march still checks every point it steps to.
 */
/* What march_sample makes of an orbit: k the index orbit_escape
   returned, h its last iterate, o its record (when f->estimate). */
static bool sample_result(const march_frame *f, int k, const double h[4],
                          const orbit *o, double *dist) {
  const struct zr_julia *j = f->j;
  *dist = 0.0;
  if (k == j->max_iteration) {
    if (f->estimate && o->n == k)
      *dist = inside_bound(f, o);
    return true;
  }
  if (!f->estimate)
    return false;
  double n = sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2] + h[3] * h[3]);
  double stretch = f->power == 2
                       ? ldexp(sqrt(o->growth2_product), k)
                       : pow(3.0, k) * o->growth2_product;
  if (n > 1.0 && stretch > 0.0 && isfinite(stretch))
    *dist = n * log(n) / (2.0 * stretch);
  return false;
}

static bool march_sample(const march_frame *f, zr_vec3 p, double *dist,
                         double slack) {
  const struct zr_julia *j = f->j;
  julia_state s;
  orbit o;
  lift(j, p, &s, false);
  int k = orbit_escape(j, s.h, slack, f->estimate ? &o : NULL);
  return sample_result(f, k, s.h, &o, dist);
}

/*
 * Two march samples at once (f->estimate: the iteration a polynomial),
 * their orbits advancing together as in lanes_inside, each recorded as
 * orbit_escape records it (the same operations in its order, stopping
 * at its own escape, its h the last iterate computed), so each result
 * is march_sample's.  The march asks for the sample at its next point
 * and, ahead of need, for the one a step of 1 / precision beyond, where
 * it goes next whenever the first sample's distance is no more than a
 * step (near the surface and in thin parts of the inside).
 */
#define REC_LANE(L, STEP)                                                    \
  do {                                                                       \
    if (!live##L)                                                            \
      break;                                                                 \
    double n2 = h##L[0] * h##L[0] + h##L[1] * h##L[1] +                     \
                h##L[2] * h##L[2] + h##L[3] * h##L[3];                       \
    if (n2 > limit2##L) {                                                    \
      live##L = false;                                                       \
      break;                                                                 \
    }                                                                        \
    double next[4], growth2 = n2;                                            \
    STEP(h##L, next, growth2);                                               \
    if (i < ORBIT_MAX) {                                                     \
      o##L->radius[i] = sqrt(n2);                                            \
      o##L->growth[i] = sqrt(growth2);                                       \
      o##L->n = i + 1;                                                       \
    }                                                                        \
    o##L->growth2_product *= growth2;                                        \
    for (int m = 0; m < 4; m++)                                              \
      h##L[m] = next[m] + c[m];                                              \
    k##L = i + 1;                                                            \
  } while (0)

/* The power steps: next = h^power, growth2 (n2 on entry) the squared
   growth of the derivative (quaternion_orbit's and bicomplex_power's
   arithmetic; for a quaternion it stays n2). */
#define QUATERNION_STEP(h, next, growth2)                                    \
  do {                                                                       \
    double vv = (growth2) - (h)[0] * (h)[0], sc;                             \
    if (power == 2) {                                                        \
      (next)[0] = (h)[0] * (h)[0] - vv;                                      \
      sc = 2.0 * (h)[0];                                                     \
    } else {                                                                 \
      (next)[0] = (h)[0] * ((h)[0] * (h)[0] - 3.0 * vv);                     \
      sc = 3.0 * (h)[0] * (h)[0] - vv;                                       \
    }                                                                        \
    for (int m = 1; m < 4; m++)                                              \
      (next)[m] = sc * (h)[m];                                               \
  } while (0)

#define BICOMPLEX_STEP(h, next, growth2)                                     \
  bicomplex_power((h), power, (next), &(growth2))

static inline __attribute__((always_inline)) void
orbits_recorded(const struct zr_julia *j, bool quaternion, int power,
                double *ha, double slacka, orbit *oa, int *ka_out,
                double *hb, double slackb, orbit *ob, int *kb_out) {
  double limit2a = j->escape * j->escape * slacka;
  double limit2b = j->escape * j->escape * slackb;
  const double *c = j->c;
  oa->n = ob->n = 0;
  oa->growth2_product = ob->growth2_product = 1.0;
  bool livea = true, liveb = true;
  int ka = 0, kb = 0;
  for (int i = 0; i < j->max_iteration && (livea || liveb); i++) {
    if (quaternion) {
      REC_LANE(a, QUATERNION_STEP);
      REC_LANE(b, QUATERNION_STEP);
    } else {
      REC_LANE(a, BICOMPLEX_STEP);
      REC_LANE(b, BICOMPLEX_STEP);
    }
  }
  *ka_out = ka;
  *kb_out = kb;
}

static void march_samples2(const march_frame *f, zr_vec3 pa, double slacka,
                           bool *ina, double *dista, zr_vec3 pb,
                           double slackb, bool *inb, double *distb) {
  const struct zr_julia *j = f->j;
  julia_state sa, sb;
  orbit oa, ob;
  int ka, kb;
  lift(j, pa, &sa, false);
  lift(j, pb, &sb, false);
  bool quaternion = j->algebra == ZR_JULIA_QUATERNION;
  if (f->power == 2) {
    if (quaternion)
      orbits_recorded(j, true, 2, sa.h, slacka, &oa, &ka, sb.h, slackb, &ob,
                      &kb);
    else
      orbits_recorded(j, false, 2, sa.h, slacka, &oa, &ka, sb.h, slackb, &ob,
                      &kb);
  } else if (quaternion) {
    orbits_recorded(j, true, 3, sa.h, slacka, &oa, &ka, sb.h, slackb, &ob,
                    &kb);
  } else {
    orbits_recorded(j, false, 3, sa.h, slacka, &oa, &ka, sb.h, slackb, &ob,
                    &kb);
  }
  *ina = sample_result(f, ka, sa.h, &oa, dista);
  *inb = sample_result(f, kb, sb.h, &ob, distb);
}

bool zr__julia_inside(const zr_object *o, zr_vec3 p) {
  return point_inside(o->u.julia.data, p);
}

/* The gradient of |h_N|^2 by (x, y, z): outward. */
static zr_vec3 julia_normal(const struct zr_julia *j, zr_vec3 p) {
  julia_state s;
  lift(j, p, &s, true);
  iterate_with_derivatives(j, &s);
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

/*
 * The march along a ray (see the top of the file): the first max_found
 * crossings in (tmin, tmax), with their normals when normal is not
 * NULL.  The march's points do not depend on tmin, tmax or max_found
 * (it runs from the bounding sphere's entry, and its last point may lie
 * beyond tmax), so a crossing found by one query is found again at the
 * same t by another: the tracer asks for the nearest crossing without
 * its normal, then for it alone again with the normal.  With lanes
 * false it takes every sample and bisection point one orbit at a time
 * (zr__julia_crossings_plain, the tests' reference).
 */
static int march(const zr_object *o, zr_vec3 org, zr_vec3 dir, double tmin,
                 double tmax, int max_found, double t[4], zr_vec3 normal[4],
                 bool lanes) {
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
  double s_stop = fmin(s_far, tmax * len);
  if (!(s < s_stop))
    return 0;
  march_frame f = frame_of(j);
  double dist;
  bool in = march_sample(&f, zr_v3_madd(org, d, s), &dist, ENTRY_SLACK);
  /* The sample taken ahead of need (march_samples2), at s_ahead. */
  bool ahead = false, in_ahead = false;
  double s_ahead = 0.0, dist_ahead = 0.0;
  int found = 0;
  while (s < s_stop && found < max_found) {
    double ds = fmax(dist, step);
    double s_next = fmin(s + ds, s_far), dist_next;
    double slack = s_next == s_far ? ENTRY_SLACK : 1.0;
    bool in_next;
    if (ahead && s_ahead == s_next) {
      in_next = in_ahead;
      dist_next = dist_ahead;
      ahead = false;
    } else if (lanes && f.estimate && s_next < s_stop) {
      s_ahead = fmin(s_next + step, s_far);
      march_samples2(&f, zr_v3_madd(org, d, s_next), slack, &in_next,
                     &dist_next, zr_v3_madd(org, d, s_ahead),
                     s_ahead == s_far ? ENTRY_SLACK : 1.0, &in_ahead,
                     &dist_ahead);
      ahead = true;
    } else {
      in_next = march_sample(&f, zr_v3_madd(org, d, s_next), &dist_next,
                             slack);
    }
    if (in_next != in) {
      /* Bisect [s, s_next] down to the tolerance: two levels at a
         time where points_inside applies, the same midpoints and
         answers as one at a time. */
      double a = s, e = s_next;
      bool lockstep = lanes && lockstep_inside(j);
      while (e - a > tol) {
        double m = 0.5 * (a + e);
        if (!lockstep) {
          if (point_inside(j, zr_v3_madd(org, d, m)) == in)
            a = m;
          else
            e = m;
          continue;
        }
        double below = 0.5 * (a + m), above = 0.5 * (m + e);
        zr_vec3 p[LANES] = {zr_v3_madd(org, d, m), zr_v3_madd(org, d, below),
                            zr_v3_madd(org, d, above)};
        bool pin[LANES];
        zr__julia_points_inside(j, p, pin);
        bool upper = pin[0] == in;
        if (upper)
          a = m;
        else
          e = m;
        if (!(e - a > tol))
          break;
        /* The next midpoint, 0.5 * (a + e), is above or below. */
        if (pin[upper ? 2 : 1] == in)
          a = upper ? above : below;
        else
          e = upper ? above : below;
      }
      /* The crossing is the bracket's inside end: its normal then
         comes from all max_iteration steps. */
      double sh = in ? a : e, th = sh / len;
      if (th > tmin && th < tmax) {
        t[found] = th;
        if (normal)
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

static int julia_march(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                       double tmin, double tmax, int max_found,
                       double t[4], zr_vec3 normal[4]) {
  return march(o, org, dir, tmin, tmax, max_found, t, normal, true);
}

int zr__julia_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                        double tmin, double tmax, double t[4],
                        zr_vec3 normal[4]) {
  return julia_march(o, org, dir, tmin, tmax, 4, t, normal);
}

int zr__julia_crossings_plain(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                              double tmin, double tmax, double t[4],
                              zr_vec3 normal[4]) {
  return march(o, org, dir, tmin, tmax, 4, t, normal, false);
}

static bool julia_box(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  zr__julia_bounds(o, lo, hi);
  return true;
}

/* The operations the tracer calls through (lib/trace/shape.h). */
const zr_shape_ops zr__shape_julia = {
    .name = "a julia_fractal",
    .search = zr__julia_crossings,
    .search_upto = julia_march,
    .inside = zr__julia_inside,
    .bounds = julia_box,
};
