/*
 * prepare.c - the scene made ready for tracing.
 *
 * The parser fills a zr_scene with objects as written (lib/scene);
 * zr__scene_finish() then flattens unions (a plain union has no inside
 * test, so its children are traced as independent primitives), gives
 * every primitive a texture, makes a textured mesh's copies, and builds
 * the bounding volume hierarchy over the list.  This is the tracer's
 * work, not the model's: it lives here so that lib/scene includes
 * nothing of lib/trace (README, "Layering").
 */
#include "trace/prepare.h"

#include <stdlib.h>
#include <string.h>

#include "core/context.h"
#include "trace/bounds_csg.h"
#include "trace/bvh.h"
#include "trace/embree.h"
#include "trace/intersect.h"
#include "trace/photons.h"
#include "trace/shaft.h"
#include "trace/shape.h"

/* Grows *items (of *cap elements of size elem) to hold one more. */
static zr_status grow(void **items, size_t *cap, size_t n, size_t elem) {
  if (n < *cap)
    return ZR_OK;
  size_t new_cap = *cap ? *cap * 2 : 16;
  void *p = realloc(*items, new_cap * elem);
  if (!p)
    return ZR_ENOMEM;
  *items = p;
  *cap = new_cap;
  return ZR_OK;
}

typedef struct flat_list {
  const zr_object **items;
  size_t n, cap;
} flat_list;

/*
 * Appends the primitives under object.  Children without a texture take
 * the nearest enclosing union's; the parser has already pushed transforms
 * down, so each primitive carries its own complete transform.
 */
/*
 * A copy of a CSG primitive's part (lib/trace/csg.c) and of everything
 * under it, with textures inherited as in a union and default interiors
 * filled in; every part records the primitive it belongs to.
 */
/* The one interior the parts that have one share (depth first); NULL
   when none has one, or when they differ (*mixed then). */
static const zr_interior *parts_interior(const zr_object *o, bool *mixed) {
  if (o->interior)
    return o->interior;
  const zr_interior *found = NULL;
  if (zr__is_csg(o->kind))
    for (size_t i = 0; i < o->u.csg.n_children && !*mixed; i++) {
      const zr_interior *in = parts_interior(o->u.csg.children[i], mixed);
      if (in && found && in != found)
        *mixed = true;
      else if (in)
        found = in;
    }
  return *mixed ? NULL : found;
}

static zr_object *resolve_part(zr_scene *scene, const zr_object *object,
                               const zr_texture *inherited,
                               const zr_object *solid) {
  zr_object *copy = zr__arena_memdup(&scene->arena, object,
                                     zr__object_size(object->kind));
  if (!copy)
    return NULL;
  copy->texture = object->texture ? object->texture : inherited;
  /* A ray inside the primitive travels in one interior.  When the CSG
     has none of its own and its parts agree on one, that is it: povray
     3.7 refracts a glass box with a sphere cut out of it (the box's
     interior { ior 1.5 }) as the box alone, where the default interior
     of the whole let the rays through unbent (advanced/glasschess.pov's
     blocks vanished).  Parts with different interiors (wineglass.pov's
     merge of rim, bowl, beads and stem) leave the whole the default, but
     a ray entering the solid takes the interior of the part it enters
     by (lib/trace/shade.c zr__media_cross, stretch_interior).  A part
     without one has the scene's default, not the whole's: it neither
     leaves nor enters the others' interior, as in povray 3.7, where
     two stacked blocks merged, one of fade_distance 0.5 and one with no
     interior, fade neither a camera nor a shadow ray through both
     (bench/conform/shadow_fade_probe.sh cases 12, 13; with the whole's,
     0.333 and 0.2).  The sphere cut out of the box above still bends a
     ray to air and back: the default interior on top of the box's. */
  if (!copy->interior && !solid) {
    bool mixed = false;
    copy->interior = parts_interior(object, &mixed);
  }
  if (!copy->interior)
    copy->interior = scene->default_interior;
  copy->solid = solid;
  if (!zr__is_csg(object->kind) || object->u.csg.n_children == 0)
    return copy;
  size_t n = object->u.csg.n_children;
  copy->u.csg.children =
      zr__arena_alloc(&scene->arena, n * sizeof *copy->u.csg.children);
  if (!copy->u.csg.children)
    return NULL;
  for (size_t i = 0; i < n; i++) {
    copy->u.csg.children[i] = resolve_part(
        scene, object->u.csg.children[i], copy->texture, solid ? solid : copy);
    if (!copy->u.csg.children[i])
      return NULL;
  }
  /* The children's boxes, for lib/trace/csg.c to skip the children a
     ray or a point is clear of (a difference of unions of a few hundred
     parts, as in the corpus' spacecraft scenes, tested every part for
     every ray).  A clip added later only shrinks a child.  A child cut
     out (inverted) has no box of its own but holds all that lies
     outside the box of its un-inverted shape (the corpus' BAMSSLB2: a
     slab minus chars.inc's letters tested every part of every letter
     for every ray and every point on the slab). */
  copy->u.csg.boxes =
      zr__arena_alloc(&scene->arena, n * sizeof *copy->u.csg.boxes);
  if (!copy->u.csg.boxes)
    return NULL;
  for (size_t i = 0; i < n; i++) {
    struct zr_csg_box *b = &copy->u.csg.boxes[i];
    /* csg.c takes a point outside a child's box to be outside the
       child, so a child whose inside reaches beyond its box (a disc, a
       height field: zr__box_holds_inside) gets none. */
    b->bounded =
        zr__box_holds_inside(copy->u.csg.children[i]) &&
        zr__object_bounds(copy->u.csg.children[i], &b->lo, &b->hi);
    b->holds_outside = false;
    if (!b->bounded)
      b->bounded = b->holds_outside = zr__complement_bounds(
          copy->u.csg.children[i], &b->lo, &b->hi);
  }
  if (zr__csg_tree_build(&scene->arena, copy) != ZR_OK ||
      zr__csg_keep_whole_box(&scene->arena, copy) != ZR_OK)
    return NULL;
  return copy;
}

