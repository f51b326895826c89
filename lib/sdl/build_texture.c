/*
 * build_texture.c - the parser's helpers for the texture constructs that
 * hold other textures (reference manual r3_4: "Layered Textures",
 * "Patterned Textures", "Texture Maps", "Pigment Maps and Pigment
 * Lists", "Normal Maps and Normal Lists", "Slope Maps", "Average",
 * "Pigment Pattern", "Material").
 *
 * Maps are built entry by entry into the scene's arena, doubling like
 * colour maps (build.c); values out of order are read as POV-Ray reads
 * them (lib/scene/texture.c).  Block
 * patterns' lists ("checker pigment {A} pigment {B}") become maps whose
 * values are the entries' indices, so evaluation (lib/scene/texture.c)
 * treats both alike.
 *
 * A layered texture is a chain from its bottom layer up through over;
 * layering copies the lower chain, since declared textures are shared,
 * and points its top at the upper one.  A pigment, finish or normal in
 * "texture { Layered ... }" or on an object with a layered texture
 * changes the top layer: the manual says the bottom one, but POV-Ray
 * 3.7 renders the top one changed (measured: an opaque pigment there
 * hides every layer below and takes the top layer's finish).  An object given a
 * texture while it has one gets the new one as a layer on top (POV-Ray
 * 3.7 renders object { S texture { T } } with T over S's texture).
 *
 * Transforms reach every part of a texture: its pigment and normal
 * (build.c), and here the map's pattern, every texture of the map and
 * every layer above, each copied before it changes.  Pigment and normal
 * maps need nothing: their items are evaluated in the outer pattern's
 * space (texture.c).
 */
#include "config.h"

#include <math.h>
#include <string.h>

#include "pov-parse.h"
#include "scene/pattern.h"
#include "scene/bitmap.h"
#include "sdl/sdl.h"

/* ---- maps ---- */

/* Entry arrays grow by doubling: room for n entries is the next power
   of two (at least 4). */
static size_t room(size_t n) {
  size_t r = 4;
  while (r < n)
    r *= 2;
  return r;
}

zr_map *zr__sdl_map_new(zr_sdl_parser *p) {
  return zr__sdl_alloc(p, sizeof(zr_map));
}

static bool append(zr_sdl_parser *p, zr_map *m, const zr_map_entry *e) {
  zr_map_entry *entries = (zr_map_entry *)m->entries;
  if (m->n == 0 || m->n == room(m->n)) {
    entries = zr__sdl_alloc(p, room(m->n + 1) * sizeof *entries);
    if (!entries)
      return false;
    if (m->n)
      memcpy(entries, m->entries, m->n * sizeof *entries);
  }
  entries[m->n] = *e;
  m->entries = entries;
  m->n++;
  return true;
}

bool zr__sdl_map_add(zr_sdl_parser *p, zr_map *m, const zr_sdl_expr *v,
                     const zr_sdl_loc *vl, zr_map_entry *e) {
  if (!zr__sdl_want_float(p, v, vl, &e->value))
    return false;
  return append(p, m, e);
}

bool zr__sdl_map_add_weight1(zr_sdl_parser *p, zr_map *m,
                             zr_map_entry *e) {
  e->value = 1;
  m->n_unweighted++;
  return append(p, m, e);
}

bool zr__sdl_map_add_block(zr_sdl_parser *p, zr_map *m, zr_map_entry *e,
                           const zr_sdl_loc *loc) {
  if (m->n == 3) {
    zr__sdl_error(p, ZR_ESYNTAX, loc, "too many items for this pattern");
    return false;
  }
  e->value = (double)m->n;
  return append(p, m, e);
}

bool zr__sdl_slope_add(zr_sdl_parser *p, zr_map *m, const zr_sdl_expr *v,
                       const zr_sdl_loc *vl, const zr_sdl_expr *hs,
                       const zr_sdl_loc *hsl) {
  zr_map_entry e;
  memset(&e, 0, sizeof e);
  if (hs->dim != 2) {
    zr__sdl_error(p, ZR_ESCENE, hsl,
                  "a slope_map entry wants <height, slope>");
    return false;
  }
  e.u.slope.height = hs->v[0];
  e.u.slope.slope = hs->v[1];
  return zr__sdl_map_add(p, m, v, vl, &e);
}

