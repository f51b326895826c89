/*
 * build_object.c - building CSG objects, quadrics and the rarer object
 * modifiers (hollow, clipped_by, bounded_by) for the grammar's actions.
 *
 * Reference manual r3_4: "Constructive Solid Geometry", "Quadric",
 * "Hollow", "Clipped_By", "Bounded_By", "Inverse", "Poly, Cubic and
 * Quartic".
 *   - A difference is an intersection of its first child with the others
 *     inverted ("Difference"); it is built so, and the tracer only knows
 *     intersection, merge and union (lib/trace/csg.c).
 *   - inverse turns an object inside out.  For a CSG object this is done
 *     by De Morgan's laws: the children are inverted and an intersection
 *     becomes a merge, a merge or union an intersection.  Inverse flags
 *     thus only sit on plain shapes, whose normals then point out of the
 *     whole solid.
 *   - clipped_by { objects } keeps the part of the object's surface that
 *     lies inside every clipping object, and nothing of theirs.  The
 *     clipping objects are kept as one intersection and follow the
 *     object's later transforms.  clipped_by { bounded_by } clips by the
 *     bounding objects.
 *   - bounded_by may only make tracing faster and never changes the
 *     picture, so zRcube keeps it (for clipped_by { bounded_by }) and
 *     bounds objects itself; only a part it cannot box (a quartic, a
 *     poly) takes the bound's box (lib/trace/prepare.c).
 *     bounded_by { clipped_by } is likewise only a bound.
 *   - hollow is stored: it matters for media only.
 *   - poly { Order, <A1, ..., An> }, cubic and quartic take exactly
 *     (Order+1)(Order+2)(Order+3)/6 coefficients, counted as they come.
 */
#include "config.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "pov-parse.h"
#include "sdl/sdl.h"
#include "sdl/build_camlight.h"
#include "sdl/build_media.h"
#include "trace/obj_poly.h"
#include "trace/roots.h"

void zr__sdl_object_invert(zr_object *o) {
  if (!zr__is_csg(o->kind)) {
    o->inverse = !o->inverse;
    return;
  }
  o->kind = o->kind == ZR_OBJ_INTERSECTION ? ZR_OBJ_MERGE
                                           : ZR_OBJ_INTERSECTION;
  for (size_t i = 0; i < o->u.csg.n_children; i++)
    zr__sdl_object_invert(o->u.csg.children[i]);
}

bool zr__sdl_difference_add(zr_sdl_parser *p, zr_object *d,
                            zr_object *child) {
  if (d->u.csg.n_children > 0)
    zr__sdl_object_invert(child);
  return zr__sdl_union_add(p, d, child);
}

bool zr__sdl_object_mod_more(zr_sdl_parser *p, zr_object *o,
                             const zr_sdl_mod *mod) {
  switch (mod->kind) {
  case ZR_SDL_MOD_HOLLOW:
    /* A union's parts are traced one by one: they carry the flag that
       lets media be seen through them (lib/trace/media.c). */
    o->hollow = mod->ptr == NULL;
    if (zr__is_csg(o->kind))
      for (size_t i = 0; i < o->u.csg.n_children; i++)
        zr__sdl_object_mod_more(p, o->u.csg.children[i], mod);
    return true;
  case ZR_SDL_MOD_CLIPPED_BY:
    o->clip = mod->ptr;
    return true;
  case ZR_SDL_MOD_BOUNDED_BY:
    o->bound = mod->ptr;
    return true;
  case ZR_SDL_MOD_CLIP_TO_BOUND:
    /* A copy, so that later transforms move the clip only once. */
    if (o->bound && !(o->clip = zr__sdl_object_copy(p, o->bound)))
      return false;
    return true;
  case ZR_SDL_MOD_BOUND_TO_CLIP:
    return true; /* a bound only: nothing to do */
  case ZR_SDL_MOD_INTERIOR_TEXTURE:
    zr__sdl_interior_texture(o, mod->ptr); /* build_media.c */
    return true;
  default:
    break;
  }
  return true;
}