/* Both clips at once: their intersection (NULL when neither clips).  The
   clip objects are only read, so they are shared, not copied. */
static const zr_object *clip_both(zr_scene *scene, const zr_object *a,
                                  const zr_object *b) {
  if (!a || !b)
    return a ? a : b;
  zr_object *both = zr__arena_alloc(&scene->arena, sizeof *both);
  zr_object **children =
      zr__arena_alloc(&scene->arena, 2 * sizeof *children);
  if (!both || !children)
    return NULL;
  children[0] = (zr_object *)a;
  children[1] = (zr_object *)b;
  both->kind = ZR_OBJ_INTERSECTION;
  both->u.csg.children = children;
  both->u.csg.n_children = 2;
  both->where = b->where;
  return both;
}

static double box_volume(zr_vec3 lo, zr_vec3 hi) {
  zr_vec3 d = zr_v3_sub(hi, lo);
  return d.x * d.y * d.z;
}

/* An object's own bounded_by, in POV-Ray 3.7, takes the place of the
   object's bounding box when the bound's box is the smaller of the two
   by volume, and rays that miss that box skip the object whatever the
   shape (the manual, "Bounded_By": a bound too small "may clip the
   object in undefined ways"; these are the ways).  Measured with povray
   (tests/bounded_box.pov, probes under /tmp at the time, a second small
   object in each scene so that its bounding slabs are on): a torus, a
   cone, a lathe, a sor, a superellipsoid, a prism, an ovus, a height
   field, a mesh, a blob, a sphere, a box, a sphere_sweep and a quadric
   (and an isosurface and a julia_fractal, whose surfaces differ from
   povray's anyway, by the same rule) under a bounding sphere or box that
   covers part of them are cut along the straight faces of the bound's
   box, surface drawn beyond the bound itself and all (a sphere bound
   drew no round edge); a bound whose box is larger than
   the object's changes nothing, even where it leaves part of the object
   out.  The volumes decide, not the sides: a cylinder of length 2.5
   along x under a sphere of radius 0.8 (a box of side 1.6, 4.096) is
   whole up to radius 0.63 (its box 3.97) and cut from 0.65 (4.23); a
   sphere of radius 1.1 (10.65) under a box 0.9 x 3 x 3 (8.1) is cut,
   under 0.9 x 6 x 6 it is whole.  A disc or a polygon (a flat box, no
   volume) keeps its bound unused.  A poly, cubic or quartic keeps its
   bound as it is (intersect.c meets_bound: the bound itself), and a
   plane its bound ignored (flatten).  Left as they were: a text's bound
   (unused; povray cuts an "O" under a small bounding sphere along a
   curve that neither the sphere nor its box gives: 20-100 pixels off
   either way at 80x60, and a bound of box 4.10 leaves it whole), and
   the sphere that is the only object of its scene, whose bound povray
   ignores (no bounding slabs then) and zRcube takes as any other. */
static zr_status bound_by_box(zr_scene *scene, zr_object *own) {
  zr_vec3 lo, hi, blo, bhi;
  if (!zr__object_bounds(own->bound, &blo, &bhi))
    return ZR_OK; /* an unbounded bound cuts nothing */
  if (zr__object_bounds(own, &lo, &hi) &&
      !(box_volume(blo, bhi) < box_volume(lo, hi)))
    return ZR_OK;
  zr_object *box = zr__arena_alloc(&scene->arena, sizeof *box);
  if (!box)
    return ZR_ENOMEM;
  box->kind = ZR_OBJ_BOX;
  box->u.box.corner1 = blo;
  box->u.box.corner2 = bhi;
  box->where = own->bound->where;
  own->bound = box;
  own->bound_cuts = true;
  return ZR_OK;
}

