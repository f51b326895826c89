/*
 * build_pattern.c - the parser's helpers for transform blocks and
 * transform identifiers (reference manual, "Transformations"), the
 * fractal patterns ("Fractal Pattern") and the function pattern
 * ("Function Pattern").
 *
 * A transform block composes its items in order; inverse, wherever it
 * stands in the block, inverts the whole block when it ends, which is
 * what povray 3.7 does (measured: transform { translate x inverse
 * translate 2*y } moves the origin to <-1,-2,0>, and so does the block
 * with inverse first).  A transform identifier holds the finished
 * transform; every use copies it, since objects keep pointers.
 *
 * min_extent and max_extent give the corners of the box the tracer's
 * bounding uses (lib/scene/bounds.c), the transformed corners of the
 * shape's own box, which is what povray 3.7 prints for a scaled and
 * rotated sphere.
 *
 * The fractal patterns' items are checked against POV-Ray 3.7's ranges:
 * exponent 2 to 33, interior and exterior types 0 to 6 (povray 3.7.0
 * rejects 7 and 8, which the manual also lists), magnet 1 or 2.
 */
#include "config.h"

#include <string.h>

#include <math.h>

#include "pov-parse.h"
#include "sdl/build_pattern.h"
#include "trace/intersect.h"

/* ---- transforms ---- */

zr_sdl_tblock *zr__sdl_transform_block_new(zr_sdl_parser *p) {
  zr_sdl_tblock *b = zr__sdl_alloc(p, sizeof *b);
  if (!b)
    return NULL;
  zr__transform_identity(&b->t);
  b->inverse = false;
  return b;
}

void zr__sdl_transform_block_add(zr_sdl_tblock *b, const zr_transform *t) {
  zr__transform_compose(&b->t, t);
}

zr_transform *zr__sdl_transform_block_end(zr_sdl_parser *p,
                                          const zr_sdl_tblock *b) {
  zr_transform *t = zr__sdl_transform_copy(p, &b->t);
  if (t && b->inverse)
    zr__transform_invert(t);
  return t;
}

zr_transform *zr__sdl_transform_copy(zr_sdl_parser *p,
                                     const zr_transform *t) {
  zr_transform *c = zr__sdl_alloc(p, sizeof *c);
  if (c)
    *c = *t;
  return c;
}

/* ---- object extents ---- */

zr_sdl_expr zr__sdl_extent(zr_sdl_parser *p, const zr_object *o, bool max) {
  (void)p;
  zr_vec3 lo, hi;
  if (!zr__object_bounds(o, &lo, &hi)) {
    /* povray 3.7 gives <-1e10,-1e10,-1e10> and its opposite for a plane
       (measured: bench/provenance/probe.py unbounded_extent). */
    lo = zr_v3(-1e10, -1e10, -1e10);
    hi = zr_v3(1e10, 1e10, 1e10);
  }
  zr_vec3 v = max ? hi : lo;
  return zr__sdl_vec(v.x, v.y, v.z);
}

/* The nearest crossing of the ray with o after tmin, unions searched
   child by child (they are flattened only when the scene ends). */
static bool nearest_hit(const zr_object *o, const zr_ray *ray, double tmin,
                        zr_hit *best) {
  if (o->kind == ZR_OBJ_UNION) {
    bool any = false;
    for (size_t i = 0; i < o->u.csg.n_children; i++) {
      zr_hit h;
      if (nearest_hit(o->u.csg.children[i], ray, tmin, &h) &&
          (!any || h.t < best->t)) {
        *best = h;
        any = true;
      }
    }
    return any;
  }
  zr_hit hits[ZR_MAX_CROSSINGS];
  if (zr__intersect(o, ray, tmin, INFINITY, hits) == 0)
    return false;
  *best = hits[0];
  return true;
}

