/*
 * obj_plane.c - the plane (POV-Ray 3.7 reference, "Plane"): an infinite
 * solid, the half-space below the surface; it has no box, so the BVH
 * keeps it among its unbounded primitives.
 */
#include "trace/shape.h"

static void plane_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                            double tmin, double tmax, zr_crossings *l) {
  (void)tmin;
  (void)tmax;
  zr_vec3 n = o->u.plane.normal;
  double dn = zr_v3_dot(n, dir);
  if (zr__plane_parallel(dn, dir)) /* dir is not unit under a transform */
    return;
  zr__crossings_add(l, (o->u.plane.distance - zr_v3_dot(n, org)) / dn, n);
}

/* The surface counts as inside, as a box's faces do (obj_box.c). */
static bool plane_inside(const zr_object *o, zr_vec3 p) {
  return zr_v3_dot(p, o->u.plane.normal) <= o->u.plane.distance;
}

const zr_shape_ops zr__shape_plane = {
    .name = "a plane",
    .crossings = plane_crossings,
    .interval_free = true,
    .inside = plane_inside,
};
