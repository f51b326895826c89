/*
 * obj_isosurface.c - the isosurface (POV-Ray 3.7 reference, "Isosurface",
 * and the tutorial "Isosurface Object"): the surface where a user
 * function f(x, y, z) equals the threshold, inside its container (a box
 * or a sphere); the solid is where f is below the threshold.  Where the
 * solid meets the container, the container's own surface closes it,
 * unless the isosurface is open.
 *
 * The search follows the manual's description: a recursive subdivision
 * of the stretch of the ray inside the container, trusting that f
 * changes by at most max_gradient per unit of length.  A stretch whose
 * ends have the same sign and whose values add up to more than
 * max_gradient times its length cannot reach the threshold, so it is
 * dropped; the others are halved until they are shorter than accuracy.
 * A short stretch whose ends differ in sign holds a crossing, which is
 * then refined (Illinois' variant of regula falsi) far below accuracy,
 * so that a secondary ray leaving the surface by the tracer's offset
 * does not find it again.  A function steeper than max_gradient can
 * lose crossings, as in POV-Ray ("holes").
 *
 * Where f is not a number (pow of a negative base, sqrt or log of a
 * negative value), povray 3.7 finds no surface in a stretch with a NaN
 * at either end and does not halve it further: a solid NaN outside the
 * unit sphere and negative inside it is not drawn at all, one inside
 * for z < 0.5 and NaN behind shows nothing (no crossing at the NaN's
 * edge), a sphere behind a slab of NaN still shows (the ray is not
 * given up), and one whose NaN slab cuts its middle vanishes
 * (tests/isosurface_nan.pov, povray's pixels in
 * tests/test_isosurface_nan.sh).  Halving such stretches down to the
 * accuracy, as before, drew what povray does not and cost 20,000
 * evaluations a ray (corpus sep05.pov: 10x povray's time).
 *
 * The subdivision always starts from the container's entry (or the ray
 * origin, t = 0, when that is inside), never from tmin, so the same ray
 * finds a crossing at the same t however narrow the interval asked
 * about: the tracer asks again beyond a crossing it has (CSG, shadows).
 * Like POV-Ray, only the first max_trace crossings along a ray are
 * reported (default 1); all_intersections reports every one.
 *
 * The normal is the gradient of f by forward differences; the
 * container's faces have their own normals.  The function is evaluated
 * by lib/sdl/function.c's machine, which never allocates and keeps no
 * state, so any number of threads trace the same isosurface.
 */
#include "trace/obj_isosurface.h"

#include <float.h>
#include <math.h>

#include "trace/shape.h"

#include "fn/fn.h"
#include "trace/obj_shapes.h"

/* The subdivision's stack: halving a stretch 100 times reaches the
   rounding of t for any container. */
enum { MAX_DEPTH = 100 };

double zr__isosurface_value(const zr_object *o, zr_vec3 p) {
  double args[3] = {p.x, p.y, p.z};
  return zr__fn_eval(o->u.isosurface.fn, args) - o->u.isosurface.threshold;
}

void zr__isosurface_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  if (o->u.isosurface.sphere) {
    double r = o->u.isosurface.radius;
    *lo = zr_v3_sub(o->u.isosurface.centre, zr_v3(r, r, r));
    *hi = zr_v3_add(o->u.isosurface.centre, zr_v3(r, r, r));
  } else {
    *lo = o->u.isosurface.lo;
    *hi = o->u.isosurface.hi;
  }
}

static bool in_container(const zr_object *o, zr_vec3 p) {
  if (o->u.isosurface.sphere) {
    zr_vec3 d = zr_v3_sub(p, o->u.isosurface.centre);
    return zr_v3_dot(d, d) <= o->u.isosurface.radius * o->u.isosurface.radius;
  }
  zr_vec3 lo = o->u.isosurface.lo, hi = o->u.isosurface.hi;
  return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y &&
         p.z >= lo.z && p.z <= hi.z;
}

bool zr__isosurface_inside(const zr_object *o, zr_vec3 p) {
  return in_container(o, p) && zr__isosurface_value(o, p) < 0.0;
}