bool zr__sdl_trace(zr_sdl_parser *p, const zr_object *o,
                   const zr_sdl_expr *start, const zr_sdl_expr *dir,
                   const zr_sdl_decl_name *normal, const zr_sdl_loc *loc,
                   zr_sdl_expr *out) {
  zr_ray ray;
  if (!zr__sdl_want_vector(p, start, loc, &ray.origin) ||
      !zr__sdl_want_vector(p, dir, loc, &ray.dir))
    return false;
  zr_vec3 point = zr_v3(0, 0, 0), n = zr_v3(0, 0, 0);
  double len = zr_v3_len(ray.dir);
  if (len > 0) {
    ray.dir = zr_v3_scale(ray.dir, 1 / len);
    /* povray 3.7's trace() skips crossings nearer than 1e-4 (a sphere's
       entry 1e-5 ahead is passed over for its exit) and finds none at
       1e7 or farther, for every shape (measured: test_pattern_more's
       trace_limits; tracevines.pov's vines grow on that). */
    zr_hit h;
    if (nearest_hit(o, &ray, 1e-4, &h) && h.t < 1e7) {
      point = zr_v3_madd(ray.origin, ray.dir, h.t);
      n = h.normal;
    }
  }
  *out = zr__sdl_vec(point.x, point.y, point.z);
  if (!normal)
    return true;
  /* povray 3.7 wants a declared vector there ("Expected ')', undeclared
     identifier found instead", and likewise for a float). */
  const zr_sdl_symbol *s = zr__sdl_lookup(p, normal->name, NULL);
  if (!s) {
    zr__sdl_error(p, ZR_EUNDEFINED, loc, "trace's normal variable '%s' "
                  "is not declared", normal->name);
    return false;
  }
  if (s->value.kind != ZR_SDL_VECTOR) {
    zr__sdl_error(p, ZR_ESYNTAX, loc, "trace's normal variable '%s' "
                  "must be a vector", normal->name);
    return false;
  }
  zr_sdl_value v;
  memset(&v, 0, sizeof v);
  v.kind = ZR_SDL_VECTOR;
  v.num = zr__sdl_vec(n.x, n.y, n.z);
  return zr__sdl_define(p, normal, false, &v, loc);
}

/* ---- fractal patterns ---- */

/* A whole number in [lo, hi] from e, or an error naming what. */
static bool want_int(zr_sdl_parser *p, const zr_sdl_expr *e,
                     const zr_sdl_loc *loc, double lo, double hi,
                     const char *what, int *out) {
  double v;
  if (!zr__sdl_want_float(p, e, loc, &v))
    return false;
  if (!(v >= lo && v <= hi)) {
    zr__sdl_error(p, ZR_ESCENE, loc, "%s must be from %g to %g", what, lo,
                  hi);
    return false;
  }
  *out = (int)v;
  return true;
}

bool zr__sdl_fractal_head(zr_sdl_parser *p, zr_sdl_fractal_head *out,
                          int kind, const zr_sdl_expr *c,
                          const zr_sdl_loc *cl, const zr_sdl_expr *n,
                          const zr_sdl_loc *nl) {
  memset(out, 0, sizeof *out);
  out->kind = kind;
  out->f.exponent = 2;
  out->f.exterior = 1;
  out->f.interior_factor = out->f.exterior_factor = 1;
  if (c) {
    if (c->dim != 2) {
      zr__sdl_error(p, ZR_ESCENE, cl,
                    "julia wants a 2-D vector (a complex number)");
      return false;
    }
    out->f.c[0] = c->v[0];
    out->f.c[1] = c->v[1];
  }
  return want_int(p, n, nl, 1, 4294967295.0, "the number of iterations",
                  &out->f.iterations);
}

bool zr__sdl_fractal_magnet(zr_sdl_parser *p, zr_sdl_fractal_head *h,
                            const zr_sdl_expr *type,
                            const zr_sdl_loc *loc) {
  return want_int(p, type, loc, 1, 2, "the magnet type", &h->f.magnet);
}

void zr__sdl_pattern_object(zr_pattern *pt, const zr_object *object) {
  pt->object = object;
  pt->object_inside = zr__inside;
}

void zr__sdl_fractal_set(zr_pattern *pt, const zr_sdl_fractal_head *h) {
  pt->fractal = h->f;
}

