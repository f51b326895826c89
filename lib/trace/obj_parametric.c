/*
 * obj_parametric.c - the parametric surface (POV-Ray 3.7 reference,
 * "Parametric"): the points P(u, v) = <fx, fy, fz>(u, v) for (u, v) in
 * a rectangle, within a container box or sphere.  It is a shell, not a
 * solid: it has no inside.
 *
 * The manual's max_gradient G bounds every partial derivative of the
 * three functions, so over a rectangle of sides du, dv about its centre
 * (uc, vc) each coordinate of P stays within G (du + dv) / 2 of
 * P(uc, vc): a box the surface cannot leave.  The search subdivides the
 * (u, v) rectangle, nearest box first along the ray, dropping those the
 * ray misses or that lie beyond the crossings already found, until a
 * box is smaller than accuracy.  There Newton's method solves
 * P(u, v) = org + t dir for (u, v, t) from the box's centre and entry,
 * so the crossing is exact, not accuracy-near, and a ray leaving the
 * surface does not meet it again; should Newton fail (a fold, a ray
 * along the surface), the box's entry is taken as the crossing, which
 * is within accuracy of the surface ("Parametric": accuracy bounds how
 * far the subdivision goes).
 * The normal is Pu x Pv, turned to face the ray.  Nothing is kept between rays, and the
 * functions are evaluated by lib/sdl/function.c's machine, which never
 * allocates, so any number of threads trace the same surface.
 */
#include "trace/obj_isosurface.h"

#include <float.h>
#include <math.h>

#include "trace/shape.h"

#include "fn/fn.h"
#include "trace/obj_shapes.h"

/* The subdivision's depth limit and its stack (four children a level). */
enum { MAX_DEPTH = 48, STACK = 4 * MAX_DEPTH + 8 };

static zr_vec3 surface(const zr_object *o, double u, double v) {
  double args[3] = {u, v, 0.0};
  return zr_v3(zr__fn_eval(o->u.parametric.fn[0], args),
               zr__fn_eval(o->u.parametric.fn[1], args),
               zr__fn_eval(o->u.parametric.fn[2], args));
}

/* The partial derivatives at (u, v) by central differences. */
static void partials(const zr_object *o, double u, double v, zr_vec3 *pu,
                     zr_vec3 *pv) {
  double hu = 1e-6 * fmax(1.0, fabs(o->u.parametric.u1 - o->u.parametric.u0));
  double hv = 1e-6 * fmax(1.0, fabs(o->u.parametric.v1 - o->u.parametric.v0));
  *pu = zr_v3_scale(zr_v3_sub(surface(o, u + hu, v), surface(o, u - hu, v)),
                    0.5 / hu);
  *pv = zr_v3_scale(zr_v3_sub(surface(o, u, v + hv), surface(o, u, v - hv)),
                    0.5 / hv);
}

void zr__parametric_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  if (o->u.parametric.sphere) {
    double r = o->u.parametric.radius;
    *lo = zr_v3_sub(o->u.parametric.centre, zr_v3(r, r, r));
    *hi = zr_v3_add(o->u.parametric.centre, zr_v3(r, r, r));
  } else {
    *lo = o->u.parametric.lo;
    *hi = o->u.parametric.hi;
  }
}

static bool in_container(const zr_object *o, zr_vec3 p) {
  if (o->u.parametric.sphere) {
    zr_vec3 d = zr_v3_sub(p, o->u.parametric.centre);
    return zr_v3_dot(d, d) <= o->u.parametric.radius * o->u.parametric.radius;
  }
  zr_vec3 lo = o->u.parametric.lo, hi = o->u.parametric.hi;
  return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y &&
         p.z >= lo.z && p.z <= hi.z;
}

/* Solves P(u, v) = org + t dir from (u, v, t) by Newton's method (Cramer
   on the 3 x 3 system [Pu Pv -dir]); false when it does not converge. */