/* The container's span of the line org + t dir, false when it misses. */
static bool container_span(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                           double *t0, double *t1) {
  if (!o->u.isosurface.sphere)
    return zr__ray_box_span(o->u.isosurface.lo, o->u.isosurface.hi, org,
                            dir, t0, t1);
  zr_vec3 oc = zr_v3_sub(org, o->u.isosurface.centre);
  double r = o->u.isosurface.radius;
  double a = zr_v3_dot(dir, dir), b = 2.0 * zr_v3_dot(dir, oc);
  double c = zr_v3_dot(oc, oc) - r * r;
  double disc = b * b - 4.0 * a * c;
  if (!(a > 0.0) || !(disc > 0.0))
    return false;
  double q = -0.5 * (b + copysign(sqrt(disc), b));
  double r0 = q / a, r1 = q != 0.0 ? c / q : r0;
  *t0 = fmin(r0, r1);
  *t1 = fmax(r0, r1);
  return true;
}

/* The container's outward normal at p (on its surface). */
static zr_vec3 container_normal(const zr_object *o, zr_vec3 p) {
  if (o->u.isosurface.sphere)
    return zr_v3_sub(p, o->u.isosurface.centre);
  /* The face p is nearest to, relative to the box's size. */
  zr_vec3 lo = o->u.isosurface.lo, hi = o->u.isosurface.hi;
  double best = INFINITY;
  zr_vec3 n = zr_v3(0, 1, 0);
  for (int axis = 0; axis < 3; axis++) {
    double l = zr_v3_get(lo, axis), h = zr_v3_get(hi, axis);
    double v = zr_v3_get(p, axis), size = fmax(h - l, DBL_MIN);
    double dl = fabs(v - l) / size, dh = fabs(h - v) / size;
    double e[3] = {0, 0, 0};
    if (dl < best) {
      best = dl;
      e[axis] = -1.0;
      n = zr_v3(e[0], e[1], e[2]);
      e[axis] = 0.0;
    }
    if (dh < best) {
      best = dh;
      e[axis] = 1.0;
      n = zr_v3(e[0], e[1], e[2]);
    }
  }
  return n;
}

/* The gradient of f at p by forward differences, a step of the accuracy
   (at least a relative hair of p's size), as povray 3.7's normals are:
   bench/conform/iso_normal_probe.sh traces y + 1000 x^2 + 2000 z^2 and
   y + x + 1000 y^2 with trace() and reads the normal's tilts as C h
   (and 1 + C (2 y + h)) for h the accuracy (0.01, 0.001, 0.0001), to
   1e-8.  Where f curves fast within the step (isocacti.pov's ridges
   near the axis) the normal follows the curve, not the slope. */
static zr_vec3 gradient(const zr_object *o, zr_vec3 p) {
  double m = fmax(fabs(p.x), fmax(fabs(p.y), fabs(p.z)));
  double h = fmax(o->u.isosurface.accuracy, 1e-9 * fmax(1.0, m));
  double f0 = zr__isosurface_value(o, p);
  double g[3];
  for (int axis = 0; axis < 3; axis++) {
    double e[3] = {0, 0, 0};
    e[axis] = h;
    zr_vec3 d = zr_v3(e[0], e[1], e[2]);
    g[axis] = (zr__isosurface_value(o, zr_v3_add(p, d)) - f0) / h;
  }
  return zr_v3(g[0], g[1], g[2]);
}

/* The value of f - threshold along the ray. */
typedef struct line {
  const zr_object *o;
  zr_vec3 org, dir;
} line;

static double at(const line *l, double t) {
  return zr__isosurface_value(l->o, zr_v3_madd(l->org, l->dir, t));
}

/* A crossing in [a, b], where the value changes sign, to a few ulps of
   t by Illinois' method (regula falsi that halves the weight of an end
   kept twice), with bisection when it stalls. */
static double refine(const line *l, double a, double fa, double b,
                     double fb) {
  double scale = fmax(fabs(a), fabs(b));
  int side = 0;
  for (int i = 0; i < 200; i++) {
    if (b - a <= 4.0 * DBL_EPSILON * scale || b - a <= DBL_MIN)
      break;
    double m = (a * fb - b * fa) / (fb - fa);
    if (!(m > a && m < b) || i % 8 == 7)
      m = 0.5 * (a + b);
    double fm = at(l, m);
    if (fm == 0.0)
      return m;
    if ((fm < 0.0) == (fa < 0.0)) {
      a = m;
      fa = fm;
      if (side == -1)
        fb *= 0.5;
      side = -1;
    } else {
      b = m;
      fb = fm;
      if (side == 1)
        fa *= 0.5;
      side = 1;
    }
  }
  return 0.5 * (a + b);
}