zr_object *zr__sdl_quadric(zr_sdl_parser *p, const zr_sdl_expr e[4],
                           const zr_sdl_loc *loc, const zr_sdl_loc at[4]) {
  zr_object *o = zr__sdl_object_new(p, ZR_OBJ_QUADRIC, loc);
  if (!o)
    return NULL;
  double *q = o->u.quadric.coef;
  zr_vec3 v;
  for (int i = 0; i < 3; i++) {
    if (!zr__sdl_want_vector(p, &e[i], &at[i], &v))
      return NULL;
    q[3 * i] = v.x;
    q[3 * i + 1] = v.y;
    q[3 * i + 2] = v.z;
  }
  if (!zr__sdl_want_float(p, &e[3], &at[3], &q[9]))
    return NULL;
  return o;
}

/* ---- poly, cubic, quartic ("Poly, Cubic and Quartic") ---- */

zr_object *zr__sdl_poly_new(zr_sdl_parser *p, const zr_sdl_expr *order,
                            const zr_sdl_loc *order_loc,
                            const zr_sdl_loc *loc) {
  double n;
  if (!zr__sdl_want_float(p, order, order_loc, &n))
    return NULL;
  /* POV-Ray takes orders 2 to 35; lib/trace/roots.c solves up to
     ZR_POLY_MAX_DEGREE, which covers cubic, quartic and the stock
     scenes' polys. */
  if (n != floor(n) || n < 2 || n > ZR_POLY_MAX_DEGREE) {
    zr__sdl_error(p, ZR_EUNSUPPORTED, order_loc,
                  "a poly's order must be a whole number from 2 to %d, "
                  "not %g", ZR_POLY_MAX_DEGREE, n);
    return NULL;
  }
  zr_object *o = zr__sdl_object_new(p, ZR_OBJ_POLY, loc);
  if (!o)
    return NULL;
  o->u.poly.order = (int)n;
  size_t terms = (size_t)zr__poly_terms(o->u.poly.order);
  if (!(o->u.poly.coef = zr__sdl_alloc(p, terms * sizeof(double))))
    return NULL;
  memset(o->u.poly.coef, 0, terms * sizeof(double));
  return o;
}

bool zr__sdl_poly_coef(zr_sdl_parser *p, zr_object *o, const zr_sdl_expr *e,
                       const zr_sdl_loc *loc) {
  double v;
  if (!zr__sdl_want_float(p, e, loc, &v))
    return false;
  int terms = zr__poly_terms(o->u.poly.order);
  if (o->u.poly.n_coef >= terms) {
    zr__sdl_error(p, ZR_ESYNTAX, loc,
                  "a poly of order %d has %d coefficients, not more",
                  o->u.poly.order, terms);
    return false;
  }
  o->u.poly.coef[o->u.poly.n_coef++] = v;
  return true;
}

bool zr__sdl_poly_done(zr_sdl_parser *p, zr_object *o,
                       const zr_sdl_loc *loc) {
  int terms = zr__poly_terms(o->u.poly.order);
  if (o->u.poly.n_coef == terms)
    return true;
  zr__sdl_error(p, ZR_ESYNTAX, loc,
                "a poly of order %d has %d coefficients, not %d",
                o->u.poly.order, terms, o->u.poly.n_coef);
  return false;
}

/* ---- light sources inside CSG ("Light Sources", "Union") ---- */

bool zr__sdl_csg_add_light(zr_sdl_parser *p, zr_object *csg, zr_light *l) {
  size_t n = csg->u.csg.n_lights;
  zr_light **grown = zr__sdl_alloc(p, (n + 1) * sizeof *grown);
  if (grown == NULL)
    return false;
  if (n > 0)
    memcpy(grown, csg->u.csg.lights, n * sizeof *grown);
  grown[n] = l;
  csg->u.csg.lights = grown;
  csg->u.csg.n_lights = n + 1;
  return true;
}

