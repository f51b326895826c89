/*
 * shape.h - one table of operations per primitive.
 *
 * Every kind of object (zr_object_kind) has one zr_shape_ops, defined
 * in the primitive's own file (obj_sphere.c, obj_torus.c, ...), and one
 * entry in the table of lib/trace/shape.c: a new primitive is a new
 * file and a table entry, not a `switch` in every module that meets
 * objects.  The generic code (lib/trace/intersect.c: transforms, clips,
 * sorting, inverse; lib/trace/bounds.c: transforms and clips;
 * lib/trace/prepare.c) calls the operations through the table.
 *
 * Every operation works in the object's own coordinates (the caller
 * maps the ray or point by the inverse transform), with normals of any
 * length that the caller transforms and normalises.  CSG objects
 * (union, intersection, merge) carry their transforms in their children
 * and are handled whole by lib/trace/csg.c; their entries give only the
 * name.
 */
#ifndef ZR_TRACE_SHAPE_H
#define ZR_TRACE_SHAPE_H

#include <math.h>
#include <stdbool.h>
#include <stdint.h>

#include "core/arena.h"
#include "scene/scene.h"

/* The crossings one shape gives for one ray before they are clipped to
   the interval and sorted (at most 4: ZR_SHAPE_MAX_CROSSINGS). */
typedef struct zr_crossings {
  int n;
  double t[4];
  zr_vec3 normal[4];  /* object space, any length */
  int32_t texture[4]; /* a mesh's texture list index, -1 for none */
  double u[4], v[4];  /* a mesh's surface coordinates, else 0 */
} zr_crossings;

/* Adds crossing (t, n) when there is room and t is finite. */
static inline void zr__crossings_add(zr_crossings *l, double t, zr_vec3 n) {
  if (l->n < 4 && isfinite(t)) {
    l->t[l->n] = t;
    l->normal[l->n] = n;
    l->texture[l->n] = -1;
    l->u[l->n] = l->v[l->n] = 0.0;
    l->n++;
  }
}

typedef struct zr_shape_ops {
  /* The object as messages name it ("a sphere", "an isosurface"). */
  const char *name;
  /*
   * The crossings of the ray org + t dir, by one of two forms (the
   * other NULL).  search gives the nearest crossings in (tmin, tmax)
   * into t[] and normal[] (at most ZR_SHAPE_MAX_CROSSINGS, 4) and
   * returns how many: the shapes whose roots are searched for take the
   * interval so that a ray leaving the shape spends no room on
   * crossings behind it.  crossings adds every crossing to l (closed
   * forms, at most 4, the interval ignored or used as the shape likes).
   */
  int (*search)(const zr_object *o, zr_vec3 org, zr_vec3 dir, double tmin,
                double tmax, double t[4], zr_vec3 normal[4]);
  void (*crossings)(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                    double tmin, double tmax, zr_crossings *l);
  /*
   * Optional, for shapes that find their crossings by a costly march
   * along the ray (julia_fractal): search's nearest crossings, at most
   * max_found of them, and their normals only when normal is not NULL,
   * the march stopping there.  Its crossings must not depend on the
   * interval or on max_found, so that the tracer may ask for the
   * nearest one alone without normals, then again with its normal.
   * When given, intersect.c calls it instead of search.
   */
  int (*search_upto)(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                     double tmin, double tmax, int max_found, double t[4],
                     zr_vec3 normal[4]);
  /* Whether p is inside (POV-Ray's inside, before inverse); NULL: the
     shape has no inside (a shell: triangle, polygon, parametric). */
  bool (*inside)(const zr_object *o, zr_vec3 p);
  /* Whether this object has an inside after all (NULL: always when
     inside is given): a mesh has one only with an inside_vector. */
  bool (*has_inside)(const zr_object *o);
  /* Flat: rays crossing it stay in the medium they were in, though it
     has an inside test (a disc's is its plane's). */
  bool flat;
  /* The box of the shape; false when it has none (NULL: unbounded, as
     a plane, a quadric or a poly unless clipped or intersected). */
  bool (*bounds)(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi);
  /* The surface coordinates at the point p ("UV Mapping"); NULL: none,
     or given by the crossing (uv_from_hit). */
  void (*uv)(const zr_object *o, zr_vec3 p, double *u, double *v);
  bool uv_from_hit; /* the hit's (u, v) are the crossing's (a mesh) */
  /* crossings (or search) uses the interval as a filter only: the
     list is that of the whole line, cut to whatever (tmin, tmax) is
     asked, so a part of a CSG object that gave all of its crossings
     in the interval at once (at most two) needs no second asking
     (lib/trace/csg.c). */
  bool interval_free;
  /* The object a crossing with texture list index k reports (a mesh's
     textured copy); NULL: the object itself. */
  const zr_object *(*hit_object)(const zr_object *o, int32_t k);
  /* Called on every primitive when the scene is made ready for tracing
     (lib/trace/prepare.c): may replace *prim by a copy in arena (a
     mesh with a texture list makes one per texture).  NULL: nothing. */
  zr_status (*prepare)(zr_arena *arena, const zr_object **prim);
} zr_shape_ops;

