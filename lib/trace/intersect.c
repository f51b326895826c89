/*
 * intersect.c - rays and points against any primitive: what every shape
 * shares, around the operations of its own table (lib/trace/shape.h,
 * one file per primitive: obj_sphere.c, obj_box.c ...).
 *
 * A transformed object is intersected in its own coordinates: the ray is
 * mapped by the inverse matrix and its direction is NOT normalised, so
 * the parameter t found there is the same t along the world ray and needs
 * no conversion.  The object-space normal goes back to world space by the
 * inverse transpose (zr__xform_normal with the inverse).  Each shape
 * gives its candidate crossings; here they are clipped (clipped_by),
 * kept inside the interval, sorted, and given world normals; inverse
 * turns normals and insides.
 */
#include "trace/intersect.h"

#include <math.h>

#include "trace/obj_shapes.h"
#include "trace/shape.h"

/* clipped_by: drops the crossings outside the clipping object, which is
   tested in world space (the ray's t is the same in both spaces). */
static void clip_crossings(const zr_object *clip, const zr_ray *ray,
                           zr_crossings *l) {
  int kept = 0;
  for (int i = 0; i < l->n; i++) {
    if (!zr__inside(clip, zr_v3_madd(ray->origin, ray->dir, l->t[i])))
      continue;
    l->t[kept] = l->t[i];
    l->normal[kept] = l->normal[i];
    l->texture[kept] = l->texture[i];
    l->u[kept] = l->u[i];
    l->v[kept] = l->v[i];
    kept++;
  }
  l->n = kept;
}

/* bounded_by on a poly, cubic or quartic: POV-Ray tests such a shape only
   for rays that meet the bounding object itself, and then keeps every
   crossing the shape has along them, inside the bound or not ("Bounded_By":
   a bound too small "may clip the object in undefined ways").  Measured
   with POV-Ray 3.7 (tests/bounded_poly.pov): a quartic torus bounded by a
   sphere that covers part of it shows the part inside the sphere's
   silhouette, round edges and all, and a poly sphere of radius 1 bounded
   by a sphere of radius 0.5 shows as a disc of radius 0.5 shaded as the
   big sphere; the bound's box alone (bounds.c, which the hierarchy keeps
   using) drew both with square edges, and cut the corners of
   objects/quartic/hyptorus.pov's two tubes, which POV-Ray leaves out.
   The test is along the whole ray from its origin, not only (tmin, tmax):
   the tracer asks a hit again from just before it for its normal
   (bvh.c), and that second question must get the same answer.  Other
   shapes test their own bound's box here, and only when that box is
   smaller than theirs (object->bound_cuts, lib/trace/prepare.c
   bound_by_box); a union's bound handed down to them is their box in
   the hierarchy only. */
static bool meets_bound(const zr_object *bound, const zr_ray *ray) {
  if (zr__inside(bound, ray->origin))
    return true;
  zr_hit h[ZR_MAX_CROSSINGS];
  return zr__intersect_first(bound, ray, 0.0, INFINITY, false, h) > 0;
}

/* The ray in the object's own space, in org and dir; false when the
   object's bound cuts it and the ray misses the bound. */
static bool local_ray(const zr_object *object, const zr_ray *ray,
                      zr_vec3 *org, zr_vec3 *dir) {
  if (object->bound &&
      (object->kind == ZR_OBJ_POLY || object->bound_cuts) &&
      !meets_bound(object->bound, ray))
    return false;
  *org = ray->origin;
  *dir = ray->dir;
  if (object->transform) {
    *org = zr__xform_point(object->transform->inv, *org);
    *dir = zr__xform_dir(object->transform->inv, *dir);
  }
  return true;
}

/* The crossings in (tmin, tmax), sorted, with world normals only when
   asked for: traversal needs t alone, and normals cost a matrix product
   and a square root each.  A shape that marches (search_upto) is asked
   for no more than `wanted` (1 or ZR_MAX_CROSSINGS), or for all its
   crossings when a clip may remove some. */
