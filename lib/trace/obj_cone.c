/*
 * obj_cone.c - the cylinder and the cone (POV-Ray 3.7 reference,
 * "Cylinder", "Cone"), one shape: a radius that grows linearly from the
 * base to the cap, with end caps unless open.
 */
#include "trace/shape.h"

#include <math.h>

/*
 * The frame of a shape with an axis from base to cap: the unit axis w,
 * the height h, and the ray split into its part along w (o_par, d_par)
 * and across it (o_perp, d_perp), measured from base.
 */
typedef struct axis_frame {
  zr_vec3 w;
  double h;
  double o_par, d_par;
  zr_vec3 o_perp, d_perp;
} axis_frame;

/*
 * The frame of the ray about the axis from base, unit axis w and height
 * h (measured by the parser: zr__axis_measure; a height of 0 has them
 * measured here from base and cap, for an object made by hand).  A
 * sqrt and a division per ray were 8% of a render of a few thousand
 * cylinders and cones (the corpus' complexity.pov).
 */
static bool make_frame(zr_vec3 base, zr_vec3 cap, zr_vec3 axis,
                       double height, zr_vec3 org, zr_vec3 dir,
                       axis_frame *f) {
  if (height > 0.0) {
    f->h = height;
    f->w = axis;
  } else if (!((f->h = zr__axis_measure(base, cap, &f->w)) > 0.0)) {
    return false;
  }
  zr_vec3 ob = zr_v3_sub(org, base);
  f->o_par = zr_v3_dot(ob, f->w);
  f->d_par = zr_v3_dot(dir, f->w);
  f->o_perp = zr_v3_madd(ob, f->w, -f->o_par);
  f->d_perp = zr_v3_madd(dir, f->w, -f->d_par);
  return true;
}

/* An end cap: the disc of radius r across the axis at height s. */
static void cap_crossing(const axis_frame *f, double s, double r,
                         double outward, zr_crossings *l) {
  if (f->d_par == 0.0 || !(r > 0.0))
    return;
  double t = (s - f->o_par) / f->d_par;
  zr_vec3 q = zr_v3_madd(f->o_perp, f->d_perp, t);
  if (zr_v3_dot(q, q) <= r * r)
    zr__crossings_add(l, t, zr_v3_scale(f->w, outward));
}

/*
 * Cylinders and cones in one: the radius grows linearly from r0 at the
 * base to r1 at the cap, r(s) = r0 + k s.  The side is where
 * |perp|^2 = r(s)^2 with 0 <= s <= h; its gradient perp - r(s) k w is
 * the outward normal.
 */
static void round_crossings(zr_vec3 base, zr_vec3 cap, zr_vec3 axis,
                            double height, double r0, double r1, bool open,
                            zr_vec3 org, zr_vec3 dir, zr_crossings *l) {
  axis_frame f;
  if (!make_frame(base, cap, axis, height, org, dir, &f))
    return;
  r0 = fabs(r0);
  r1 = fabs(r1);
  double k = (r1 - r0) / f.h;
  double rq = r0 + k * f.o_par; /* the radius at the origin's height */
  double a = zr_v3_dot(f.d_perp, f.d_perp) - k * k * f.d_par * f.d_par;
  double b = 2.0 * (zr_v3_dot(f.o_perp, f.d_perp) - k * f.d_par * rq);
  double c = zr_v3_dot(f.o_perp, f.o_perp) - rq * rq;
  double t[2];
  int n = zr__solve_quadratic(a, b, c, t);
  for (int i = 0; i < n; i++) {
    double s = f.o_par + t[i] * f.d_par;
    if (s < 0.0 || s > f.h)
      continue;
    double rs = r0 + k * s;
    if (rs < 0.0)
      continue; /* the mirror nappe of a cone beyond its apex */
    zr_vec3 perp = zr_v3_madd(f.o_perp, f.d_perp, t[i]);
    zr__crossings_add(l, t[i], zr_v3_madd(perp, f.w, -rs * k));
  }
  if (!open) {
    cap_crossing(&f, 0.0, r0, -1.0, l);
    cap_crossing(&f, f.h, r1, 1.0, l);
  }
}

/* Inside: between the end planes and within the radius there. */
static bool round_inside(zr_vec3 base, zr_vec3 cap, zr_vec3 axis,
                         double height, double r0, double r1, zr_vec3 p) {
  axis_frame f;
  if (!make_frame(base, cap, axis, height, p, zr_v3(0, 0, 0), &f))
    return false;
  if (f.o_par < 0.0 || f.o_par > f.h)
    return false;
  double r = fabs(r0) + (fabs(r1) - fabs(r0)) * f.o_par / f.h;
  return zr_v3_dot(f.o_perp, f.o_perp) < r * r;
}

static void cylinder_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                               double tmin, double tmax, zr_crossings *l) {
  (void)tmin;
  (void)tmax;
  round_crossings(o->u.cylinder.base, o->u.cylinder.cap,
                  o->u.cylinder.axis, o->u.cylinder.height,
                  o->u.cylinder.radius, o->u.cylinder.radius,
                  o->u.cylinder.open, org, dir, l);
}

static bool cylinder_inside(const zr_object *o, zr_vec3 p) {
  return round_inside(o->u.cylinder.base, o->u.cylinder.cap,
                      o->u.cylinder.axis, o->u.cylinder.height,
                      o->u.cylinder.radius, o->u.cylinder.radius, p);
}

/* The exact box of the two end circles. */
static bool cylinder_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  zr__bounds_empty(lo, hi);
  zr_vec3 a = zr_v3_norm(zr_v3_sub(o->u.cylinder.cap, o->u.cylinder.base));
  zr__bounds_add_circle(o->u.cylinder.base, a, fabs(o->u.cylinder.radius),
                        lo, hi);
  zr__bounds_add_circle(o->u.cylinder.cap, a, fabs(o->u.cylinder.radius),
                        lo, hi);
  return true;
}

const zr_shape_ops zr__shape_cylinder = {
    .name = "a cylinder",
    .crossings = cylinder_crossings,
    .interval_free = true,
    .inside = cylinder_inside,
    .bounds = cylinder_bounds,
};

static void cone_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                           double tmin, double tmax, zr_crossings *l) {
  (void)tmin;
  (void)tmax;
  round_crossings(o->u.cone.base, o->u.cone.cap, o->u.cone.axis,
                  o->u.cone.height, o->u.cone.base_radius,
                  o->u.cone.cap_radius, o->u.cone.open, org, dir, l);
}

static bool cone_inside(const zr_object *o, zr_vec3 p) {
  return round_inside(o->u.cone.base, o->u.cone.cap, o->u.cone.axis,
                      o->u.cone.height, o->u.cone.base_radius,
                      o->u.cone.cap_radius, p);
}

static bool cone_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  zr__bounds_empty(lo, hi);
  zr_vec3 a = zr_v3_norm(zr_v3_sub(o->u.cone.cap, o->u.cone.base));
  zr__bounds_add_circle(o->u.cone.base, a, fabs(o->u.cone.base_radius), lo,
                        hi);
  zr__bounds_add_circle(o->u.cone.cap, a, fabs(o->u.cone.cap_radius), lo,
                        hi);
  return true;
}

const zr_shape_ops zr__shape_cone = {
    .name = "a cone",
    .crossings = cone_crossings,
    .interval_free = true,
    .inside = cone_inside,
    .bounds = cone_bounds,
};
