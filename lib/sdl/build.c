/*
 * build.c - what the grammar's actions call to build the scene model.
 *
 * The semantics are the reference manual's (r3_4):
 *   - Modifiers apply in the order written: "scale 2 translate x" scales,
 *     then translates (lib/core/transform.c composes in that order).
 *   - A transform moves the object's texture with it ("Transformations"
 *     on textures): the pigment gets a new transform, so patterns will
 *     stay glued to the surface.  Textures, pigments and finishes that may
 *     be shared (declared, or on another object) are never changed in
 *     place: each change makes a copy in the scene's arena.
 *   - A union's modifiers reach every child ("CSG Union"): a transform is
 *     pushed into each child; a texture is given to the union, and
 *     children without one inherit it when the scene is flattened.
 *   - object { Name } copies the declared object, children and all, so
 *     later modifiers never change the declaration.
 *   - The camera ("Placing the Camera"): angle sets the direction's
 *     length to 0.5 |right| / tan(angle / 2); look_at turns direction,
 *     right and up toward the target about the sky vector, keeping their
 *     lengths and the right vector's handedness (right <-1,0,0> stays
 *     mirrored).  Both act at the end of the block, before the
 *     transforms, whatever the order of the items: that is what POV-Ray
 *     3.7 renders show.
 *   - Patterns ("Pattern Modifiers"): turbulence, octaves, omega, lambda,
 *     frequency, phase and the wave types set the pattern's fields; a
 *     turbulence warp acts as turbulence (applied before the
 *     transforms, where POV-Ray would apply it in order).  A block
 *     pattern takes up to 2 (checker, brick) or 3 (hexagon) colours.
 *     color_map entries must not decrease.  A normal's transform, like
 *     a pigment's, follows the object's transforms.  image_map pictures
 *     are searched like #include files and decoded into the arena.
 */
#include "config.h"

#include <math.h>
#include <string.h>

#include <stdlib.h>

#include "core/strbuf.h"
#include "image/image.h"
#include "pov-parse.h"
#include "scene/pattern.h"
#include "scene/texture.h"
#include "sdl/sdl.h"

static const char *kind_name(zr_object_kind kind) {
  static const char *const names[] = {"a sphere",   "a box",   "a plane",
                                      "a triangle", "a cylinder",
                                      "a cone",     "a disc",  "a union"};
  return names[kind];
}

zr_object *zr__sdl_object_new(zr_sdl_parser *p, zr_object_kind kind,
                              const zr_sdl_loc *loc) {
  zr_object *o = zr__sdl_alloc(p, sizeof *o);
  if (!o)
    return NULL;
  o->kind = kind;
  o->where.file = p->files[loc->file].scene_path;
  o->where.line = loc->line;
  o->where.column = loc->column;
  return o;
}

/* The room a union's children array has for n children: arrays grow by
   doubling, and the arena cannot resize, so the size tells the room. */
static size_t children_room(size_t n) {
  size_t room = 4;
  while (room < n)
    room *= 2;
  return n ? room : 0;
}

zr_object *zr__sdl_object_copy(zr_sdl_parser *p, const zr_object *o) {
  zr_object *copy = zr__sdl_alloc(p, sizeof *copy);
  if (!copy)
    return NULL;
  *copy = *o;
  if (o->kind != ZR_OBJ_UNION || o->u.csg.n_children == 0)
    return copy;
  size_t n = o->u.csg.n_children;
  copy->u.csg.children =
      zr__sdl_alloc(p, children_room(n) * sizeof *copy->u.csg.children);
  if (!copy->u.csg.children)
    return NULL;
  for (size_t i = 0; i < n; i++) {
    copy->u.csg.children[i] = zr__sdl_object_copy(p, o->u.csg.children[i]);
    if (!copy->u.csg.children[i])
      return NULL;
  }
  return copy;
}

bool zr__sdl_union_add(zr_sdl_parser *p, zr_object *u, zr_object *child) {
  size_t n = u->u.csg.n_children;
  if (n == children_room(n)) {
    zr_object **grown =
        zr__sdl_alloc(p, children_room(n + 1) * sizeof *grown);
    if (!grown)
      return false;
    if (n)
      memcpy(grown, u->u.csg.children, n * sizeof *grown);
    u->u.csg.children = grown;
  }
  u->u.csg.children[n] = child;
  u->u.csg.n_children = n + 1;
  return true;
}

