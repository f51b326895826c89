/*
 * bounds.c - world-space axis-aligned bounding boxes of primitives.
 *
 * The tracer's bounding volume hierarchy (lib/trace/bvh.c) needs a box
 * around every finite primitive.  Each shape first gets a tight box in its
 * own coordinates: a sphere's cube, a box's corners, and for the round
 * shapes with an axis (cylinder, cone, disc) the exact extent of a circle
 * of radius r about a unit axis a, which along world axis i is
 * r * sqrt(1 - a_i^2).  When the object carries a transform, the eight
 * corners of that box are mapped to world space and boxed again, which is
 * conservative for any affine map.
 *
 * Meshes and text keep the box of their own geometry (lib/trace), as
 * do the shapes of lib/trace/obj_shapes.h.
 * Planes and anything marked `inverse` have no finite extent (POV-Ray
 * reference, "Plane" and "Inverse"), so they report false and the BVH
 * keeps them in its list of unbounded primitives.
 */
#include "trace/intersect.h"

#include <math.h>

#include "trace/obj_isosurface.h"
#include "trace/obj_mesh.h"
#include "trace/obj_shapes.h"
#include "trace/obj_sweep.h"
#include "trace/obj_text.h"

/* The half extents along x, y and z of a circle of radius r about the
   unit axis a. */
static zr_vec3 circle_extent(zr_vec3 a, double r) {
  return zr_v3(r * sqrt(fmax(0.0, 1.0 - a.x * a.x)),
               r * sqrt(fmax(0.0, 1.0 - a.y * a.y)),
               r * sqrt(fmax(0.0, 1.0 - a.z * a.z)));
}

/* Grows [lo, hi] by the circle of radius r about axis a centred at c. */
static void add_circle(zr_vec3 c, zr_vec3 a, double r, zr_vec3 *lo,
                       zr_vec3 *hi) {
  zr_vec3 e = circle_extent(a, r);
  *lo = zr_v3_min(*lo, zr_v3_sub(c, e));
  *hi = zr_v3_max(*hi, zr_v3_add(c, e));
}

/* The box of the untransformed shape; false when it is unbounded. */
static bool local_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  const zr_vec3 inf = zr_v3(INFINITY, INFINITY, INFINITY);
  *lo = inf;
  *hi = zr_v3_neg(inf);
  switch (o->kind) {
  case ZR_OBJ_SPHERE: {
    double r = fabs(o->u.sphere.radius);
    zr_vec3 e = zr_v3(r, r, r);
    *lo = zr_v3_sub(o->u.sphere.centre, e);
    *hi = zr_v3_add(o->u.sphere.centre, e);
    return true;
  }
  case ZR_OBJ_BOX:
    *lo = zr_v3_min(o->u.box.corner1, o->u.box.corner2);
    *hi = zr_v3_max(o->u.box.corner1, o->u.box.corner2);
    return true;
  case ZR_OBJ_TRIANGLE:
    for (int i = 0; i < 3; i++) {
      *lo = zr_v3_min(*lo, o->u.triangle.p[i]);
      *hi = zr_v3_max(*hi, o->u.triangle.p[i]);
    }
    return true;
  case ZR_OBJ_CYLINDER: {
    zr_vec3 a = zr_v3_norm(zr_v3_sub(o->u.cylinder.cap, o->u.cylinder.base));
    add_circle(o->u.cylinder.base, a, fabs(o->u.cylinder.radius), lo, hi);
    add_circle(o->u.cylinder.cap, a, fabs(o->u.cylinder.radius), lo, hi);
    return true;
  }
  case ZR_OBJ_CONE: {
    zr_vec3 a = zr_v3_norm(zr_v3_sub(o->u.cone.cap, o->u.cone.base));
    add_circle(o->u.cone.base, a, fabs(o->u.cone.base_radius), lo, hi);
    add_circle(o->u.cone.cap, a, fabs(o->u.cone.cap_radius), lo, hi);
    return true;
  }
  case ZR_OBJ_DISC:
    add_circle(o->u.disc.centre, zr_v3_norm(o->u.disc.normal),
               fabs(o->u.disc.radius), lo, hi);
    return true;
  case ZR_OBJ_MESH:
    /* The box of the mesh's vertices; an empty mesh has none. */
    *lo = o->u.mesh.data->lo;
    *hi = o->u.mesh.data->hi;
    return o->u.mesh.data->n_faces > 0;
  case ZR_OBJ_TEXT:
    *lo = o->u.text.data->lo;
    *hi = o->u.text.data->hi;
    return o->u.text.data->n_glyphs > 0;
  case ZR_OBJ_TORUS:
    zr__torus_bounds(o, lo, hi);
    return true;
  case ZR_OBJ_POLYGON:
    *lo = o->u.polygon.lo;
    *hi = o->u.polygon.hi;
    return o->u.polygon.n_edges > 0;
  case ZR_OBJ_PRISM:
    zr__prism_bounds(o, lo, hi);
    return o->u.prism.n_seg > 0;
  case ZR_OBJ_LATHE:
    zr__lathe_bounds(o, lo, hi);
    return o->u.lathe.n_seg > 0;
  case ZR_OBJ_BLOB:
    return zr__blob_bounds(o, lo, hi);
  case ZR_OBJ_SOR:
    zr__sor_bounds(o, lo, hi);
    return true;
  case ZR_OBJ_SPHERE_SWEEP:
    zr__sweep_bounds(o, lo, hi);
    return o->u.sweep.data->n_segments > 0;
  case ZR_OBJ_JULIA:
    zr__julia_bounds(o, lo, hi);
    return true;
  case ZR_OBJ_ISOSURFACE:
    zr__isosurface_bounds(o, lo, hi);
    return true;
  case ZR_OBJ_HEIGHT_FIELD:
    return zr__height_field_bounds(o, lo, hi);
  case ZR_OBJ_OVUS:
    zr__ovus_bounds(o, lo, hi);
    return true;
  case ZR_OBJ_PARAMETRIC:
    zr__parametric_bounds(o, lo, hi);
    return true;
  case ZR_OBJ_SUPERELLIPSOID:
    *lo = zr_v3(-1, -1, -1);
    *hi = zr_v3(1, 1, 1);
    return true;
  case ZR_OBJ_PLANE:
  case ZR_OBJ_QUADRIC: /* infinite unless clipped or intersected */
  case ZR_OBJ_POLY:
  case ZR_OBJ_UNION:
  case ZR_OBJ_INTERSECTION:
  case ZR_OBJ_MERGE:
    return false;
  }
  return false;
}

