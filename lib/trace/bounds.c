/*
 * bounds.c - world-space axis-aligned bounding boxes of primitives.
 *
 * The tracer's bounding volume hierarchy (lib/trace/bvh.c) needs a box
 * around every finite primitive.  Each shape first gets a tight box in its
 * own coordinates from its table of operations (lib/trace/shape.h): a
 * sphere's cube, a box's corners, and for the round shapes with an axis
 * (cylinder, cone, disc) the exact extent of a circle of radius r about a
 * unit axis a, which along world axis i is r * sqrt(1 - a_i^2).  When the
 * object carries a transform, the eight corners of that box are mapped to
 * world space and boxed again, which is conservative for any affine map.
 * Planes and anything marked `inverse` have no finite extent (POV-Ray
 * reference, "Plane" and "Inverse"), so they report false and the BVH
 * keeps them in its list of unbounded primitives.
 */
#include "trace/intersect.h"

#include <math.h>

#include "trace/bounds_csg.h"
#include "trace/shape.h"

/* The box of the untransformed shape (its table's bounds); false when
   it is unbounded. */
static bool local_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  const zr_shape_ops *ops = zr__shape(o->kind);
  if (!ops->bounds) {
    zr__bounds_empty(lo, hi);
    return false;
  }
  return ops->bounds(o, lo, hi);
}

/* An intersection's box: bounds_csg.c; a clip limits an object the way
   an intersection's child does. */
static bool unclipped_bounds(const zr_object *object, zr_vec3 *lo,
                             zr_vec3 *hi);

bool zr__object_bounds(const zr_object *object, zr_vec3 *lo, zr_vec3 *hi) {
  zr_vec3 l, h, cl, ch;
  bool bounded = unclipped_bounds(object, &l, &h);
  if (!object->clip || !zr__object_bounds(object->clip, &cl, &ch)) {
    *lo = l;
    *hi = h;
    return bounded;
  }
  if (!bounded) {
    *lo = cl;
    *hi = ch;
    return true;
  }
  *lo = zr_v3_max(l, cl);
  *hi = zr_v3_max(*lo, zr_v3_min(h, ch));
  return true;
}

static bool unclipped_bounds(const zr_object *object, zr_vec3 *lo,
                             zr_vec3 *hi) {
  if (zr__is_csg(object->kind) && object->u.csg.whole) {
    *lo = object->u.csg.whole->lo;
    *hi = object->u.csg.whole->hi;
    return object->u.csg.whole->bounded;
  }
  if (object->inverse)
    return false;
  if (object->kind == ZR_OBJ_INTERSECTION)
    /* The children's constraints narrow an unbounded box, which also
       bounds planes and quadrics cut by each other (bounds_csg.c). */
    return zr__intersection_bounds(object, lo, hi);
  if (object->kind == ZR_OBJ_UNION || object->kind == ZR_OBJ_MERGE) {
    /* Unions are flattened before the BVH is built; for completeness a
       union's box is the box of its children's boxes. */
    bool any = false;
    zr_vec3 l = zr_v3(INFINITY, INFINITY, INFINITY), h = zr_v3_neg(l);
    for (size_t i = 0; i < object->u.csg.n_children; i++) {
      zr_vec3 cl, ch;
      if (!zr__object_bounds(object->u.csg.children[i], &cl, &ch))
        return false;
      l = zr_v3_min(l, cl);
      h = zr_v3_max(h, ch);
      any = true;
    }
    if (!any)
      return false;
    *lo = l;
    *hi = h;
    return true;
  }
  zr_vec3 l, h;
  if (!local_bounds(object, &l, &h))
    return false;
  if (object->transform)
    zr__box_through(object->transform->m, &l, &h);
  /* A degenerate box (a flat triangle along an axis) is widened by a
     relative hair so slab tests against it stay well defined. */
  double pad = 1e-9 * fmax(1.0, fmax(zr_v3_max_comp(zr_v3_max(
                                         zr_v3_neg(l), h)), 0.0));
  *lo = zr_v3_sub(l, zr_v3(pad, pad, pad));
  *hi = zr_v3_add(h, zr_v3(pad, pad, pad));
  return isfinite(lo->x) && isfinite(lo->y) && isfinite(lo->z) &&
         isfinite(hi->x) && isfinite(hi->y) && isfinite(hi->z);
}

bool zr__primitive_bounds(const zr_object *object, zr_vec3 *lo,
                          zr_vec3 *hi) {
  if (zr__object_bounds(object, lo, hi))
    return true;
  /* What the tracer cannot box itself takes its bounded_by's box
     (prepare.c hands a union's down to its parts), as the hierarchy's
     box only: the bound holds the surface, which is all a ray test
     needs, but not the inside of an inverted or CSG object, so CSG
     children's boxes (inside tests) never use it. */
  if (!object->bound || object->inverse || zr__is_csg(object->kind))
    return false;
  return zr__object_bounds(object->bound, lo, hi);
}

zr_status zr__csg_keep_whole_box(zr_arena *arena, zr_object *part) {
  struct zr_csg_box *b = zr__arena_alloc(arena, sizeof *b);
  if (!b)
    return ZR_ENOMEM;
  zr__bounds_empty(&b->lo, &b->hi);
  part->u.csg.whole = NULL;
  b->bounded = unclipped_bounds(part, &b->lo, &b->hi);
  part->u.csg.whole = b;
  return ZR_OK;
}