static bool newton(const zr_object *o, zr_vec3 org, zr_vec3 dir, double *u,
                   double *v, double *t) {
  for (int it = 0; it < 16; it++) {
    zr_vec3 p = surface(o, *u, *v);
    zr_vec3 f = zr_v3_sub(p, zr_v3_madd(org, dir, *t));
    double scale = 1.0 + zr_v3_max_comp(zr_v3_max(p, zr_v3_neg(p)));
    if (fmax(fabs(f.x), fmax(fabs(f.y), fabs(f.z))) <= 1e-12 * scale)
      return true;
    zr_vec3 pu, pv;
    partials(o, *u, *v, &pu, &pv);
    zr_vec3 nd = zr_v3_neg(dir);
    double det = zr_v3_dot(pu, zr_v3_cross(pv, nd));
    if (!(fabs(det) > 1e-300) || !isfinite(det))
      return false;
    zr_vec3 rhs = zr_v3_neg(f);
    double du = zr_v3_dot(rhs, zr_v3_cross(pv, nd)) / det;
    double dv = zr_v3_dot(pu, zr_v3_cross(rhs, nd)) / det;
    double dt = zr_v3_dot(pu, zr_v3_cross(pv, rhs)) / det;
    *u += du;
    *v += dv;
    *t += dt;
    if (!isfinite(*u) || !isfinite(*v) || !isfinite(*t))
      return false;
  }
  return false;
}

typedef struct rect {
  double u0, v0, u1, v1;
  double t; /* where the ray enters the rectangle's box */
  int depth;
} rect;

/* The ray's entry into the box of r, within [t0, t1]; false if none. */
static bool box_entry(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                      rect *r, double t0, double t1, double *extent) {
  double uc = 0.5 * (r->u0 + r->u1), vc = 0.5 * (r->v0 + r->v1);
  double e = o->u.parametric.max_gradient *
             0.5 * ((r->u1 - r->u0) + (r->v1 - r->v0));
  zr_vec3 c = surface(o, uc, vc);
  zr_vec3 lo = zr_v3_sub(c, zr_v3(e, e, e)), hi = zr_v3_add(c, zr_v3(e, e, e));
  double s0, s1;
  *extent = e;
  if (!zr__ray_box_span(lo, hi, org, dir, &s0, &s1))
    return false;
  s0 = fmax(s0, t0);
  s1 = fmin(s1, t1);
  if (!(s0 <= s1))
    return false;
  r->t = s0;
  return true;
}

typedef struct found {
  int n;
  double t[2], u[2], v[2];
} found;

static void record(found *f, double t, double u, double v) {
  for (int i = 0; i < f->n; i++)
    if (fabs(t - f->t[i]) <= 1e-9 * (1.0 + fabs(t)))
      return; /* the same crossing, from a neighbouring box */
  int j = f->n < 2 ? f->n++ : 2;
  if (j == 2) {
    if (t >= f->t[1])
      return;
    j = 1;
  }
  while (j > 0 && f->t[j - 1] > t) {
    f->t[j] = f->t[j - 1];
    f->u[j] = f->u[j - 1];
    f->v[j] = f->v[j - 1];
    j--;
  }
  f->t[j] = t;
  f->u[j] = u;
  f->v[j] = v;
}

/* The leaf at the end of the subdivision: its crossing, if any. */
static void leaf(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                 const rect *r, double tmin, double tmax, found *f) {
  double u = 0.5 * (r->u0 + r->u1), v = 0.5 * (r->v0 + r->v1), t = r->t;
  double su = r->u1 - r->u0, sv = r->v1 - r->v0;
  if (newton(o, org, dir, &u, &v, &t)) {
    /* A crossing far from this box is another box's (boxes overlap),
       and one within a hair of tmin is the one the caller has. */
    if (u >= r->u0 - su && u <= r->u1 + su && v >= r->v0 - sv &&
        v <= r->v1 + sv && u >= o->u.parametric.u0 &&
        u <= o->u.parametric.u1 && v >= o->u.parametric.v0 &&
        v <= o->u.parametric.v1 && t > tmin + 1e-12 * fmax(1.0, fabs(t)) &&
        t < tmax && in_container(o, zr_v3_madd(org, dir, t)))
      record(f, t, u, v);
    return;
  }
  if (r->t > tmin + 1e-12 * fmax(1.0, fabs(r->t)) && r->t < tmax &&
      in_container(o, zr_v3_madd(org, dir, r->t)))
    record(f, r->t, 0.5 * (r->u0 + r->u1), 0.5 * (r->v0 + r->v1));
}

