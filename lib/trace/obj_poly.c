/*
 * obj_poly.c - POV-Ray's polynomial surfaces poly, cubic and quartic
 * (reference manual r3_4, "Poly, Cubic and Quartic"): the points where
 * a polynomial P(x,y,z) of total degree n is zero, inside where it is
 * negative.  The manual lists the coefficients term by term with x's
 * power falling, then y's, then z's (for n = 2: x^2, xy, xz, x, y^2, yz,
 * y, z^2, z, 1), so a term's position follows from walking those powers
 * in that order, which term_walk() does.
 *
 * Along a ray o + t d each factor x^i is the power of a linear
 * polynomial in t, expanded by the binomial theorem; the products give
 * P(t), a polynomial of degree n whose real roots are found by
 * lib/trace/roots.c.  That solver needs a finite interval: a poly is
 * unbounded, so the interval is cut to the smaller of Cauchy's and
 * Fujiwara's bounds on the roots' size, outside which P(t) has no root.
 * Leading
 * coefficients that vanish against the others (rays along an asymptotic
 * direction) lower the degree first.  The normal is P's gradient.
 * Expanding P(t) costs digits, so roots nearer the ray's origin than a
 * millionth of its scale are dropped (see zr__poly_crossings).
 */
#include "trace/obj_poly.h"

#include <math.h>

#include "trace/shape.h"

#include "trace/roots.h"

/* The powers of the linear polynomial a + b t: pw[i][m] is the
   coefficient of t^m in (a + b t)^i, each row the one before times
   (a + b t) (binomial(i, m) a^(i-m) b^m; with pow() per entry, 2(n+1)^2
   calls a ray and axis, pow was half of pawns.pov's render time). */
static void linear_powers(double a, double b, int n,
                          double pw[ZR_POLY_MAX_DEGREE + 1]
                                   [ZR_POLY_MAX_DEGREE + 1]) {
  for (int m = 0; m <= n; m++)
    pw[0][m] = m == 0 ? 1.0 : 0.0;
  for (int i = 1; i <= n; i++) {
    pw[i][0] = a * pw[i - 1][0];
    for (int m = 1; m <= n; m++)
      pw[i][m] = m <= i ? a * pw[i - 1][m] + b * pw[i - 1][m - 1] : 0.0;
  }
}

/* Both Cauchy's bound, 1 + max |c_m / c_deg|, and Fujiwara's,
   2 max |c_m / c_deg|^(1 / (deg - m)) (with c_0 halved), hold every
   root; Fujiwara's is far smaller when the leading coefficient is
   small (a ray nearly along an asymptotic direction, or a quartic's
   x^4 for a ray almost across x), where Cauchy's put the search's ends
   at 1e9 for roots near 1.  c[deg] is not zero. */
static double root_bound(const double *c, int deg) {
  double cauchy = 0.0, fujiwara = 0.0;
  for (int m = 0; m < deg; m++) {
    double r = fabs(c[m] / c[deg]);
    cauchy = fmax(cauchy, r);
    if (m == 0)
      r *= 0.5;
    fujiwara = fmax(fujiwara, deg - m == 1   ? r
                              : deg - m == 2 ? sqrt(r)
                                             : pow(r, 1.0 / (deg - m)));
  }
  return fmin(cauchy + 1.0, 2.0 * fujiwara);
}

/*
 * The degree P(t) is solved at: leading coefficients that vanish
 * against the others (1e-12 of the largest) are dropped, but only while
 * they stay negligible (1e-9 of the largest term) out to the bound on
 * the roots of what is left.  A ray nearly across a quartic's x (the
 * Piriform of objects/quartic/teardrop.pov, seen at eye height) has an
 * x^4 term of 1e-11 beside terms of 16: dropped, the cubic left had a
 * root at 1e7 that the quartic has not, and a line of false hits ran
 * across the picture.  0 when P is constant.
 */
static int lowered_degree(const double *c, int n) {
  double big = 0.0;
  for (int m = 0; m <= n; m++)
    big = fmax(big, fabs(c[m]));
  int deg = n;
  while (deg > 0 && c[deg] == 0.0)
    deg--;
  while (deg > 0 && !(fabs(c[deg]) > 1e-12 * big)) {
    int r = deg - 1;
    while (r > 0 && c[r] == 0.0)
      r--;
    if (r == 0)
      return 0;
    double b = root_bound(c, r), head = 0.0, rest = 0.0, bm = 1.0;
    for (int m = 0; m <= deg; m++, bm *= b) {
      if (m <= r)
        rest = fmax(rest, fabs(c[m]) * bm);
      else
        head = fmax(head, fabs(c[m]) * bm);
    }
    if (head > 1e-9 * rest)
      break;
    deg = r;
  }
  return deg;
}