static int crossings(const zr_object *object, const zr_ray *ray,
                     double tmin, double tmax, bool want_normals,
                     int wanted, zr_hit hits[ZR_MAX_CROSSINGS],
                     bool *all) {
  *all = false;
  if (zr__is_csg(object->kind)) /* children carry their transforms */
    return zr__csg_crossings(object, ray, tmin, tmax, want_normals, wanted,
                             hits);
  zr_vec3 org, dir;
  if (!local_ray(object, ray, &org, &dir))
    return 0;
  const zr_shape_ops *ops = zr__shape(object->kind);
  zr_crossings l;
  l.n = 0;
  if (ops->search_upto) {
    double t[ZR_SHAPE_MAX_CROSSINGS];
    zr_vec3 n[ZR_SHAPE_MAX_CROSSINGS];
    int k = ops->search_upto(object, org, dir, tmin, tmax,
                             object->clip ? ZR_SHAPE_MAX_CROSSINGS : wanted,
                             t, want_normals ? n : NULL);
    for (int i = 0; i < k; i++)
      zr__crossings_add(&l, t[i], want_normals ? n[i] : zr_v3(0, 0, 0));
  } else if (ops->search) {
    double t[ZR_SHAPE_MAX_CROSSINGS];
    zr_vec3 n[ZR_SHAPE_MAX_CROSSINGS];
    int k = ops->search(object, org, dir, tmin, tmax, t, n);
    for (int i = 0; i < k; i++)
      zr__crossings_add(&l, t[i], n[i]);
  } else {
    ops->crossings(object, org, dir, tmin, tmax, &l);
  }
  if (object->clip)
    clip_crossings(object->clip, ray, &l);
  *all = ops->interval_free && l.n <= ZR_MAX_CROSSINGS;
  int n = 0;
  for (int i = 0; i < l.n; i++) {
    double t = l.t[i];
    if (!(t > tmin && t < tmax))
      continue;
    /* Insertion keeps the list sorted; a third crossing (only possible
       through rounding at a cap edge) replaces the farthest if nearer. */
    int j = n < ZR_MAX_CROSSINGS ? n++ : ZR_MAX_CROSSINGS;
    if (j == ZR_MAX_CROSSINGS) {
      if (t >= hits[j - 1].t)
        continue;
      j--;
    }
    while (j > 0 && hits[j - 1].t > t) {
      hits[j] = hits[j - 1];
      j--;
    }
    zr_vec3 nrm = zr_v3(0, 0, 0);
    if (want_normals) {
      nrm = l.normal[i];
      if (object->transform)
        nrm = zr__xform_normal(object->transform->inv, nrm);
      nrm = zr_v3_norm(nrm);
      if (object->inverse)
        nrm = zr_v3_neg(nrm);
    }
    hits[j].t = t;
    hits[j].normal = nrm;
    hits[j].object =
        ops->hit_object ? ops->hit_object(object, l.texture[i]) : object;
    hits[j].u = l.u[i];
    hits[j].v = l.v[i];
  }
  return n;
}

int zr__intersect_march_t(const zr_object *object, const zr_ray *ray,
                          double tmin, double tmax, double t[4],
                          bool *complete) {
  *complete = true;
  zr_vec3 org, dir;
  if (!local_ray(object, ray, &org, &dir))
    return 0;
  double found[ZR_SHAPE_MAX_CROSSINGS];
  int k = zr__shape(object->kind)->search_upto(
      object, org, dir, tmin, tmax, ZR_SHAPE_MAX_CROSSINGS, found, NULL);
  /* Fewer than asked for: the march reached the interval's end. */
  *complete = k < ZR_SHAPE_MAX_CROSSINGS;
  /* What crossings() keeps of them: finite (zr__crossings_add) and in
     the interval, in the march's order, which is t's. */
  int n = 0;
  for (int i = 0; i < k; i++)
    if (isfinite(found[i]) && found[i] > tmin && found[i] < tmax)
      t[n++] = found[i];
  return n;
}

int zr__intersect(const zr_object *object, const zr_ray *ray, double tmin,
                  double tmax, zr_hit hits[ZR_MAX_CROSSINGS]) {
  bool all;
  return crossings(object, ray, tmin, tmax, true, ZR_MAX_CROSSINGS, hits,
                   &all);
}

int zr__intersect_t(const zr_object *object, const zr_ray *ray, double tmin,
                    double tmax, zr_hit hits[ZR_MAX_CROSSINGS]) {
  bool all;
  return crossings(object, ray, tmin, tmax, false, ZR_MAX_CROSSINGS, hits,
                   &all);
}

int zr__intersect_first(const zr_object *object, const zr_ray *ray,
                        double tmin, double tmax, bool want_normals,
                        zr_hit hits[ZR_MAX_CROSSINGS]) {
  bool all;
  return crossings(object, ray, tmin, tmax, want_normals, 1, hits, &all);
}

int zr__intersect_all(const zr_object *object, const zr_ray *ray,
                      double tmin, double tmax, bool want_normals,
                      zr_hit hits[ZR_MAX_CROSSINGS], bool *all) {
  return crossings(object, ray, tmin, tmax, want_normals, ZR_MAX_CROSSINGS,
                   hits, all);
}

bool zr__inside(const zr_object *object, zr_vec3 p) {
  if (zr__is_csg(object->kind))
    return zr__csg_inside(object, p);
  const zr_shape_ops *ops = zr__shape(object->kind);
  if (!ops->inside || (ops->has_inside && !ops->has_inside(object)))
    return false; /* no inside, inverse or not */
  zr_vec3 local = p;
  if (object->transform)
    local = zr__xform_point(object->transform->inv, p);
  bool in = ops->inside(object, local) != object->inverse;
  /* A clipped object is inside where it and its clip both are. */
  return in && (!object->clip || zr__inside(object->clip, p));
}

bool zr__has_inside(const zr_object *object) {
  const zr_shape_ops *ops = zr__shape(object->kind);
  return ops->inside && !ops->flat &&
         (!ops->has_inside || ops->has_inside(object));
}

bool zr__hit_uv(const zr_hit *hit, zr_vec3 p, double *u, double *v) {
  const zr_object *o = hit->object;
  const zr_shape_ops *ops = zr__shape(o->kind);
  if (ops->uv_from_hit) {
    *u = hit->u;
    *v = hit->v;
    return true;
  }
  if (!ops->uv) {
    *u = *v = 0.0;
    return false;
  }
  if (o->transform)
    p = zr__xform_point(o->transform->inv, p);
  ops->uv(o, p, u, v);
  return true;
}