int zr__parametric_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                             double tmin, double tmax, double t[4],
                             zr_vec3 normal[4]) {
  /* An empty range (sep05.pov's <2*pi, pi*clock> at clock 0) has no
     points: POV-Ray draws nothing (tests/legacy/parametric_empty.pov). */
  if (!(o->u.parametric.u0 < o->u.parametric.u1) ||
      !(o->u.parametric.v0 < o->u.parametric.v1))
    return 0;
  zr_vec3 clo, chi;
  zr__parametric_bounds(o, &clo, &chi);
  double t0, t1;
  if (!zr__ray_box_span(clo, chi, org, dir, &t0, &t1))
    return 0;
  t0 = fmax(t0, tmin);
  t1 = fmin(t1, tmax);
  if (!(t0 <= t1))
    return 0;
  const double acc = o->u.parametric.accuracy;
  found f = {0, {0, 0}, {0, 0}, {0, 0}};
  rect stack[STACK];
  int n = 0;
  double extent;
  rect top = {o->u.parametric.u0, o->u.parametric.v0, o->u.parametric.u1,
              o->u.parametric.v1, 0, 0};
  if (box_entry(o, org, dir, &top, t0, t1, &extent))
    stack[n++] = top;
  while (n > 0) {
    rect r = stack[--n];
    if (f.n == 2 && r.t > f.t[1])
      continue;
    double e = o->u.parametric.max_gradient *
               0.5 * ((r.u1 - r.u0) + (r.v1 - r.v0));
    if (e <= acc || r.depth >= MAX_DEPTH || n + 4 > STACK) {
      leaf(o, org, dir, &r, tmin, tmax, &f);
      continue;
    }
    /* The four quarters, pushed farthest first so the nearest is
       searched first. */
    double um = 0.5 * (r.u0 + r.u1), vm = 0.5 * (r.v0 + r.v1);
    rect q[4] = {{r.u0, r.v0, um, vm, 0, r.depth + 1},
                 {um, r.v0, r.u1, vm, 0, r.depth + 1},
                 {r.u0, vm, um, r.v1, 0, r.depth + 1},
                 {um, vm, r.u1, r.v1, 0, r.depth + 1}};
    rect hit[4];
    int k = 0;
    for (int i = 0; i < 4; i++)
      if (box_entry(o, org, dir, &q[i], t0, t1, &extent))
        hit[k++] = q[i];
    for (int i = 1; i < k; i++) /* by entry, farthest first */
      for (int j = i; j > 0 && hit[j - 1].t < hit[j].t; j--) {
        rect s = hit[j];
        hit[j] = hit[j - 1];
        hit[j - 1] = s;
      }
    for (int i = 0; i < k; i++)
      stack[n++] = hit[i];
  }
  for (int i = 0; i < f.n; i++) {
    zr_vec3 pu, pv;
    partials(o, f.u[i], f.v[i], &pu, &pv);
    zr_vec3 nrm = zr_v3_cross(pu, pv);
    if (!(zr_v3_dot(nrm, nrm) > 0.0) || !isfinite(zr_v3_dot(nrm, nrm)))
      nrm = zr_v3_neg(dir); /* a pole of the parametrisation */
    /* A shell has no outside, and a (u, v) rectangle may cover the
       surface twice with opposite orientations (the manual's sphere
       does): the normal faces the ray, so every crossing is the side
       the ray comes from. */
    if (zr_v3_dot(nrm, dir) > 0.0)
      nrm = zr_v3_neg(nrm);
    t[i] = f.t[i];
    normal[i] = nrm;
  }
  return f.n;
}

/* A shell: no inside. */
static bool parametric_box(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  zr__parametric_bounds(o, lo, hi);
  return true;
}

/* The operations the tracer calls through (lib/trace/shape.h). */
const zr_shape_ops zr__shape_parametric = {
    .name = "a parametric",
    .search = zr__parametric_crossings,
    .bounds = parametric_box,
};
