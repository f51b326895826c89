/*
 * intersect.h - rays against the scene's primitives.
 *
 * Every primitive answers two questions: where does a ray cross its
 * surface (all crossings in an interval, nearest first, with the outward
 * geometric normal), and is a point inside it.  Both work in the
 * object's own coordinates when it carries a transform.
 */
#ifndef ZR_TRACE_INTERSECT_H
#define ZR_TRACE_INTERSECT_H

#include <stdbool.h>

#include "core/arena.h"
#include "scene/scene.h"

/* A ray: points origin + t * dir for t in some interval.  dir need not be
   a unit vector; t is measured in units of |dir|. */
typedef struct zr_ray {
  zr_vec3 origin;
  zr_vec3 dir;
} zr_ray;

/* One crossing of a ray with a surface. */
typedef struct zr_hit {
  double t;
  /* World space, unit length, pointing out of the object (into it when the
     object is inverse): it does not yet face the ray. */
  zr_vec3 normal;
  const zr_object *object;
  /* A mesh's surface coordinates at the hit (uv_vectors interpolated,
     "UV Mapping"); 0 for other objects, whose (u, v) the shader derives
     from the point only when a texture asks (zr__hit_uv). */
  double u, v;
} zr_hit;

/* The most crossings one primitive gives in an interval: every shape
   here is convex, or flat, or a plane; meshes, text, tori and
   superellipsoids, which may have more, give their nearest two. */
#define ZR_MAX_CROSSINGS 2

/*
 * Fills hits[] with the crossings of ray and object for tmin < t < tmax,
 * nearest first, and returns how many there are (0..ZR_MAX_CROSSINGS).
 * A ray that only grazes a surface (tangent) counts as a miss.
 */
int zr__intersect(const zr_object *object, const zr_ray *ray, double tmin,
                  double tmax, zr_hit hits[ZR_MAX_CROSSINGS]);

/* The same crossings without their normals (left zero), for searches
   that need only t and the object. */
int zr__intersect_t(const zr_object *object, const zr_ray *ray, double tmin,
                    double tmax, zr_hit hits[ZR_MAX_CROSSINGS]);

/* The nearest crossing in (tmin, tmax) first, with its normal when
   want_normals: zr__intersect or zr__intersect_t for most shapes, which
   may give a second crossing too; a shape that marches along the ray
   (julia_fractal, shape.h's search_upto) stops at the first. */
int zr__intersect_first(const zr_object *object, const zr_ray *ray,
                        double tmin, double tmax, bool want_normals,
                        zr_hit hits[ZR_MAX_CROSSINGS]);

/* For an unclipped object whose shape marches (shape.h's search_upto):
   the first crossings in (tmin, tmax), up to four, in t[] in order, t
   only, as zr__intersect_t gives the first two; *complete tells whether
   they are all of the interval's.  The march's points do not depend on
   tmin, so the crossings beyond some t' > tmin are those of t[] beyond
   t' (and, unless *complete, more): a shadow ray that asks again beyond
   each pair (lib/trace/bvh.c, visit_leaf) need not march again. */
int zr__intersect_march_t(const zr_object *object, const zr_ray *ray,
                          double tmin, double tmax, double t[4],
                          bool *complete);

/* The crossings as zr__intersect (want_normals) or zr__intersect_t
   give them; *all tells whether they are every crossing in (tmin,
   tmax), so that asking again beyond the last would find none (a shape
   whose list does not depend on the interval, with no more crossings
   than hits[] holds). */
int zr__intersect_all(const zr_object *object, const zr_ray *ray,
                      double tmin, double tmax, bool want_normals,
                      zr_hit hits[ZR_MAX_CROSSINGS], bool *all);

/* The surface coordinates (u, v) of hit at world point p, as POV-Ray
   3.7 defines them ("UV Mapping", "Supported Objects"); false when the
   object has none. */
bool zr__hit_uv(const zr_hit *hit, zr_vec3 p, double *u, double *v);

/* The object's world-space bounding box; false for unbounded objects
   (planes, and anything inverse) (lib/trace/bounds.c). */