/* What the search has found: the crossings reported in (tmin, tmax),
   and how many it met along the ray in all. */
typedef struct found {
  double tmin, tmax;
  int max_trace; /* 0: all */
  int met, n;
  double t[2];
  bool container[2]; /* the crossing is on the container's surface */
  bool done;         /* nothing more is wanted */
} found;

static void record(found *f, double t, bool container) {
  f->met++;
  if (t > f->tmin && t < f->tmax && f->n < 2) {
    f->t[f->n] = t;
    f->container[f->n] = container;
    f->n++;
  }
  if (f->n == 2 || (f->max_trace > 0 && f->met >= f->max_trace) ||
      t >= f->tmax)
    f->done = true;
}

typedef struct stretch {
  double a, fa, b, fb;
} stretch;

/* The subdivision of [a, b] in order along the ray (see the top). */
static void search(const line *l, double a, double b, double dlen,
                   found *f) {
  const double grad = l->o->u.isosurface.max_gradient;
  const double acc = l->o->u.isosurface.accuracy;
  const bool skip_before = f->max_trace == 0;
  stretch stack[MAX_DEPTH + 2];
  int n = 0;
  stack[n++] = (stretch){a, at(l, a), b, at(l, b)};
  while (n > 0 && !f->done) {
    stretch s = stack[--n];
    if (s.a >= f->tmax) {
      f->done = true;
      break;
    }
    /* With every crossing wanted, those before tmin need not be
       counted; with max_trace they must. */
    if (skip_before && s.b <= f->tmin)
      continue;
    if (isnan(s.fa) || isnan(s.fb))
      continue; /* no crossing where f is not a number (see the top) */
    bool in_a = s.fa < 0.0, in_b = s.fb < 0.0;
    double len = (s.b - s.a) * dlen;
    if (in_a == in_b && fabs(s.fa) + fabs(s.fb) > grad * len)
      continue; /* f cannot reach the threshold in between */
    double m = 0.5 * (s.a + s.b);
    if (len <= acc || n >= MAX_DEPTH || !(m > s.a && m < s.b)) {
      if (in_a != in_b)
        record(f, refine(l, s.a, s.fa, s.b, s.fb), false);
      continue;
    }
    double fm = at(l, m);
    stack[n++] = (stretch){m, fm, s.b, s.fb};
    stack[n++] = (stretch){s.a, s.fa, m, fm};
  }
}

int zr__isosurface_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                             double tmin, double tmax, double t[4],
                             zr_vec3 normal[4]) {
  double t0, t1;
  double dlen = zr_v3_len(dir);
  if (!(dlen > 0.0) || !container_span(o, org, dir, &t0, &t1))
    return 0;
  /* Crossings are counted from the ray's origin (from tmin for a ray
     asked about behind it). */
  double start = fmin(tmin, 0.0);
  if (t1 <= start || t0 >= tmax)
    return 0;
  found f = {tmin, tmax, o->u.isosurface.max_trace, 0, 0, {0, 0},
             {false, false}, false};
  line l = {o, org, dir};
  bool closed = !o->u.isosurface.open;
  if (t0 > start) {
    if (closed && at(&l, t0) < 0.0)
      record(&f, t0, true);
  } else {
    t0 = start;
  }
  if (!f.done)
    search(&l, t0, t1, dlen, &f);
  if (!f.done && closed && at(&l, t1) < 0.0)
    record(&f, t1, true);
  for (int i = 0; i < f.n; i++) {
    zr_vec3 p = zr_v3_madd(org, dir, f.t[i]);
    zr_vec3 n = f.container[i] ? container_normal(o, p) : gradient(o, p);
    if (!(zr_v3_dot(n, n) > 0.0) || !isfinite(zr_v3_dot(n, n)))
      n = zr_v3_neg(dir); /* a flat spot of f: face the ray */
    t[i] = f.t[i];
    normal[i] = n;
  }
  return f.n;
}

static bool isosurface_box(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  zr__isosurface_bounds(o, lo, hi);
  return true;
}

/* The operations the tracer calls through (lib/trace/shape.h). */
const zr_shape_ops zr__shape_isosurface = {
    .name = "an isosurface",
    .search = zr__isosurface_crossings,
    .inside = zr__isosurface_inside,
    .bounds = isosurface_box,
};
