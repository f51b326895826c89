/*
 * build_pattern.h - the parser's helpers for transform blocks and
 * identifiers, the fractal patterns and the function pattern
 * (lib/sdl/build_pattern.c).
 */
#ifndef ZR_SDL_BUILD_PATTERN_H
#define ZR_SDL_BUILD_PATTERN_H

#include <stdbool.h>

#include "sdl/function.h"
#include "sdl/sdl.h"

/* transform { ... } while it is read: the transforms so far, and
   whether inverse was written anywhere in it. */
typedef struct zr_sdl_tblock {
  zr_transform t;
  bool inverse;
} zr_sdl_tblock;

zr_sdl_tblock *zr__sdl_transform_block_new(zr_sdl_parser *p);
/* Appends t (applied after what the block holds). */
void zr__sdl_transform_block_add(zr_sdl_tblock *b, const zr_transform *t);
/* The block's transform, inverted when it said inverse. */
zr_transform *zr__sdl_transform_block_end(zr_sdl_parser *p,
                                          const zr_sdl_tblock *b);
/* A private copy of a declared transform. */
zr_transform *zr__sdl_transform_copy(zr_sdl_parser *p,
                                     const zr_transform *t);

/* A fractal pattern as written: its kind and fractal settings. */
typedef struct zr_sdl_fractal_head {
  int kind; /* ZR_PAT_MANDEL or ZR_PAT_JULIA */
  zr_fractal f;
} zr_sdl_fractal_head;

/* mandel Iterations (c NULL) or julia <c>, Iterations. */
bool zr__sdl_fractal_head(zr_sdl_parser *p, zr_sdl_fractal_head *out,
                          int kind, const zr_sdl_expr *c,
                          const zr_sdl_loc *cl, const zr_sdl_expr *n,
                          const zr_sdl_loc *nl);
/* magnet 1 or magnet 2 in front. */
bool zr__sdl_fractal_magnet(zr_sdl_parser *p, zr_sdl_fractal_head *h,
                            const zr_sdl_expr *type, const zr_sdl_loc *loc);
/* Gives pt, already of the head's kind, the fractal's settings. */
void zr__sdl_fractal_set(zr_pattern *pt, const zr_sdl_fractal_head *h);
/* object { OBJECT ... }: the object and the tracer's inside test. */
void zr__sdl_pattern_object(zr_pattern *pt, const zr_object *object);
/* interior Type, Factor or exterior Type, Factor as a pattern modifier
   (type and factor in out->value.v[0], v[1]). */
bool zr__sdl_fractal_colouring(zr_sdl_parser *p, int token,
                               const zr_sdl_expr *type,
                               const zr_sdl_expr *factor,
                               const zr_sdl_loc *loc, zr_sdl_pmod *out);
/* The pattern modifiers zr__sdl_pattern_mod (build.c) leaves here:
   exponent, interior, exterior. */
bool zr__sdl_pattern_mod_more(zr_sdl_parser *p, zr_pattern *pt,
                              const zr_sdl_pmod *m);
/* function { ... } as pt's pattern: fn must take (x, y, z) and be one
   zRcube can evaluate. */
bool zr__sdl_pattern_function(zr_sdl_parser *p, zr_pattern *pt,
                              const zr_fn *fn, const zr_sdl_loc *loc);

/* min_extent(O) (max false) or max_extent(O): the corners of the
   object's bounding box, +-1e10 for an unbounded one, as in POV-Ray. */
zr_sdl_expr zr__sdl_extent(zr_sdl_parser *p, const zr_object *o, bool max);

/* normal { accuracy A }: A > 0. */
bool zr__sdl_normal_accuracy(zr_sdl_parser *p, zr_normal *nm,
                             const zr_sdl_expr *e, const zr_sdl_loc *loc);

/* trace(Object, Start, Direction [, Normal]) ("Vector Functions"): the
   nearest point where the ray from Start along Direction meets the
   object, <0,0,0> when it does not; the surface's normal there (or
   <0,0,0>) goes to the variable named by normal when not NULL. */
bool zr__sdl_trace(zr_sdl_parser *p, const zr_object *o,
                   const zr_sdl_expr *start, const zr_sdl_expr *dir,
                   const zr_sdl_decl_name *normal, const zr_sdl_loc *loc,
                   zr_sdl_expr *out);

/* tiles { A tile2 B } on tx, already a checker texture. */
bool zr__sdl_tiles(zr_sdl_parser *p, zr_texture *tx, const zr_texture *a,
                   const zr_texture *b, const zr_sdl_loc *loc);

#endif /* ZR_SDL_BUILD_PATTERN_H */
