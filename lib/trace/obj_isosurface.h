/*
 * obj_isosurface.h - the isosurface (obj_isosurface.c), the parametric
 * surface (obj_parametric.c), the height field (obj_height_field.c) and
 * the ovus (obj_ovus.c): the shapes defined by user functions, a grid of
 * heights, and POV-Ray 3.7's egg.  The same contracts as lib/trace/obj_shapes.h:
 * object coordinates, crossings in (tmin, tmax) nearest first, outward
 * normals of any length.
 */
#ifndef ZR_TRACE_OBJ_ISOSURFACE_H
#define ZR_TRACE_OBJ_ISOSURFACE_H

#include <stdbool.h>

#include "scene/scene.h"

int zr__isosurface_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                             double tmin, double tmax, double t[4],
                             zr_vec3 normal[4]);
bool zr__isosurface_inside(const zr_object *o, zr_vec3 p);
void zr__isosurface_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi);
/* fn(p) - threshold: negative inside, zero on the surface. */
double zr__isosurface_value(const zr_object *o, zr_vec3 p);

int zr__height_field_crossings(const zr_object *o, zr_vec3 org,
                               zr_vec3 dir, double tmin, double tmax,
                               double t[4], zr_vec3 normal[4]);
bool zr__height_field_inside(const zr_object *o, zr_vec3 p);
/* false when every triangle is under the water */
bool zr__height_field_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi);
/* The height of the triangles at (x, z) in [0, 1]^2 (object space). */
double zr__height_field_height(const zr_object *o, double x, double z);
/* The samples (w x h, image order, 8 or 16-bit codes or floats, kept
   by pointer) and their block hierarchy, made in arena. */
struct zr_hf_grid;
zr_status zr__height_field_grid(zr_arena *arena, const void *samples,
                                int bits, int w, int h,
                                const struct zr_hf_grid **out);
/* The height field's triangles as a mesh with its BVH, in arena (for
   radiosity, which models faces). */
struct zr_mesh;
zr_status zr__height_field_mesh(const zr_object *o, zr_arena *arena,
                                const struct zr_mesh **out);

/* A parametric surface has no inside (it is a shell). */
int zr__parametric_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                             double tmin, double tmax, double t[4],
                             zr_vec3 normal[4]);
void zr__parametric_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi);

int zr__ovus_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                       double tmin, double tmax, double t[4],
                       zr_vec3 normal[4]);
bool zr__ovus_inside(const zr_object *o, zr_vec3 p);
void zr__ovus_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi);

#endif /* ZR_TRACE_OBJ_ISOSURFACE_H */
