/*
 * obj_superellipsoid.c - the superquadric ellipsoid (POV-Ray 3.7
 * reference, "Superquadric Ellipsoid"):
 *   F(x, y, z) = (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1
 * in the box [-1, 1]^3, inside where F < 1.  e = n = 1 is the sphere,
 * small values give rounded boxes and cylinders, values above 2 pinched
 * stars.
 *
 * The ray equation is not a polynomial, so the crossings are searched.
 * The search uses F^(n/2) - 1 instead of F - 1: it has the same zero set
 * but grows linearly with the distance from the centre (F^(n/2) is
 * homogeneous of degree one, a norm when e, n <= 2), so its values along
 * a ray are well scaled however small e and n are, where F itself jumps
 * from 0 to huge within a hair.  When e, n <= 2 (the shape is convex,
 * and F^(n/2) a norm) the value along the ray is a convex function,
 * and Newton's steps from each end of the ray's span in the box walk to
 * the two crossings without passing them (convex_walk): a handful of
 * values a crossing, where the sampled search below takes fifty or more
 * (superel1.pov renders in 0.12 CPU s instead of 0.32).  Otherwise the
 * ray is clipped to the box and cut where it crosses the planes x = 0, y = 0, z = 0 and x = +-y, on which
 * the shape's pieces meet; between those cuts each piece is sampled at
 * equal steps, a change of sign is refined (false position), and a sample
 * that is a local minimum is followed down by a golden-section search, so
 * a ray that clips a corner between two samples is not lost.  The normal
 * is the gradient of F, computed through logarithms so that the large
 * powers of small values neither overflow nor underflow on their way to
 * a finite product.
 */
#include "trace/obj_shapes.h"

#include <math.h>

#include "trace/shape.h"

/* The steps each piece of the ray is sampled in. */
enum { SAMPLES = 8 };

/* x^k for x in [0, 1]: by repeated squaring when k is a whole number
   up to 4096 (rounded boxes have k = 2 / e of 20 to 400, where pow's
   general path costs most of a crossing search), by pow otherwise. */
static double power(double x, double k) {
  if (k == 1.0)
    return x;
  if (k >= 2.0 && k <= 4096.0 && k == floor(k)) {
    unsigned u = (unsigned)k;
    double r = 1.0, b = x;
    while (u) {
      if (u & 1u)
        r *= b;
      u >>= 1;
      if (u)
        b *= b;
    }
    return r;
  }
  return pow(x, k);
}

double zr__superellipsoid_value(double e, double n, zr_vec3 p) {
  double ax = fabs(p.x), ay = fabs(p.y), az = fabs(p.z);
  /* Factor out the largest coordinate so no power overflows: F^(n/2)
     is homogeneous of degree one. */
  double m = fmax(ax, fmax(ay, az));
  if (m == 0.0)
    return -1.0;
  ax /= m;
  ay /= m;
  az /= m;
  double xy = power(ax, 2.0 / e) + power(ay, 2.0 / e);
  double f = power(xy, e / n) + power(az, 2.0 / n);
  return m * power(f, n / 2.0) - 1.0;
}

/* The same value as zr__superellipsoid_value (the same operations, so
   the same bits) and its gradient, from the powers the value computes
   anyway: for the norm N = F^(n/2), with X = |x|^(2/e), A = X + Y,
   B = A^(e/n), C = |z|^(2/n), dN/dx = N/F B (X/A) / |x| sign(x) and
   dN/dz = N/F C / |z| sign(z) (the chain rule through F's three powers;
   N is homogeneous of degree one, so its gradient is the same at p and
   at p / m).  A zero coordinate gets slope 0, which is the derivative
   when its power is above 1 and, where e or n is 2 and the shape has an
   edge, a subgradient. */