/* A clip whose inside reaches beyond its box (a height field, a disc:
   zr__box_holds_inside) is a bound too, by the same rule as
   bound_by_box: its box takes the place of the object's when it is the
   smaller by volume (always, for an object the tracer cannot box, such
   as an infinite quadric), and rays that miss it skip the object.
   Measured with povray 3.7 (tests/clip_box.pov): an infinite quadric
   cylinder clipped by a height field ends at a straight edge where the
   rays leave the field's box (stock objects/csg/hfclip.pov), and a
   sphere clipped by a disc is seen only through the disc's flat box,
   where zRcube drew the whole clipped surface, the field's and the
   disc's insides reaching down without end; a finite cylinder (box
   2 x 6 x 2) clipped by a height field of box 6 x 0.8 x 6 is drawn
   whole in both.  A clip whose inside its box holds cuts nothing this
   way, so it is left alone. */
static bool clip_box(const zr_object *clip, zr_vec3 *lo, zr_vec3 *hi,
                     bool *beyond) {
  if (clip->inverse)
    return false;
  if (clip->kind != ZR_OBJ_INTERSECTION) {
    *beyond = *beyond || !zr__box_holds_inside(clip);
    return zr__object_bounds(clip, lo, hi);
  }
  /* clipped_by { A B } is the intersection of A and B, whose box
     (bounds_csg.c) leaves out the parts whose inside reaches beyond
     their box; here the box of every part's surface counts. */
  bool any = false;
  for (size_t i = 0; i < clip->u.csg.n_children; i++) {
    zr_vec3 l, h;
    if (!clip_box(clip->u.csg.children[i], &l, &h, beyond))
      continue;
    *lo = any ? zr_v3_max(*lo, l) : l;
    *hi = any ? zr_v3_max(*lo, zr_v3_min(*hi, h)) : h;
    any = true;
  }
  return any;
}

static zr_status clip_by_box(zr_scene *scene, zr_object *own) {
  zr_vec3 lo, hi, clo, chi;
  bool beyond = false;
  if (own->bound_cuts || !clip_box(own->clip, &clo, &chi, &beyond) ||
      !beyond)
    return ZR_OK;
  const zr_object *clip = own->clip;
  own->clip = NULL; /* the object's own box */
  bool bounded = zr__object_bounds(own, &lo, &hi);
  if (bounded && !(box_volume(clo, chi) < box_volume(lo, hi))) {
    own->clip = clip;
    return ZR_OK;
  }
  zr_object *box = zr__arena_alloc(&scene->arena, sizeof *box);
  zr_object *both = zr__arena_alloc(&scene->arena, sizeof *both);
  zr_object **children =
      zr__arena_alloc(&scene->arena, 2 * sizeof *children);
  if (!box || !both || !children) {
    own->clip = clip;
    return ZR_ENOMEM;
  }
  box->kind = ZR_OBJ_BOX;
  box->u.box.corner1 = clo;
  box->u.box.corner2 = chi;
  box->where = clip->where;
  /* The box is the clip's narrowed by the object's own form: povray
     ends hfclip.pov's infinite cylinder x^2 + z^2 = 1 where the rays
     leave the box of |x|, |z| <= 1 within the field's box (the field's
     box alone, 6 wide, let the rays that enter its front face reach
     the cylinder far below it: 280 pixels off at 80x60). */
  children[0] = own;
  children[1] = box;
  both->kind = ZR_OBJ_INTERSECTION;
  both->u.csg.children = children;
  both->u.csg.n_children = 2;
  zr_vec3 nlo, nhi;
  if (zr__intersection_bounds(both, &nlo, &nhi)) {
    box->u.box.corner1 = nlo;
    box->u.box.corner2 = nhi;
  }
  own->clip = clip;
  own->bound = box;
  own->bound_cuts = true;
  return ZR_OK;
}

/* A union's clipped_by ("Clipped_By": only the part inside the clipping
   object is seen) is handed down to every primitive under it, joined to
   the clip each may have of its own, since the union itself is gone once
   flattened; clip is that inherited clip (NULL: none). */
