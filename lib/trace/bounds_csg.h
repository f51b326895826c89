/*
 * bounds_csg.h - the box of an intersection found by narrowing an
 * unbounded box with each child's constraint (lib/trace/bounds_csg.c).
 */
#ifndef ZR_TRACE_BOUNDS_CSG_H
#define ZR_TRACE_BOUNDS_CSG_H

#include <stdbool.h>

#include "scene/scene.h"

/* The world box of intersection node (not inverted, clip not applied);
   false when no finite box is found. */
bool zr__intersection_bounds(const zr_object *node, zr_vec3 *lo,
                             zr_vec3 *hi);

/* The box of box [lo, hi] mapped by the affine matrix map: its eight
   corners mapped and boxed again (conservative for any affine map). */
void zr__box_through(const double map[4][4], zr_vec3 *lo, zr_vec3 *hi);

#endif /* ZR_TRACE_BOUNDS_CSG_H */
