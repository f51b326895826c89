/*
 * obj_sphere.c - the sphere (POV-Ray 3.7 reference, "Sphere"): ray
 * crossings, inside, box and POV-Ray's spherical (u, v).
 */
#include "trace/shape.h"

#include <math.h>

static void sphere_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                             double tmin, double tmax, zr_crossings *l) {
  (void)tmin;
  (void)tmax;
  zr_vec3 oc = zr_v3_sub(org, o->u.sphere.centre);
  double r = o->u.sphere.radius;
  double a = zr_v3_dot(dir, dir);
  double b = 2.0 * zr_v3_dot(dir, oc);
  double c = zr_v3_dot(oc, oc) - r * r;
  double t[2];
  if (zr__solve_quadratic(a, b, c, t) != 2)
    return;
  for (int i = 0; i < 2; i++)
    zr__crossings_add(l, t[i], zr_v3_sub(zr_v3_madd(org, dir, t[i]),
                                         o->u.sphere.centre));
}

static bool sphere_inside(const zr_object *o, zr_vec3 p) {
  zr_vec3 d = zr_v3_sub(p, o->u.sphere.centre);
  return zr_v3_dot(d, d) < o->u.sphere.radius * o->u.sphere.radius;
}

/* The cube about the centre. */
static bool sphere_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  double r = fabs(o->u.sphere.radius);
  zr_vec3 e = zr_v3(r, r, r);
  *lo = zr_v3_sub(o->u.sphere.centre, e);
  *hi = zr_v3_add(o->u.sphere.centre, e);
  return true;
}

#define UV_PI 3.14159265358979323846

/* POV-Ray 3.7's sphere mapping ("UV Mapping"): u the angle about y from
   +x towards +z over a full turn, v from the south pole (0) to the
   north (1). */
static void sphere_uv(const zr_object *o, zr_vec3 p, double *u, double *v) {
  zr_vec3 d = zr_v3_sub(p, o->u.sphere.centre);
  double len = zr_v3_len(d);
  if (!(len > 0.0)) {
    *u = *v = 0.0;
    return;
  }
  d = zr_v3_scale(d, 1.0 / len);
  *v = 0.5 + asin(fmax(-1.0, fmin(1.0, d.y))) / UV_PI;
  double r = sqrt(d.x * d.x + d.z * d.z);
  double theta = 0.0;
  if (r > 1e-10) {
    theta = acos(fmax(-1.0, fmin(1.0, d.x / r)));
    if (d.z < 0.0)
      theta = 2.0 * UV_PI - theta;
  }
  *u = theta / (2.0 * UV_PI);
}

const zr_shape_ops zr__shape_sphere = {
    .name = "a sphere",
    .crossings = sphere_crossings,
    .interval_free = true,
    .inside = sphere_inside,
    .bounds = sphere_bounds,
    .uv = sphere_uv,
};
