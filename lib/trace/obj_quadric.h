/*
 * obj_quadric.h - the general quadric surface (lib/trace/obj_quadric.c),
 * in its own coordinates; lib/trace/intersect.c applies the transform.
 */
#ifndef ZR_TRACE_OBJ_QUADRIC_H
#define ZR_TRACE_OBJ_QUADRIC_H

#include <stdbool.h>

#include "core/vec.h"

/* The crossings of org + t dir with the quadric (any t), at most two,
   into t[] and their unnormalised outward normals into n[]. */
int zr__quadric_crossings(const double coef[10], zr_vec3 org, zr_vec3 dir,
                          double t[2], zr_vec3 n[2]);

/* Whether p is inside: the quadric's value there is negative. */
bool zr__quadric_inside(const double coef[10], zr_vec3 p);

#endif /* ZR_TRACE_OBJ_QUADRIC_H */
