/*
 * obj_disc.c - the disc (POV-Ray 3.7 reference, "Disc"): a flat ring
 * whose inside is its plane's half-space, though rays crossing it stay
 * in the medium they were in.
 */
#include "trace/shape.h"

static void disc_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                           double tmin, double tmax, zr_crossings *l) {
  (void)tmin;
  (void)tmax;
  zr_vec3 n = o->u.disc.normal;
  double dn = zr_v3_dot(n, dir);
  if (dn == 0.0)
    return;
  double t = zr_v3_dot(n, zr_v3_sub(o->u.disc.centre, org)) / dn;
  zr_vec3 q = zr_v3_sub(zr_v3_madd(org, dir, t), o->u.disc.centre);
  double d2 = zr_v3_dot(q, q);
  double r = o->u.disc.radius, hole = o->u.disc.hole_radius;
  if (d2 <= r * r && d2 >= hole * hole)
    zr__crossings_add(l, t, n);
}

static bool disc_inside(const zr_object *o, zr_vec3 p) {
  return zr_v3_dot(zr_v3_sub(p, o->u.disc.centre), o->u.disc.normal) < 0.0;
}

/* The exact box of the circle about its normal. */
static bool disc_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  zr__bounds_empty(lo, hi);
  zr__bounds_add_circle(o->u.disc.centre, zr_v3_norm(o->u.disc.normal),
                        fabs(o->u.disc.radius), lo, hi);
  return true;
}

const zr_shape_ops zr__shape_disc = {
    .name = "a disc",
    .crossings = disc_crossings,
    .interval_free = true,
    .inside = disc_inside,
    .flat = true,
    .bounds = disc_bounds,
};