/* ---- transforms ---- */

zr_transform *zr__sdl_transform(zr_sdl_parser *p, int token,
                                const zr_sdl_expr *e, const zr_sdl_loc *loc) {
  zr_vec3 v;
  if (!zr__sdl_want_vector(p, e, loc, &v))
    return NULL;
  zr_transform *t = zr__sdl_alloc(p, sizeof *t);
  if (!t)
    return NULL;
  zr__transform_identity(t);
  if (token == T_SCALE) {
    /* POV-Ray turns a zero scale into 1 with a warning ("Scale"). */
    if (v.x == 0 || v.y == 0 || v.z == 0) {
      zr__sdl_warning(p, loc, "scale by 0 in %s%s%s changed to 1",
                      v.x == 0 ? "x" : "", v.y == 0 ? "y" : "",
                      v.z == 0 ? "z" : "");
      v = zr_v3(v.x == 0 ? 1 : v.x, v.y == 0 ? 1 : v.y, v.z == 0 ? 1 : v.z);
    }
    zr__transform_scale(t, v);
  } else if (token == T_ROTATE) {
    zr__transform_rotate(t, v);
  } else {
    zr__transform_translate(t, v);
  }
  return t;
}

zr_transform *zr__sdl_matrix(zr_sdl_parser *p, const zr_sdl_list *l,
                             const zr_sdl_loc *loc) {
  if (l->n != 12) {
    zr__sdl_error(p, ZR_ESYNTAX, loc, "a matrix has 12 values, not %d",
                  l->n);
    return NULL;
  }
  zr_transform *t = zr__sdl_alloc(p, sizeof *t);
  if (!t)
    return NULL;
  /* zr__transform_matrix applies the matrix after what t holds. */
  zr__transform_identity(t);
  if (!zr__transform_matrix(t, l->v)) {
    zr__sdl_error(p, ZR_ESCENE, loc, "the matrix is singular");
    return NULL;
  }
  return t;
}

/* A new transform: 'before' (NULL: identity), then t. */
static const zr_transform *composed(zr_sdl_parser *p,
                                    const zr_transform *before,
                                    const zr_transform *t) {
  zr_transform *c = zr__sdl_alloc(p, sizeof *c);
  if (!c)
    return NULL;
  if (before)
    *c = *before;
  else
    zr__transform_identity(c);
  zr__transform_compose(c, t);
  return c;
}

/* ---- pigments, finishes, textures, interiors ---- */

zr_pigment *zr__sdl_pigment_new(zr_sdl_parser *p, const zr_pigment *from) {
  zr_pigment *pg = zr__sdl_alloc(p, sizeof *pg);
  if (!pg)
    return NULL;
  if (from)
    *pg = *from;
  else
    zr__pigment_init(pg);
  return pg;
}

bool zr__sdl_pigment_transform(zr_sdl_parser *p, zr_pigment *pg,
                               const zr_transform *t) {
  pg->transform = composed(p, pg->transform, t);
  return pg->transform != NULL;
}

zr_finish *zr__sdl_finish_new(zr_sdl_parser *p, const zr_finish *from) {
  zr_finish *f = zr__sdl_alloc(p, sizeof *f);
  if (!f)
    return NULL;
  if (from)
    *f = *from;
  else
    zr__finish_init(f);
  return f;
}

void zr__sdl_finish_reflection(zr_finish *f, const zr_sdl_reflection *r) {
  f->reflection = r->min;
  f->reflection_max = r->max;
  if (r->falloff_given)
    f->reflection_falloff = r->falloff;
  if (r->fresnel_given)
    f->reflection_fresnel = r->fresnel;
  if (r->metallic_given)
    f->reflection_metallic = r->metallic;
}

zr_texture *zr__sdl_texture_new(zr_sdl_parser *p, const zr_texture *from) {
  zr_texture *tx = zr__sdl_alloc(p, sizeof *tx);
  if (tx && from)
    *tx = *from;
  return tx;
}

