/*
 * obj_sweep.h - the sphere sweep (lib/trace/obj_sweep.c) and the julia
 * fractal (lib/trace/obj_julia.c): their shared data and the ray and
 * inside tests lib/trace/intersect.c dispatches to.
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

/* One piece of a sphere sweep: the ball of centre c(u) and radius r(u)
   moving for u in [0, 1], c(u) = c[0] + c[1] u + c[2] u^2 + c[3] u^3,
   r(u) likewise (c[2], c[3], r[2], r[3] zero for a linear one). */
typedef struct zr_sweep_segment {
  zr_vec3 c[4];
  double r[4];
  zr_vec3 lo, hi; /* a box holding every ball of the piece */
} zr_sweep_segment;

typedef enum zr_sweep_spline {
  ZR_SWEEP_LINEAR = 0,
  ZR_SWEEP_B_SPLINE,
  ZR_SWEEP_CUBIC /* cubic_spline: Catmull-Rom */
} zr_sweep_spline;

struct zr_sphere_sweep {
  zr_sweep_spline spline;
  /* tolerance: the manual's "depth tolerance" against self-shading
     ("Sphere Sweep", 3.4.5.1.13), kept for the record; the crossings
     here are exact, so it changes nothing. */
  double tolerance;
  /* The spheres as written (kept while parsing). */
  zr_vec3 *centres;
  double *radii;
  size_t n_spheres, n_expected;
  bool centre_pending; /* a centre was read, its radius not yet */
  zr_sweep_segment *segments;
  size_t n_segments;
  zr_vec3 lo, hi;
};

/* Fills segments from the spheres: n - 1 linear pieces, n - 3 cubic
   ones (segments must have room for them). */
void zr__sweep_build(struct zr_sphere_sweep *s);

int zr__sweep_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                        double tmin, double tmax, double t[4],
                        zr_vec3 normal[4]);
bool zr__sweep_inside(const zr_object *o, zr_vec3 p);
void zr__sweep_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi);

/* ---- julia_fractal ---- */

typedef enum zr_julia_algebra {
  ZR_JULIA_QUATERNION = 0,
  ZR_JULIA_HYPERCOMPLEX
} zr_julia_algebra;

typedef enum zr_julia_function {
  ZR_JULIA_SQR = 0,
  ZR_JULIA_CUBE,
  /* hypercomplex only: */
  ZR_JULIA_RECIPROCAL,
  ZR_JULIA_EXP,
  ZR_JULIA_LN,
  ZR_JULIA_SIN,
  ZR_JULIA_ASIN,
  ZR_JULIA_COS,
  ZR_JULIA_ACOS,
  ZR_JULIA_TAN,
  ZR_JULIA_ATAN,
  ZR_JULIA_SINH,
  ZR_JULIA_ASINH,
  ZR_JULIA_COSH,
  ZR_JULIA_ACOSH,
  ZR_JULIA_TANH,
  ZR_JULIA_ATANH,
  ZR_JULIA_PWR /* pwr(X, Y): z^(X + i Y) */
} zr_julia_function;

struct zr_julia {
  double c[4];     /* the julia parameter */
  zr_julia_algebra algebra;
  zr_julia_function function;
  double exponent[2]; /* pwr's */
  int max_iteration; /* default 20 */
  double precision;  /* default 20, at least 1 */
  /* slice <n>, d: the hyperplane n . h = d (n a unit vector) that 3-D
     space is mapped onto (lib/trace/obj_julia.c). */
  double slice[4], distance;
  double escape; /* the escape radius: |h| beyond it escapes; the
                    bounding sphere about the origin too */
};

/* Computes the slice's frame from slice and distance; false when the
   normal is zero or its fourth component is zero. */
bool zr__julia_prepare(struct zr_julia *j);

int zr__julia_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                        double tmin, double tmax, double t[4],
                        zr_vec3 normal[4]);
bool zr__julia_inside(const zr_object *o, zr_vec3 p);
void zr__julia_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi);

#endif /* ZR_TRACE_OBJ_SWEEP_H */
