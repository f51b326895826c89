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
 * The same ray's colour with an alpha channel (+UA, lib/trace/render.c):
 * what the background and sky_sphere add of their own, with what shows
 * through them transparent black, and in *clear the share of the pixel
 * left transparent (0 to 1).  Scenes before #version 3.7 (or with none)
 * see neither background nor sky there: black, *clear 1.
 */
zr_rgb zr__sky_clear(const zr_scene *scene, zr_vec3 dir, double *clear);

/* The grey of a colour, 0.297 r + 0.589 g + 0.114 b (the weights the
   project measured for pigment_pattern and bump maps), by which filter
   lets a background through for +UA (tests/test_alpha_povray.sh). */
double zr__grey(zr_rgb c);

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