bool zr__sdl_texture_done(zr_sdl_parser *p, zr_texture *tx) {
  if (!tx->pigment)
    tx->pigment = p->scene->default_texture->pigment;
  if (!tx->finish)
    tx->finish = p->scene->default_texture->finish;
  return true;
}

bool zr__sdl_texture_transform(zr_sdl_parser *p, zr_texture *tx,
                               const zr_transform *t) {
  zr_pigment *pg = zr__sdl_pigment_new(
      p, tx->pigment ? tx->pigment : p->scene->default_texture->pigment);
  if (!pg || !zr__sdl_pigment_transform(p, pg, t))
    return false;
  tx->pigment = pg;
  if (tx->normal) {
    zr_normal *nm = zr__sdl_normal_new(p, tx->normal);
    if (!nm || !zr__sdl_normal_transform(p, nm, t))
      return false;
    tx->normal = nm;
  }
  return true;
}

zr_interior *zr__sdl_interior_new(zr_sdl_parser *p, const zr_interior *from) {
  zr_interior *in = zr__sdl_alloc(p, sizeof *in);
  if (!in)
    return NULL;
  if (from)
    *in = *from;
  else
    zr__interior_init(in);
  return in;
}

/* ---- patterns, colour maps, normals, image maps ---- */

bool zr__sdl_pigment_pattern(zr_sdl_parser *p, zr_pigment *pg, int kind,
                             const zr_sdl_clist *list) {
  zr__pigment_set_pattern(pg, (zr_pattern_kind)kind);
  if (!list || list->n == 0)
    return true;
  int most = kind == ZR_PAT_HEXAGON ? 3 : 2;
  if (!zr__pattern_is_block((zr_pattern_kind)kind) || list->n > most) {
    zr__sdl_error(p, ZR_ESYNTAX, &list->loc,
                  zr__pattern_is_block((zr_pattern_kind)kind)
                      ? "too many colours for this pattern"
                      : "only checker, hexagon and brick take colours");
    return false;
  }
  for (int i = 0; i < list->n; i++)
    pg->list[i] = list->c[i];
  return true;
}

bool zr__sdl_clist_add(zr_sdl_parser *p, zr_sdl_clist *l,
                       const zr_sdl_expr *e, const zr_sdl_loc *loc) {
  l->loc = *loc;
  if (l->n == 3) {
    zr__sdl_error(p, ZR_ESYNTAX, loc, "too many colours for this pattern");
    return false;
  }
  return zr__sdl_want_colour(p, e, loc, &l->c[l->n++]);
}

bool zr__sdl_gradient(zr_sdl_parser *p, zr_pattern *pt,
                      const zr_sdl_expr *e, const zr_sdl_loc *loc) {
  zr_vec3 v;
  if (!zr__sdl_want_vector(p, e, loc, &v))
    return false;
  if (zr_v3_len(v) == 0) {
    zr__sdl_error(p, ZR_ESCENE, loc, "the gradient's vector is zero");
    return false;
  }
  /* POV-Ray renders gradient <2,0,0> like gradient x: the direction
     only counts (measured). */
  pt->vector = zr_v3_norm(v);
  return true;
}

static bool want_positive(zr_sdl_parser *p, const zr_sdl_pmod *m,
                          const char *what, double *out) {
  if (!zr__sdl_want_float(p, &m->value, &m->loc, out))
    return false;
  if (!(*out > 0)) {
    zr__sdl_error(p, ZR_ESCENE, &m->loc, "%s must be positive", what);
    return false;
  }
  return true;
}