/* The table (lib/trace/shape.c), indexed by zr_object_kind. */
/* Whether a ray of direction dir (any length) misses a plane whose
   unit normal n gives dn = n . dir: povray 3.7 finds no crossing within
   1e-10 of parallel (n . unit dir; measured with trace():
   test_pattern_more's trace_limits).  The plane's one test, shared by
   obj_plane.c and the in-place copies in bvh.c and csg.c. */
static inline bool zr__plane_parallel(double dn, zr_vec3 dir) {
  return dn == 0.0 || dn * dn < 1e-20 * zr_v3_dot(dir, dir);
}

extern const zr_shape_ops *const zr__shapes[];

static inline const zr_shape_ops *zr__shape(zr_object_kind kind) {
  return zr__shapes[kind];
}

/* Each primitive's operations, in its own file. */
extern const zr_shape_ops zr__shape_sphere;         /* obj_sphere.c */
extern const zr_shape_ops zr__shape_box;            /* obj_box.c */
extern const zr_shape_ops zr__shape_plane;          /* obj_plane.c */
extern const zr_shape_ops zr__shape_triangle;       /* obj_triangle.c */
extern const zr_shape_ops zr__shape_cylinder;       /* obj_cone.c */
extern const zr_shape_ops zr__shape_cone;           /* obj_cone.c */
extern const zr_shape_ops zr__shape_disc;           /* obj_disc.c */
extern const zr_shape_ops zr__shape_union;          /* csg.c */
extern const zr_shape_ops zr__shape_intersection;   /* csg.c */
extern const zr_shape_ops zr__shape_merge;          /* csg.c */
extern const zr_shape_ops zr__shape_mesh;           /* obj_mesh.c */
extern const zr_shape_ops zr__shape_text;           /* obj_text.c */
extern const zr_shape_ops zr__shape_quadric;        /* obj_quadric.c */
extern const zr_shape_ops zr__shape_torus;          /* obj_torus.c */
extern const zr_shape_ops zr__shape_polygon;        /* obj_polygon.c */
extern const zr_shape_ops zr__shape_superellipsoid; /* obj_superellipsoid.c */
extern const zr_shape_ops zr__shape_prism;          /* obj_prism.c */
extern const zr_shape_ops zr__shape_lathe;          /* obj_lathe.c */
extern const zr_shape_ops zr__shape_blob;           /* obj_blob.c */
extern const zr_shape_ops zr__shape_poly;           /* obj_poly.c */
extern const zr_shape_ops zr__shape_sor;            /* obj_sor.c */
extern const zr_shape_ops zr__shape_sphere_sweep;   /* obj_sweep.c */
extern const zr_shape_ops zr__shape_julia;          /* obj_julia.c */
extern const zr_shape_ops zr__shape_isosurface;     /* obj_isosurface.c */
extern const zr_shape_ops zr__shape_height_field;   /* obj_height_field.c */
extern const zr_shape_ops zr__shape_ovus;           /* obj_ovus.c */
extern const zr_shape_ops zr__shape_parametric;     /* obj_parametric.c */

/*
 * Real roots of a t^2 + b t + c = 0 into r[0] <= r[1]; returns their
 * number (0 or 2; a double root counts as a graze and is dropped; 1 when
 * a is 0).  The cancellation-free form of the quadratic formula, so a
 * root next to the ray origin (a secondary ray leaving the surface) is
 * computed to full relative precision and lands on the right side of
 * the caller's offset.
 */
static inline int zr__solve_quadratic(double a, double b, double c,
                                      double r[2]) {
  if (a == 0.0) {
    if (b == 0.0)
      return 0;
    r[0] = r[1] = -c / b;
    return 1;
  }
  double disc = b * b - 4.0 * a * c;
  if (!(disc > 0.0))
    return 0;
  double q = -0.5 * (b + copysign(sqrt(disc), b));
  double r0 = q / a, r1 = q != 0.0 ? c / q : r0;
  /* fmin and fmax as glibc computes them (the second operand when the
     two are equal, the other one when one is a NaN) in comparisons:
     the calls were 1.5% of bench/peers.sh's sphereflake. */
  r[0] = r0 < r1 || r1 != r1 ? r0 : r1;
  r[1] = r0 > r1 || r1 != r1 ? r0 : r1;
  return 2;
}

/* Grows [lo, hi] by the circle of radius r about the unit axis a centred
   at c: along world axis i its half extent is r sqrt(1 - a_i^2). */
static inline void zr__bounds_add_circle(zr_vec3 c, zr_vec3 a, double r,
                                         zr_vec3 *lo, zr_vec3 *hi) {
  zr_vec3 e = zr_v3(r * sqrt(fmax(0.0, 1.0 - a.x * a.x)),
                    r * sqrt(fmax(0.0, 1.0 - a.y * a.y)),
                    r * sqrt(fmax(0.0, 1.0 - a.z * a.z)));
  *lo = zr_v3_min(*lo, zr_v3_sub(c, e));
  *hi = zr_v3_max(*hi, zr_v3_add(c, e));
}

/* The empty box (lo above hi), which bounds grow from. */
static inline void zr__bounds_empty(zr_vec3 *lo, zr_vec3 *hi) {
  *lo = zr_v3(INFINITY, INFINITY, INFINITY);
  *hi = zr_v3_neg(*lo);
}

#endif /* ZR_TRACE_SHAPE_H */
