/*
 * scene.c - building and finishing the scene model.
 *
 * The parser fills a zr_scene with objects as written; zr__scene_finish()
 * then flattens unions (a plain union has no inside test, so its children
 * are traced as independent primitives), gives every primitive a texture,
 * and hands the list to the tracer to build its bounding volume hierarchy.
 */
#include "scene/scene.h"

#include "core/budget.h"

#include <stdlib.h>
#include <string.h>

#include "core/context.h"
#include "trace/bvh.h"
#include "trace/photons.h"

void zr__finish_init(zr_finish *f) {
  memset(f, 0, sizeof *f);
  f->ambient = zr_rgb3(0.1, 0.1, 0.1);
  f->diffuse = 0.6;
  f->brilliance = 1.0;
  f->phong_size = 40.0;
  f->roughness = 0.05;
  f->reflection_falloff = 1.0;
  f->reflection_exponent = 1.0;
}

void zr__pigment_init(zr_pigment *p) {
  memset(p, 0, sizeof *p);
  p->kind = ZR_PIGMENT_SOLID;
  p->colour = zr_colour5(0, 0, 0, 0, 0);
}

void zr__interior_init(zr_interior *i) {
  memset(i, 0, sizeof *i);
  i->ior = 1.0;
}

void zr__camera_init(zr_camera *c) {
  memset(c, 0, sizeof *c);
  c->kind = ZR_CAMERA_PERSPECTIVE;
  c->location = zr_v3(0, 0, 0);
  c->direction = zr_v3(0, 0, 1);
  c->up = zr_v3(0, 1, 0);
  c->right = zr_v3(1.33, 0, 0);
  c->sky = zr_v3(0, 1, 0);
}

void zr__settings_init(zr_settings *s) {
  memset(s, 0, sizeof *s);
  s->max_trace_level = 5;
  s->number_of_waves = 10;
  s->adc_bailout = 1.0 / 255.0;
  s->assumed_gamma = 1.0;
  s->ambient_light = zr_rgb3(1, 1, 1);
  s->irid_wavelength = zr_rgb3(0.70, 0.52, 0.48);
  s->background = zr_colour5(0, 0, 0, 0, 0);
  s->version = 3.7;
  s->radiosity.brightness = 1.0;
  s->photons.gather_min = 20;
  s->photons.gather_max = 100;
  s->photons.jitter = 0.4;
  s->photons.max_trace_level = -1;
  s->photons.adc_bailout = -1.0;
  s->photons.radius_multiplier = 1.0;
  s->photons.expand_increase = 0.2;
  s->photons.expand_min = 40;
}

zr_scene *zr__scene_new(void) {
  zr_scene *scene = calloc(1, sizeof *scene);
  if (!scene)
    return NULL;
  zr__arena_init(&scene->arena);
  zr__camera_init(&scene->camera);
  zr__settings_init(&scene->settings);
  zr_pigment *pigment = zr__arena_alloc(&scene->arena, sizeof *pigment);
  zr_finish *finish = zr__arena_alloc(&scene->arena, sizeof *finish);
  zr_texture *texture = zr__arena_alloc(&scene->arena, sizeof *texture);
  zr_interior *interior = zr__arena_alloc(&scene->arena, sizeof *interior);
  if (!pigment || !finish || !texture || !interior) {
    zr_scene_free(scene);
    return NULL;
  }
  zr__pigment_init(pigment);
  zr__finish_init(finish);
  zr__interior_init(interior);
  texture->pigment = pigment;
  texture->finish = finish;
  scene->default_texture = texture;
  scene->default_interior = interior;
  return scene;
}

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

zr_status zr__scene_add_object(zr_scene *scene, zr_object *object) {
  zr_status s = grow((void **)&scene->objects, &scene->cap_objects,
                     scene->n_objects, sizeof *scene->objects);
  if (s == ZR_OK)
    scene->objects[scene->n_objects++] = object;
  return s;
}