bool zr__sdl_pattern_mod(zr_sdl_parser *p, zr_pattern *pt,
                         const zr_sdl_pmod *m) {
  double v;
  switch (m->token) {
  case T_TURBULENCE:
    return zr__sdl_want_vector(p, &m->value, &m->loc, &pt->turbulence);
  case T_WARP:
    pt->turbulence = m->warp.turbulence;
    pt->octaves = m->warp.octaves;
    pt->omega = m->warp.omega;
    pt->lambda = m->warp.lambda;
    return true;
  case T_OCTAVES:
    if (!zr__sdl_want_float(p, &m->value, &m->loc, &v))
      return false;
    /* POV-Ray limits octaves to 1 .. 10 ("Octaves"). */
    if (v < 1 || v > 10) {
      zr__sdl_error(p, ZR_ESCENE, &m->loc,
                    "octaves must be between 1 and 10");
      return false;
    }
    pt->octaves = (int)v;
    return true;
  case T_OMEGA:
    return zr__sdl_want_float(p, &m->value, &m->loc, &pt->omega);
  case T_LAMBDA:
    return zr__sdl_want_float(p, &m->value, &m->loc, &pt->lambda);
  case T_FREQUENCY:
    return zr__sdl_want_float(p, &m->value, &m->loc, &pt->frequency);
  case T_PHASE:
    return zr__sdl_want_float(p, &m->value, &m->loc, &pt->phase);
  case T_AGATE_TURB:
    return zr__sdl_want_float(p, &m->value, &m->loc, &pt->agate_turb);
  case T_MORTAR:
    return zr__sdl_want_float(p, &m->value, &m->loc, &pt->mortar);
  case T_BRICK_SIZE: {
    zr_vec3 s;
    if (!zr__sdl_want_vector(p, &m->value, &m->loc, &s))
      return false;
    if (!(s.x > 0 && s.y > 0 && s.z > 0)) {
      zr__sdl_error(p, ZR_ESCENE, &m->loc, "brick_size must be positive");
      return false;
    }
    pt->vector = s;
    return true;
  }
  case T_RAMP_WAVE:
    pt->wave = ZR_WAVE_RAMP;
    return true;
  case T_TRIANGLE_WAVE:
    pt->wave = ZR_WAVE_TRIANGLE;
    return true;
  case T_SINE_WAVE:
    pt->wave = ZR_WAVE_SINE;
    return true;
  case T_SCALLOP_WAVE:
    pt->wave = ZR_WAVE_SCALLOP;
    return true;
  case T_CUBIC_WAVE:
    pt->wave = ZR_WAVE_CUBIC;
    return true;
  case T_POLY_WAVE:
    pt->wave = ZR_WAVE_POLY;
    pt->wave_exponent = 1;
    if (m->value.dim == 0)
      return true;
    return want_positive(p, m, "poly_wave's exponent", &pt->wave_exponent);
  default:
    return true;
  }
}

/* Entry arrays grow by doubling in the arena, like union children. */
static size_t entries_room(size_t n) { return children_room(n); }

zr_colour_map *zr__sdl_colour_map_new(zr_sdl_parser *p,
                                      const zr_colour_map *from) {
  zr_colour_map *m = zr__sdl_alloc(p, sizeof *m);
  if (!m || !from || from->n == 0)
    return m;
  zr_colour_map_entry *e =
      zr__sdl_alloc(p, entries_room(from->n) * sizeof *e);
  if (!e)
    return NULL;
  memcpy(e, from->entries, from->n * sizeof *e);
  m->entries = e;
  m->n = from->n;
  return m;
}

bool zr__sdl_colour_map_add(zr_sdl_parser *p, zr_colour_map *m,
                            const zr_sdl_expr *v, const zr_sdl_loc *vl,
                            const zr_sdl_expr *c, const zr_sdl_loc *cl) {
  zr_colour_map_entry entry;
  if (!zr__sdl_want_float(p, v, vl, &entry.value) ||
      !zr__sdl_want_colour(p, c, cl, &entry.colour))
    return false;
  if (m->n > 0 && entry.value < m->entries[m->n - 1].value) {
    zr__sdl_error(p, ZR_ESCENE, vl,
                  "color_map values must not decrease (%g after %g)",
                  entry.value, m->entries[m->n - 1].value);
    return false;
  }
  zr_colour_map_entry *e = (zr_colour_map_entry *)m->entries;
  if (m->n == entries_room(m->n)) {
    e = zr__sdl_alloc(p, entries_room(m->n + 1) * sizeof *e);
    if (!e)
      return false;
    if (m->n)
      memcpy(e, m->entries, m->n * sizeof *e);
  }
  e[m->n] = entry;
  m->entries = e;
  m->n++;
  return true;
}

