/*
 * build_camlight.h - what the grammar's camera, light_source, fog,
 * sky_sphere and rainbow actions call (lib/sdl/build_camlight.c).
 */
#ifndef ZR_SDL_BUILD_CAMLIGHT_H
#define ZR_SDL_BUILD_CAMLIGHT_H

#include "sdl/sdl.h"

/* A point light with POV-Ray's defaults and its place set; the grammar
   fills the rest. */
bool zr__sdl_light(zr_sdl_parser *p, zr_light *l, const zr_sdl_loc *loc);
/* spotlight or cylinder: the kind and that kind's defaults. */
void zr__sdl_light_kind(zr_sdl_parser *p, zr_light *l, zr_light_kind kind);
/* Moves the light's points and vectors (and its looks_like object). */
void zr__sdl_light_transform(zr_sdl_parser *p, zr_light *l,
                             const zr_transform *t);
/* area_light Axis1, Axis2, Size1, Size2 */
bool zr__sdl_area_light(zr_sdl_parser *p, zr_light *l,
                        const zr_sdl_expr e[4], const zr_sdl_loc at[4]);
/* An integer of at least min (adaptive, octaves). */
bool zr__sdl_light_int(zr_sdl_parser *p, const zr_sdl_expr *e,
                       const zr_sdl_loc *loc, int min, int *out);
bool zr__sdl_light_bool(zr_sdl_parser *p, const zr_sdl_expr *e,
                        const zr_sdl_loc *loc, bool *out);
bool zr__sdl_looks_like(zr_sdl_parser *p, zr_light *l, zr_object *o,
                        const zr_sdl_loc *loc);
/* Checks the finished light. */
bool zr__sdl_light_end(zr_sdl_parser *p, zr_light *l,
                       const zr_sdl_loc *loc);
/* Adds the light (and its looks_like object) to the scene. */
bool zr__sdl_light_add(zr_sdl_parser *p, zr_light *l,
                       const zr_sdl_loc *loc);

void zr__sdl_camera_begin(zr_sdl_parser *p, const zr_sdl_loc *loc);
/* camera { CAMERA_IDENTIFIER ...: start from the declared camera. */
void zr__sdl_camera_from(zr_sdl_parser *p, const zr_camera *declared);
/* The finished camera as a #declare value; the scene's camera is given
   back the value it had before the block.  NULL when out of memory. */
const zr_camera *zr__sdl_camera_value(zr_sdl_parser *p);
/* The projection; cylinder needs its type (1-4) in e. */
bool zr__sdl_camera_type(zr_sdl_parser *p, zr_camera_kind kind,
                         const zr_sdl_expr *e, const zr_sdl_loc *loc);
/* angle H [, V]; v NULL when only H is given. */
bool zr__sdl_camera_angle(zr_sdl_parser *p, double degrees,
                          const double *v, const zr_sdl_loc *loc);
bool zr__sdl_camera_blur_samples(zr_sdl_parser *p, const zr_sdl_expr *min,
                                 const zr_sdl_expr *max,
                                 const zr_sdl_loc *loc);
void zr__sdl_camera_look_at(zr_sdl_parser *p, zr_vec3 target,
                            const zr_sdl_loc *at);
void zr__sdl_camera_transform(zr_sdl_parser *p, const zr_transform *t);
/* Applies what the block deferred: angle, look_at, then transforms. */
bool zr__sdl_camera_end(zr_sdl_parser *p);

/* mesh_camera { rays distribution [max_distance] ...: makes the camera
   a mesh camera (lib/sdl/build_meshcam.c); max may be NULL. */
bool zr__sdl_mesh_camera(zr_sdl_parser *p, const zr_sdl_loc *at,
                         const zr_sdl_expr *rays, const zr_sdl_loc *rays_at,
                         const zr_sdl_expr *dist, const zr_sdl_loc *dist_at,
                         const zr_sdl_expr *max, const zr_sdl_loc *max_at);
/* One mesh or mesh2 of the block. */
bool zr__sdl_mesh_camera_add(zr_sdl_parser *p, const zr_object *mesh,
                             const zr_sdl_loc *loc);
bool zr__sdl_mesh_camera_smooth(zr_sdl_parser *p, const zr_sdl_loc *loc);
/* The block's '}': checks it and, for distribution 3, sorts the first
   mesh's faces into its uv grid. */
bool zr__sdl_mesh_camera_end(zr_sdl_parser *p, const zr_sdl_loc *loc);

/* Applies one colour item (rgb ..., filter ...) to *colour. */
bool zr__sdl_colour_item_to(zr_sdl_parser *p, const zr_sdl_colour_mod *m,
                            zr_colour *colour);

zr_fog *zr__sdl_fog_new(zr_sdl_parser *p, const zr_sdl_loc *loc);
bool zr__sdl_fog_type(zr_sdl_parser *p, zr_fog *f, const zr_sdl_expr *e,
                      const zr_sdl_loc *loc);
bool zr__sdl_fog_transform(zr_sdl_parser *p, zr_fog *f,
                           const zr_transform *t);
/* Appends the fog to the scene's list. */
void zr__sdl_fog_end(zr_sdl_parser *p, zr_fog *f);

/* A new sky_sphere, a copy of from when not NULL (a declared one). */
zr_sky_sphere *zr__sdl_sky_new(zr_sdl_parser *p, const zr_sky_sphere *from);
bool zr__sdl_sky_pigment(zr_sdl_parser *p, zr_sky_sphere *sky,
                         const zr_pigment *pg);
bool zr__sdl_sky_transform(zr_sdl_parser *p, zr_sky_sphere *sky,
                           const zr_transform *t);
bool zr__sdl_sky_end(zr_sdl_parser *p, zr_sky_sphere *sky,
                     const zr_sdl_loc *loc);

zr_rainbow *zr__sdl_rainbow_new(zr_sdl_parser *p);
bool zr__sdl_rainbow_end(zr_sdl_parser *p, zr_rainbow *rb,
                         const zr_sdl_loc *loc);

#endif /* ZR_SDL_BUILD_CAMLIGHT_H */
