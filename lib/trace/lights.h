/*
 * lights.h - how much of a light source reaches a surface point: the
 * kinds of POV-Ray 3.7's light_source (lib/trace/lights.c).
 */
#ifndef ZR_TRACE_LIGHTS_H
#define ZR_TRACE_LIGHTS_H

#include <stdbool.h>

#include "scene/scene.h"
#include "trace/shade.h"

/*
 * The light arriving at point p before shadows: *l is the unit vector
 * toward the light (the centre of an area light; along the axis for
 * parallel and cylinder lights) and *colour the light's colour after
 * the spotlight or cylinder cone and distance fading.  False when no
 * light arrives (outside a cone).
 */
bool zr__light_arrive(const zr_light *light, zr_vec3 p, zr_vec3 *l,
                      zr_rgb *colour);

/*
 * The way from p to a light's location, its length and the length's
 * reciprocal, as zr__light_arrive computes them, and zr__light_arrive
 * given them (the same result, bit for bit).  Shading asks for several
 * lights' ways before it lights the point by the first: their square
 * roots and divisions then run side by side, where each light's, asked
 * after the shadow ray of the light before, held up the processor on
 * its own (zr__light_arrive was 5-7% of the sphereflake's CPU samples,
 * most of them on the two results).
 */
typedef struct zr_light_way {
  zr_vec3 to_light;
  double distance, inv_distance;
} zr_light_way;

static inline void zr__light_way(const zr_light *light, zr_vec3 p,
                                 zr_light_way *way) {
  way->to_light = zr_v3_sub(light->location, p);
  way->distance = zr_v3_len(way->to_light);
  way->inv_distance = 1.0 / way->distance;
}

bool zr__light_arrive_way(const zr_light *light, zr_vec3 p,
                          const zr_light_way *way, zr_vec3 *l,
                          zr_rgb *colour);

/* The spot or cylinder factor alone at p, in [0, 1] (1 for others). */
double zr__light_cone(const zr_light *light, zr_vec3 p);

/* The distance fading factor 2 / (1 + (d / fade_distance)^fade_power),
   or 1 for a light that does not fade. */
double zr__light_fade(const zr_light *light, double distance);

/*
 * The share of the light that gets past the scene to lit_from (a point
 * just off the surface at p), per channel: 1 unblocked, 0 in full
 * shadow, between for transparent blockers and the soft shadows of area
 * lights (averaged over the light's grid of points).
 */
zr_rgb zr__light_visibility(const zr_tracer *tracer, const zr_light *light,
                            zr_vec3 p, zr_vec3 lit_from);

/*
 * Whether zr__light_visibility is, for this light, one shadow ray from
 * lit_from to the light's location, zr__shadow_transmission(tracer,
 * light, light->location, lit_from): a point light (no area, no
 * projected_through, neither parallel nor cylindrical) that casts
 * shadows.  Shading then calls it directly: the steps of
 * zr__light_visibility, each passing the points down to the next, cost
 * ~150 instructions a shadow ray, 7% of the sphereflake's (callgrind,
 * 512^2).
 */
static inline bool zr__light_one_ray(const zr_tracer *tracer,
                                     const zr_light *light) {
  return !light->area && !light->projected_through && !light->shadowless &&
         !tracer->no_shadows && !light->parallel &&
         light->kind != ZR_LIGHT_CYLINDER;
}

/*
 * Whether light lights object, as light groups decide ("Light Group"):
 * a light of no group lights the objects of no group, and those of a
 * group with global_lights on; a light of a group lights the objects of
 * that group and of the groups nested in it.  Every object casts
 * shadows for every light, in a group or not (measured on POV-Ray 3.7).
 */
static inline bool zr__light_lights(const zr_scene *scene,
                                    const zr_light *light,
                                    const zr_object *object) {
  uint32_t g = object->light_group;
  if (light->light_group == 0 && g == 0)
    return true;
  if (light->light_group == 0)
    return scene->light_groups[g].global_lights;
  for (; g != 0; g = scene->light_groups[g].parent)
    if (g == light->light_group)
      return true;
  return false;
}

/* The grid point (i, j) of an area light seen from p, jitter included
   (the hash is of p, so the picture does not depend on threads). */
zr_vec3 zr__area_light_point(const zr_light *light, zr_vec3 p, int i, int j);

#endif /* ZR_TRACE_LIGHTS_H */