/*
 * An intersection lies in each of its children, so its box is the
 * overlap of the bounded children's boxes; unbounded ones (inverted
 * children of a difference, quadrics) add no limit.  A clip limits an
 * object the same way.
 */
static bool overlap_bounds(const zr_object *const *parts, size_t n,
                           zr_vec3 *lo, zr_vec3 *hi) {
  bool any = false;
  zr_vec3 l = zr_v3(-INFINITY, -INFINITY, -INFINITY), h = zr_v3_neg(l);
  for (size_t i = 0; i < n; i++) {
    zr_vec3 cl, ch;
    if (!zr__object_bounds(parts[i], &cl, &ch))
      continue;
    l = zr_v3_max(l, cl);
    h = zr_v3_min(h, ch);
    any = true;
  }
  if (!any)
    return false;
  /* Disjoint children leave an empty box: keep it a point, so the BVH
     still holds the object (it has no surface anyway). */
  *lo = l;
  *hi = zr_v3_max(l, h);
  return true;
}

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
  if (object->inverse)
    return false;
  if (object->kind == ZR_OBJ_INTERSECTION)
    return overlap_bounds((const zr_object *const *)object->u.csg.children,
                          object->u.csg.n_children, lo, hi);
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
  if (object->transform) {
    zr_vec3 wl = zr_v3(INFINITY, INFINITY, INFINITY), wh = zr_v3_neg(wl);
    for (int c = 0; c < 8; c++) {
      zr_vec3 p = zr_v3(c & 1 ? h.x : l.x, c & 2 ? h.y : l.y,
                        c & 4 ? h.z : l.z);
      p = zr__xform_point(object->transform->m, p);
      wl = zr_v3_min(wl, p);
      wh = zr_v3_max(wh, p);
    }
    l = wl;
    h = wh;
  }
  /* A degenerate box (a flat triangle along an axis) is widened by a
     relative hair so slab tests against it stay well defined. */
  double pad = 1e-9 * fmax(1.0, fmax(zr_v3_max_comp(zr_v3_max(
                                         zr_v3_neg(l), h)), 0.0));
  *lo = zr_v3_sub(l, zr_v3(pad, pad, pad));
  *hi = zr_v3_add(h, zr_v3(pad, pad, pad));
  return isfinite(lo->x) && isfinite(lo->y) && isfinite(lo->z) &&
         isfinite(hi->x) && isfinite(hi->y) && isfinite(hi->z);
}
