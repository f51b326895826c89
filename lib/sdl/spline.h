/*
 * spline.h - POV-Ray 3.7 splines in the scene language (reference manual
 * 3.3.1.11, "Spline"): `spline { [type] T1, <V1> T2, <V2> ... }`, called
 * as S(t) or S(t, type), and the bodies of `function { spline { } }`.
 */
#ifndef ZR_SDL_SPLINE_H
#define ZR_SDL_SPLINE_H

#include <stdbool.h>
#include <stddef.h>

#include "sdl/sdl.h"

/* The interpolations, in the order of their keywords. */
typedef enum zr_sdl_spline_type {
  ZR_SPLINE_LINEAR = 0,
  ZR_SPLINE_QUADRATIC,
  ZR_SPLINE_CUBIC,
  ZR_SPLINE_NATURAL
} zr_sdl_spline_type;

/* A spline: its points sorted by parameter, each a value of 5
   components (shorter vectors padded with zeros, as POV-Ray does).  The
   second derivatives of the natural spline are kept for every type,
   since a call may ask for natural interpolation of any spline.  In the
   scene's arena and never changed once its block is closed. */
typedef struct zr_sdl_spline {
  zr_sdl_spline_type type;
  int dim;      /* components of a result: the most of any point */
  size_t n, cap;
  double *t;
  double (*v)[5];
  double (*d2)[5]; /* natural spline: second derivatives at the points */
} zr_sdl_spline;

/* A new spline, a copy of from (or empty, linear, if from is NULL). */
zr_sdl_spline *zr__sdl_spline_new(zr_sdl_parser *p,
                                  const zr_sdl_spline *from);
/* Adds the point (t, v); a point with the same t replaces the older. */
bool zr__sdl_spline_add(zr_sdl_parser *p, zr_sdl_spline *s,
                        const zr_sdl_expr *t, const zr_sdl_loc *t_loc,
                        const zr_sdl_expr *v);
/* Closes the block: checks it has a point and computes what evaluation
   needs.  loc is the block's. */
bool zr__sdl_spline_finish(zr_sdl_parser *p, zr_sdl_spline *s,
                           const zr_sdl_loc *loc);
/* The spline at t, interpolated as type (the spline's own if < 0),
   into out[0..5); never allocates, safe from any number of threads. */
void zr__sdl_spline_eval(const zr_sdl_spline *s, int type, double t,
                         double out[5]);
/* The same as a value of the scene language (a vector of s->dim). */
zr_sdl_expr zr__sdl_spline_value(const zr_sdl_spline *s, int type,
                                 double t);

#endif /* ZR_SDL_SPLINE_H */