static double value_and_gradient(double e, double n, zr_vec3 p,
                                 zr_vec3 *g) {
  double ax = fabs(p.x), ay = fabs(p.y), az = fabs(p.z);
  double m = fmax(ax, fmax(ay, az));
  if (m == 0.0) {
    *g = zr_v3(0, 0, 0);
    return -1.0;
  }
  ax /= m;
  ay /= m;
  az /= m;
  double X = power(ax, 2.0 / e), Y = power(ay, 2.0 / e), A = X + Y;
  double B = power(A, e / n), C = power(az, 2.0 / n), F = B + C;
  double Fn = power(F, n / 2.0);
  /* F >= 1: the largest scaled coordinate is 1. */
  double k = Fn / F;
  double gx = ax > 0.0 ? k * B * (X / A) / ax : 0.0;
  double gy = ay > 0.0 ? k * B * (Y / A) / ay : 0.0;
  double gz = az > 0.0 ? k * C / az : 0.0;
  *g = zr_v3(copysign(gx, p.x), copysign(gy, p.y), copysign(gz, p.z));
  return m * Fn - 1.0;
}

bool zr__superellipsoid_inside(const zr_object *o, zr_vec3 p) {
  return zr__superellipsoid_value(o->u.superellipsoid.e,
                                  o->u.superellipsoid.n, p) < 0.0;
}

/* log |v|, with zero taken as a tiny number so the products below
   stay finite. */
static double log_of(double v) { return log(fmax(fabs(v), 1e-300)); }

static zr_vec3 gradient(double e, double n, zr_vec3 p) {
  double a = 2.0 / e, b = e / n, c = 2.0 / n;
  double lx = log_of(p.x), ly = log_of(p.y), lz = log_of(p.z);
  double lxy = log(exp(a * lx) + exp(a * ly));
  if (!isfinite(lxy))
    lxy = -690.0;
  /* dF/dx = b A^(b-1) a |x|^(a-1) sign(x), A = |x|^a + |y|^a. */
  double gx = a * b * exp((b - 1.0) * lxy + (a - 1.0) * lx);
  double gy = a * b * exp((b - 1.0) * lxy + (a - 1.0) * ly);
  double gz = c * exp((c - 1.0) * lz);
  return zr_v3(copysign(gx, p.x), copysign(gy, p.y), copysign(gz, p.z));
}

typedef struct search {
  double e, n;
  zr_vec3 org, dir; /* dir of unit length */
} search;

typedef struct root_list {
  int n;
  double s[8];
} root_list;

static void add_root(root_list *r, double s) {
  if (r->n < 8)
    r->s[r->n++] = s;
}

static double value_at(const search *s, double x) {
  return zr__superellipsoid_value(s->e, s->n, zr_v3_madd(s->org, s->dir, x));
}

/* The value at org + x dir and its slope along dir. */
static double value_slope_at(const search *s, double x, double *slope) {
  zr_vec3 g;
  double v = value_and_gradient(s->e, s->n, zr_v3_madd(s->org, s->dir, x),
                                &g);
  *slope = zr_v3_dot(g, s->dir);
  return v;
}

/*
 * The first crossing met walking from `from` towards `to` (either order)
 * when the shape is convex (e, n <= 2: F^(n/2) is then a norm, made of
 * the 2/e-norm of (x, y) and the 2/n-norm of that and z, so the value
 * along a ray is a convex function).  Both ends are outside (the box
 * holds the unit ball of a norm that is at least max(|x|, |y|, |z|), and
 * the ends lie on a slightly larger box).  A convex function lies above
 * each of its tangents, so Newton's step from outside never passes the
 * first root: the steps walk towards it from one side, quadratically
 * once near, and a slope that turns upward, or a step beyond `to`,
 * proves there is none.  Returns false for a miss.
 */
static bool convex_walk(const search *s, double from, double to,
                        double *root) {
  double dir = to > from ? 1.0 : -1.0, x = from, slope;
  double f = value_slope_at(s, x, &slope);
  for (int i = 0; i < 100; i++) {
    if (f <= 0.0) {
      *root = x;
      return true;
    }
    double down = slope * dir; /* the slope in the walking direction */
    if (!(down < 0.0))
      return false;
    double step = -f / down, next = x + dir * step;
    if (!((next - to) * dir < 0.0))
      return false;
    x = next;
    /* A step at rounding's scale: x is the root to 1e-15. */
    if (step <= 1e-15 * (1.0 + fabs(x))) {
      *root = x;
      return true;
    }
    f = value_slope_at(s, x, &slope);
  }
  return false;
}

