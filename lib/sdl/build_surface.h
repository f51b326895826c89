/*
 * build_surface.h - building bicubic_patch, sphere_sweep and
 * julia_fractal objects from the grammar's actions
 * (lib/sdl/build_surface.c).
 */
#ifndef ZR_SDL_BUILD_SURFACE_H
#define ZR_SDL_BUILD_SURFACE_H

#include "sdl/sdl.h"

/* bicubic_patch { type T flatness F u_steps U v_steps V <P1> ... <P16>
   [uv_vectors <c1> <c2> <c3> <c4>] }: new, then one call per item in
   order, done after the last. */
typedef enum zr_sdl_patch_item {
  ZR_SDL_PATCH_TYPE = 0,
  ZR_SDL_PATCH_FLATNESS,
  ZR_SDL_PATCH_U_STEPS,
  ZR_SDL_PATCH_V_STEPS
} zr_sdl_patch_item;

zr_object *zr__sdl_patch_new(zr_sdl_parser *p, const zr_sdl_loc *loc);
bool zr__sdl_patch_item(zr_sdl_parser *p, zr_object *o,
                        zr_sdl_patch_item item, const zr_sdl_expr *e,
                        const zr_sdl_loc *loc);
bool zr__sdl_patch_point(zr_sdl_parser *p, zr_object *o,
                         const zr_sdl_expr *e, const zr_sdl_loc *loc);
bool zr__sdl_patch_uv(zr_sdl_parser *p, zr_object *o,
                      const zr_sdl_expr e[4], const zr_sdl_loc at[4]);
bool zr__sdl_patch_done(zr_sdl_parser *p, zr_object *o,
                        const zr_sdl_loc *loc);

/* sphere_sweep { SPLINE N, <C1>, R1, ... [tolerance T] }: new with the
   spline (0 linear_spline, 1 b_spline, 2 cubic_spline) and the count,
   one call per centre or radius, tolerance, done. */
zr_object *zr__sdl_sweep_new(zr_sdl_parser *p, const zr_sdl_loc *loc,
                             int spline, const zr_sdl_expr *count,
                             const zr_sdl_loc *count_loc);
bool zr__sdl_sweep_item(zr_sdl_parser *p, zr_object *o,
                        const zr_sdl_expr *e, const zr_sdl_loc *loc);
bool zr__sdl_sweep_tolerance(zr_sdl_parser *p, zr_object *o,
                             const zr_sdl_expr *e, const zr_sdl_loc *loc);
bool zr__sdl_sweep_done(zr_sdl_parser *p, zr_object *o,
                        const zr_sdl_loc *loc);

/* julia_fractal { <P> items }: new with the parameter, then the items:
   algebra (0 quaternion, 1 hypercomplex), function (the keyword's
   token), max_iteration, precision, slice; done. */
zr_object *zr__sdl_julia_new(zr_sdl_parser *p, const zr_sdl_loc *loc,
                             const zr_sdl_expr *param,
                             const zr_sdl_loc *param_loc);
void zr__sdl_julia_algebra(zr_object *o, int algebra);
bool zr__sdl_julia_function(zr_sdl_parser *p, zr_object *o, int token,
                            const zr_sdl_loc *loc);
/* pwr(X, Y): the function z^(X + i Y). */
bool zr__sdl_julia_pwr(zr_sdl_parser *p, zr_object *o, const zr_sdl_expr *x,
                       const zr_sdl_loc *x_loc, const zr_sdl_expr *y,
                       const zr_sdl_loc *y_loc);
bool zr__sdl_julia_iterations(zr_sdl_parser *p, zr_object *o,
                              const zr_sdl_expr *e, const zr_sdl_loc *loc);
bool zr__sdl_julia_precision(zr_sdl_parser *p, zr_object *o,
                             const zr_sdl_expr *e, const zr_sdl_loc *loc);
bool zr__sdl_julia_slice(zr_sdl_parser *p, zr_object *o,
                         const zr_sdl_expr *normal,
                         const zr_sdl_loc *normal_loc,
                         const zr_sdl_expr *distance,
                         const zr_sdl_loc *distance_loc);
bool zr__sdl_julia_done(zr_sdl_parser *p, zr_object *o,
                        const zr_sdl_loc *loc);

#endif /* ZR_SDL_BUILD_SURFACE_H */
