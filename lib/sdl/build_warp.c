/*
 * build_warp.c - the parser's helpers for warp { } (POV-Ray 3.7
 * reference manual, "Warps"; the warps themselves are lib/scene/warp.c).
 *
 * The grammar starts a warp from its kind's keyword (turbulence, repeat,
 * black_hole, planar, cylindrical, spherical, toroidal) and hands each
 * later item here, which checks that the item belongs to that kind: a
 * misplaced item is an error naming both, never ignored.  When the warp
 * reaches a pigment, normal or texture it is appended to the pattern's
 * list (a fresh copy in the arena, as declared patterns may share the
 * old one) with the owner's transform as it stands: the warp's frame.
 *
 * Checks beyond the grammar's, as POV-Ray 3.7 makes them: repeat's
 * direction has exactly one non-zero component; flip's non-zero
 * components flip; a repeated black hole is fitted into its block
 * (fit_repeated_hole).  We also reject a black hole radius that is not
 * positive and a zero orientation or planar normal (these are divided
 * by), and normalise orientations and the planar normal.
 */
#include "config.h"

#include <string.h>

#include "pov-parse.h"
#include "scene/warp.h"
#include "sdl/sdl.h"

static const char *kind_name(zr_warp_kind k) {
  static const char *const names[] = {"turbulence", "repeat", "black_hole",
                                      "planar", "cylindrical", "spherical",
                                      "toroidal", "cubic"};
  return names[k];
}

static const char *item_name(int token) {
  switch (token) {
  case T_OCTAVES: return "octaves";
  case T_OMEGA: return "omega";
  case T_LAMBDA: return "lambda";
  case T_TURBULENCE: return "turbulence";
  case T_OFFSET: return "offset";
  case T_FLIP: return "flip";
  case T_STRENGTH: return "strength";
  case T_FALLOFF: return "falloff";
  case T_INVERSE: return "inverse";
  case T_REPEAT: return "repeat";
  case T_ORIENTATION: return "orientation";
  case T_DIST_EXP: return "dist_exp";
  case T_MAJOR_RADIUS: return "major_radius";
  default: return "?";
  }
}

static bool want_unit(zr_sdl_parser *p, const zr_sdl_expr *e,
                      const zr_sdl_loc *loc, const char *what,
                      zr_vec3 *out) {
  zr_vec3 v;
  if (!zr__sdl_want_vector(p, e, loc, &v))
    return false;
  double len = zr_v3_len(v);
  if (!(len > 0)) {
    zr__sdl_error(p, ZR_ESCENE, loc, "%s must not be zero", what);
    return false;
  }
  *out = zr_v3_scale(v, 1 / len);
  return true;
}

static bool repeat_direction(zr_sdl_parser *p, const zr_sdl_expr *e,
                             const zr_sdl_loc *loc, zr_warp *w) {
  zr_vec3 d;
  if (!zr__sdl_want_vector(p, e, loc, &d))
    return false;
  double c[3] = {d.x, d.y, d.z};
  int axis = -1;
  for (int i = 0; i < 3; i++) {
    if (c[i] == 0)
      continue;
    if (axis >= 0) {
      zr__sdl_error(p, ZR_ESCENE, loc,
                    "a repeat warp repeats along one axis only");
      return false;
    }
    axis = i;
  }
  if (axis < 0) {
    zr__sdl_error(p, ZR_ESCENE, loc,
                  "a repeat warp needs a non-zero direction");
    return false;
  }
  w->axis = axis;
  w->width = c[axis];
  return true;
}