bool zr__sdl_colour_map_done(zr_sdl_parser *p, const zr_colour_map *m,
                             const zr_sdl_loc *loc) {
  if (m->n == 0) {
    zr__sdl_error(p, ZR_ESYNTAX, loc, "a color_map needs an entry");
    return false;
  }
  return true;
}

zr_normal *zr__sdl_normal_new(zr_sdl_parser *p, const zr_normal *from) {
  zr_normal *nm = zr__sdl_alloc(p, sizeof *nm);
  if (!nm)
    return NULL;
  if (from) {
    *nm = *from;
  } else {
    zr__pattern_init(&nm->pattern, ZR_PAT_NONE);
    nm->amount = 0.5;
  }
  return nm;
}

bool zr__sdl_normal_pattern(zr_sdl_parser *p, zr_normal *nm, int kind,
                            const zr_sdl_expr *amount,
                            const zr_sdl_loc *loc) {
  zr__pattern_init(&nm->pattern, (zr_pattern_kind)kind);
  /* POV-Ray's default bump size is 0.5 for every normal pattern. */
  nm->amount = 0.5;
  return !amount || zr__sdl_want_float(p, amount, loc, &nm->amount);
}

bool zr__sdl_normal_transform(zr_sdl_parser *p, zr_normal *nm,
                              const zr_transform *t) {
  nm->transform = composed(p, nm->transform, t);
  return nm->transform != NULL;
}

/* dir/name, or name alone when dir is empty; NULL when out of memory. */
static char *image_path(const char *dir, size_t n, const char *name) {
  zr_strbuf sb;
  zr__strbuf_init(&sb);
  if (n) {
    zr__strbuf_printf(&sb, "%.*s/", (int)n, dir);
  }
  zr__strbuf_puts(&sb, name);
  if (sb.failed) {
    zr__strbuf_free(&sb);
    return NULL;
  }
  return zr__strbuf_take(&sb);
}

/* The first of the places #include searches where name can be read,
   malloc'ed; NULL when none. */
static char *find_image(zr_sdl_parser *p, const char *name) {
  const char *scene = p->files[zr__sdl_top(p)->file].path;
  const char *slash = strrchr(scene, '/');
  size_t n_dirs = p->ctx ? p->ctx->n_include_paths : 0;
  for (size_t i = 0; i <= n_dirs; i++) {
    char *path;
    if (name[0] == '/')
      path = i == 0 ? image_path("", 0, name) : NULL;
    else if (i == 0)
      path = image_path(scene, slash ? (size_t)(slash - scene) : 0, name);
    else
      path = image_path(p->ctx->include_paths[i - 1],
                        strlen(p->ctx->include_paths[i - 1]), name);
    if (!path)
      continue;
    char *bytes = NULL;
    size_t size = 0;
    if (zr__context_read(p->ctx, path, &bytes, &size) == ZR_OK) {
      free(bytes);
      return path;
    }
    free(path);
  }
  return NULL;
}

zr_image_map *zr__sdl_image_map_new(zr_sdl_parser *p, const char *name,
                                    const zr_sdl_loc *loc) {
  char *path = find_image(p, name);
  if (!path) {
    zr__sdl_error(p, ZR_ENOTFOUND, loc, "image_map file '%s' not found",
                  name);
    return NULL;
  }
  zr_image *image = NULL;
  zr_status s = zr_image_read(p->ctx, path, &image);
  free(path);
  if (s != ZR_OK) {
    zr__sdl_error(p, s, loc, "cannot use '%s' as an image_map", name);
    return NULL;
  }
  zr_image_map *im = zr__sdl_alloc(p, sizeof *im);
  size_t n = (size_t)image->width * (size_t)image->height * 3;
  float *pixels = im ? zr__sdl_alloc(p, n * sizeof *pixels) : NULL;
  if (pixels) {
    memcpy(pixels, image->pixels, n * sizeof *pixels);
    im->path = zr__sdl_strdup(p, name, strlen(name));
    im->width = image->width;
    im->height = image->height;
    im->pixels = pixels;
  }
  zr_image_free(image);
  return pixels && im->path ? im : NULL;
}