zr_light *zr__sdl_light_copy(zr_sdl_parser *p, const zr_light *l) {
  zr_light *copy = zr__sdl_alloc(p, sizeof *copy);
  if (copy == NULL)
    return NULL;
  *copy = *l;
  /* The looks_like object moves with the light: each copy needs its
     own. */
  if (l->looks_like &&
      !(copy->looks_like = zr__sdl_object_copy(p, l->looks_like)))
    return NULL;
  /* So does the projected_through one. */
  if (l->projected_through &&
      !(copy->projected_through =
            zr__sdl_object_copy(p, l->projected_through)))
    return NULL;
  return copy;
}

bool zr__sdl_csg_copy_lights(zr_sdl_parser *p, zr_object *copy) {
  size_t n = copy->u.csg.n_lights;
  if (n == 0)
    return true;
  zr_light **lights = zr__sdl_alloc(p, n * sizeof *lights);
  if (lights == NULL)
    return false;
  for (size_t i = 0; i < n; i++)
    if (!(lights[i] = zr__sdl_light_copy(p, copy->u.csg.lights[i])))
      return false;
  copy->u.csg.lights = lights;
  return true;
}

/* ---- light_group ("Light Group") ---- */

/* Puts the objects under o that are in no group yet into group g, and
   the groups directly under it inside g. */
static void join_group(zr_scene *scene, zr_object *o, uint32_t g) {
  if (o->light_group != 0 && o->light_group != g) {
    uint32_t top = o->light_group;
    while (scene->light_groups[top].parent != 0)
      top = scene->light_groups[top].parent;
    if (top != g)
      scene->light_groups[top].parent = g;
  } else {
    o->light_group = g;
  }
  if (zr__is_csg(o->kind)) {
    for (size_t i = 0; i < o->u.csg.n_children; i++)
      join_group(scene, o->u.csg.children[i], g);
    for (size_t i = 0; i < o->u.csg.n_lights; i++)
      if (o->u.csg.lights[i]->light_group == 0)
        o->u.csg.lights[i]->light_group = g;
  }
}

bool zr__sdl_light_group_done(zr_sdl_parser *p, zr_object *group,
                              bool global, const zr_sdl_loc *loc) {
  zr_scene *scene = p->scene;
  size_t n = scene->n_light_groups ? scene->n_light_groups : 1;
  if (n >= UINT32_MAX) {
    zr__sdl_error(p, ZR_ELIMIT, loc, "too many light groups");
    return false;
  }
  struct zr_light_group *grown =
      zr__sdl_alloc(p, (n + 1) * sizeof *grown);
  if (!grown)
    return false;
  if (scene->n_light_groups)
    memcpy(grown, scene->light_groups, n * sizeof *grown);
  else
    memset(grown, 0, sizeof *grown);
  grown[n].parent = 0;
  grown[n].global_lights = global;
  scene->light_groups = grown;
  scene->n_light_groups = n + 1;
  join_group(scene, group, (uint32_t)n);
  return true;
}

/* The lights of o and of its CSG children, in the order written. */
static bool add_lights(zr_sdl_parser *p, const zr_object *o,
                       const zr_sdl_loc *loc) {
  if (!zr__is_csg(o->kind))
    return true;
  for (size_t i = 0; i < o->u.csg.n_lights; i++)
    if (!zr__sdl_light_add(p, o->u.csg.lights[i], loc))
      return false;
  for (size_t i = 0; i < o->u.csg.n_children; i++)
    if (!add_lights(p, o->u.csg.children[i], loc))
      return false;
  return true;
}

bool zr__sdl_add_object(zr_sdl_parser *p, zr_object *o,
                        const zr_sdl_loc *loc) {
  if (zr__scene_add_object(p->scene, o) != ZR_OK) {
    zr__sdl_error(p, ZR_ENOMEM, loc, "out of memory");
    return false;
  }
  return add_lights(p, o, loc);
}