bool zr__sdl_map_done(zr_sdl_parser *p, const zr_map *m, const char *what,
                      const zr_sdl_loc *loc) {
  if (m->n == 0) {
    zr__sdl_error(p, ZR_ESYNTAX, loc, "a %s needs an entry", what);
    return false;
  }
  return true;
}

/* A block pattern takes at most as many items as it has blocks, and
   only an average's entries may leave out their value (povray 3.7:
   "gradient x pigment_map { [bozo] }" is "Expected 'numeric
   expression', bozo found"). */
static bool block_fits(zr_sdl_parser *p, zr_pattern_kind kind,
                       const zr_map *m, const zr_sdl_loc *loc) {
  if (kind == ZR_PAT_AVERAGE)
    return true;
  if (m->n_unweighted && kind != ZR_PAT_NONE) {
    zr__sdl_error(p, ZR_ESYNTAX, loc, "only an average's map entries may "
                  "leave out their value");
    return false;
  }
  if (!zr__pattern_is_block(kind))
    return true;
  size_t most = kind == ZR_PAT_HEXAGON ? 3 : 2;
  if (m->n > most) {
    zr__sdl_error(p, ZR_ESYNTAX, loc, "too many items for this pattern");
    return false;
  }
  return true;
}

bool zr__sdl_pigment_map_set(zr_sdl_parser *p, zr_pigment *pg,
                             const zr_map *m, const zr_sdl_loc *loc) {
  if (pg->kind == ZR_PIGMENT_SOLID)
    pg->kind = ZR_PIGMENT_PATTERN;
  if (!block_fits(p, pg->pattern.kind, m, loc))
    return false;
  size_t want = pg->pattern.kind == ZR_PAT_HEXAGON ? 3 : 2;
  if (zr__pattern_is_block(pg->pattern.kind) && m->n < want) {
    /* Blocks left out are black: POV-Ray 3.7 renders "checker pigment
       { Green }" green and black (measured: tests/legacy/blocks.pov). */
    zr_map *full = zr__sdl_map_new(p);
    if (!full)
      return false;
    for (size_t i = 0; i < want; i++) {
      zr_map_entry e;
      if (i < m->n) {
        e = m->entries[i];
      } else {
        memset(&e, 0, sizeof e);
        if (!(e.u.pigment = zr__sdl_pigment_new(p, NULL)))
          return false;
      }
      if (!append(p, full, &e))
        return false;
    }
    m = full;
  }
  pg->pigment_map = m;
  return true;
}

bool zr__sdl_normal_map_set(zr_sdl_parser *p, zr_normal *nm,
                            const zr_map *m, const zr_sdl_loc *loc) {
  if (!block_fits(p, nm->pattern.kind, m, loc))
    return false;
  nm->normal_map = m;
  return true;
}

static const zr_texture *transformed(zr_sdl_parser *p, const zr_texture *tx,
                                     const zr_transform *t);

bool zr__sdl_texture_map_set(zr_sdl_parser *p, zr_texture *tx,
                             const zr_map *m, const zr_sdl_loc *loc) {
  if (!block_fits(p, tx->pattern.kind, m, loc))
    return false;
  if (tx->transform) {
    /* Transforms written before the map move its textures too: POV-Ray
       renders "gradient x scale 10 texture_map { [0 T] [1 T] }" with T
       scaled by 10 (T a gradient y pigment: 0.063 to 0.937 over y = 0
       to 10). */
    zr_map *moved = zr__sdl_map_new(p);
    if (!moved)
      return false;
    for (size_t i = 0; i < m->n; i++) {
      zr_map_entry e = m->entries[i];
      if (!(e.u.texture = transformed(p, e.u.texture, tx->transform)) ||
          !append(p, moved, &e))
        return false;
    }
    m = moved;
  }
  tx->map = m;
  return true;
}

