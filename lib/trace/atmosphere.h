/*
 * atmosphere.h - what a ray sees beyond the last surface and on its way
 * there: sky_sphere or background, fog and rainbows
 * (lib/trace/atmosphere.c).
 */
#ifndef ZR_TRACE_ATMOSPHERE_H
#define ZR_TRACE_ATMOSPHERE_H

#include "core/vec.h"
#include "scene/scene.h"

/* The colour of a ray that hits nothing: the sky_sphere's pigments at
   its direction, else the background (before fog). */
zr_rgb zr__sky_colour(const zr_scene *scene, zr_vec3 dir);

/*
 * colour seen through the scene's fogs and rainbows along a ray from
 * origin in direction dir (any length) over distance t along dir
 * (INFINITY for a ray that hit nothing).
 */
zr_rgb zr__atmosphere_apply(const zr_scene *scene, zr_vec3 origin,
                            zr_vec3 dir, double t, zr_rgb colour);

/*
 * colour (a light's) dimmed by the scene's fogs along the same path, no
 * fog colour added: the manual's "Atmospheric Attenuation" (a light
 * with media_attenuation on is "diminished as it travels through the
 * fog or media"); tests/test_fog_povray.sh compares with povray.
 */
zr_rgb zr__fog_attenuate(const zr_scene *scene, zr_vec3 origin, zr_vec3 dir,
                         double t, zr_rgb colour);

#endif /* ZR_TRACE_ATMOSPHERE_H */