static zr_status flatten(zr_scene *scene, zr_object *object,
                         const zr_texture *inherited, const zr_object *clip,
                         const zr_object *bound, flat_list *out) {
  const zr_texture *texture = object->texture ? object->texture : inherited;
  /* An object's own bound (not a union's handed down) may become its
     box (bound_by_box); a poly keeps its bound, a plane ignores it, and a
     text keeps it unused (see bound_by_box). */
  bool own_bound = object->bound && !zr__is_csg(object->kind) &&
                   object->kind != ZR_OBJ_PLANE &&
                   object->kind != ZR_OBJ_POLY &&
                   object->kind != ZR_OBJ_TEXT;
  /* A union's bounded_by ("Bounded_By": rays that miss the bound skip the
     object) is handed down too: a part the tracer cannot box itself (a
     quartic torus, a poly) takes the bound's box (bounds.c), as POV-Ray
     tests such a part only for rays that meet the bound. */
  /* A plane's own bound is ignored, as POV-Ray 3.7 ignores it: plane { y,
     0 bounded_by { box { -1, 1 } } } is the whole plane in its picture
     (tests/bounded_poly.pov case 4; a union's bound still limits a plane
     in it, case 5), where the bound's box cut a square out of it. */
  if (object->bound && object->kind != ZR_OBJ_PLANE)
    bound = object->bound;
  if (object->kind == ZR_OBJ_UNION) {
    const zr_object *inner = clip_both(scene, clip, object->clip);
    if ((clip || object->clip) && !inner)
      return ZR_ENOMEM;
    for (size_t i = 0; i < object->u.csg.n_children; i++) {
      zr_status s =
          flatten(scene, object->u.csg.children[i], texture, inner, bound,
                  out);
      if (s != ZR_OK)
        return s;
    }
    return ZR_OK;
  }
  zr_status s = grow((void **)&out->items, &out->cap, out->n,
                     sizeof *out->items);
  if (s != ZR_OK)
    return s;
  const zr_object *prim = object;
  zr_object *own = object;
  if (zr__is_csg(object->kind)) {
    /* Intersections and merges stay whole: one primitive. */
    if (!(own = resolve_part(scene, object, texture, NULL)))
      return ZR_ENOMEM;
    prim = own;
  } else {
    /* Every object of the tree is its own (the parser copies a declared
       object where it is used), so it takes what it inherits itself: a
       copy of each would double the memory of a million spheres. */
    object->texture = texture;
    if (!object->interior)
      object->interior = scene->default_interior;
  }
  if (clip && !(own->clip = clip_both(scene, own->clip, clip)))
    return ZR_ENOMEM;
  own->bound = bound;
  if (own_bound && (s = bound_by_box(scene, own)) != ZR_OK)
    return s;
  if (own->clip && !zr__is_csg(own->kind) && own->kind != ZR_OBJ_PLANE &&
      (s = clip_by_box(scene, own)) != ZR_OK)
    return s;
  /* A mesh with a texture list gets one copy per texture, each placed
     and textured like this one (lib/trace/obj_mesh.c). */
  const zr_shape_ops *ops = zr__shape(prim->kind);
  if (ops->prepare && (s = ops->prepare(&scene->arena, &prim)) != ZR_OK)
    return s;
  out->items[out->n++] = prim;
  return ZR_OK;
}

zr_status zr__scene_finish(zr_scene *scene, zr_context *ctx) {
  flat_list list = {0};
  for (size_t i = 0; i < scene->n_objects; i++) {
    zr_status s = flatten(scene, scene->objects[i], scene->default_texture,
                          NULL, NULL, &list);
    if (s != ZR_OK) {
      free(list.items);
      return zr__diag(ctx, ZR_DIAG_ERROR, s, NULL,
                      "cannot finish the scene: %s", zr_status_str(s));
    }
  }
  scene->primitives = list.items;
  scene->n_primitives = list.n;
  scene->n_finite_primitives = 0;
  for (size_t i = 0; i < list.n; i++) {
    zr_vec3 lo, hi;
    if (zr__object_bounds(list.items[i], &lo, &hi))
      scene->n_finite_primitives++;
  }
  /* The objects around the camera: a scan of every primitive, once (a
     render of 10^6 spheres did it for each row). */
  scene->n_camera_inside = 0;
  int most = (int)(sizeof scene->camera_inside /
                   sizeof *scene->camera_inside);
  for (size_t i = 0; i < list.n && scene->n_camera_inside < most; i++) {
    const zr_object *o = list.items[i];
    if (zr__has_inside(o) && zr__inside(o, scene->camera.location))
      scene->camera_inside[scene->n_camera_inside++] = o;
  }
  scene->bvh_free = zr__bvh_free;
  zr_status s = zr__bvh_build(scene, ctx);
  if (s == ZR_OK)
    s = zr__embree_attach(scene, ctx); /* lib/trace/embree.c */
  if (s == ZR_OK) {
    scene->shafts_free = zr__shafts_free;
    s = zr__shafts_build(scene); /* lib/trace/shaft.c */
  }
  if (s == ZR_OK && scene->settings.photons.on) {
    scene->photons_free = zr__photons_free;
    s = zr__photons_build(scene, ctx); /* lib/trace/photons.c */
  }
  return s;
}