/* ---- patterns ---- */

bool zr__sdl_spiral_arms(zr_sdl_parser *p, zr_pattern *pt,
                         const zr_sdl_expr *arms, const zr_sdl_loc *loc) {
  double n;
  if (!zr__sdl_want_float(p, arms, loc, &n))
    return false;
  pt->arms = (int)n;
  return true;
}

bool zr__sdl_tiling(zr_sdl_parser *p, zr_pattern *pt, const zr_sdl_expr *n,
                    const zr_sdl_loc *loc) {
  double v;
  if (!zr__sdl_want_float(p, n, loc, &v))
    return false;
  /* povray reads tiling 2.5 as tiling 2 (measured). */
  if (!(v >= 1 && v < 28)) {
    zr__sdl_error(p, ZR_ESCENE, loc, "the tiling number must be from 1 "
                  "to 27, not %g", v);
    return false;
  }
  if (!zr__pattern_tiling_known((int)v)) {
    zr__sdl_error(p, ZR_EUNSUPPORTED, loc, "tiling %d is not supported "
                  "yet", (int)v);
    return false;
  }
  pt->tiling = (int)v;
  return true;
}

void zr__sdl_pigment_pattern_of(zr_pattern *pt, const zr_pigment *pg) {
  pt->pigment = pg;
}

void zr__sdl_texture_pattern(zr_texture *tx, int kind) {
  zr__pattern_init(&tx->pattern, (zr_pattern_kind)kind);
}

/* ---- layers and transforms ---- */

zr_texture *zr__sdl_texture_layer(zr_sdl_parser *p, const zr_texture *below,
                                  const zr_texture *above) {
  if (!below)
    return zr__sdl_texture_new(p, above);
  zr_texture *bottom = zr__sdl_texture_new(p, below);
  if (!bottom)
    return NULL;
  zr_texture *last = bottom;
  while (last->over) {
    zr_texture *copy = zr__sdl_texture_new(p, last->over);
    if (!copy)
      return NULL;
    last->over = copy;
    last = copy;
  }
  last->over = above;
  return bottom;
}

zr_texture *zr__sdl_texture_shared(zr_sdl_parser *p, zr_texture *tx) {
  const zr_texture *from = p->texture_copied;
  if (tx != p->texture_copy || !from || memcmp(tx, from, sizeof *tx) != 0)
    return tx;
  p->texture_copy = NULL;
  p->texture_copied = NULL;
  if (p->own_body.tx == tx)
    p->own_body.tx = NULL;
  /* The copy was the last thing allocated when nothing changed it. */
  zr__arena_give_back(&p->scene->arena, tx, sizeof *tx);
  return (zr_texture *)from; /* the grammar's values are not const */
}

zr_texture *zr__sdl_texture_top(zr_sdl_parser *p, zr_texture *tx) {
  zr_texture *last = tx;
  while (last->over) {
    zr_texture *copy = zr__sdl_texture_new(p, last->over);
    if (!copy)
      return NULL;
    last->over = copy;
    last = copy;
  }
  return last;
}

/* A transformed copy of a whole texture (layers and map included). */
static const zr_texture *transformed(zr_sdl_parser *p, const zr_texture *tx,
                                     const zr_transform *t) {
  zr_texture *copy = zr__sdl_texture_new(p, tx);
  if (!copy || !zr__sdl_texture_transform(p, copy, t))
    return NULL;
  return copy;
}