bool zr__sdl_warp_new(zr_sdl_parser *p, int kind, const zr_sdl_expr *a,
                      const zr_sdl_expr *b, const zr_sdl_loc *loc,
                      zr_sdl_pmod *out) {
  memset(out, 0, sizeof *out);
  out->token = T_WARP;
  out->loc = *loc;
  zr_warp *w = zr__sdl_alloc(p, sizeof *w);
  if (!w)
    return false;
  zr__warp_init(w, (zr_warp_kind)kind);
  out->warp = w;
  switch (w->kind) {
  case ZR_WARP_TURBULENCE:
    return zr__sdl_want_vector(p, a, loc, &w->turbulence);
  case ZR_WARP_REPEAT:
    return repeat_direction(p, a, loc, w);
  case ZR_WARP_BLACK_HOLE:
    if (!zr__sdl_want_vector(p, a, loc, &w->centre) ||
        !zr__sdl_want_float(p, b, loc, &w->radius))
      return false;
    if (!(w->radius > 0)) {
      zr__sdl_error(p, ZR_ESCENE, loc,
                    "a black_hole's radius must be positive");
      return false;
    }
    return true;
  case ZR_WARP_PLANAR:
    if (!a)
      return true;
    return want_unit(p, a, loc, "a planar warp's normal", &w->orientation) &&
           zr__sdl_want_float(p, b, loc, &w->distance);
  default:
    return true;
  }
}

/* On each repeated axis povray 3.7 moves the centre up to at least the
   radius and widens the spacing to at least centre + radius, so each
   copy lies in its block (measured: black_hole <0.5,0,0>, 1 repeat
   <3,0,0> acts on [0, 2] in every block of 3; <2.8,0,0>, 0.6 repeats
   every 3.4). */
static void fit_repeated_hole(zr_warp *w) {
  double *c[3] = {&w->centre.x, &w->centre.y, &w->centre.z};
  double *r[3] = {&w->repeat.x, &w->repeat.y, &w->repeat.z};
  for (int i = 0; i < 3; i++) {
    if (!(*r[i] > 0))
      continue;
    if (*c[i] < w->radius)
      *c[i] = w->radius;
    if (*r[i] < *c[i] + w->radius)
      *r[i] = *c[i] + w->radius;
  }
}

/* A repeated black hole's turbulence moves each copy by the turbulence
   times a random number in [0, 1) per block, as the manual says, but
   povray 3.7's numbers are not ours (measured, pics s10: 0.8003, 0.5670,
   0.7118, 0.6813 in x blocks -2..1 against our 0.7863, 0.1943, 0.9722,
   0.9540), so the holes land elsewhere (blkhole.pov).  Said at the
   second of turbulence and repeat, once both are non-zero. */
static void warn_hole_turbulence(zr_sdl_parser *p, const zr_warp *w,
                                 const zr_sdl_loc *loc) {
  if (w->kind != ZR_WARP_BLACK_HOLE)
    return;
  zr_vec3 t = w->turbulence, r = w->repeat;
  if ((t.x != 0 || t.y != 0 || t.z != 0) &&
      (r.x != 0 || r.y != 0 || r.z != 0))
    zr__sdl_warning(p, loc,
                    "black_hole turbulence moves each repeated hole by "
                    "random amounts that are not povray's: the holes are "
                    "placed differently");
}

/* Whether an item belongs to a warp of this kind. */
static bool item_fits(zr_warp_kind k, int token) {
  switch (token) {
  case T_OCTAVES:
  case T_OMEGA:
  case T_LAMBDA:
    return k == ZR_WARP_TURBULENCE;
  case T_TURBULENCE:
    return k == ZR_WARP_TURBULENCE || k == ZR_WARP_BLACK_HOLE;
  case T_OFFSET:
  case T_FLIP:
    return k == ZR_WARP_REPEAT;
  case T_STRENGTH:
  case T_FALLOFF:
  case T_INVERSE:
  case T_REPEAT:
    return k == ZR_WARP_BLACK_HOLE;
  case T_ORIENTATION:
  case T_DIST_EXP:
    return k == ZR_WARP_CYLINDRICAL || k == ZR_WARP_SPHERICAL ||
           k == ZR_WARP_TOROIDAL;
  case T_MAJOR_RADIUS:
    return k == ZR_WARP_TOROIDAL;
  default:
    return false;
  }
}

