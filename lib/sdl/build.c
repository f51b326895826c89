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
 *   - The camera and lights are built in build_camlight.c.
 *   - Patterns ("Pattern Modifiers"): turbulence, octaves, omega, lambda,
 *     frequency, phase and the wave types set the pattern's fields;
 *     warps are applied in the order written among the transforms
 *     (build_warp.c, lib/scene/warp.c).  A block
 *     pattern takes up to 2 (checker, brick) or 3 (hexagon) colours.
 *     color_map entries may come out of order, as in POV-Ray
 *     (lib/scene/texture.c says how they are read).  A normal's transform, like
 *     a pigment's, follows the object's transforms.  image_map pictures
 *     are searched like #include files and decoded into the arena.
 */
#include "config.h"

#include <math.h>
#include <string.h>

#include <stdlib.h>

#include "core/strbuf.h"
#include "image/image.h"
#include "trace/obj_mesh.h"
#include "pov-parse.h"
#include "scene/bitmap.h"
#include "scene/pattern.h"
#include "scene/texture.h"
#include "sdl/sdl.h"
#include "sdl/build_camlight.h"
#include "sdl/build_media.h"
#include "sdl/build_pattern.h"
#include "trace/shape.h"

/* The object as messages name it (its table, lib/trace/shape.h). */
static const char *kind_name(zr_object_kind kind) {
  return zr__shape(kind)->name;
}

/* Degenerate means the corners span no area: the cross product of two
   edges is exactly zero (collinear or repeated corners), a fact of
   geometry that needs no tolerance. */
void zr__sdl_degenerate_triangle(zr_sdl_parser *p, const zr_vec3 *corners,
                                 const zr_sdl_loc *at) {
  zr_vec3 n = zr_v3_cross(zr_v3_sub(corners[1], corners[0]),
                          zr_v3_sub(corners[2], corners[0]));
  if (zr_v3_len(n) == 0)
    zr__sdl_warning(p, at, "degenerate triangle: its corners are on one "
                    "line, so it shows nothing (remove it)");
}

void zr__sdl_sphere_radius(zr_sdl_parser *p, const zr_object *sphere,
                           const zr_sdl_loc *at) {
  double r = sphere->u.sphere.radius;
  if (r < 0)
    zr__sdl_warning(p, at, "a sphere with a negative radius (%g) is drawn "
                    "with radius %g (POV-Ray 3.7 draws it too, shaded "
                    "inside out)", r, -r);
}

void zr__sdl_sphere_run(const double *run, zr_object *sphere) {
  sphere->u.sphere.centre = zr_v3(run[0], run[1], run[2]);
  sphere->u.sphere.radius = run[3];
}

/*
 * "sphere { <x, y, z>, r texture { T } }" as one token (issue 13): the
 * grammar's actions for its seven tokens are these calls, in this
 * order - object_head's for T_SPHERE_RUN, texture_start's for T, the
 * texture block's, and object_body's for the texture modifier - so the
 * scene is the same; what goes is bison's work for the tokens (about
 * ten reductions and six shifts a sphere, with an 80-byte semantic
 * value copied at each) and the engine's for five of them.  The one
 * difference: where the block's copy of T would be given back, none is
 * made (below), so the arena holds the same values with no gap left
 * where a copy opened a new block.  tests/test_parser.c
 * (textured_spheres_same) compares the two paths' scenes.
 */
zr_object *zr__sdl_sphere_textured(zr_sdl_parser *p,
                                   const zr_sdl_sphere_tex *s,
                                   const zr_sdl_loc *at) {
  zr_object *o = zr__sdl_object_new(p, ZR_OBJ_SPHERE, at);
  if (!o)
    return NULL;
  zr__sdl_sphere_run(s->sphere, o);
  zr__sdl_sphere_radius(p, o, at);
  /* The block's copy of T is given back, and T itself taken, when
     zr__sdl_texture_done leaves the copy the same bytes
     (zr__sdl_texture_shared): nothing else can change it here, so that
     is known from a copy on the stack.  The arena's copy (472 bytes of
     memory not yet in the cache, written and then given back) was 8% of
     the samples of a --parse-only run of bench/peers.sh's sphereflake
     (perf, cpu-clock). */
  zr_texture probe;
  memcpy(&probe, s->texture, sizeof probe);
  if (!zr__sdl_texture_done(p, &probe))
    return NULL;
  const zr_texture *texture = s->texture;
  if (memcmp(&probe, s->texture, sizeof probe) == 0) {
    /* What zr__sdl_texture_new and zr__sdl_texture_shared leave. */
    p->own_body.tx = NULL;
    p->texture_copy = NULL;
    p->texture_copied = NULL;
  } else {
    zr_texture *tx = zr__sdl_texture_new(p, s->texture);
    if (!tx)
      return NULL;
    p->texture_copy = tx;
    p->texture_copied = s->texture;
    if (!zr__sdl_texture_done(p, tx))
      return NULL;
    texture = zr__sdl_texture_shared(p, tx);
  }
  zr_sdl_mod m = {ZR_SDL_MOD_TEXTURE, texture};
  zr_sdl_loc tl = {at->file, at->line, s->texture_column,
                   s->texture_length};
  return zr__sdl_object_mod(p, o, &m, &tl) ? o : NULL;
}

bool zr__sdl_axis_given(zr_sdl_parser *p, zr_vec3 base, zr_vec3 cap,
                        const char *shape, const zr_sdl_loc *at) {
  if (zr_v3_len(zr_v3_sub(cap, base)) != 0)
    return true;
  zr__sdl_error(p, ZR_ESCENE, at, "degenerate %s: its base point and cap "
                "point are the same", shape);
  return false;
}