int zr__poly_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                       double tmin, double tmax, double t[4],
                       zr_vec3 normal[4]) {
  int n = o->u.poly.order;
  if (n < 1 || n > ZR_POLY_MAX_DEGREE)
    return 0;
  double px[ZR_POLY_MAX_DEGREE + 1][ZR_POLY_MAX_DEGREE + 1];
  double py[ZR_POLY_MAX_DEGREE + 1][ZR_POLY_MAX_DEGREE + 1];
  double pz[ZR_POLY_MAX_DEGREE + 1][ZR_POLY_MAX_DEGREE + 1];
  linear_powers(org.x, dir.x, n, px);
  linear_powers(org.y, dir.y, n, py);
  linear_powers(org.z, dir.z, n, pz);
  double c[ZR_POLY_MAX_DEGREE + 1] = {0};
  const double *a = o->u.poly.coef;
  int term = 0;
  for (int i = n; i >= 0; i--)
    for (int j = n - i; j >= 0; j--)
      for (int k = n - i - j; k >= 0; k--, term++) {
        if (a[term] == 0.0)
          continue;
        /* (x^i)(y^j) first, then times z^k, into c. */
        double xy[ZR_POLY_MAX_DEGREE + 1] = {0};
        for (int u = 0; u <= i; u++)
          for (int v = 0; v <= j; v++)
            xy[u + v] += px[i][u] * py[j][v];
        for (int u = 0; u <= i + j; u++)
          for (int w = 0; w <= k; w++)
            c[u + w] += a[term] * xy[u] * pz[k][w];
      }
  int deg = lowered_degree(c, n);
  if (deg == 0)
    return 0;
  double bound = root_bound(c, deg);
  /* A ray leaving the surface starts where the expanded coefficients
     put a spurious root within their rounding of t = 0, so roots closer
     than a millionth of the origin's scale are not crossings (our own
     margin: far above the rounding of the coefficients, far below any
     feature a scene of 1e-3 to 1e5 units draws). */
  double near = 1e-6 * (1.0 + zr_v3_len(org)) / zr_v3_len(dir);
  double lo = fmax(fmax(tmin, near), -bound), hi = fmin(tmax, bound);
  if (!(lo < hi))
    return 0;
  double roots[ZR_POLY_MAX_DEGREE];
  int k = zr__poly_roots(c, deg, lo, hi, roots);
  int out = 0;
  for (int r = 0; r < k && out < 4; r++) {
    t[out] = roots[r];
    normal[out] = zr__poly_gradient(o, zr_v3_madd(org, dir, roots[r]));
    out++;
  }
  return out;
}

/* x^e, with 0^0 = 1. */
static double ipow(double x, int e) {
  double r = 1.0;
  for (int i = 0; i < e; i++)
    r *= x;
  return r;
}

static double value(const zr_object *o, zr_vec3 p) {
  int n = o->u.poly.order;
  const double *a = o->u.poly.coef;
  double v = 0.0;
  int term = 0;
  for (int i = n; i >= 0; i--)
    for (int j = n - i; j >= 0; j--)
      for (int k = n - i - j; k >= 0; k--, term++)
        if (a[term] != 0.0)
          v += a[term] * ipow(p.x, i) * ipow(p.y, j) * ipow(p.z, k);
  return v;
}

zr_vec3 zr__poly_gradient(const zr_object *o, zr_vec3 p) {
  int n = o->u.poly.order;
  const double *a = o->u.poly.coef;
  double gx = 0.0, gy = 0.0, gz = 0.0;
  int term = 0;
  for (int i = n; i >= 0; i--)
    for (int j = n - i; j >= 0; j--)
      for (int k = n - i - j; k >= 0; k--, term++) {
        if (a[term] == 0.0)
          continue;
        double xi = ipow(p.x, i), yj = ipow(p.y, j), zk = ipow(p.z, k);
        if (i > 0)
          gx += a[term] * i * ipow(p.x, i - 1) * yj * zk;
        if (j > 0)
          gy += a[term] * j * xi * ipow(p.y, j - 1) * zk;
        if (k > 0)
          gz += a[term] * k * xi * yj * ipow(p.z, k - 1);
      }
  return zr_v3(gx, gy, gz);
}

bool zr__poly_inside(const zr_object *o, zr_vec3 p) {
  return value(o, p) < 0.0;
}

/* No box: a poly is infinite unless clipped or intersected. */
/* The operations the tracer calls through (lib/trace/shape.h). */
const zr_shape_ops zr__shape_poly = {
    .name = "a poly",
    .search = zr__poly_crossings,
    .inside = zr__poly_inside,
};
