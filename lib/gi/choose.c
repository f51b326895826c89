/*
 * choose.c - which model of global illumination a scene gets, and the
 * irradiance cache's parameters from POV-Ray's radiosity block.
 *
 * "Model no more than a scene needs": hierarchical radiosity
 * (lib/radiosity) solves every bounce of a closed room lit by emitting
 * surfaces once for all views, but knows neither the sky nor objects it
 * has no exact surface for, and its links grow with the square of the
 * surfaces; the irradiance cache (cache.c) gathers only what the camera
 * sees, from anything the tracer can hit, the sky included.  The rule
 * zr_gi_choose() applies is stated in zrcube(1), "Global illumination",
 * and tested by tests/test_gi.c.
 */
#include "gi/gi.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "radiosity/radiosity.h"
#include "trace/intersect.h"

/* POV-Ray 3.7's defaults (manual, "Adjusting Radiosity"). */
ZR_API void zr_gi_params_init(zr_gi_params *p, const zr_scene *scene) {
  memset(p, 0, sizeof *p);
  p->size = sizeof *p;
  p->count = 35;
  p->recursion_limit = 2;
  p->nearest_count = 5;
  p->error_bound = 1.8;
  p->low_error_factor = 0.5;
  p->gray_threshold = 0.0;
  p->brightness = 1.0;
  p->minimum_reuse = 0.015;
  p->maximum_reuse = 0.2;
  p->pretrace_start = 0.08;
  p->pretrace_end = 0.04;
  p->adc_bailout = 0.01;
  p->max_sample = -1.0;
  p->normal = 0;
  p->media = 0;
  p->always_sample = 0;
  p->sky_only = 0;
  p->threads = 0;
  if (!scene || !scene->settings.radiosity.on)
    return;
  const zr_radiosity_settings *r = &scene->settings.radiosity;
  p->brightness = r->brightness;
  if (r->count > 0)
    p->count = r->count;
  if (r->recursion_limit > 0)
    p->recursion_limit = r->recursion_limit;
  if (r->nearest_count > 0)
    p->nearest_count = r->nearest_count;
  /* "nearest_count N, M": M stops the pretrace's passes; N, N is what
     N alone does (a point served by N records gathers no more). */
  if (r->nearest_count_max > 0 && r->nearest_count_max != r->nearest_count)
    p->nearest_count_stop = r->nearest_count_max;
  if (r->count_pool > p->count)
    p->count_pool = r->count_pool;
  if (r->error_bound > 0.0)
    p->error_bound = r->error_bound;
  if (r->low_error_factor > 0.0)
    p->low_error_factor = r->low_error_factor;
  if (r->gray_given)
    p->gray_threshold = r->gray_threshold;
  if (r->minimum_reuse > 0.0)
    p->minimum_reuse = r->minimum_reuse;
  if (r->maximum_reuse > 0.0)
    p->maximum_reuse = r->maximum_reuse;
  if (p->minimum_reuse >= p->maximum_reuse)
    p->minimum_reuse = p->maximum_reuse; /* warned by the parser */
  if (r->pretrace_start > 0.0)
    p->pretrace_start = r->pretrace_start;
  if (r->pretrace_end > 0.0)
    p->pretrace_end = r->pretrace_end;
  if (p->pretrace_end > p->pretrace_start)
    p->pretrace_end = p->pretrace_start;
  if (r->adc_given)
    p->adc_bailout = r->adc_bailout;
  if (r->max_sample_given)
    p->max_sample = r->max_sample;
  if (r->normal >= 0)
    p->normal = r->normal;
  if (r->media >= 0)
    p->media = r->media;
  if (r->always_sample >= 0)
    p->always_sample = r->always_sample;
  p->save_file = r->save_file;
  p->load_file = r->load_file;
}

ZR_API const char *zr_gi_method_name(zr_gi_method m) {
  switch (m) {
  case ZR_GI_AUTO:
    return "auto";
  case ZR_GI_OFF:
    return "off";
  case ZR_GI_HIERARCHICAL:
    return "hierarchical";
  case ZR_GI_CACHE:
    return "cache";
  case ZR_GI_PATH:
    return "path";
  }
  return "?";
}

