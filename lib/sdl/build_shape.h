/*
 * build_shape.h - building torus, polygon, superellipsoid, prism, lathe,
 * blob and sor objects from the grammar's actions (lib/sdl/build_shape.c).
 */
#ifndef ZR_SDL_BUILD_SHAPE_H
#define ZR_SDL_BUILD_SHAPE_H

#include "sdl/sdl.h"

/* torus { Major, Minor } */
zr_object *zr__sdl_torus(zr_sdl_parser *p, const zr_sdl_loc *loc,
                         const zr_sdl_expr *major,
                         const zr_sdl_loc *major_loc,
                         const zr_sdl_expr *minor,
                         const zr_sdl_loc *minor_loc);
/* superellipsoid { <E, N> } */
zr_object *zr__sdl_superellipsoid(zr_sdl_parser *p, const zr_sdl_loc *loc,
                                  const zr_sdl_expr *en,
                                  const zr_sdl_loc *en_loc);
/* polygon { Number_Of_Points, <Point_1> ... }: the object after its
   count, one call per point, then done after the last point. */
zr_object *zr__sdl_polygon_new(zr_sdl_parser *p, const zr_sdl_loc *loc,
                               const zr_sdl_expr *count,
                               const zr_sdl_loc *count_loc);
bool zr__sdl_polygon_point(zr_sdl_parser *p, zr_object *o,
                           const zr_sdl_expr *point,
                           const zr_sdl_loc *point_loc);
bool zr__sdl_polygon_done(zr_sdl_parser *p, zr_object *o,
                          const zr_sdl_loc *loc);
/* prism { [SPLINE_TYPE SWEEP_TYPE...] Height_1, Height_2, N, points }:
   new, then option for each keyword before the heights (0-3: linear,
   quadratic, cubic, bezier spline; 4, 5: linear, conic sweep), size,
   one point call per point and done after the last. */
zr_object *zr__sdl_prism_new(zr_sdl_parser *p, const zr_sdl_loc *loc);
void zr__sdl_prism_option(zr_object *o, int option);
bool zr__sdl_prism_size(zr_sdl_parser *p, zr_object *o,
                        const zr_sdl_expr e[3], const zr_sdl_loc at[3]);
bool zr__sdl_prism_point(zr_sdl_parser *p, zr_object *o,
                         const zr_sdl_expr *point,
                         const zr_sdl_loc *point_loc);
bool zr__sdl_prism_done(zr_sdl_parser *p, zr_object *o,
                        const zr_sdl_loc *loc);
/* lathe { [SPLINE_TYPE] N, points }: new, option for the spline keyword
   (0-3 as for a prism; the sweeps are refused), count, points, done. */
zr_object *zr__sdl_lathe_new(zr_sdl_parser *p, const zr_sdl_loc *loc);
bool zr__sdl_lathe_option(zr_sdl_parser *p, zr_object *o, int option,
                          const zr_sdl_loc *loc);
bool zr__sdl_lathe_count(zr_sdl_parser *p, zr_object *o,
                         const zr_sdl_expr *count, const zr_sdl_loc *at);
bool zr__sdl_lathe_point(zr_sdl_parser *p, zr_object *o,
                         const zr_sdl_expr *point,
                         const zr_sdl_loc *point_loc);
bool zr__sdl_lathe_done(zr_sdl_parser *p, zr_object *o,
                        const zr_sdl_loc *loc);
/* blob { threshold T, sphere { c, r, [strength] s [transforms] },
   cylinder { a, b, r, [strength] s [transforms] }, component s, r, c }:
   new, then the items in order. */
zr_object *zr__sdl_blob_new(zr_sdl_parser *p, const zr_sdl_loc *loc);
bool zr__sdl_blob_threshold(zr_sdl_parser *p, zr_object *o,
                            const zr_sdl_expr *e, const zr_sdl_loc *at);
/* A component: e[] are centre, radius, strength (sphere, or the
   obsolete component with strength first when component is true) or
   end, end, radius, strength (cylinder). */
zr_blob_component *zr__sdl_blob_component(zr_sdl_parser *p, zr_object *o,
                                          bool cylinder, bool component,
                                          const zr_sdl_expr *e,
                                          const zr_sdl_loc *at);
/* An item inside a component of blob: a transformation or texture. */
bool zr__sdl_blob_component_mod(zr_sdl_parser *p, zr_object *blob,
                                zr_blob_component *c, const zr_sdl_mod *mod,
                                const zr_sdl_loc *loc);
/* sor { N, points }: new after the count, one call per point, done. */
zr_object *zr__sdl_sor_new(zr_sdl_parser *p, const zr_sdl_loc *loc,
                           const zr_sdl_expr *count,
                           const zr_sdl_loc *count_loc);
bool zr__sdl_sor_point(zr_sdl_parser *p, zr_object *o,
                       const zr_sdl_expr *point,
                       const zr_sdl_loc *point_loc);
bool zr__sdl_sor_done(zr_sdl_parser *p, zr_object *o,
                      const zr_sdl_loc *loc);
/* The sturm keyword, for the shapes whose manual entry lists it. */
bool zr__sdl_sturm(zr_sdl_parser *p, zr_object *o, const zr_sdl_loc *loc);

#endif /* ZR_SDL_BUILD_SHAPE_H */