bool zr__sdl_image_map_mod(zr_sdl_parser *p, zr_image_map *im, int token,
                           const zr_sdl_expr *e, const zr_sdl_loc *loc) {
  double v = 0;
  if (e && !zr__sdl_want_float(p, e, loc, &v))
    return false;
  switch (token) {
  case T_MAP_TYPE:
    if (v != 0 && v != 1 && v != 2) {
      zr__sdl_error(p, ZR_ESCENE, loc,
                    "map_type %g is not supported (0, 1 or 2)", v);
      return false;
    }
    im->map_type = (int)v;
    return true;
  case T_ONCE:
    im->once = true;
    return true;
  case T_INTERPOLATE:
    im->interpolate = (int)v;
    return true;
  case T_FILTER:
    im->filter_all = v;
    return true;
  default:
    im->transmit_all = v;
    return true;
  }
}

/* ---- object modifiers ---- */

static bool transform_object(zr_sdl_parser *p, zr_object *o,
                             const zr_transform *t) {
  if (!(o->transform = composed(p, o->transform, t)))
    return false;
  if (o->texture) {
    zr_texture *tx = zr__sdl_texture_new(p, o->texture);
    if (!tx || !zr__sdl_texture_transform(p, tx, t))
      return false;
    o->texture = tx;
  }
  if (o->kind == ZR_OBJ_UNION)
    for (size_t i = 0; i < o->u.csg.n_children; i++)
      if (!transform_object(p, o->u.csg.children[i], t))
        return false;
  return true;
}

/* A copy of the object's texture (or of the default one) to change. */
static zr_texture *own_texture(zr_sdl_parser *p, zr_object *o) {
  zr_texture *tx = zr__sdl_texture_new(
      p, o->texture ? o->texture : p->scene->default_texture);
  if (tx)
    o->texture = tx;
  return tx;
}

static void set_interior(zr_object *o, const zr_interior *in, bool force) {
  if (force || !o->interior)
    o->interior = in;
  if (o->kind == ZR_OBJ_UNION)
    for (size_t i = 0; i < o->u.csg.n_children; i++)
      set_interior(o->u.csg.children[i], in, false);
}

static void set_flag(zr_object *o, zr_sdl_mod_kind kind) {
  if (kind == ZR_SDL_MOD_NO_SHADOW)
    o->no_shadow = true;
  else
    o->inverse = !o->inverse;
  if (o->kind == ZR_OBJ_UNION)
    for (size_t i = 0; i < o->u.csg.n_children; i++)
      set_flag(o->u.csg.children[i], kind);
}

bool zr__sdl_object_mod(zr_sdl_parser *p, zr_object *o,
                        const zr_sdl_mod *mod, const zr_sdl_loc *loc) {
  zr_texture *tx;
  switch (mod->kind) {
  case ZR_SDL_MOD_TRANSFORM:
    return transform_object(p, o, mod->ptr);
  case ZR_SDL_MOD_PIGMENT:
    if (!(tx = own_texture(p, o)))
      return false;
    tx->pigment = mod->ptr;
    return true;
  case ZR_SDL_MOD_FINISH:
    if (!(tx = own_texture(p, o)))
      return false;
    tx->finish = mod->ptr;
    return true;
  case ZR_SDL_MOD_TEXTURE:
    o->texture = mod->ptr;
    return true;
  case ZR_SDL_MOD_NORMAL:
    if (!(tx = own_texture(p, o)))
      return false;
    tx->normal = mod->ptr;
    return true;
  case ZR_SDL_MOD_INTERIOR:
    set_interior(o, mod->ptr, true);
    return true;
  case ZR_SDL_MOD_NO_SHADOW:
  case ZR_SDL_MOD_INVERSE:
    set_flag(o, mod->kind);
    return true;
  case ZR_SDL_MOD_OPEN:
    if (o->kind == ZR_OBJ_CYLINDER) {
      o->u.cylinder.open = true;
      return true;
    }
    if (o->kind == ZR_OBJ_CONE) {
      o->u.cone.open = true;
      return true;
    }
    zr__sdl_error(p, ZR_ESYNTAX, loc,
                  "'open' is for cylinders and cones, not for %s",
                  kind_name(o->kind));
    return false;
  }
  return true;
}

