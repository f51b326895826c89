/*
 * obj_shapes.h - the finite shapes of issue 3 that are not quadrics:
 * torus (obj_torus.c), polygon (obj_polygon.c), superellipsoid
 * (obj_superellipsoid.c), prism (obj_prism.c), lathe (obj_lathe.c),
 * blob (obj_blob.c) and sor (obj_sor.c).
 *
 * Each works in the object's own coordinates.  Crossings are those in
 * (tmin, tmax) of the ray org + t dir, nearest first, at most
 * ZR_SHAPE_MAX_CROSSINGS of them, with outward normals of any length;
 * the caller (lib/trace/intersect.c) transforms and normalises them.
 */
#ifndef ZR_TRACE_OBJ_SHAPES_H
#define ZR_TRACE_OBJ_SHAPES_H

#include <stdbool.h>

#include "scene/scene.h"

#define ZR_SHAPE_MAX_CROSSINGS 4

/* The nearest crossings found so far, sorted (prism, lathe, sor). */
typedef struct zr_hit_list {
  int n;
  double t[ZR_SHAPE_MAX_CROSSINGS];
  zr_vec3 normal[ZR_SHAPE_MAX_CROSSINGS];
} zr_hit_list;
/* Keeps crossing (t, n) if it is among the nearest (obj_prism.c). */
void zr__hits_keep(zr_hit_list *l, double t, zr_vec3 n);

int zr__torus_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                        double tmin, double tmax, double t[4],
                        zr_vec3 normal[4]);
bool zr__torus_inside(const zr_object *o, zr_vec3 p);
void zr__torus_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi);

/* Whether the point p of the polygon's plane (object space) is on the
   polygon, by the even-odd rule. */
bool zr__polygon_covers(const zr_object *o, zr_vec3 p);
int zr__polygon_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                          double tmin, double tmax, double t[4],
                          zr_vec3 normal[4]);

int zr__superellipsoid_crossings(const zr_object *o, zr_vec3 org,
                                 zr_vec3 dir, double tmin, double tmax,
                                 double t[4], zr_vec3 normal[4]);
bool zr__superellipsoid_inside(const zr_object *o, zr_vec3 p);
/* The implicit function, negative inside, zero on the surface. */
double zr__superellipsoid_value(double e, double n, zr_vec3 p);

int zr__prism_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                        double tmin, double tmax, double t[4],
                        zr_vec3 normal[4]);
bool zr__prism_inside(const zr_object *o, zr_vec3 p);
void zr__prism_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi);
/* Which way each piece's wall faces, side[i] for the prism's n_seg
   pieces (see lib/scene/scene.h), once its curves and box are made. */
void zr__prism_wall_sides(const zr_object *o, signed char *side);
/* Whether (x, z) is inside the curves of n pieces (a prism's or a
   lathe's seg, with its box, which may be NULL) by the even-odd rule. */
bool zr__curves_cover(const double *seg, const double *box, size_t n,
                      double x, double z);
/* The range of the cubic c[0] + c[1] s + c[2] s^2 + c[3] s^3 over s in
   [0, 1] (its ends and turning points), in *lo and *hi. */
void zr__cubic_range(const double *c, double *lo, double *hi);
/* The box of piece i of seg in out: xlo, xhi, zlo, zhi (a prism's or a
   lathe's box[4 i ..] when box is not NULL, else worked out).  Inline:
   it runs for every piece of every curve a ray or point is tested
   against. */
static inline void zr__piece_box(const double *seg, const double *box,
                                 size_t i, double out[4]) {
  if (box) {
    for (int k = 0; k < 4; k++)
      out[k] = box[4 * i + k];
    return;
  }
  zr__cubic_range(seg + 8 * i, &out[0], &out[1]);
  zr__cubic_range(seg + 8 * i + 4, &out[2], &out[3]);
}

int zr__lathe_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                        double tmin, double tmax, double t[4],
                        zr_vec3 normal[4]);
bool zr__lathe_inside(const zr_object *o, zr_vec3 p);
void zr__lathe_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi);

int zr__blob_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                       double tmin, double tmax, double t[4],
                       zr_vec3 normal[4]);
bool zr__blob_inside(const zr_object *o, zr_vec3 p);
bool zr__blob_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi);
/* The sum of the components' fields at p (blob space). */
double zr__blob_density(const zr_object *o, zr_vec3 p);
/* Component i's field at p (blob space): its texture's weight there. */
double zr__blob_component_density(const zr_object *o, size_t i, zr_vec3 p);

int zr__sor_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                      double tmin, double tmax, double t[4],
                      zr_vec3 normal[4]);
bool zr__sor_inside(const zr_object *o, zr_vec3 p);
void zr__sor_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi);

/* The parameters (s0, s1) along org + s dir for which the point is in
   the box [lo, hi]; false when the ray misses it.  Shared by the
   shapes that clip their search to a box. */
bool zr__ray_box_span(zr_vec3 lo, zr_vec3 hi, zr_vec3 org, zr_vec3 dir,
                      double *s0, double *s1);

#endif /* ZR_TRACE_OBJ_SHAPES_H */