zr_object *zr__sdl_object_new(zr_sdl_parser *p, zr_object_kind kind,
                              const zr_sdl_loc *loc) {
  zr_object *o = zr__sdl_alloc(p, zr__object_size(kind));
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

/*
 * The interiors of one object tree being copied, each with its copy.
 * Every copy of an object has interiors of its own, shared within the
 * copy as in the original (a merge's interior handed down to its
 * parts): a ray's path of media holds interiors (lib/trace/shade.c
 * zr__media_cross), and povray 3.7 refracts two overlapping copies of
 * one declared glass sphere as two objects, going into the second
 * inside the first (tests/test_interior_path.sh, case 8).  A tree with
 * more distinct interiors than the map holds shares the rest.
 */
#define COPY_INTERIORS 32
typedef struct interior_map {
  const zr_interior *from[COPY_INTERIORS];
  const zr_interior *to[COPY_INTERIORS];
  int n;
} interior_map;

static const zr_interior *copy_interior(zr_sdl_parser *p, interior_map *map,
                                        const zr_interior *in) {
  if (!in)
    return NULL;
  for (int i = 0; i < map->n; i++)
    if (map->from[i] == in)
      return map->to[i];
  if (map->n == COPY_INTERIORS)
    return in;
  zr_interior *copy = zr__sdl_interior_new(p, in);
  if (!copy)
    return NULL;
  map->from[map->n] = in;
  map->to[map->n++] = copy;
  return copy;
}

static zr_object *copy_tree(zr_sdl_parser *p, const zr_object *o,
                            interior_map *map);

zr_object *zr__sdl_object_copy(zr_sdl_parser *p, const zr_object *o) {
  interior_map map;
  map.n = 0;
  return copy_tree(p, o, &map);
}

static zr_object *copy_tree(zr_sdl_parser *p, const zr_object *o,
                            interior_map *map) {
  size_t size = zr__object_size(o->kind);
  zr_object *copy = zr__sdl_alloc(p, size);
  if (!copy)
    return NULL;
  memcpy(copy, o, size); /* an object may be smaller than zr_object */
  /* Both now hold the same transform: neither may change it in place
     (transform_object).  The original is the parser's own memory. */
  copy->own_transform = false;
  ((zr_object *)o)->own_transform = false;
  /* The copy shares the texture: neither may change it in place now
     (zr__sdl_texture_move). */
  p->own_object.tx = NULL;
  /* Clipping and bounding objects follow the object's later transforms,
     so each copy needs its own. */
  if (o->clip && !(copy->clip = zr__sdl_object_copy(p, o->clip)))
    return NULL;
  if (o->bound && !(copy->bound = zr__sdl_object_copy(p, o->bound)))
    return NULL;
  if (o->interior && !(copy->interior = copy_interior(p, map, o->interior)))
    return NULL;
  if (zr__is_csg(o->kind) && !zr__sdl_csg_copy_lights(p, copy))
    return NULL;
  if (!zr__is_csg(o->kind) || o->u.csg.n_children == 0)
    return copy;
  size_t n = o->u.csg.n_children;
  copy->u.csg.children =
      zr__sdl_alloc(p, children_room(n) * sizeof *copy->u.csg.children);
  if (!copy->u.csg.children)
    return NULL;
  for (size_t i = 0; i < n; i++) {
    copy->u.csg.children[i] = copy_tree(p, o->u.csg.children[i], map);
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
  if (from) {
    *pg = *from;
  } else {
    zr__pigment_init(pg);
    /* Pattern defaults already, for a map entry whose function comes
       first ("[function { ... } color_map { ... }]"). */
    zr__pattern_init(&pg->pattern, ZR_PAT_NONE);
  }
  return pg;
}

bool zr__sdl_pigment_transform(zr_sdl_parser *p, zr_pigment *pg,
                               const zr_transform *t) {
  if (p->moving_object && pg->uv_mapping)
    return true;
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

/*
 * "reflection { R fresnel }", one value: povray 3.7 renders it exactly as
 * "reflection { 0, R fresnel }" (Fresnel's law from none up to R;
 * measured on a dark plane under a sky, ior 1.5 and 1: identical pixels,
 * tests/test_reflection_forms.sh).  One value without fresnel stays a
 * constant R, with or without falloff (same measurement).
 */
void zr__sdl_finish_reflection(zr_finish *f, const zr_sdl_reflection *r) {
  f->reflection = r->min;
  f->reflection_max = r->max;
  if (r->fresnel_given && r->fresnel && !r->max_given)
    f->reflection = zr_rgb3(0.0, 0.0, 0.0);
  if (r->falloff_given)
    f->reflection_falloff = r->falloff;
  if (r->fresnel_given)
    f->reflection_fresnel = r->fresnel;
  if (r->metallic_given)
    f->reflection_metallic = r->metallic;
  if (r->exponent_given)
    f->reflection_exponent = r->exponent;
}

bool zr__sdl_reflection_exponent(zr_sdl_parser *p, double e,
                                 const zr_sdl_loc *loc) {
  if (e > 0.0)
    return true;
  zr__sdl_error(p, ZR_ESCENE, loc,
                "the exponent of reflection must be positive, not %g", e);
  return false;
}

zr_texture *zr__sdl_texture_new(zr_sdl_parser *p, const zr_texture *from) {
  /* A copy is written whole, padding too (zr__sdl_texture_shared
     compares the bytes): zeroing it first was a second pass over 472
     bytes a sphere of bench/peers.sh's sphereflake, whose spheres each
     copy their texture { Ball }. */
  zr_texture *tx = from ? zr__sdl_alloc_raw(p, sizeof *tx)
                        : zr__sdl_alloc(p, sizeof *tx);
  if (tx && from)
    memcpy(tx, from, sizeof *tx);
  /* A new texture block, or a copy: the block's texture is no longer
     the last value read (zr__sdl_texture_given). */
  p->own_body.tx = NULL;
  return tx;
}

/*
 * "Pigment", "Normal", "Finish": the items of a block without an
 * identifier modify the current values, those of the texture the block
 * is in (the top layer of a texture identifier, or what an earlier
 * block of the same texture gave), else those of the default texture
 * (#default).  POV-Ray 3.7's renders: texture { T pigment { quick_color
 * C } } keeps T's pattern (advanced/chess2.pov's pieces), #default {
 * normal { onion } } reaches object { X normal { } } (slopemap.pov).
 */
void zr__sdl_texture_base(zr_sdl_parser *p, const zr_texture *tx, int kind) {
  while (tx && tx->over)
    tx = tx->over;
  const zr_texture *d = p->default_changed ? p->scene->default_texture : NULL;
  switch (kind) {
  case 'p':
    p->pigment_base = tx && tx->pigment ? tx->pigment
                      : d               ? d->pigment
                                        : NULL;
    break;
  case 'n':
    p->normal_base = tx && tx->normal ? tx->normal
                     : d              ? d->normal
                                      : NULL;
    break;
  default:
    p->finish_base = tx && tx->finish ? tx->finish
                     : d              ? d->finish
                                      : NULL;
    break;
  }
  p->base_set |= kind == 'p' ? 1 : kind == 'n' ? 2 : 4;
}

void zr__sdl_block_base(zr_sdl_parser *p, int kind) {
  int bit = kind == 'p' ? 1 : kind == 'n' ? 2 : 4;
  if (!(p->base_set & bit))
    zr__sdl_texture_base(p, NULL, kind);
}

const zr_pigment *zr__sdl_take_pigment_base(zr_sdl_parser *p) {
  const zr_pigment *b = p->pigment_base;
  p->pigment_base = NULL;
  p->base_set &= ~1;
  return b;
}

const zr_normal *zr__sdl_take_normal_base(zr_sdl_parser *p) {
  const zr_normal *b = p->normal_base;
  p->normal_base = NULL;
  p->base_set &= ~2;
  return b;
}

const zr_finish *zr__sdl_take_finish_base(zr_sdl_parser *p) {
  const zr_finish *b = p->finish_base;
  p->finish_base = NULL;
  p->base_set &= ~4;
  return b;
}

bool zr__sdl_texture_done(zr_sdl_parser *p, zr_texture *tx) {
  if (tx->map && tx->map->n > 0) {
    /* A patterned texture shows as its first entry wherever one plain
       texture is wanted (radiosity, shadows): build_texture.c. */
    const zr_texture *first = tx->map->entries[0].u.texture;
    tx->pigment = first->pigment;
    tx->finish = first->finish;
    tx->normal = first->normal;
  }
  if (!tx->pigment)
    tx->pigment = p->scene->default_texture->pigment;
  if (!tx->finish)
    tx->finish = p->scene->default_texture->finish;
  return true;
}

/*
 * Transforming a texture in place (issue 16).  Textures are shared
 * (declared, or given to many objects), so a transformation copies
 * what it changes: the pigment and the normal with their transforms,
 * the map's transform and textures, the layers above (the "copy path"
 * below, zr__sdl_texture_transform).  A second transformation of the
 * same texture block, or of the same object, would copy all that
 * again, though the first copies belong to nobody else: 40,000 boxes
 * each with "texture { T_Wood1 translate A rotate B scale C }
 * translate D" made 4 copies of a two-layer texture apiece.  So the
 * parser remembers the texture its last copy path made (own_body for
 * a texture block, own_object for an object's texture) and, while
 * that texture is still the same pointer, holds the same bytes and
 * belongs to the same object, the next transformation changes the
 * same parts in place: the same arithmetic on the same values (a
 * transform composed with t), so the same scene.
 *
 * The texture a block made can pass to the object that takes it as
 * its first texture (zr__sdl_texture_given): the block's value goes
 * nowhere else in between, and every other use of a texture begins a
 * new block (texture { T }), whose zr__sdl_texture_new forgets the
 * block's texture.
 */

static void own_record(zr_sdl_parser *p, zr_sdl_own *own, const void *owner,
                       const zr_texture *tx) {
  own->owner = owner;
  own->tx = tx;
  own->moving = p->moving_object;
  memcpy(&own->seen, tx, sizeof *tx);
}

static bool own_holds(const zr_sdl_parser *p, const zr_sdl_own *own,
                      const void *owner, const zr_texture *tx) {
  return own->tx && own->tx == tx && own->owner == owner &&
         (p->moving_object || !own->moving) &&
         memcmp(&own->seen, tx, sizeof *tx) == 0;
}

/* t after what *slot holds, in place: the copy path made *slot (NULL:
   none yet, as after a copy of a pigment without one). */
static bool compose_in_place(zr_sdl_parser *p, const zr_transform **slot,
                             const zr_transform *t) {
  if (*slot) {
    zr__transform_compose((zr_transform *)*slot, t);
    return true;
  }
  return (*slot = composed(p, NULL, t)) != NULL;
}

/* zr__sdl_texture_transform and zr__sdl_texture_transform_more on a
   texture whose parts the copy path copied: the same steps, in the same
   order, with the same parts left alone. */
static bool texture_move_in_place(zr_sdl_parser *p, zr_texture *tx,
                                  const zr_transform *t) {
  if (p->moving_object && tx->uv_mapping)
    return true;
  zr_pigment *pg = (zr_pigment *)tx->pigment;
  if (!(p->moving_object && pg->uv_mapping) &&
      !compose_in_place(p, &pg->transform, t))
    return false;
  if (tx->normal) {
    zr_normal *nm = (zr_normal *)tx->normal;
    p->normal_fresh = nm; /* as zr__sdl_normal_new leaves it */
    if (!(p->moving_object && nm->uv_mapping) &&
        !compose_in_place(p, &nm->transform, t))
      return false;
  }
  if ((tx->map || tx->pattern.kind != ZR_PAT_NONE) &&
      !compose_in_place(p, &tx->transform, t))
    return false;
  if (tx->map)
    for (size_t i = 0; i < tx->map->n; i++)
      if (!texture_move_in_place(
              p, (zr_texture *)tx->map->entries[i].u.texture, t))
        return false;
  if (tx->over && !texture_move_in_place(p, (zr_texture *)tx->over, t))
    return false;
  return true;
}

bool zr__sdl_texture_move(zr_sdl_parser *p, zr_sdl_own *own,
                          const void *owner, zr_texture *tx,
                          const zr_transform *t) {
  if (own_holds(p, own, owner, tx)) {
    if (!texture_move_in_place(p, tx, t))
      return false;
    memcpy(&own->seen, tx, sizeof *tx);
    return true;
  }
  own->tx = NULL;
  if (!zr__sdl_texture_transform(p, tx, t))
    return false;
  own_record(p, own, owner, tx);
  return true;
}

void zr__sdl_texture_given(zr_sdl_parser *p, const zr_object *o,
                           const zr_texture *tx) {
  if (own_holds(p, &p->own_body, NULL, tx)) {
    p->own_object = p->own_body;
    p->own_object.owner = o;
  }
  p->own_body.tx = NULL;
}

bool zr__sdl_texture_transform(zr_sdl_parser *p, zr_texture *tx,
                               const zr_transform *t) {
  if (p->moving_object && tx->uv_mapping) /* layers above stay too */
    return true;
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
  return zr__sdl_texture_transform_more(p, tx, t);
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

/*
 * A pattern named in a pigment block replaces the pattern's kind and its
 * own parameters, but the pattern modifiers of the pigment the block
 * modifies stay: POV-Ray 3.7 draws object { B pigment { gradient x } },
 * B's pigment having turbulence (with octaves), a warp, frequency,
 * phase or a wave type, with that modifier (tests/test_pigment_keep.sh
 * cases 6-10).  A fresh pigment holds the defaults, so for it nothing
 * changes.
 */
bool zr__sdl_pigment_pattern(zr_sdl_parser *p, zr_pigment *pg, int kind,
                             const zr_sdl_clist *list) {
  zr__pigment_set_pattern(pg, (zr_pattern_kind)kind);
  /* global_settings { number_of_waves } sets the default. */
  pg->pattern.waves = p->scene->settings.number_of_waves;
  pg->pattern.noise_generator = p->scene->settings.noise_generator;
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

bool zr__sdl_octaves(zr_sdl_parser *p, const zr_sdl_expr *e,
                     const zr_sdl_loc *loc, int *octaves) {
  double v;
  if (!zr__sdl_want_float(p, e, loc, &v))
    return false;
  /* The manual's range ("Octaves", 3.4.7.5.5.4: "Legal values range
     from 1 to <10"), with 10 let through; povray 3.7 itself accepts
     larger counts (11 and 30 parse without a word). */
  if (v < 1 || v > 10) {
    zr__sdl_error(p, ZR_ESCENE, loc, "octaves must be between 1 and 10");
    return false;
  }
  *octaves = (int)v;
  return true;
}

bool zr__sdl_pattern_mod(zr_sdl_parser *p, zr_pattern *pt,
                         const zr_sdl_pmod *m) {
  double v;
  switch (m->token) {
  case T_TURBULENCE:
    return zr__sdl_want_vector(p, &m->value, &m->loc, &pt->turbulence);
  case T_WARP:
    return zr__sdl_pattern_warp(p, pt, NULL, m);
  case T_OCTAVES:
    return zr__sdl_octaves(p, &m->value, &m->loc, &pt->octaves);
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
  case T_CONTROL0:
    return zr__sdl_want_float(p, &m->value, &m->loc, &pt->control0);
  case T_CONTROL1:
    return zr__sdl_want_float(p, &m->value, &m->loc, &pt->control1);
  case T_NUMBER_OF_WAVES:
    /* povray 3.7 takes number_of_waves in global_settings only: in a
       pattern it stops with "Cannot parse input". */
    zr__sdl_error(p, ZR_ESYNTAX, &m->loc,
                  "number_of_waves belongs in global_settings, not in a "
                  "pattern");
    return false;
  case T_NOISE_GENERATOR:
    if (!zr__sdl_want_float(p, &m->value, &m->loc, &v))
      return false;
    if (v != 1 && v != 2 && v != 3) {
      zr__sdl_error(p, ZR_ESCENE, &m->loc,
                    "noise_generator must be 1, 2 or 3");
      return false;
    }
    pt->noise_generator = (int)v;
    return true;
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
    return zr__sdl_pattern_mod_more(p, pt, m);
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
    const zr_normal *d = p->scene->default_texture->normal;
    zr__pattern_init(&nm->pattern, ZR_PAT_NONE);
    nm->amount = d ? d->amount : 0.5;
    nm->accuracy = 0.02;
  }
  p->normal_fresh = nm;
  return nm;
}

bool zr__sdl_normal_pattern(zr_sdl_parser *p, zr_normal *nm, int kind,
                            const zr_sdl_expr *amount,
                            const zr_sdl_loc *loc) {
  /* As in a pigment, the modifiers of the normal this block modifies
     stay (measured: tests/test_pigment_keep.sh's normal cases). */
  zr__pattern_set_kind(&nm->pattern, (zr_pattern_kind)kind);
  nm->pattern.waves = p->scene->settings.number_of_waves;
  nm->pattern.noise_generator = p->scene->settings.noise_generator;
  /* Only the ten wave centres povray makes by default are measured
     (lib/scene/waves_tables.h): more are not reproduced. */
  if ((kind == ZR_PAT_RIPPLES || kind == ZR_PAT_WAVES) &&
      nm->pattern.waves > zr__pattern_wave_count(&nm->pattern))
    zr__sdl_warning(p, loc,
                    "number_of_waves %d: this %s normal sums only %d waves "
                    "(povray's further wave centres are not reproduced)",
                    nm->pattern.waves,
                    kind == ZR_PAT_RIPPLES ? "ripples" : "waves",
                    zr__pattern_wave_count(&nm->pattern));
  /* A normal pattern without an amount has bump size 0.5 (not in the
     manual; measured: bench/provenance/probe.py normal_amount), but the
     first one in a normal block keeps the bump size the block starts
     from: under "#default { normal { bump_size 1.5 } }", "normal {
     gradient x }" is gradient x, 1.5 in povray 3.7, in a normal_map's
     entries too, and "normal { N gradient x }" keeps N's bump size
     (tests/test_default_normal.sh; textures/normals/normmap.pov). */
  if (p->normal_fresh != nm)
    nm->amount = 0.5;
  p->normal_fresh = NULL;
  return !amount || zr__sdl_want_float(p, amount, loc, &nm->amount);
}

bool zr__sdl_normal_transform(zr_sdl_parser *p, zr_normal *nm,
                              const zr_transform *t) {
  if (p->moving_object && nm->uv_mapping)
    return true;
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

zr_status zr__sdl_read_image(zr_sdl_parser *p, const char *name,
                             const zr_sdl_loc *at, const char *what,
                             char **path_out, char **bytes, size_t *size) {
  /* The places #include searches but POV-Ray's include folder: next
     to the file being read, then along the include paths. */
  const char *scene = p->files[zr__sdl_top(p)->file].path;
  const char *slash = strrchr(scene, '/');
  size_t n_dirs = p->ctx ? p->ctx->n_include_paths : 0;
  *path_out = NULL;
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
    zr_status s = zr__sdl_read_file(p, path, name[0] != '/', at, what,
                                   bytes, size);
    if (s == ZR_OK) {
      *path_out = path;
      return ZR_OK;
    }
    free(path);
    if (s != ZR_ENOTFOUND)
      return s;
  }
  return ZR_ENOTFOUND;
}

/*
 * "gamma G" after an image_map's file name ("Image File Gamma"): the
 * stored codes are decoded again with linear = code ^ G instead of the
 * transfer the file asks for; "gamma srgb" (srgb true) decodes them
 * with the sRGB transfer function ("The Gamma Option": "srgb may be
 * specified to denote that the file is encoded or pre-corrected using
 * the sRGB transfer function").  "This applies in all contexts and to
 * all file formats" ("Gamma in Input Images"): POV-Ray 3.7 decodes a
 * JPEG's, BMP's, PPM's or TIFF's codes so as a PNG's (the manual's own
 * example is a JPEG's "gamma 1.8"; tests/test_image_gamma_formats.sh).
 * The float pictures (OpenEXR, Radiance HDR, PFM) have no codes to
 * decode: refused.  A picture of floats beside 8-bit codes (BMP, TIFF)
 * gets its floats again from the codes.
 */
static bool image_gamma(zr_sdl_parser *p, zr_image *image,
                        const char *what, const char *name, double g,
                        bool srgb, const zr_sdl_loc *loc) {
  if (!srgb && (!(g > 0) || !isfinite(g))) {
    zr__sdl_error(p, ZR_ESCENE, loc, "%s gamma %g must be positive", what,
                  g);
    return false;
  }
  bool floats = image->layout == ZR_LAYOUT_FLOAT;
  if (floats && !(image->codes && image->maxval == 255)) {
    zr__sdl_error(p, ZR_EUNSUPPORTED, loc,
                  "%s gamma is for files of stored samples (PNG, JPEG, "
                  "GIF, TGA, BMP, PPM, PGM, TIFF), not '%s', whose floats "
                  "are light already", what, name);
    return false;
  }
  float *table = zr__decode_table(
      image->maxval, srgb ? ZR_TRANSFER_SRGB : ZR_TRANSFER_POWER, g);
  if (!table) {
    zr__sdl_error(p, ZR_ENOMEM, loc, "out of memory");
    return false;
  }
  if (floats) {
    size_t n = 3 * (size_t)image->width * (size_t)image->height;
    const unsigned char *c = image->codes;
    for (size_t k = 0; k < n; k++)
      image->pixels[k] = table[c[k]];
    free(table);
    return true;
  }
  free(image->table);
  image->table = table;
  return true;
}

/* The palette indices of a palette image, with every entry's filter and
   transmit 0 until the image_map says otherwise. */
static bool keep_palette(zr_sdl_parser *p, zr_image_map *im,
                         const zr_image *image) {
  size_t n = (size_t)image->width * (size_t)image->height;
  unsigned char *indices = zr__sdl_alloc(p, n);
  /* Every byte value gets an entry: a file may hold indices past its
     palette (read as black). */
  float *ft = zr__sdl_alloc(p, 2 * 256 * sizeof *ft);
  if (!indices || !ft)
    return false;
  memcpy(indices, image->indices, n);
  /* A tRNS chunk's transparency: each entry's transmit 1 - alpha, which
     "transmit INDEX, AMOUNT" then overrides, as POV-Ray 3.7 does
     (tests/test_image_alpha.sh). */
  for (size_t i = 0; image->alpha && i < n; i++)
    ft[2 * (size_t)indices[i] + 1] = 1.0f - image->alpha[i];
  im->indices = indices;
  im->palette_size = image->palette_size;
  im->palette_ft = ft;
  return true;
}

/*
 * What a bump_map or material_map reads of each code
 * (lib/scene/bitmap.c), one number a code: the code over its maximum for
 * files that keep their stored codes, the sRGB encoding of its colour
 * for the others (whose codes the sRGB decoding would round back to
 * the same), or under a "gamma" the decoded colour.  A bump map's
 * height is then the grey 0.297 red + 0.589 green + 0.114 blue (the
 * manual's grey, 2.3.3.3.7, and POV-Ray 3.7 renders of pure red, green
 * and blue steps measure these weights); use_index replaces it later
 * (zr__sdl_bump_map_end).  A material map's is the palette index, else
 * the red sample on a 0 .. 255 scale ("Material Maps").
 */
static bool bitmap_values(zr_sdl_parser *p, zr_image_map *im,
                          const zr_image *image, bool material,
                          bool decoded) {
  im->value_kind = material && image->indices ? ZR_BITMAP_VALUE_INDEX
                   : material                 ? ZR_BITMAP_VALUE_RED
                                              : ZR_BITMAP_VALUE_GREY;
  if (image->layout != ZR_LAYOUT_FLOAT) {
    double *v = zr__sdl_alloc(p, ((size_t)image->maxval + 1) * sizeof *v);
    if (!v)
      return false;
    for (unsigned c = 0; c <= image->maxval; c++)
      v[c] = decoded ? (double)image->table[c]
             : image->stored_codes ? c / (double)image->maxval
                                   : zr__srgb_encode(image->table[c]);
    im->code_value = v;
    return true;
  }
  /* Float pictures keep one number a pixel. */
  size_t n = (size_t)image->width * (size_t)image->height;
  float *values = zr__sdl_alloc(p, n * sizeof *values);
  if (!values)
    return false;
  for (size_t i = 0; i < n; i++) {
    double rgb[3];
    for (int c = 0; c < 3; c++)
      rgb[c] = decoded ? image->pixels[3 * i + c]
                       : zr__srgb_encode(image->pixels[3 * i + c]);
    values[i] = material ? (float)floor(rgb[0] * 255 + 0.5)
                         : (float)(0.297 * rgb[0] + 0.589 * rgb[1] +
                                   0.114 * rgb[2]);
  }
  im->value_kind = ZR_BITMAP_VALUE_ARRAY;
  im->values = values;
  return true;
}

/*
 * An image_map's colours are light as its file says ("Image File
 * Gamma"), while scene colours live in the assumed_gamma space, so under
 * assumed_gamma G they are raised to 1/G: POV-Ray 3.7 shows a picture
 * with ambient 1 under assumed_gamma 2.2 as it is, not darker
 * (advanced/sunsethf.pov, drums2; scenes/image_gamma.pov).  G is known
 * only when the parse ends: the buffers (a float picture's pixels, or
 * the table of a coded picture's colours) wait in the parser.
 */
static bool remember_image(zr_sdl_parser *p, float *pixels, size_t n,
                           float *codes) {
  if (p->n_images == p->cap_images) {
    size_t cap = p->cap_images ? 2 * p->cap_images : 8;
    float **a = realloc(p->image_pixels, cap * sizeof *a);
    if (a)
      p->image_pixels = a;
    size_t *b = a ? realloc(p->image_sizes, cap * sizeof *b) : NULL;
    if (b)
      p->image_sizes = b;
    float **c = b ? realloc(p->image_codes, cap * sizeof *c) : NULL;
    if (c)
      p->image_codes = c;
    if (!a || !b || !c) {
      zr__sdl_error(p, ZR_ENOMEM, NULL, "out of memory");
      return false;
    }
    p->cap_images = cap;
  }
  p->image_pixels[p->n_images] = pixels;
  p->image_codes[p->n_images] = codes;
  p->image_sizes[p->n_images++] = n;
  return true;
}

/*
 * With gamma correction off (a legacy scene without assumed_gamma,
 * known only at the parse's end) POV-Ray 3.7 takes every coded file's
 * codes as they are, those with an sRGB or gAMA chunk and BMP files
 * too: codes 40, 85, 200 are written back as 40, 85, 200 under no
 * #version or #version 3.6 (bench/conform/legacy_gamma_probe.py
 * --section images).  The files codes_as_working does not already take
 * so, read in a legacy part of the scene, keep their code values for
 * then: n values from a table of maxval + 1 or from 8-bit RGB codes.
 */
static float *legacy_codes(zr_sdl_parser *p, const zr_image *image,
                           bool gamma_given, size_t n) {
  bool legacy = !p->version_given || p->version < 3.7 - 1e-9;
  if (!legacy || gamma_given || !image->codes)
    return NULL;
  float *codes = zr__sdl_alloc(p, n * sizeof *codes);
  if (!codes)
    return NULL;
  if (image->layout != ZR_LAYOUT_FLOAT) {
    for (size_t k = 0; k < n; k++)
      codes[k] = (float)((double)k / image->maxval);
  } else { /* BMP: 8-bit RGB codes beside the pixels (image.h) */
    const unsigned char *c = image->codes;
    for (size_t k = 0; k < n; k++)
      codes[k] = (float)(c[k] / 255.0);
  }
  return codes;
}

/*
 * Whether an image_map's codes are taken as they are, in the scene's
 * working space: in a legacy scene (no #version, or one below 3.7, in
 * force where the image_map is read), for a coded file that does not
 * state its transfer, unless "gamma G" was given.  The manual ("Gamma
 * in Legacy Scenes") says so of every format but PNG, OpenEXR and HDR;
 * for PNG, POV-Ray 3.7 measured does the same when the file has no sRGB
 * or gAMA chunk: a #version 3.6 scene with assumed_gamma 1 shows code
 * 85 with ambient 1 as linear 0.3333 (0.0908, the sRGB decoding, under
 * #version 3.7; 85/255 raised to 2.2 under assumed_gamma 2.2), while
 * files with either chunk are decoded by it in both versions
 * (tests/test_image_gamma_povray.sh; interior/media/media3.pov's
 * test.png).
 */
static bool codes_as_working(const zr_sdl_parser *p, const zr_image *image,
                             bool gamma_given) {
  bool legacy = !p->version_given || p->version < 3.7 - 1e-9;
  /* BMP keeps 8-bit codes beside its float pixels (image.h); PPM and
     PGM codes are in the working space in every version, as the manual
     says ("Gamma in Input Images"): codes 40, 85, 200 show as sRGB(40 /
     255) under #version 3.7 (bench/conform/legacy_gamma_probe.py
     --section images), and BMP's as the other formats' under 3.6
     rules. */
  bool coded = image->layout != ZR_LAYOUT_FLOAT ||
               (image->codes && image->maxval == 255);
  return !gamma_given && coded &&
         (image->codes_working || (legacy && !image->transfer_stated));
}

/* An image map's colours into the scene: a float picture's pixels, or
   a coded one's codes or indices and its table of colours. */
static bool image_samples(zr_sdl_parser *p, zr_image_map *im,
                          const zr_image *image, bool gamma_given) {
  size_t n = (size_t)image->width * (size_t)image->height;
  if (image->layout == ZR_LAYOUT_FLOAT &&
      codes_as_working(p, image, gamma_given)) {
    /* BMP's codes, already in the working space: not raised. */
    float *pixels = zr__sdl_alloc(p, 3 * n * sizeof *pixels);
    if (!pixels)
      return false;
    const unsigned char *c = image->codes;
    for (size_t k = 0; k < 3 * n; k++)
      pixels[k] = (float)(c[k] / 255.0);
    im->pixels = pixels;
    return true;
  }
  if (image->layout == ZR_LAYOUT_FLOAT) {
    float *pixels = zr__sdl_alloc(p, 3 * n * sizeof *pixels);
    bool byte_codes = image->codes && image->maxval == 255;
    float *codes =
        pixels && byte_codes ? legacy_codes(p, image, gamma_given, 3 * n)
                             : NULL;
    if (!pixels || (byte_codes && !codes && p->status != ZR_OK) ||
        !remember_image(p, pixels, 3 * n, codes))
      return false;
    memcpy(pixels, image->pixels, 3 * n * sizeof *pixels);
    im->pixels = pixels;
    return true;
  }
  size_t ntable = (size_t)image->maxval + 1;
  float *table = zr__sdl_alloc(p, ntable * sizeof *table);
  if (codes_as_working(p, image, gamma_given)) {
    /* Already in the working space: not raised at the parse's end. */
    if (!table)
      return false;
    for (size_t k = 0; k < ntable; k++)
      table[k] = (float)((double)k / image->maxval);
    im->table = table;
    return true;
  }
  float *codes = table ? legacy_codes(p, image, gamma_given, ntable) : NULL;
  if (!table || p->status != ZR_OK ||
      !remember_image(p, table, ntable, codes))
    return false;
  memcpy(table, image->table, ntable * sizeof *table);
  im->table = table;
  return true;
}

/* The codes (or the palette's) of a coded picture, shared by every kind
   of map. */
static bool picture_codes(zr_sdl_parser *p, zr_image_map *im,
                          const zr_image *image) {
  im->layout = (int)image->layout;
  im->maxval = image->maxval;
  if (image->layout == ZR_LAYOUT_FLOAT)
    return true;
  if (image->palette) {
    size_t bytes = 3 * 256 * sizeof *image->palette;
    unsigned short *palette = zr__sdl_alloc(p, bytes);
    if (!palette)
      return false;
    memcpy(palette, image->palette, bytes);
    im->palette = palette;
  }
  if (image->codes) {
    size_t bytes = (size_t)image->width * (size_t)image->height *
                   (size_t)zr__image_channels(image) *
                   (image->maxval > 255 ? 2 : 1);
    void *codes = zr__sdl_alloc(p, bytes);
    if (!codes)
      return false;
    memcpy(codes, image->codes, bytes);
    im->codes = codes;
  }
  return true;
}

/* Whether every pixel of the image is opaque (or it has no alpha). */
static bool opaque(const zr_image *image) {
  size_t n = (size_t)image->width * (size_t)image->height;
  for (size_t i = 0; image->alpha && i < n; i++)
    if (image->alpha[i] < 1.0f)
      return false;
  return true;
}

/* Every pixel clear (alpha 0): a 32-bit BMP or TGA whose writer left
   the fourth byte 0 is read so, as POV-Ray 3.7 reads it. */
static bool clear(const zr_image *image) {
  size_t n = (size_t)image->width * (size_t)image->height;
  for (size_t i = 0; i < n; i++)
    if (image->alpha[i] > 0.0f)
      return false;
  return true;
}

static bool keep_alpha(zr_sdl_parser *p, zr_image_map *im,
                       const zr_image *image) {
  size_t n = (size_t)image->width * (size_t)image->height;
  float *a = zr__sdl_alloc(p, n * sizeof *a);
  if (!a)
    return false;
  memcpy(a, image->alpha, n * sizeof *a);
  im->alpha = a;
  return true;
}

/*
 * "premultiplied B" after an image_map's file name ("Using the Alpha
 * Channel": whether the file's colours are associated with alpha,
 * overriding the format's default; no effect without alpha).  POV-Ray
 * 3.7 measured (tests/test_image_alpha.sh): a PNG, TGA or BMP with
 * "premultiplied on" shows each pixel's linear colour divided by its
 * alpha (colour code 60 of alpha 128/255 composes as 0.045 + (1 - a)
 * behind, not as 0.045 a + ...); a TIFF, associated already, with
 * "premultiplied off" shows its colours multiplied by alpha.  The
 * picture becomes one of floats with that done (codes dropped); a
 * palette picture's alpha is its entries' transmit, left as it is.
 */
static bool premultiply(zr_sdl_parser *p, zr_image *image, bool on,
                        const zr_sdl_loc *loc) {
  if (!image->alpha || image->indices || on == image->alpha_associated)
    return true;
  size_t n = (size_t)image->width * (size_t)image->height;
  if (image->codes_working && image->codes && image->maxval == 255) {
    /* TIFF (associated, so "off" here): its codes are in the working
       space (lib/image/tiff.c), and so are their products with alpha. */
    unsigned char *c = image->codes;
    for (size_t k = 0; k < 3 * n; k++)
      c[k] = (unsigned char)floor(c[k] * (double)image->alpha[k / 3] + 0.5);
    return true;
  }
  bool floats = image->layout == ZR_LAYOUT_FLOAT;
  float *pixels = floats ? image->pixels : malloc(3 * n * sizeof *pixels);
  if (!pixels) {
    zr__sdl_error(p, ZR_ENOMEM, loc, "out of memory");
    return false;
  }
  for (size_t i = 0; i < n; i++) {
    float a = image->alpha[i];
    float f = on ? (a > 0.0f ? 1.0f / a : 0.0f) : a;
    for (int c = 0; c < 3; c++) {
      size_t k = 3 * i + (size_t)c;
      float v = floats ? pixels[k]
                       : image->table[zr__image_stored(image, k)];
      pixels[k] = v * f;
    }
  }
  if (!floats) {
    image->pixels = pixels;
    image->pixels_bytes = 0;
    image->layout = ZR_LAYOUT_FLOAT;
  }
  /* The floats are the picture now: no codes to take as they are. */
  free(image->codes);
  image->codes = NULL;
  image->codes_working = false;
  return true;
}

zr_image_map *zr__sdl_bitmap_new(zr_sdl_parser *p, const char *what,
                                 const zr_sdl_bitmap_file *file) {
  const char *name = file->name;
  const zr_sdl_loc *loc = &file->loc, *gamma_loc = &file->gamma_loc;
  bool srgb = file->srgb, gamma_given = file->has_gamma || srgb;
  double g = 0, premult = 0;
  if (file->has_gamma &&
      !zr__sdl_want_float(p, &file->gamma, gamma_loc, &g))
    return NULL;
  bool premult_given = file->has_premultiplied;
  if (premult_given && !zr__sdl_want_float(p, &file->premultiplied,
                                           &file->premultiplied_loc,
                                           &premult))
    return NULL;
  char *path = NULL, *bytes = NULL;
  size_t size = 0;
  zr_status s = zr__sdl_read_image(p, name, loc, what, &path, &bytes,
                                   &size);
  if (s == ZR_ENOTFOUND)
    zr__sdl_error(p, ZR_ENOTFOUND, loc, "%s file '%s' not found", what,
                  name);
  if (s != ZR_OK)
    return NULL;
  zr_image *image = NULL;
  s = zr__image_decode(p->ctx, path, bytes, size, &image);
  free(bytes);
  free(path);
  if (s != ZR_OK) {
    zr__sdl_error(p, s, loc, "cannot use '%s' as %s %s", name,
                  what[0] == 'i' ? "an" : "a", what);
    return NULL;
  }
  /* A TIFF's codes are multiplied before a gamma decodes them, as
     libtiff hands them to povray; other pictures' colours are divided
     once decoded. */
  bool premult_first = image->codes_working;
  bool premult_now = premult_given && strcmp(what, "image_map") == 0;
  if ((premult_now && premult_first &&
       !premultiply(p, image, premult != 0.0, &file->premultiplied_loc)) ||
      (gamma_given &&
       !image_gamma(p, image, what, name, g, srgb, gamma_loc)) ||
      (premult_now && !premult_first &&
       !premultiply(p, image, premult != 0.0, &file->premultiplied_loc))) {
    zr_image_free(image);
    return NULL;
  }
  bool is_image = strcmp(what, "image_map") == 0;
  zr_image_map *im = zr__sdl_alloc(p, sizeof *im);
  bool ok = im != NULL;
  if (ok && image->indices)
    ok = keep_palette(p, im, image);
  /* Bump and material maps read only their numbers (bitmap_values);
     image maps their colours. */
  if (ok && (is_image || image->layout != ZR_LAYOUT_FLOAT))
    ok = picture_codes(p, im, image);
  if (ok)
    ok = is_image ? image_samples(p, im, image, gamma_given)
                  : bitmap_values(p, im, image,
                                  strcmp(what, "material_map") == 0,
                                  gamma_given);
  /* An image map's alpha, if the file has any that is not all opaque. */
  if (ok && image->alpha && !opaque(image) &&
      ((is_image && !image->indices) || strcmp(what, "image_pattern") == 0))
    ok = keep_alpha(p, im, image);
  if (ok && is_image && image->alpha && clear(image))
    zr__sdl_warning(p, loc,
                    "every pixel of '%s' has alpha 0, so the image_map is "
                    "fully transparent (as in POV-Ray 3.7, which reads a "
                    "32-bit BMP's or TGA's fourth byte as alpha)", name);
  if (ok) {
    im->path = zr__sdl_strdup(p, name, strlen(name));
    im->width = image->width;
    im->height = image->height;
    ok = im->path != NULL;
  }
  zr_image_free(image);
  return ok ? im : NULL;
}

void zr__sdl_images_to_working_gamma(zr_sdl_parser *p, double gamma,
                                     bool gamma_off) {
  for (size_t i = 0; i < p->n_images; i++) {
    float *v = p->image_pixels[i];
    if (gamma_off && p->image_codes[i])
      memcpy(v, p->image_codes[i], p->image_sizes[i] * sizeof *v);
    else if (gamma != 1.0)
      for (size_t k = 0; k < p->image_sizes[i]; k++)
        v[k] = v[k] > 0 ? (float)pow(v[k], 1.0 / gamma) : v[k];
  }
}

bool zr__sdl_image_map_mod(zr_sdl_parser *p, zr_image_map *im, int token,
                           const zr_sdl_expr *e, const zr_sdl_loc *loc) {
  double v = 0;
  if (e && !zr__sdl_want_float(p, e, loc, &v))
    return false;
  switch (token) {
  case T_MAP_TYPE:
    /* "Types 3 and 4 are still under development" ("The map_type
       Option"). */
    if (v != 0 && v != 1 && v != 2 && v != 5) {
      zr__sdl_error(p, ZR_ESCENE, loc,
                    "map_type %g is not supported (0, 1, 2 or 5)", v);
      return false;
    }
    im->map_type = (int)v;
    return true;
  case T_ONCE:
    im->once = true;
    return true;
  case T_USE_ALPHA: /* image_pattern's */
    im->value_kind = ZR_BITMAP_VALUE_CLEAR;
    return true;
  case T_INTERPOLATE:
    im->interpolate = (int)v;
    return true;
  case T_FILTER:
  case T_TRANSMIT:
    /* "filter all" sets every palette entry, as POV-Ray 3.7 does, so a
       later "filter INDEX, AMOUNT" overrides one entry. */
    if (token == T_FILTER)
      im->filter_all = v;
    else
      im->transmit_all = v;
    for (int k = 0; im->palette_ft && k < 256; k++)
      im->palette_ft[2 * k + (token == T_TRANSMIT)] = (float)v;
    return true;
  default:
    return true;
  }
}

bool zr__sdl_image_map_index(zr_sdl_parser *p, zr_image_map *im, int token,
                             const zr_sdl_expr *index,
                             const zr_sdl_loc *index_loc,
                             const zr_sdl_expr *amount,
                             const zr_sdl_loc *amount_loc) {
  const char *kw = token == T_FILTER ? "filter" : "transmit";
  double k = 0, v = 0;
  if (!zr__sdl_want_float(p, index, index_loc, &k) ||
      !zr__sdl_want_float(p, amount, amount_loc, &v))
    return false;
  /* The manual gives the index form for "the color palette/registers"
     of palette images only ("The Filter and Transmit Bitmap
     Modifiers"); POV-Ray 3.7 stops with a parse error when it is used
     on an RGB PNG (measured), and so do we. */
  if (!im->indices) {
    zr__sdl_error(p, ZR_ESCENE, index_loc,
                  "'%s INDEX, AMOUNT' needs a palette image; '%s' has no "
                  "palette (use '%s all AMOUNT')", kw, im->path, kw);
    return false;
  }
  /* The entry is INDEX + 0.01 rounded towards zero, as measured with
     POV-Ray 3.7 on a two-entry palette: 0.995 and 1.989 pick entry 1,
     0.985 and -1.005 entry 0; -1.02 and 1.991 are out of range.  The
     manual says nothing of fractional indices; bisection puts povray's
     three edges (entry 1, and out of range above and below) at 0.99,
     1.99 and -1.01 to 1e-5 (bench/provenance/probe.py
     image_map_index). */
  double r = trunc(k + 0.01);
  if (!(r >= 0 && r < im->palette_size)) {
    zr__sdl_error(p, ZR_ESCENE, index_loc,
                  "%s palette index %g is out of range: '%s' has %d "
                  "palette entries", kw, k, im->path, im->palette_size);
    return false;
  }
  im->palette_ft[2 * (size_t)r + (token == T_TRANSMIT)] = (float)v;
  return true;
}

/* ---- object modifiers ---- */

/* The object's texture and interior_texture, moved with it (media
   densities move with the interior, build_media.c).  An object with
   uv_mapping keeps its textures on its surface. */
static bool transform_textures(zr_sdl_parser *p, zr_object *o,
                               const zr_transform *t) {
  if (o->uv_mapping)
    return true;
  if (o->texture) {
    /* Once copied for this object, its texture is moved in place. */
    zr_texture *tx = (zr_texture *)o->texture;
    if (!own_holds(p, &p->own_object, o, tx)) {
      if (!(tx = zr__sdl_texture_new(p, o->texture)))
        return false;
      p->own_object.tx = NULL;
    }
    if (!zr__sdl_texture_move(p, &p->own_object, o, tx, t))
      return false;
    o->texture = tx;
  }
  if (o->interior_texture) {
    zr_texture *tx = zr__sdl_texture_new(p, o->interior_texture);
    if (!tx || !zr__sdl_texture_transform(p, tx, t))
      return false;
    o->interior_texture = tx;
  }
  return true;
}

/* A blob's components' own textures move with the blob: into a new
   array, as copies of the blob share the old one. */
static bool transform_blob_textures(zr_sdl_parser *p, zr_object *o,
                                    const zr_transform *t) {
  size_t n = o->u.blob.n_components;
  zr_blob_component *c = zr__sdl_alloc(p, (n ? n : 1) * sizeof *c);
  if (!c)
    return false;
  for (size_t i = 0; i < n; i++) {
    c[i] = o->u.blob.components[i];
    if (!c[i].texture)
      continue;
    zr_texture *tx = zr__sdl_texture_new(p, c[i].texture);
    if (!tx || !zr__sdl_texture_transform(p, tx, t))
      return false;
    c[i].texture = tx;
  }
  o->u.blob.components = c;
  o->u.blob.cap_components = n;
  return true;
}

/* A mesh's texture_list moves with the object: into a new array, as
   other objects made from the mesh share the old one. */
static bool transform_mesh_textures(zr_sdl_parser *p, zr_object *o,
                                    const zr_transform *t) {
  const struct zr_mesh *m = o->u.mesh.data;
  size_t n = m->n_textures;
  const zr_texture **list = zr__sdl_alloc(p, n * sizeof *list);
  if (!list)
    return false;
  for (size_t i = 0; i < n; i++) {
    const zr_texture *from =
        o->u.mesh.textures ? o->u.mesh.textures[i] : m->textures[i];
    zr_texture *tx = zr__sdl_texture_new(p, from);
    if (!tx || !zr__sdl_texture_transform(p, tx, t))
      return false;
    list[i] = tx;
  }
  o->u.mesh.textures = list;
  return true;
}

/*
 * The object's transform, then t.  A CSG object of a few hundred nodes
 * under "rotate A rotate B translate C" composed a new transform for
 * every node at every step, three of them garbage (truchet3d: 8,000
 * unions of ten nodes, 15% of its CPU time in first touches of that
 * memory).  The first step gives each node a transform of its own
 * (own_transform, cleared when a copy shares it), which later steps
 * change in place: the same arithmetic on the same values, so the same
 * scene.
 */
static bool compose_object(zr_sdl_parser *p, zr_object *o,
                           const zr_transform *t) {
  if (o->own_transform) {
    zr__transform_compose((zr_transform *)o->transform, t);
    return true;
  }
  if (!(o->transform = composed(p, o->transform, t)))
    return false;
  o->own_transform = true;
  return true;
}

/*
 * The interior of o carried through t, the same copy for every object of
 * the tree that shared it before (map: the interiors moved so far and
 * their moved copies).  A CSG's interior is handed down to its parts
 * (set_interior), and a ray's path of media tells interiors apart by
 * pointer (lib/trace/shade.c zr__media_cross): were each part's interior
 * moved to a copy of its own, a ray would go into a second interior where
 * it leaves a difference's shell through the inner surface.  povray 3.7
 * sees one interior there: tests/test_media_shell.sh, a shell of media
 * (difference of two spheres, density { rgb 1 }, translated after its
 * interior) whose hole is clear, and advanced/benchmark/benchmark.pov's
 * clouds, whose sky was white (SSIM 0.76) when the rays from the hole
 * carried the inner sphere's media out to the sky sphere.  A tree with
 * more distinct interiors than the map holds moves the rest one by one.
 */
static bool transform_interior(zr_sdl_parser *p, zr_object *o,
                               const zr_transform *t, interior_map *map) {
  const zr_interior *in = o->interior;
  for (int i = 0; i < map->n; i++)
    if (map->from[i] == in) {
      o->interior = map->to[i];
      return true;
    }
  if (!(o->interior = zr__sdl_interior_transform(p, in, t)))
    return false;
  if (o->interior != in && map->n < COPY_INTERIORS) {
    map->from[map->n] = in;
    map->to[map->n++] = o->interior;
  }
  return true;
}

static bool transform_tree(zr_sdl_parser *p, zr_object *o,
                           const zr_transform *t, interior_map *map);

static bool transform_object(zr_sdl_parser *p, zr_object *o,
                             const zr_transform *t) {
  interior_map map;
  map.n = 0;
  return transform_tree(p, o, t, &map);
}

static bool transform_tree(zr_sdl_parser *p, zr_object *o,
                           const zr_transform *t, interior_map *map) {
  if (!compose_object(p, o, t))
    return false;
  if (o->kind == ZR_OBJ_BLOB && o->u.blob.textured &&
      !transform_blob_textures(p, o, t))
    return false;
  /* Patterns with uv_mapping stay put on the surface (zr_sdl_parser). */
  bool was_moving = p->moving_object;
  p->moving_object = true;
  bool ok = transform_textures(p, o, t);
  if (ok && o->kind == ZR_OBJ_MESH && o->u.mesh.data &&
      o->u.mesh.data->n_textures > 0 && !o->uv_mapping)
    ok = transform_mesh_textures(p, o, t);
  p->moving_object = was_moving;
  if (!ok)
    return false;
  if (o->interior && !transform_interior(p, o, t, map))
    return false;
  if (zr__is_csg(o->kind)) {
    for (size_t i = 0; i < o->u.csg.n_children; i++)
      if (!transform_tree(p, o->u.csg.children[i], t, map))
        return false;
    /* The lights are the object's own copies too. */
    for (size_t i = 0; i < o->u.csg.n_lights; i++)
      zr__sdl_light_transform(p, o->u.csg.lights[i], t);
  }
  /* The clip and the bound are the object's own copies (see
     zr__sdl_object_copy), so they may be changed in place. */
  if (o->clip && !transform_object(p, (zr_object *)o->clip, t))
    return false;
  if (o->bound && !transform_object(p, (zr_object *)o->bound, t))
    return false;
  return true;
}

/* A copy of the object's texture (or of the default one) to change. */
static zr_texture *own_texture(zr_sdl_parser *p, zr_object *o) {
  zr_texture *tx = zr__sdl_texture_new(
      p, o->texture ? o->texture : p->scene->default_texture);
  if (!tx)
    return NULL;
  o->texture = tx;
  /* A layered texture changes at its top (build_texture.c). */
  return zr__sdl_texture_top(p, tx);
}

static void set_interior(zr_object *o, const zr_interior *in, bool force) {
  if (force || !o->interior)
    o->interior = in;
  if (zr__is_csg(o->kind))
    for (size_t i = 0; i < o->u.csg.n_children; i++)
      set_interior(o->u.csg.children[i], in, false);
}

/* A finish with POV-Ray 3.0's "ior N" gives its object that ior. */
static bool legacy_ior(zr_sdl_parser *p, zr_object *o,
                       const zr_finish *f) {
  if (!f || f->legacy_ior <= 0)
    return true;
  zr_interior *in = zr__sdl_interior_new(p, o->interior);
  if (!in)
    return false;
  in->ior = f->legacy_ior;
  in->ior_given = true;
  set_interior(o, in, true);
  return true;
}

static void set_flag(zr_object *o, zr_sdl_mod_kind kind) {
  if (kind == ZR_SDL_MOD_INVERSE) {
    zr__sdl_object_invert(o); /* De Morgan for CSG: build_object.c */
    return;
  }
  if (kind == ZR_SDL_MOD_NO_IMAGE)
    o->no_image = true;
  else if (kind == ZR_SDL_MOD_NO_REFLECTION)
    o->no_reflection = true;
  else if (kind == ZR_SDL_MOD_DOUBLE_ILLUMINATE)
    o->double_illuminate = true;
  else
    o->no_shadow = true;
  if (zr__is_csg(o->kind))
    for (size_t i = 0; i < o->u.csg.n_children; i++)
      set_flag(o->u.csg.children[i], kind);
}

/* ---- uv_mapping ("UV Mapping", "Supported Objects") ---- */

static bool texture_uses_uv(const zr_texture *tx) {
  for (; tx; tx = tx->over) {
    if (tx->uv_mapping || (tx->pigment && tx->pigment->uv_mapping) ||
        (tx->normal && tx->normal->uv_mapping))
      return true;
    if (tx->map)
      for (size_t i = 0; i < tx->map->n; i++)
        if (texture_uses_uv(tx->map->entries[i].u.texture))
          return true;
  }
  return false;
}

/* The first primitive in o without surface coordinates (those of
   lib/trace/intersect.c, zr__hit_uv), NULL if all have them. */
static const zr_object *without_uv(const zr_object *o) {
  if (zr__is_csg(o->kind)) {
    for (size_t i = 0; i < o->u.csg.n_children; i++) {
      const zr_object *c = without_uv(o->u.csg.children[i]);
      if (c)
        return c;
    }
    return NULL;
  }
  bool has = o->kind == ZR_OBJ_MESH || o->kind == ZR_OBJ_SPHERE ||
             o->kind == ZR_OBJ_TORUS || o->kind == ZR_OBJ_BOX;
  return has ? NULL : o;
}

/* Shading looks at the primitive hit, so CSG passes the flag down. */
static void set_uv_mapping(zr_object *o) {
  o->uv_mapping = true;
  if (zr__is_csg(o->kind))
    for (size_t i = 0; i < o->u.csg.n_children; i++)
      set_uv_mapping(o->u.csg.children[i]);
}

static bool uv_mapping_allowed(zr_sdl_parser *p, const zr_object *o,
                               const zr_sdl_mod *mod,
                               const zr_sdl_loc *loc) {
  bool uses = false;
  if (mod->kind == ZR_SDL_MOD_UV_MAPPING)
    uses = true;
  else if (mod->kind == ZR_SDL_MOD_PIGMENT)
    uses = ((const zr_pigment *)mod->ptr)->uv_mapping;
  else if (mod->kind == ZR_SDL_MOD_NORMAL)
    uses = ((const zr_normal *)mod->ptr)->uv_mapping;
  else if (mod->kind == ZR_SDL_MOD_TEXTURE ||
           mod->kind == ZR_SDL_MOD_INTERIOR_TEXTURE)
    uses = texture_uses_uv(mod->ptr);
  else if (mod->kind == ZR_SDL_MOD_MATERIAL)
    uses = texture_uses_uv(((const zr_sdl_material *)mod->ptr)->texture);
  const zr_object *bare = uses ? without_uv(o) : NULL;
  if (!bare)
    return true;
  zr__sdl_error(p, ZR_EUNSUPPORTED, loc,
                "uv_mapping on %s: zRcube has surface coordinates only "
                "for mesh, mesh2, sphere, box and torus",
                kind_name(bare->kind));
  return false;
}

bool zr__sdl_object_mod(zr_sdl_parser *p, zr_object *o,
                        const zr_sdl_mod *mod, const zr_sdl_loc *loc) {
  zr_texture *tx;
  if (!uv_mapping_allowed(p, o, mod, loc))
    return false;
  switch (mod->kind) {
  case ZR_SDL_MOD_UV_MAPPING:
    set_uv_mapping(o);
    return true;
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
    return legacy_ior(p, o, tx->finish);
  case ZR_SDL_MOD_TEXTURE:
    /* A texture on a textured object goes on top as a layer, as in
       POV-Ray (build_texture.c). */
    /* The first texture is shared, not copied: textures never change
       once made (the changes above copy them), but for the one a
       texture block just copied, which is this object's alone. */
    if (!o->texture)
      zr__sdl_texture_given(p, o, mod->ptr);
    o->texture = o->texture ? zr__sdl_texture_layer(p, o->texture, mod->ptr)
                            : (const zr_texture *)mod->ptr;
    return o->texture != NULL &&
           legacy_ior(p, o, ((const zr_texture *)mod->ptr)->finish);
  case ZR_SDL_MOD_MATERIAL: {
    const zr_sdl_material *m = mod->ptr;
    if (m->texture && !(o->texture = o->texture ? zr__sdl_texture_layer(
                                          p, o->texture, m->texture)
                                                 : m->texture))
      return false;
    if (m->interior)
      set_interior(o, m->interior, true);
    return true;
  }
  case ZR_SDL_MOD_NORMAL:
    if (!(tx = own_texture(p, o)))
      return false;
    tx->normal = mod->ptr;
    return true;
  case ZR_SDL_MOD_INTERIOR:
    set_interior(o, mod->ptr, true);
    return true;
  case ZR_SDL_MOD_NO_SHADOW:
  case ZR_SDL_MOD_NO_IMAGE:
  case ZR_SDL_MOD_NO_REFLECTION:
  case ZR_SDL_MOD_DOUBLE_ILLUMINATE:
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
    if (o->kind == ZR_OBJ_PRISM) {
      o->u.prism.open = true;
      return true;
    }
    if (o->kind == ZR_OBJ_SOR) {
      o->u.sor.open = true;
      return true;
    }
    if (o->kind == ZR_OBJ_ISOSURFACE) {
      o->u.isosurface.open = true;
      return true;
    }
    zr__sdl_error(p, ZR_ESYNTAX, loc,
                  "'open' is for cylinders and cones, not for %s",
                  kind_name(o->kind));
    return false;
  case ZR_SDL_MOD_PHOTONS:
    return zr__sdl_photons_object(p, o, mod->ptr); /* build_media.c */
  case ZR_SDL_MOD_IGNORED:
    return true; /* warned about as it was read */
  default:
    return zr__sdl_object_mod_more(p, o, mod);
  }
  return true;
}

/* Lights and the camera: lib/sdl/build_camlight.c. */