/* ---- lights and camera ---- */

bool zr__sdl_light(zr_sdl_parser *p, zr_light *l, const zr_sdl_loc *loc) {
  memset(l, 0, sizeof *l);
  l->kind = ZR_LIGHT_POINT;
  l->where.file = p->files[loc->file].scene_path;
  l->where.line = loc->line;
  l->where.column = loc->column;
  return true;
}

void zr__sdl_camera_begin(zr_sdl_parser *p, const zr_sdl_loc *loc) {
  zr_camera *c = &p->scene->camera;
  zr__camera_init(c);
  c->given = true;
  c->where.file = p->files[loc->file].scene_path;
  c->where.line = loc->line;
  c->where.column = loc->column;
  memset(&p->camera, 0, sizeof p->camera);
  zr__transform_identity(&p->camera.transform);
}

bool zr__sdl_camera_angle(zr_sdl_parser *p, double degrees,
                          const zr_sdl_loc *loc) {
  if (!(degrees > 0 && degrees < 180)) {
    zr__sdl_error(p, ZR_ESCENE, loc,
                  "a perspective camera's angle must be between 0 and 180 "
                  "degrees, not %g", degrees);
    return false;
  }
  p->camera.angle_given = true;
  p->camera.angle = degrees;
  return true;
}

void zr__sdl_camera_look_at(zr_sdl_parser *p, zr_vec3 target) {
  p->camera.look_at_given = true;
  p->camera.look_at = target;
}

void zr__sdl_camera_transform(zr_sdl_parser *p, const zr_transform *t) {
  zr__transform_compose(&p->camera.transform, t);
}

/* Turns direction, right and up toward target about the sky vector. */
static void look_at(zr_camera *c, zr_vec3 target) {
  zr_vec3 d = zr_v3_sub(target, c->location);
  if (zr_v3_len(d) == 0)
    return; /* looking at itself: nothing to turn toward */
  double dl = zr_v3_len(c->direction);
  double rl = zr_v3_len(c->right);
  double ul = zr_v3_len(c->up);
  /* POV-Ray's space is left-handed: right = up x direction normally; a
     right vector pointing the other way mirrors the image and stays so. */
  double handed =
      zr_v3_dot(zr_v3_cross(c->up, c->direction), c->right) < 0 ? -1 : 1;
  zr_vec3 dn = zr_v3_norm(d);
  zr_vec3 rn = zr_v3_norm(zr_v3_cross(c->sky, dn));
  if (zr_v3_len(rn) == 0) /* looking along the sky: keep the old right */
    rn = zr_v3_norm(zr_v3_scale(c->right, handed));
  zr_vec3 un = zr_v3_cross(dn, rn);
  c->direction = zr_v3_scale(dn, dl);
  c->right = zr_v3_scale(rn, rl * handed);
  c->up = zr_v3_scale(un, ul);
}

/*
 * POV-Ray 3.7 (measured with renders, see tests/test_parser.c) treats
 * location, direction, up, right, sky, angle and look_at as settings
 * whose last value counts wherever it is written, then aims the camera,
 * then applies the transforms in the order written.
 */
void zr__sdl_camera_end(zr_sdl_parser *p) {
  zr_camera *c = &p->scene->camera;
  if (p->camera.angle_given) {
    double half = p->camera.angle * 3.14159265358979323846 / 360.0;
    double length = 0.5 * zr_v3_len(c->right) / tan(half);
    c->direction = zr_v3_scale(zr_v3_norm(c->direction), length);
  }
  if (p->camera.look_at_given)
    look_at(c, p->camera.look_at);
  const zr_transform *t = &p->camera.transform;
  c->location = zr__xform_point(t->m, c->location);
  c->direction = zr__xform_dir(t->m, c->direction);
  c->up = zr__xform_dir(t->m, c->up);
  c->right = zr__xform_dir(t->m, c->right);
  c->sky = zr__xform_dir(t->m, c->sky);
}