bool zr__object_bounds(const zr_object *object, zr_vec3 *lo, zr_vec3 *hi);
/* The box the hierarchy keeps a primitive in: zr__object_bounds(), or
   else its bounded_by's box for a plain shape that is not inverted. */
bool zr__primitive_bounds(const zr_object *object, zr_vec3 *lo,
                          zr_vec3 *hi);
/* For an object that holds everything far enough away (an inverted
   shape, a CSG part cut out by a difference): a box outside which it
   holds every point, and which holds its surface, so that a ray that
   misses the box cannot cross it.  It is the box of the un-inverted
   object.  False when there is none: no inverted part, a clip, a shape
   whose inside may reach beyond its box (a disc's half-space, a height
   field below its lowest sample), or a CSG part whose children's boxes
   (prepare.c, read from u.csg.boxes) do not give one. */
bool zr__complement_bounds(const zr_object *object, zr_vec3 *lo,
                           zr_vec3 *hi);
/* Whether every point the object's inside test takes lies in its box
   (zr__object_bounds; true when it has none), so that a CSG object may
   answer "not inside this part" outside the part's box and keep only
   the other parts' crossings that lie in it.  False for a disc (its
   inside is its plane's half-space) and a height field (its inside
   reaches below its lowest sample), and for a union or merge, or a clip,
   with such a part. */
bool zr__box_holds_inside(const zr_object *object);
/* The CSG part's box before its own clip, kept in its u.csg.whole
   (NULL before) when the scene is prepared: zr__object_bounds() then
   reads it instead of narrowing it from the children again. */
zr_status zr__csg_keep_whole_box(zr_arena *arena, zr_object *part);

/* Whether the world point p lies inside the object (POV-Ray's inside, with
   inverse applied).  Triangles have no inside; a disc's is its plane's. */
bool zr__inside(const zr_object *object, zr_vec3 p);

/* CSG primitives (lib/trace/csg.c): the same contracts as
   zr__intersect (normals only when want_normals) and zr__inside; with
   wanted 1 only the nearest crossing is sure to be reported (the
   second, if any, may not be the second nearest), with
   ZR_MAX_CROSSINGS the nearest two. */
int zr__csg_crossings(const zr_object *object, const zr_ray *ray,
                      double tmin, double tmax, bool want_normals,
                      int wanted, zr_hit hits[ZR_MAX_CROSSINGS]);
bool zr__csg_inside(const zr_object *object, zr_vec3 p);
/* Makes node->u.csg.tree from its children's boxes when it has many
   (ZR_CSG_TREE_MIN or more) bounded children; the tree lives in arena. */
#define ZR_CSG_TREE_MIN 8
zr_status zr__csg_tree_build(zr_arena *arena, zr_object *node);

/* Whether the object encloses a volume (triangles and discs do not, so
   rays crossing them stay in the medium they were in). */
bool zr__mesh_has_inside(const zr_object *object); /* obj_mesh.c */
bool zr__has_inside(const zr_object *object);

/*
 * The distance by which a secondary ray leaving point p is moved off the
 * surface along the normal, so that rounding in the hit point cannot make
 * the ray find its own surface again: relative to the size of the
 * coordinates, as POV-Ray scenes range from 1e-3 to 1e5 units.
 */
static inline double zr__surface_offset(zr_vec3 p) {
  double m = fmax(fabs(p.x), fmax(fabs(p.y), fabs(p.z)));
  return 1e-8 * fmax(1.0, m);
}

/* Whether kind is one of the simple shapes whose crossings cost one
   closed-form test (no search, no hierarchy of its own): the shadow
   cache (shade.c) and the light shafts (shaft.c) keep only these. */
static inline bool zr__simple_kind(zr_object_kind kind) {
  switch (kind) {
  case ZR_OBJ_SPHERE:
  case ZR_OBJ_BOX:
  case ZR_OBJ_PLANE:
  case ZR_OBJ_TRIANGLE:
  case ZR_OBJ_CYLINDER:
  case ZR_OBJ_CONE:
  case ZR_OBJ_DISC:
    return true;
  default:
    return false;
  }
}

#endif /* ZR_TRACE_INTERSECT_H */
