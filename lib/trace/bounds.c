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
 * keeps them in its list of unbounded primitives.  Inside a CSG object
 * an inverted part still has a box of another kind
 * (zr__complement_bounds): its surface lies in the box of its
 * un-inverted shape, and it holds every point outside that box.
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
/* The box of a plain shape (not CSG), inverse or not. */
static bool shape_bounds(const zr_object *object, zr_vec3 *lo,
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
  return shape_bounds(object, lo, hi);
}

static bool shape_bounds(const zr_object *object, zr_vec3 *lo,
                         zr_vec3 *hi) {
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

/* The shapes whose inside lies within their box (bounds.c's box holds
   every point their inside test takes): the solids bounded by their
   own surface.  Not a disc (its inside is its plane's half-space), a
   height field (its inside reaches down without end below it),
   a mesh (inside_vector's parity of an open mesh), a blob (a threshold
   at or below zero holds all space), nor the unbounded shapes. */
static bool inside_within_box(zr_object_kind kind) {
  switch (kind) {
  case ZR_OBJ_SPHERE:
  case ZR_OBJ_BOX:
  case ZR_OBJ_CYLINDER:
  case ZR_OBJ_CONE:
  case ZR_OBJ_TORUS:
  case ZR_OBJ_SUPERELLIPSOID:
  case ZR_OBJ_OVUS:
  case ZR_OBJ_LATHE:
  case ZR_OBJ_SOR:
  case ZR_OBJ_PRISM:
    return true;
  default:
    return false;
  }
}

/* The shapes whose inside reaches beyond their box (zr__box_holds_inside):
   a disc's inside is its plane's half-space (the manual: "not
   constrained by the radius of the disc"), a height field's reaches
   below its lowest sample.  POV-Ray 3.7 draws intersection { sphere {
   -0.5*y, 1 } disc { 0, -y, 1.5 } } as the sphere's cap above the disc
   (stock advanced/desk/desk.pov's paperweight) and intersection {
   height_field { function 8, 8 { 0.5 } } box { <0.1, -0.5, 0.1>, <0.9,
   2, 0.9> } } with the box's sides up to the field (tests/csg_inside.pov);
   taking the disc's or the field's box as the box of its inside drew the
   flat disc alone and the field's top alone.  Meshes and blobs keep
   their box (an open mesh or a blob with a threshold at or below zero
   may hold points outside it; not measured). */
static bool inside_beyond_box(zr_object_kind kind) {
  return kind == ZR_OBJ_DISC || kind == ZR_OBJ_HEIGHT_FIELD;
}

bool zr__box_holds_inside(const zr_object *object) {
  /* A clipped object's box is its own box within the clip's (or the
     clip's alone when it has none), and its inside is within both
     insides. */
  zr_vec3 lo, hi;
  if (object->clip && !zr__box_holds_inside(object->clip))
    return false;
  if (object->clip && !unclipped_bounds(object, &lo, &hi))
    return true;
  if (object->kind == ZR_OBJ_UNION || object->kind == ZR_OBJ_MERGE) {
    for (size_t i = 0; i < object->u.csg.n_children; i++)
      if (!zr__box_holds_inside(object->u.csg.children[i]))
        return false;
    return true;
  }
  /* An intersection's box is narrowed only by the parts whose box holds
     their inside (bounds_csg.c), and an inverted shape has no box. */
  if (zr__is_csg(object->kind) || object->inverse)
    return true;
  return !inside_beyond_box(object->kind);
}

/*
 * A CSG part holds what lies outside its box when (De Morgan, as
 * lib/sdl/build_object.c inverts) it is an inverted merge or
 * intersection:
 *   - an intersection holds p when every child does: outside the union
 *     of its children's boxes, if each child holds what lies outside
 *     its own; its surface is made of theirs, so it lies in that union;
 *   - a merge holds p when some child does: outside the overlap of the
 *     boxes of the children that hold what lies outside theirs; a
 *     crossing of one child survives only where no other holds it, so
 *     inside the other children's boxes, and a crossing of one of those
 *     children lies in its own box too.
 * A union keeps every child's crossings, so it gets none.
 */
bool zr__complement_bounds(const zr_object *object, zr_vec3 *lo,
                           zr_vec3 *hi) {
  if (object->clip)
    return false;
  if (!zr__is_csg(object->kind))
    return object->inverse && inside_within_box(object->kind) &&
           shape_bounds(object, lo, hi);
  const struct zr_csg_box *b = object->u.csg.boxes;
  size_t n = object->u.csg.n_children;
  if (object->inverse || !b || n == 0 || object->kind == ZR_OBJ_UNION)
    return false;
  bool merge = object->kind == ZR_OBJ_MERGE, any = false;
  zr_vec3 all = zr_v3(INFINITY, INFINITY, INFINITY), none = zr_v3_neg(all);
  /* A merge's overlap starts from all space, an intersection's union
     from nothing. */
  zr_vec3 l = merge ? none : all, h = merge ? all : none;
  for (size_t i = 0; i < n; i++) {
    if (!b[i].bounded || !b[i].holds_outside) {
      if (!merge)
        return false;
      continue;
    }
    any = true;
    l = merge ? zr_v3_max(l, b[i].lo) : zr_v3_min(l, b[i].lo);
    h = merge ? zr_v3_min(h, b[i].hi) : zr_v3_max(h, b[i].hi);
  }
  if (!any)
    return false;
  /* Boxes that do not overlap: the merge holds all space and has no
     surface; a flat box at the corner keeps the tests well defined. */
  *lo = l;
  *hi = zr_v3_max(l, h);
  return true;
}
