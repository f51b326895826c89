/*
 * build_iso.h - building isosurface, parametric and ovus
 * (lib/sdl/build_iso.c) and height field (lib/sdl/build_hf.c) objects
 * from the grammar's actions.
 */
#ifndef ZR_SDL_BUILD_ISO_H
#define ZR_SDL_BUILD_ISO_H

#include "sdl/function.h"
#include "sdl/sdl.h"

/* isosurface { function { ... } ...: the object with POV-Ray's
   defaults, once the grammar has compiled the function (at fn_loc). */
zr_object *zr__sdl_isosurface_new(zr_sdl_parser *p, const zr_sdl_loc *loc,
                                  const zr_fn *fn, const zr_sdl_loc *fn_loc);
/* contained_by { sphere { ... } | box { ... } } */
bool zr__sdl_isosurface_container(zr_sdl_parser *p, zr_object *o,
                                  const zr_object *container,
                                  const zr_sdl_loc *loc);
/* threshold, accuracy, max_gradient, max_trace (token, one value),
   all_intersections (e NULL) and evaluate (e[0..2]). */
bool zr__sdl_isosurface_item(zr_sdl_parser *p, zr_object *o, int token,
                             const zr_sdl_expr *e, const zr_sdl_loc *at);

/* parametric { function {..} function {..} function {..} <u1, v1>,
   <u2, v2> ...: the object, then contained_by, and max_gradient,
   accuracy and precompute (its depth; token, one value). */
zr_object *zr__sdl_parametric_new(zr_sdl_parser *p, const zr_sdl_loc *loc,
                                  const zr_fn *const fn[3],
                                  const zr_sdl_loc fn_loc[3],
                                  const zr_sdl_expr uv[2],
                                  const zr_sdl_loc uv_loc[2]);
bool zr__sdl_parametric_container(zr_sdl_parser *p, zr_object *o,
                                  const zr_object *container,
                                  const zr_sdl_loc *loc);
/* At the parametric's end: a max_gradient below the functions' slopes
   measured on a grid is raised to them (build_iso.c). */
bool zr__sdl_parametric_done(zr_sdl_parser *p, zr_object *o,
                             const zr_sdl_loc *loc);
bool zr__sdl_parametric_item(zr_sdl_parser *p, zr_object *o, int token,
                             const zr_sdl_expr *e, const zr_sdl_loc *at);

/* ovus { Bottom_radius, Top_radius } */
zr_object *zr__sdl_ovus(zr_sdl_parser *p, const zr_sdl_loc *loc,
                        const zr_sdl_expr *bottom,
                        const zr_sdl_loc *bottom_loc,
                        const zr_sdl_expr *top, const zr_sdl_loc *top_loc);

/*
 * height_field { [type] "file" | function W, H { ... } [smooth]
 * [water_level L] [hierarchy [B]] } (lib/sdl/build_hf.c): the object
 * from an image file (its type from the file itself), or from a
 * function sampled W x H times; then the items; then done after the
 * last one, which makes the triangles.  pot: the file was named with
 * the pot keyword (a Fractint POT file, 16-bit heights in a GIF).
 */
zr_object *zr__sdl_height_field_image(zr_sdl_parser *p,
                                      const zr_sdl_loc *loc,
                                      const char *name,
                                      const zr_sdl_loc *name_loc, bool pot);
/* The function body whose '{' (at brace) the grammar has just shifted,
   read from the token array. */
const zr_fn *zr__sdl_height_field_fn_body(zr_sdl_parser *p,
                                          const zr_sdl_loc *brace);
zr_object *zr__sdl_height_field_function(zr_sdl_parser *p,
                                         const zr_sdl_loc *loc,
                                         const zr_sdl_expr size[2],
                                         const zr_sdl_loc size_loc[2],
                                         const zr_fn *fn,
                                         const zr_sdl_loc *fn_loc);
/* smooth (e NULL) and water_level. */
bool zr__sdl_height_field_item(zr_sdl_parser *p, zr_object *o, int token,
                               const zr_sdl_expr *e, const zr_sdl_loc *at);
bool zr__sdl_height_field_done(zr_sdl_parser *p, zr_object *o,
                               const zr_sdl_loc *loc);

#endif /* ZR_SDL_BUILD_ISO_H */