bool zr__sdl_texture_transform_more(zr_sdl_parser *p, zr_texture *tx,
                                    const zr_transform *t) {
  /* The pattern moves even before its map is given, as in "gradient y
     scale 10 texture_map { ... }" (slopemt_36.pov): POV-Ray renders it
     the same as with the scale after the map. */
  if (tx->map || tx->pattern.kind != ZR_PAT_NONE) {
    zr_transform *c = zr__sdl_alloc(p, sizeof *c);
    if (!c)
      return false;
    if (tx->transform)
      *c = *tx->transform;
    else
      zr__transform_identity(c);
    zr__transform_compose(c, t);
    tx->transform = c;
  }
  if (tx->map) {
    zr_map *m = zr__sdl_map_new(p);
    if (!m)
      return false;
    for (size_t i = 0; i < tx->map->n; i++) {
      zr_map_entry e = tx->map->entries[i];
      if (!(e.u.texture = transformed(p, e.u.texture, t)) ||
          !append(p, m, &e))
        return false;
    }
    tx->map = m;
  }
  if (tx->over && !(tx->over = transformed(p, tx->over, t)))
    return false;
  return true;
}

/* ---- materials ---- */

zr_sdl_material *zr__sdl_material_new(zr_sdl_parser *p,
                                      const zr_sdl_material *from) {
  zr_sdl_material *m = zr__sdl_alloc(p, sizeof *m);
  if (m && from)
    *m = *from;
  return m;
}

bool zr__sdl_material_texture(zr_sdl_parser *p, zr_sdl_material *m,
                              const zr_texture *tx) {
  m->texture = zr__sdl_texture_layer(p, m->texture, tx);
  return m->texture != NULL;
}

bool zr__sdl_material_transform(zr_sdl_parser *p, zr_sdl_material *m,
                                const zr_transform *t) {
  if (!m->texture)
    return true;
  m->texture = transformed(p, m->texture, t);
  return m->texture != NULL;
}

/* ---- iridescence ("Iridescence", "Irid_Wavelength") ---- */

bool zr__sdl_finish_irid(zr_sdl_parser *p, zr_finish *f, int kw,
                         const zr_sdl_expr *e, const zr_sdl_loc *loc) {
  double v;
  if (!zr__sdl_want_float(p, e, loc, &v))
    return false;
  const char *what = kw == T_IRID        ? "irid amount"
                     : kw == T_THICKNESS ? "irid thickness"
                                         : "irid turbulence";
  if (!(v >= 0.0) || !isfinite(v)) {
    zr__sdl_error(p, ZR_ESCENE, loc, "%s must be a number >= 0", what);
    return false;
  }
  if (kw == T_IRID)
    f->irid = v;
  else if (kw == T_THICKNESS)
    f->irid_thickness = v;
  else
    f->irid_turbulence = v;
  return true;
}

bool zr__sdl_irid_wavelength(zr_sdl_parser *p, const zr_sdl_expr *e,
                             const zr_sdl_loc *loc) {
  zr_rgb w;
  if (!zr__sdl_want_rgb(p, e, loc, &w))
    return false;
  if (!(w.r > 0.0 && w.g > 0.0 && w.b > 0.0 && isfinite(w.r) &&
        isfinite(w.g) && isfinite(w.b))) {
    zr__sdl_error(p, ZR_ESCENE, loc,
                  "irid_wavelength must be > 0 in every channel");
    return false;
  }
  p->scene->settings.irid_wavelength = w;
  return true;
}

/* ---- the slope pattern ("Slope Pattern") ---- */

/* A range's two floats; a missing range leaves the defaults. */
static bool slope_range(zr_sdl_parser *p, const zr_sdl_expr *lo,
                        const zr_sdl_expr *hi, const zr_sdl_loc *loc,
                        double *lo_out, double *hi_out) {
  if (!lo)
    return true;
  return zr__sdl_want_float(p, lo, loc, lo_out) &&
         zr__sdl_want_float(p, hi, loc, hi_out);
}

zr_slope *zr__sdl_slope_new(zr_sdl_parser *p, const zr_sdl_expr *d,
                            const zr_sdl_loc *d_loc, const zr_sdl_expr *lo,
                            const zr_sdl_expr *hi,
                            const zr_sdl_loc *lo_loc) {
  zr_slope *sl = zr__sdl_alloc(p, sizeof *sl);
  if (!sl)
    return NULL;
  zr_pattern defaults;
  zr__pattern_init(&defaults, ZR_PAT_SLOPE);
  *sl = defaults.slope;
  if (!zr__sdl_want_vector(p, d, d_loc, &sl->direction))
    return NULL;
  if (!(zr_v3_len(sl->direction) > 0.0)) {
    zr__sdl_error(p, ZR_ESCENE, d_loc,
                  "the slope direction must not be a zero vector");
    return NULL;
  }
  if (!slope_range(p, lo, hi, lo_loc, &sl->lo, &sl->hi))
    return NULL;
  return sl;
}