bool zr__sdl_warp_item(zr_sdl_parser *p, zr_sdl_pmod *wm,
                       const zr_sdl_pmod *m) {
  zr_warp *w = wm->warp;
  const zr_sdl_expr *e = &m->value;
  const zr_sdl_loc *loc = &m->loc;
  if (!item_fits(w->kind, m->token)) {
    zr__sdl_error(p, ZR_ESCENE, loc, "'%s' is not an item of a %s warp",
                  item_name(m->token), kind_name(w->kind));
    return false;
  }
  switch (m->token) {
  case T_OCTAVES:
    return zr__sdl_octaves(p, e, loc, &w->octaves);
  case T_OMEGA:
    return zr__sdl_want_float(p, e, loc, &w->omega);
  case T_LAMBDA:
    return zr__sdl_want_float(p, e, loc, &w->lambda);
  case T_TURBULENCE:
    if (!zr__sdl_want_vector(p, e, loc, &w->turbulence))
      return false;
    warn_hole_turbulence(p, w, loc);
    return true;
  case T_OFFSET:
    return zr__sdl_want_vector(p, e, loc, &w->offset);
  case T_FLIP: {
    zr_vec3 f;
    if (!zr__sdl_want_vector(p, e, loc, &f))
      return false;
    w->flip = zr_v3(f.x != 0 ? -1 : 1, f.y != 0 ? -1 : 1, f.z != 0 ? -1 : 1);
    return true;
  }
  case T_STRENGTH:
    return zr__sdl_want_float(p, e, loc, &w->strength);
  case T_FALLOFF:
    return zr__sdl_want_float(p, e, loc, &w->falloff);
  case T_INVERSE:
    w->inverse = true;
    return true;
  case T_REPEAT:
    if (!zr__sdl_want_vector(p, e, loc, &w->repeat))
      return false;
    fit_repeated_hole(w);
    warn_hole_turbulence(p, w, loc);
    return true;
  case T_ORIENTATION:
    return want_unit(p, e, loc, "orientation", &w->orientation);
  case T_DIST_EXP:
    return zr__sdl_want_float(p, e, loc, &w->dist_exp);
  case T_MAJOR_RADIUS:
    return zr__sdl_want_float(p, e, loc, &w->major_radius);
  default:
    return false;
  }
}

bool zr__sdl_pattern_warp(zr_sdl_parser *p, zr_pattern *pt,
                          const zr_transform *frame, const zr_sdl_pmod *m) {
  zr_warp *list = p->warp_tail;
  if (!(pt->warps && pt->warps == p->warp_tail &&
        pt->n_warps == p->warp_tail_n && pt->n_warps < p->warp_tail_cap)) {
    int cap = pt->n_warps < 4 ? 4 : 2 * pt->n_warps;
    list = zr__sdl_alloc(p, (size_t)cap * sizeof *list);
    if (!list)
      return false;
    if (pt->n_warps > 0)
      memcpy(list, pt->warps, (size_t)pt->n_warps * sizeof *list);
    p->warp_tail = list;
    p->warp_tail_cap = cap;
  }
  p->warp_tail_n = pt->n_warps + 1;
  zr_warp *w = &list[pt->n_warps];
  *w = *m->warp;
  if (frame)
    w->frame = *frame;
  else
    zr__transform_identity(&w->frame);
  pt->warps = list;
  pt->n_warps++;
  return true;
}

bool zr__sdl_pattern_mod_in(zr_sdl_parser *p, zr_pattern *pt,
                            const zr_transform *frame,
                            const zr_sdl_pmod *m) {
  if (m->token == T_WARP)
    return zr__sdl_pattern_warp(p, pt, frame, m);
  return zr__sdl_pattern_mod(p, pt, m);
}
