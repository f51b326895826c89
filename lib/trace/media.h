/*
 * media.h - participating media along a ray: interior media of hollow
 * containers and atmospheric media (lib/trace/media.c).
 */
#ifndef ZR_TRACE_MEDIA_H
#define ZR_TRACE_MEDIA_H

#include <stdbool.h>
#include <stddef.h>

#include "scene/scene.h"
#include "trace/shade.h"

/* The most media one integration combines (the rest are left out). */
#define ZR_MEDIA_LIST_MAX 32

/*
 * The phase function of medium's scattering for cos_angle, the cosine
 * between the direction toward the light and the ray's direction, in
 * POV-Ray's scale (lib/trace/media.c says how it was measured).
 */
double zr__media_phase(const zr_medium *medium, double cos_angle);

/* The product of medium's density { } colours at p (1 without any). */
zr_rgb zr__media_density(const zr_medium *medium, zr_vec3 p);

/*
 * colour arriving at origin from distance depth along unit direction
 * dir, seen through the media in list: colour * exp(-optical depth) plus
 * the light the media emit and scatter toward origin.  With shadow set
 * only the extinction is computed (the light a shadow ray keeps).
 */
zr_rgb zr__media_integrate(const zr_tracer *tracer,
                           const zr_medium *const *list, size_t n,
                           zr_vec3 origin, zr_vec3 dir, double depth,
                           bool shadow, zr_rgb colour);

/*
 * What a ray that travelled from origin along dir (any length) to t
 * (a hit, or INFINITY for a ray to the sky, which sees atmospheric media
 * only) brings back through the media of the interiors in `inside` and
 * the atmosphere, when every object the ray is in is hollow ("Empty and
 * Solid Objects").  colour is returned unchanged in a scene without
 * media.
 */
zr_rgb zr__media_along(const zr_tracer *tracer, const zr_media *inside,
                       zr_vec3 origin, zr_vec3 dir, double t, zr_rgb colour);

/* What the atmospheric media leave of a light with media_attenuation on
   its way to p (1 for other lights: "Atmospheric Attenuation"). */
zr_rgb zr__media_light_attenuation(const zr_tracer *tracer,
                                   const zr_light *light, zr_vec3 p);

/*
 * The light a shadow ray origin + t dir (t from 0 to 1) keeps after the
 * media of the hollow containers it crosses: crossings are its hits on
 * such containers, entering when the ray goes in, gathered in any order
 * by the shadow walk (lib/trace/shade.c); they are sorted here.
 */
typedef struct zr_media_crossing {
  double t;
  const zr_object *solid;
  bool entering;
} zr_media_crossing;

zr_rgb zr__media_shadow(const zr_tracer *tracer, zr_vec3 origin,
                        zr_vec3 dir, zr_media_crossing *crossings,
                        size_t n);

/* The light a media sample's shadow ray keeps: as zr__media_shadow, the
   ray starting inside the containers of start (the interiors of the ray
   whose media were sampled) and going in or out of a container at each
   crossing by turns (lib/trace/media.c says why). */
zr_rgb zr__media_sample_shadow(const zr_tracer *tracer, zr_vec3 origin,
                               zr_vec3 dir, zr_media_crossing *crossings,
                               size_t n, const zr_media *start);

#endif /* ZR_TRACE_MEDIA_H */