bool zr__sdl_slope_altitude(zr_sdl_parser *p, zr_slope *sl,
                            const zr_sdl_expr *a, const zr_sdl_loc *a_loc,
                            const zr_sdl_expr *lo, const zr_sdl_expr *hi,
                            const zr_sdl_loc *lo_loc) {
  if (!zr__sdl_want_vector(p, a, a_loc, &sl->altitude))
    return false;
  if (!(zr_v3_len(sl->altitude) > 0.0)) {
    zr__sdl_error(p, ZR_ESCENE, a_loc,
                  "the slope's altitude must not be a zero vector");
    return false;
  }
  return slope_range(p, lo, hi, lo_loc, &sl->alt_lo, &sl->alt_hi);
}

/* ---- bump maps and material maps (lib/scene/bitmap.c) ---- */

zr_normal *zr__sdl_bump_map_new(zr_sdl_parser *p, zr_image_map *im) {
  zr_normal *bump = im ? zr__sdl_normal_new(p, NULL) : NULL;
  if (bump)
    bump->bump_map = im;
  return bump;
}

bool zr__sdl_bump_map_mod(zr_sdl_parser *p, zr_normal *bump, int token,
                          const zr_sdl_expr *e, const zr_sdl_loc *loc) {
  /* The picture is this bump map's own, read by zr__sdl_bump_map_new. */
  zr_image_map *im = (zr_image_map *)bump->bump_map;
  switch (token) {
  case T_USE_INDEX:
  case T_USE_COLOR:
    im->use_index = token == T_USE_INDEX;
    return true;
  case T_BUMP_SIZE:
    return zr__sdl_want_float(p, e, loc, &bump->amount);
  default:
    return zr__sdl_image_map_mod(p, im, token, e, loc);
  }
}

bool zr__sdl_bump_map_end(zr_sdl_parser *p, zr_normal *nm,
                          const zr_normal *bump, const zr_sdl_loc *loc) {
  zr_image_map *im = (zr_image_map *)bump->bump_map;
  if (im->use_index && !im->indices) {
    /* POV-Ray 3.7 then bumps by the colours' grey (measured: a red step
       in an RGB PNG tilts by 0.297 with or without use_index). */
    zr__sdl_warning(p, loc, "use_index needs a palette image; '%s' has "
                    "none, so its grey is used", im->path);
  } else if (im->use_index) {
    /* The index itself is the height: POV-Ray 3.7 tilts by 5 times the
       bump size at a step from index 0 to 5, whatever the palette's
       size (measured with 6 and 256 entries). */
    im->value_kind = ZR_BITMAP_VALUE_INDEX;
  }
  zr__pattern_init(&nm->pattern, ZR_PAT_NONE);
  nm->normal_map = NULL;
  nm->slope_map = NULL;
  nm->bump_map = im;
  nm->amount = bump->amount;
  return true;
}

bool zr__sdl_material_add(zr_sdl_parser *p, zr_map *m, zr_map_entry *e) {
  e->value = (double)m->n;
  return append(p, m, e);
}

bool zr__sdl_material_map(zr_sdl_parser *p, zr_texture *tx,
                          const zr_image_map *im, const zr_map *textures,
                          const zr_transform *t, const zr_sdl_loc *loc) {
  zr__sdl_texture_pattern(tx, ZR_PAT_NONE);
  if (!zr__sdl_texture_map_set(p, tx, textures, loc))
    return false;
  tx->material = im;
  /* Transforms inside the block move the picture and its textures, like
     those after it. */
  return !t || zr__sdl_texture_transform_more(p, tx, t);
}