zr_status zr__scene_add_light(zr_scene *scene, const zr_light *light) {
  zr_status s = grow((void **)&scene->lights, &scene->cap_lights,
                     scene->n_lights, sizeof *scene->lights);
  if (s == ZR_OK)
    scene->lights[scene->n_lights++] = *light;
  return s;
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
  zr_object *copy = zr__arena_memdup(&scene->arena, object, sizeof *copy);
  if (!copy)
    return NULL;
  copy->texture = object->texture ? object->texture : inherited;
  /* A ray inside the primitive travels in one interior.  When the CSG
     has none of its own and its parts agree on one, that is it: povray
     3.7 refracts a glass box with a sphere cut out of it (the box's
     interior { ior 1.5 }) as the box alone, where the default interior
     of the whole let the rays through unbent (advanced/glasschess.pov's
     blocks vanished).  Parts with different interiors (wineglass.pov's
     merge of rim, bowl, beads and stem) keep the default: one interior
     per part is not modelled. */
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

/* A union's clipped_by ("Clipped_By": only the part inside the clipping
   object is seen) is handed down to every primitive under it, joined to
   the clip each may have of its own, since the union itself is gone once
   flattened; clip is that inherited clip (NULL: none). */
static zr_status flatten(zr_scene *scene, zr_object *object,
                         const zr_texture *inherited, const zr_object *clip,
                         flat_list *out) {
  const zr_texture *texture = object->texture ? object->texture : inherited;
  if (object->kind == ZR_OBJ_UNION) {
    const zr_object *inner = clip_both(scene, clip, object->clip);
    if ((clip || object->clip) && !inner)
      return ZR_ENOMEM;
    for (size_t i = 0; i < object->u.csg.n_children; i++) {
      zr_status s =
          flatten(scene, object->u.csg.children[i], texture, inner, out);
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
  /* A mesh with a texture list gets one copy per texture, each placed
     and textured like this one (lib/trace/obj_mesh.c). */
  if ((s = zr__mesh_instance(&scene->arena, &prim)) != ZR_OK)
    return s;
  out->items[out->n++] = prim;
  return ZR_OK;
}

zr_status zr__scene_finish(zr_scene *scene, zr_context *ctx) {
  flat_list list = {0};
  for (size_t i = 0; i < scene->n_objects; i++) {
    zr_status s = flatten(scene, scene->objects[i], scene->default_texture,
                          NULL, &list);
    if (s != ZR_OK) {
      free(list.items);
      return zr__diag(ctx, ZR_DIAG_ERROR, s, NULL,
                      "cannot finish the scene: %s", zr_status_str(s));
    }
  }
  scene->primitives = list.items;
  scene->n_primitives = list.n;
  zr_status s = zr__bvh_build(scene, ctx);
  if (s == ZR_OK && scene->settings.photons.on)
    s = zr__photons_build(scene, ctx); /* lib/trace/photons.c */
  return s;
}

ZR_API void zr_scene_free(zr_scene *scene) {
  if (!scene)
    return;
  zr__bvh_free(scene->bvh);
  zr__photons_free(scene->photons);
  free(scene->primitives);
  free(scene->objects);
  free(scene->lights);
  zr__arena_free(&scene->arena);
  zr__budget_unref(scene->arena.budget);
  free(scene);
}

ZR_API void zr_scene_get_info(const zr_scene *scene, zr_scene_info *info) {
  memset(info, 0, sizeof *info);
  info->objects = scene->n_objects;
  info->primitives = scene->n_primitives;
  info->lights = scene->n_lights;
  info->parse_steps = scene->parse_steps;
  info->has_camera = scene->camera.given;
  info->has_radiosity = scene->settings.radiosity.on;
  for (size_t i = 0; i < scene->n_primitives; i++) {
    zr_vec3 lo, hi;
    if (zr__object_bounds(scene->primitives[i], &lo, &hi))
      info->finite_primitives++;
    else
      info->infinite_primitives++;
  }
}

ZR_API double zr_scene_assumed_gamma(const zr_scene *scene) {
  return scene->settings.assumed_gamma;
}
