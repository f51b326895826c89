/*
 * obj_triangle.c - the triangle (POV-Ray 3.7 reference, "Triangle and
 * Smooth_triangle"): a flat patch with no inside.
 */
#include "trace/shape.h"

#include <math.h>

/* Moller and Trumbore's test ("Fast, minimum storage ray/triangle
   intersection", 1997), with edges taken from the first vertex. */
static void triangle_crossings(const zr_object *o, zr_vec3 org,
                               zr_vec3 dir, double tmin, double tmax,
                               zr_crossings *l) {
  (void)tmin;
  (void)tmax;
  const zr_vec3 *p = o->u.triangle.p;
  zr_vec3 e1 = zr_v3_sub(p[1], p[0]), e2 = zr_v3_sub(p[2], p[0]);
  zr_vec3 pv = zr_v3_cross(dir, e2);
  double det = zr_v3_dot(e1, pv);
  if (det == 0.0 || !isfinite(det))
    return;
  double inv = 1.0 / det;
  zr_vec3 tv = zr_v3_sub(org, p[0]);
  double u = zr_v3_dot(tv, pv) * inv;
  if (u < 0.0 || u > 1.0)
    return;
  zr_vec3 qv = zr_v3_cross(tv, e1);
  double v = zr_v3_dot(dir, qv) * inv;
  if (v < 0.0 || u + v > 1.0)
    return;
  zr__crossings_add(l, zr_v3_dot(e2, qv) * inv, zr_v3_cross(e1, e2));
}

static bool triangle_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  zr__bounds_empty(lo, hi);
  for (int i = 0; i < 3; i++) {
    *lo = zr_v3_min(*lo, o->u.triangle.p[i]);
    *hi = zr_v3_max(*hi, o->u.triangle.p[i]);
  }
  return true;
}

const zr_shape_ops zr__shape_triangle = {
    .name = "a triangle",
    .crossings = triangle_crossings,
    .interval_free = true,
    .bounds = triangle_bounds,
};
