/*
 * obj_poly.h - poly, cubic and quartic surfaces (lib/trace/obj_poly.c),
 * in the object's own coordinates; intersect.c applies the transform.
 */
#ifndef ZR_TRACE_OBJ_POLY_H
#define ZR_TRACE_OBJ_POLY_H

#include <stdbool.h>

#include "scene/scene.h"

/* The number of coefficients of a poly of this order. */
static inline int zr__poly_terms(int order) {
  return (order + 1) * (order + 2) * (order + 3) / 6;
}

/* The crossings of org + t dir in (tmin, tmax), ascending, at most four,
   with unnormalised outward normals. */
int zr__poly_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                       double tmin, double tmax, double t[4],
                       zr_vec3 normal[4]);

/* The gradient, and whether p is inside (the polynomial is negative). */
zr_vec3 zr__poly_gradient(const zr_object *o, zr_vec3 p);
bool zr__poly_inside(const zr_object *o, zr_vec3 p);

#endif /* ZR_TRACE_OBJ_POLY_H */