bool zr__sdl_fractal_colouring(zr_sdl_parser *p, int token,
                               const zr_sdl_expr *type,
                               const zr_sdl_expr *factor,
                               const zr_sdl_loc *loc, zr_sdl_pmod *out) {
  double t, f;
  if (!zr__sdl_want_float(p, type, loc, &t) ||
      !zr__sdl_want_float(p, factor, loc, &f))
    return false;
  memset(out, 0, sizeof *out);
  out->token = token;
  out->loc = *loc;
  out->value.dim = 2;
  out->value.v[0] = t;
  out->value.v[1] = f;
  return true;
}

bool zr__sdl_pattern_mod_more(zr_sdl_parser *p, zr_pattern *pt,
                              const zr_sdl_pmod *m) {
  switch (m->token) {
  case T_EXPONENT:
    return want_int(p, &m->value, &m->loc, 2, 33, "exponent",
                    &pt->fractal.exponent);
  case T_FORM:
    return zr__sdl_want_vector(p, &m->value, &m->loc, &pt->crackle_form);
  case T_METRIC: {
    double v;
    if (!zr__sdl_want_float(p, &m->value, &m->loc, &v))
      return false;
    if (!(v > 0)) {
      zr__sdl_error(p, ZR_ESCENE, &m->loc, "crackle's metric must be "
                    "positive");
      return false;
    }
    pt->crackle_metric = v;
    return true;
  }
  case T_OFFSET:
    return zr__sdl_want_float(p, &m->value, &m->loc, &pt->crackle_offset);
  case T_SOLID:
    pt->crackle_solid = true;
    return true;
  case T_INTERIOR:
  case T_EXTERIOR: {
    bool in = m->token == T_INTERIOR;
    double t = m->value.v[0];
    if (!(t >= 0 && t <= 6) || t != (int)t) {
      zr__sdl_error(p, ZR_ESCENE, &m->loc, "the %s type must be 0 to 6",
                    in ? "interior" : "exterior");
      return false;
    }
    if (in) {
      pt->fractal.interior = (int)t;
      pt->fractal.interior_factor = m->value.v[1];
    } else {
      pt->fractal.exterior = (int)t;
      pt->fractal.exterior_factor = m->value.v[1];
    }
    return true;
  }
  default:
    return true;
  }
}

/* ---- the function pattern ---- */

bool zr__sdl_pattern_function(zr_sdl_parser *p, zr_pattern *pt,
                              const zr_fn *fn, const zr_sdl_loc *loc) {
  const char *missing = zr__fn_unsupported(fn);
  if (missing) {
    zr__sdl_error(p, ZR_EUNSUPPORTED, loc,
                  "this function pattern uses %s, which is not supported "
                  "yet", missing);
    return false;
  }
  pt->fn = fn;
  return true;
}

bool zr__sdl_normal_accuracy(zr_sdl_parser *p, zr_normal *nm,
                             const zr_sdl_expr *e, const zr_sdl_loc *loc) {
  double a;
  if (!zr__sdl_want_float(p, e, loc, &a))
    return false;
  if (!(a > 0)) {
    zr__sdl_error(p, ZR_ESCENE, loc, "a normal's accuracy must be "
                  "positive");
    return false;
  }
  nm->accuracy = a;
  return true;
}

/* ---- tiles ---- */

bool zr__sdl_tiles(zr_sdl_parser *p, zr_texture *tx, const zr_texture *a,
                   const zr_texture *b, const zr_sdl_loc *loc) {
  zr_map *m = zr__sdl_map_new(p);
  if (!m)
    return false;
  /* tile2's texture takes checker's first cells and the tiles texture
     the others: povray 3.7 renders tiles { A tile2 B } as checker
     texture { B } texture { A } (measured). */
  zr_map_entry e;
  memset(&e, 0, sizeof e);
  e.u.texture = b;
  if (!zr__sdl_map_add_block(p, m, &e, loc))
    return false;
  e.u.texture = a;
  return zr__sdl_map_add_block(p, m, &e, loc) &&
         zr__sdl_texture_map_set(p, tx, m, loc);
}