static bool rgb_positive(zr_rgb c) {
  return c.r > 0.0 || c.g > 0.0 || c.b > 0.0;
}

/* Whether the scene has a sky that gives light: a sky_sphere, or a
   background that is not black. */
bool zr__gi_has_sky(const zr_scene *scene) {
  const zr_settings *s = &scene->settings;
  if (s->sky_sphere && s->sky_sphere->n_pigments > 0)
    return true;
  return rgb_positive(zr_colour_rgb(s->background));
}

static bool emits(const zr_object *o) {
  const zr_texture *t = o->texture;
  for (; t; t = t->over)
    if (t->finish &&
        (rgb_positive(t->finish->emission) || rgb_positive(t->finish->energy)))
      return true;
  return false;
}

static zr_gi_method say(char *why, size_t size, zr_gi_method m,
                        const char *fmt, const char *arg) {
  if (why && size > 0)
    snprintf(why, size, fmt, arg ? arg : "");
  return m;
}

ZR_API int zr_gi_has_sky(const zr_scene *scene) {
  return scene && zr__gi_has_sky(scene);
}

ZR_API zr_gi_method zr_gi_choose(const zr_scene *scene, zr_gi_method asked,
                                 char *why, size_t size) {
  if (asked != ZR_GI_AUTO)
    return say(why, size, asked, "asked for", NULL);
  if (!scene || !scene->settings.radiosity.on)
    return say(why, size, ZR_GI_OFF, "the scene has no radiosity block",
               NULL);
  if (zr__gi_has_sky(scene))
    return say(why, size, ZR_GI_CACHE,
               "the sky (sky_sphere or background) lights the scene",
               NULL);
  /* The hierarchical solver's transfer between two patches is a form
     factor times a visibility, with nothing in between, as povray's
     radiosity rays see it by default: fog never dims them, media only
     under "media on" (measured, tests/test_gi_room.sh: in a closed
     room lit by an emitting panel a black fog of distance 3 leaves
     0.488 of the floor's linear light in povray's picture, the camera
     ray's fog alone, and 0.488 in the solver's; fogging the light
     between surfaces too, as the path tracer did, left 0.123).  With
     media on the room's floor is 0.0292 in povray's picture and was
     0.1059 in the solver's, so such a scene goes to the cache, whose
     sample rays cross the media (0.0290). */
  if (zr__rad_media_counts(scene))
    return say(why, size, ZR_GI_CACHE,
               "its radiosity block has media on and the scene has "
               "media, which the hierarchical solver carries no light "
               "through%s", NULL);
  /* Meshes of any size: the solver clusters their faces (and takes no
     face limit unless a library caller sets one in the solver's own
     parameters, which this choice does not see). */
  bool emitter = false;
  for (size_t i = 0; i < scene->n_primitives; i++) {
    const zr_object *o = scene->primitives[i];
    size_t f = 0;
    if (!zr__rad_models(o, &f))
      return say(why, size, ZR_GI_CACHE,
                 "it has an object the hierarchical solver does not "
                 "model (%s)", zr__rad_kind_name(o->kind));
    /* The solver's closed emitters shine from their outside only
       (flat ones from both sides: zrcube(1), --one-sided-emission);
       povray's emission shines both ways.
       An emitting sky dome or room around the camera then lights
       nothing (measured: a box on a floor under an emitting sphere of
       radius 50, povray's and the cache's pixels 160,170,198, the
       solver's 1,0,0), so such a scene goes to the cache. */
    if (emits(o) && zr__has_inside(o) &&
        zr__inside(o, scene->camera.location))
      return say(why, size, ZR_GI_CACHE,
                 "the camera is inside an emitting %s, which the "
                 "hierarchical solver lights from its outside only",
                 zr__rad_kind_name(o->kind));
    emitter = emitter || emits(o);
  }
  if (!emitter)
    return say(why, size, ZR_GI_CACHE,
               "no surface emits light (POV-Ray's radiosity lit by light "
               "sources)%s", NULL);
  /* Without a sky, light that leaves the scene brings nothing back, so
     an opening (the Cornell box's missing wall) needs no other model. */
  return say(why, size, ZR_GI_HIERARCHICAL,
             "lit by emitting surfaces under a black sky, every object of "
             "a kind the hierarchical solver models%s", NULL);
}
