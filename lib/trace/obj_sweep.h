/*
 * obj_sweep.h - the sphere sweep (lib/trace/obj_sweep.c) and the julia
 * fractal (lib/trace/obj_julia.c): the ray and inside tests
 * lib/trace/intersect.c dispatches to (their data is the scene model's,
 * lib/scene/shapes.h).
 *
 * Both work in the object's own coordinates, with the contract of
 * lib/trace/obj_shapes.h: crossings in (tmin, tmax), nearest first, at
 * most ZR_SHAPE_MAX_CROSSINGS, normals of any length.
 */
#ifndef ZR_TRACE_OBJ_SWEEP_H
#define ZR_TRACE_OBJ_SWEEP_H

#include <stdbool.h>
#include <stddef.h>

#include "scene/scene.h"
#include "scene/shapes.h"

/* Fills segments from the spheres: n - 1 linear pieces, n - 3 cubic
   ones (segments must have room for them). */
void zr__sweep_build(struct zr_sphere_sweep *s);

int zr__sweep_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                        double tmin, double tmax, double t[4],
                        zr_vec3 normal[4]);
bool zr__sweep_inside(const zr_object *o, zr_vec3 p);
void zr__sweep_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi);

/* ---- julia_fractal ---- */

/* Computes the slice's frame from slice and distance; false when the
   normal is zero or its fourth component is zero. */
bool zr__julia_prepare(struct zr_julia *j);

int zr__julia_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                        double tmin, double tmax, double t[4],
                        zr_vec3 normal[4]);
/* zr__julia_crossings with every orbit of the march taken one at a
   time, as before the march iterated two or three together: the same
   crossings and normals, bit for bit (tests/test_shapes.c). */
int zr__julia_crossings_plain(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                              double tmin, double tmax, double t[4],
                              zr_vec3 normal[4]);
bool zr__julia_inside(const zr_object *o, zr_vec3 p);
/* Whether each of three points (the fractal's own coordinates) is
   inside, as zr__julia_inside says, the three orbits iterated together
   (the march's bisection); false, in[] untouched, for the functions
   other than sqr and cube of hypercomplex numbers. */
bool zr__julia_points_inside(const struct zr_julia *j, const zr_vec3 p[3],
                             bool in[3]);
void zr__julia_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi);

#endif /* ZR_TRACE_OBJ_SWEEP_H */
