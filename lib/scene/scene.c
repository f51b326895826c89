/*
 * scene.c - building and finishing the scene model.
 *
 * The parser fills a zr_scene with objects as written; the tracer then
 * prepares it (zr__scene_finish(), lib/trace/prepare.c): unions
 * flattened, textures resolved, its bounding volume hierarchy built.
 */
#include "scene/scene.h"
#include "scene/pattern.h"

#include "core/budget.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/context.h"

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
  /* The pattern's defaults too: a pigment block that modifies this one
     (the default texture's, after #default) keeps its pattern
     modifiers for the pattern it names (lib/sdl/build.c). */
  zr__pattern_init(&p->pattern, ZR_PAT_NONE);
}

void zr__interior_init(zr_interior *i) {
  memset(i, 0, sizeof *i);
  i->ior = 1.0;
  i->dispersion = 1.0;
  i->dispersion_samples = 7;
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
  s->mm_per_unit = 10.0;
  s->subsurface_samples[0] = s->subsurface_samples[1] = 50;
  s->adc_bailout = 1.0 / 255.0;
  s->assumed_gamma = 1.0;
  s->ambient_light = zr_rgb3(1, 1, 1);
  s->irid_wavelength = zr_rgb3(0.70, 0.52, 0.48);
  /* Black and clear: povray 3.7 +UA leaves a #version 3.7 scene
     without a background transparent (lib/trace/atmosphere.c); the
     colour ignores transmit. */
  s->background = zr_colour5(0, 0, 0, 0, 1);
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
  s->photons.media_factor = 1.0;
  s->photons.media_radius_multiplier = 1.0;
}

size_t zr__object_size(zr_object_kind kind) {
  size_t common = offsetof(zr_object, u);
  /* The union's end keeps the alignment its largest member needs. */
  size_t part;
  switch (kind) {
  case ZR_OBJ_SPHERE:
    part = sizeof ((zr_object *)0)->u.sphere;
    break;
  case ZR_OBJ_PLANE:
    part = sizeof ((zr_object *)0)->u.plane;
    break;
  case ZR_OBJ_TRIANGLE:
    part = sizeof ((zr_object *)0)->u.triangle;
    break;
  case ZR_OBJ_BOX:
    part = sizeof ((zr_object *)0)->u.box;
    break;
  default:
    return sizeof(zr_object);
  }
  size_t size = common + part;
  return size < sizeof(zr_object) ? size : sizeof(zr_object);
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

void zr__light_derive(zr_light *light) {
  const double deg = 3.14159265358979323846 / 180.0;
  zr_vec3 a = zr_v3_sub(light->location, light->point_at);
  light->axis = zr_v3_len(a) == 0.0 ? zr_v3(0, 1, 0) : zr_v3_norm(a);
  light->cos_falloff = cos(light->falloff * deg);
  light->cos_radius = cos(light->radius * deg);
}

zr_status zr__scene_add_light(zr_scene *scene, const zr_light *light) {
  zr_status s = grow((void **)&scene->lights, &scene->cap_lights,
                     scene->n_lights, sizeof *scene->lights);
  if (s == ZR_OK) {
    scene->lights[scene->n_lights] = *light;
    zr__light_derive(&scene->lights[scene->n_lights++]);
  }
  return s;
}

ZR_API void zr_scene_free(zr_scene *scene) {
  if (!scene)
    return;
  if (scene->bvh_free)
    scene->bvh_free(scene->bvh);
  if (scene->photons_free)
    scene->photons_free(scene->photons);
  if (scene->embree_free)
    scene->embree_free(scene->embree);
  if (scene->shafts_free)
    scene->shafts_free(scene->shafts);
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
  info->photons_shot = scene->photons_shot;
  info->photons_stored = scene->photons_stored;
  info->media_photons_stored = scene->media_photons_stored;
  info->media_photons_radius = scene->media_photons_radius;
  info->finite_primitives = scene->n_finite_primitives;
  info->infinite_primitives = scene->n_primitives - scene->n_finite_primitives;
}

ZR_API double zr_scene_assumed_gamma(const zr_scene *scene) {
  return scene->settings.assumed_gamma;
}

ZR_API double zr_scene_file_gamma(const zr_scene *scene) {
  return scene->settings.gamma_correction_off
             ? scene->settings.assumed_gamma
             : 0.0;
}

ZR_API void zr_scene_image_encoding(const zr_scene *scene,
                                    zr_image_format format,
                                    zr_image_encoding *e) {
  zr_image_encoding_init(e, format);
  e->assumed_gamma = zr_scene_assumed_gamma(scene);
  e->file_gamma = zr_scene_file_gamma(scene);
}