/* The crossings of a convex superellipsoid in the span [s0, s1]: none,
   or the one walked to from each end (a ray grazing the surface can
   meet it from one side only within rounding: a tangent counts twice). */
static void convex_search(const search *s, double s0, double s1,
                          root_list *r) {
  double first, last;
  if (!convex_walk(s, s0, s1, &first))
    return;
  if (!convex_walk(s, s1, first, &last) || last < first)
    last = first;
  add_root(r, first);
  add_root(r, last);
}


/* The root between a and b, whose values fa and fb have opposite signs:
   false position with the Illinois rule (the end that stays twice in a
   row has its value halved), which shrinks the bracket to the same
   1e-15 as bisection in a fraction of the steps, F^(n/2) being close
   to linear along a ray near the surface; a step that lands outside
   the bracket or stalls falls back on the midpoint. */
static double bisect(const search *s, double a, double b, double fa,
                     double fb) {
  int kept = 0; /* -1: a stayed last time, 1: b stayed */
  for (int i = 0; i < 200 && b - a > 1e-15 * (1.0 + fabs(a)); i++) {
    double m = (i % 4 == 3) ? 0.5 * (a + b)
                            : (a * fb - b * fa) / (fb - fa);
    if (!(m > a && m < b))
      m = 0.5 * (a + b);
    double fm = value_at(s, m);
    if (fm == 0.0)
      return m;
    if ((fm < 0.0) == (fa < 0.0)) {
      a = m;
      fa = fm;
      if (kept == 1)
        fb *= 0.5;
      kept = 1;
    } else {
      b = m;
      fb = fm;
      if (kept == -1)
        fa *= 0.5;
      kept = -1;
    }
  }
  return 0.5 * (a + b);
}

/* The smallest value in [a, b] by golden-section search, at *where. */
static double dip(const search *s, double a, double b, double *where) {
  const double g = 0.6180339887498949;
  double x1 = b - g * (b - a), x2 = a + g * (b - a);
  double f1 = value_at(s, x1), f2 = value_at(s, x2);
  /* Any point below zero splits the dip into two crossings: stop at
     the first. */
  for (int i = 0; i < 60 && b - a > 1e-13 && f1 >= 0.0 && f2 >= 0.0;
       i++) {
    if (f1 < f2) {
      b = x2;
      x2 = x1;
      f2 = f1;
      x1 = b - g * (b - a);
      f1 = value_at(s, x1);
    } else {
      a = x1;
      x1 = x2;
      f1 = f2;
      x2 = a + g * (b - a);
      f2 = value_at(s, x2);
    }
  }
  *where = f1 < f2 ? x1 : x2;
  return fmin(f1, f2);
}

/* The roots in one piece [a, b] of the ray. */
static void search_piece(const search *s, double a, double b,
                         root_list *r) {
  double x[SAMPLES + 1], f[SAMPLES + 1];
  for (int i = 0; i <= SAMPLES; i++) {
    x[i] = a + (b - a) * i / SAMPLES;
    f[i] = value_at(s, x[i]);
  }
  for (int i = 0; i < SAMPLES; i++) {
    if ((f[i] < 0.0) != (f[i + 1] < 0.0)) {
      add_root(r, bisect(s, x[i], x[i + 1], f[i], f[i + 1]));
      continue;
    }
    if (f[i] < 0.0)
      continue;
    /* Both ends outside: a dip below zero needs the values to fall
       into the step from the left and rise out of it to the right, and
       it cannot happen when the ends are higher than the steepest slope
       the function has (under 8 for these shapes near the surface) lets
       it fall within half a step. */
    bool falls_in = i == 0 || f[i - 1] >= f[i];
    bool rises_out = i + 1 == SAMPLES || f[i + 2] >= f[i + 1];
    if (!(falls_in && rises_out) ||
        fmin(f[i], f[i + 1]) > 8.0 * (x[i + 1] - x[i]))
      continue;
    double lo = x[i], hi = x[i + 1];
    double at, fmin_v = dip(s, lo, hi, &at);
    if (fmin_v < 0.0) {
      add_root(r, bisect(s, x[i], at, f[i], fmin_v));
      add_root(r, bisect(s, at, x[i + 1], fmin_v, f[i + 1]));
    }
  }
}

static void sort(double *v, int n) {
  for (int i = 1; i < n; i++)
    for (int j = i; j > 0 && v[j - 1] > v[j]; j--) {
      double tt = v[j];
      v[j] = v[j - 1];
      v[j - 1] = tt;
    }
}

/* The roots (distances along the unit direction) as crossings of the
   caller's ray in (tmin, tmax), ascending, with their normals. */
static int finish(const search *s, root_list *r, double len, double tmin,
                  double tmax, double t[4], zr_vec3 normal[4]) {
  sort(r->s, r->n);
  int n = 0;
  for (int i = 0; i < r->n && n < ZR_SHAPE_MAX_CROSSINGS; i++) {
    zr_vec3 p = zr_v3_madd(s->org, s->dir, r->s[i]);
    t[n] = r->s[i] / len;
    if (!(t[n] > tmin && t[n] < tmax))
      continue;
    normal[n] = gradient(s->e, s->n, p);
    n++;
  }
  return n;
}

int zr__superellipsoid_crossings(const zr_object *o, zr_vec3 org,
                                 zr_vec3 dir, double tmin, double tmax,
                                 double t[4], zr_vec3 normal[4]) {
  double len = zr_v3_len(dir);
  if (!(len > 0.0) || !isfinite(len))
    return 0;
  search s = {o->u.superellipsoid.e, o->u.superellipsoid.n, org,
              zr_v3_scale(dir, 1.0 / len)};
  double pad = 1.0 + 1e-9, s0, s1;
  if (!zr__ray_box_span(zr_v3(-pad, -pad, -pad), zr_v3(pad, pad, pad),
                        org, s.dir, &s0, &s1))
    return 0;
  /* The whole span in the box is searched whatever the interval, so a
     crossing's t does not depend on it (the tracer finds a crossing
     again by its exact t over a narrower interval). */
  if (!(fmax(s0, tmin * len) < fmin(s1, tmax * len)))
    return 0;
  root_list r = {0, {0}};
  if (s.e <= 2.0 && s.n <= 2.0) {
    convex_search(&s, s0, s1, &r);
    return finish(&s, &r, len, tmin, tmax, t, normal);
  }
  /* The cuts: where the ray crosses x = 0, y = 0, z = 0, x = y, x = -y. */
  double cut[7];
  int n_cut = 0;
  cut[n_cut++] = s0;
  double num[5] = {org.x, org.y, org.z, org.x - org.y, org.x + org.y};
  double den[5] = {s.dir.x, s.dir.y, s.dir.z, s.dir.x - s.dir.y,
                   s.dir.x + s.dir.y};
  for (int i = 0; i < 5; i++) {
    if (den[i] == 0.0)
      continue;
    double c = -num[i] / den[i];
    if (c > s0 && c < s1)
      cut[n_cut++] = c;
  }
  sort(cut + 1, n_cut - 1);
  cut[n_cut++] = s1;
  for (int i = 0; i + 1 < n_cut; i++)
    if (cut[i + 1] > cut[i])
      search_piece(&s, cut[i], cut[i + 1], &r);
  return finish(&s, &r, len, tmin, tmax, t, normal);
}

/* The unit cube holds it for any exponents. */
static bool superellipsoid_box(const zr_object *o, zr_vec3 *lo,
                               zr_vec3 *hi) {
  (void)o;
  *lo = zr_v3(-1, -1, -1);
  *hi = zr_v3(1, 1, 1);
  return true;
}

/* The operations the tracer calls through (lib/trace/shape.h). */
const zr_shape_ops zr__shape_superellipsoid = {
    .name = "a superellipsoid",
    .search = zr__superellipsoid_crossings,
    .inside = zr__superellipsoid_inside,
    .bounds = superellipsoid_box,
};
