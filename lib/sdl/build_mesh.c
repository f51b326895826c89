/*
 * build_mesh.c - the parser's side of mesh, mesh2, smooth_triangle and
 * text (POV-Ray 3.7 reference manual, "Mesh", "Mesh2", "Smooth
 * Triangle", "Text").
 *
 * A mesh is filled as the grammar reads it and closed by
 * zr__sdl_mesh_done(), which checks every index and builds the mesh's
 * own BVH (lib/trace/obj_mesh.c).  mesh { } collects triangles one by
 * one; mesh2 { } announces the size of each list, so its arrays are
 * allocated once, exactly.
 *
 * mesh2 files are mostly numbers: a million-triangle mesh is tens of
 * millions of tokens, and handing each to bison costs far more than the
 * triangles themselves.  So after a list's '{', when bison has read
 * nothing further, the plain items - a count, then vectors of signed
 * numbers, and the texture indices after a face - are read straight from
 * the token array (the way lib/sdl/fastexpr.c reads simple directive
 * values).  The fast reader stops before the first token it does not
 * know (an identifier, an operator, a directive) and leaves the rest of
 * the list, item by item, to the grammar, which ends in the same
 * helpers; an item is only taken when it is complete and followed by a
 * comma, '}' or the next vector, so "<1,2,3>*2" goes to the grammar whole.
 *
 * The text object reads its TrueType font (lib/scene/ttf.c), searched
 * like #include files, and lays the glyphs out on the x axis (one unit is
 * the font's em height), each advanced by its advance width, its kerning
 * with the previous glyph and the scene's offset vector, the first
 * glyph's left edge at x = 0.
 */
#include "config.h"

#include "sdl/build_mesh.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/context.h"
#include "pov-parse.h"
#include "scene/ttf.h"
#include "trace/obj_mesh.h"
#include "trace/obj_text.h"

/* A mesh while it is read: the mesh first, so the object's pointer to
   it leads back here. */
typedef struct mesh_build {
  struct zr_mesh mesh; /* first: add_vertex finds the build from it */
  /* mesh.vertices are the corners of the file's triangle runs as they
     lie in the scene's arena (tokens.c, zr__sdl_mesh_triangle_run), not
     an array of the mesh's own: the first vertex added otherwise copies
     them (own_vertices). */
  bool borrowed;
  int borrowed_file; /* whose corners (the parser's file index) */
  /* mesh.normals are the normals of the same file's smooth runs
     (tokens.c), likewise (own_normals). */
  bool borrowed_normals;
  bool mesh2;
  bool open;          /* a mesh2 list is being read */
  zr_sdl_mesh2_list list;
  bool have_count;
  size_t announced, got;
  int texture_indices; /* after a face: how many texture indices so far */
  bool warned_blend;
  bool lists_seen[ZR_SDL_M2_TEXTURES + 1];
} mesh_build;

static mesh_build *build_of(zr_object *o) {
  /* The object's mesh is const for the tracer; the parser owns it until
     zr__sdl_mesh_done(). */
  return (mesh_build *)(void *)o->u.mesh.data;
}

static const char *const list_names[] = {
    "vertex_vectors", "normal_vectors", "uv_vectors",  "face_indices",
    "normal_indices", "uv_indices",     "texture_list"};

zr_object *zr__sdl_mesh_new(zr_sdl_parser *p, bool mesh2,
                            const zr_sdl_loc *loc) {
  zr_object *o = zr__sdl_object_new(p, ZR_OBJ_MESH, loc);
  mesh_build *b = o ? zr__sdl_alloc(p, sizeof *b) : NULL;
  if (!b)
    return NULL;
  b->mesh2 = mesh2;
  o->u.mesh.data = &b->mesh;
  return o;
}

/* Room for one more row of size bytes in an arena array that grows by
   doubling.  A large array is resized in its own block
   (zr__arena_grow), so the rows it had are not left behind, and the
   rows not yet written are not zeroed (their pages are not touched). */
static bool grow(zr_sdl_parser *p, void **rows, size_t *cap, size_t n,
                 size_t size) {
  if (n < *cap)
    return true;
  size_t c = *cap ? 2 * *cap : 16;
  zr_arena *a = &p->scene->arena;
  a->over_budget = 0;
  void *q = c <= SIZE_MAX / size
                ? zr__arena_grow(a, *rows, *cap * size, c * size)
                : NULL;
  if (!q) {
    zr__sdl_alloc_failed(p, c <= SIZE_MAX / size ? c * size : SIZE_MAX);
    return false;
  }
  *rows = q;
  *cap = c;
  return true;
}

/* A borrowed array of n vectors (*rows, the file's corners or normals)
   becomes one of the mesh's own, with room for one more (grow's
   doubling from there). */
static bool own_array(zr_sdl_parser *p, zr_vec3 **rows, size_t n,
                      size_t *cap, bool *borrowed) {
  if (!*borrowed)
    return true;
  size_t c = 16;
  while (c <= n)
    c *= 2;
  zr_vec3 *own = zr__arena_grow(&p->scene->arena, NULL, 0, c * sizeof *own);
  if (!own) {
    zr__sdl_alloc_failed(p, c * sizeof *own);
    return false;
  }
  memcpy(own, *rows, n * sizeof *own);
  *rows = own;
  *cap = c;
  *borrowed = false;
  return true;
}

/* A mesh whose vertices are borrowed corners gets an array of its own. */
static bool own_vertices(zr_sdl_parser *p, struct zr_mesh *m) {
  mesh_build *b = (mesh_build *)(void *)m;
  return own_array(p, &m->vertices, m->n_vertices, &m->cap_vertices,
                   &b->borrowed);
}

/* The same for borrowed normals. */
static bool own_normals(zr_sdl_parser *p, struct zr_mesh *m) {
  mesh_build *b = (mesh_build *)(void *)m;
  return own_array(p, &m->normals, m->n_normals, &m->cap_normals,
                   &b->borrowed_normals);
}

static bool add_vertex(zr_sdl_parser *p, struct zr_mesh *m, zr_vec3 v,
                       uint32_t *index) {
  if (!own_vertices(p, m) ||
      !grow(p, (void **)&m->vertices, &m->cap_vertices, m->n_vertices,
            sizeof *m->vertices))
    return false;
  *index = (uint32_t)m->n_vertices;
  m->vertices[m->n_vertices++] = v;
  return true;
}

static bool add_normal(zr_sdl_parser *p, struct zr_mesh *m, zr_vec3 v,
                       uint32_t *index) {
  if (!own_normals(p, m) ||
      !grow(p, (void **)&m->normals, &m->cap_normals, m->n_normals,
            sizeof *m->normals))
    return false;
  *index = (uint32_t)m->n_normals;
  m->normals[m->n_normals++] = v;
  return true;
}

/* The index of texture t in the mesh's list, adding it when new. */
static bool texture_index(zr_sdl_parser *p, struct zr_mesh *m,
                          const zr_texture *t, int32_t *index) {
  for (size_t i = 0; i < m->n_textures; i++)
    if (m->textures[i] == t) {
      *index = (int32_t)i;
      return true;
    }
  /* Few distinct textures: the list grows one at a time. */
  const zr_texture **list =
      zr__sdl_alloc(p, (m->n_textures + 1) * sizeof *list);
  if (!list)
    return false;
  if (m->n_textures)
    memcpy(list, m->textures, m->n_textures * sizeof *list);
  list[m->n_textures] = t;
  m->textures = list;
  *index = (int32_t)m->n_textures++;
  return true;
}

/* Makes the optional per-face arrays of mesh { } exist for faces
   0..cap_faces, the faces before this one filled with "none". */
static bool face_extra(zr_sdl_parser *p, uint32_t (**rows)[3], size_t old,
                       size_t cap, size_t n, uint32_t none) {
  if (*rows && old == cap)
    return true;
  uint32_t (*q)[3] = zr__sdl_alloc(p, cap * sizeof *q);
  if (!q)
    return false;
  if (*rows)
    memcpy(q, *rows, n * sizeof *q);
  else
    for (size_t f = 0; f < n; f++)
      q[f][0] = q[f][1] = q[f][2] = none;
  *rows = q;
  return true;
}

static bool add_uv(zr_sdl_parser *p, struct zr_mesh *m, double u, double v,
                   uint32_t *index) {
  if (!grow(p, (void **)&m->uvs, &m->cap_uvs, m->n_uvs, sizeof *m->uvs))
    return false;
  *index = (uint32_t)m->n_uvs;
  m->uvs[m->n_uvs][0] = u;
  m->uvs[m->n_uvs++][1] = v;
  return true;
}

/*
 * A triangle's uv_vectors ("Mesh"), or for one written without them
 * once another has them, the corners POV-Ray gives a triangle without
 * uv_vectors: (0,0), (1,0) and (1,1), kept once as uvs 0 to 2.
 */
static bool face_uvs(zr_sdl_parser *p, struct zr_mesh *m, size_t f,
                     size_t old_cap, const zr_vec3 *uv) {
  if (!uv && !m->face_uvs)
    return true;
  bool first = !m->face_uvs;
  if (!face_extra(p, &m->face_uvs, old_cap, m->cap_faces, f, 0))
    return false;
  if (first) {
    static const double corner[3][2] = {{0, 0}, {1, 0}, {1, 1}};
    uint32_t at;
    for (int k = 0; k < 3; k++)
      if (!add_uv(p, m, corner[k][0], corner[k][1], &at))
        return false;
    for (size_t g = 0; g < f; g++)
      for (int k = 0; k < 3; k++)
        m->face_uvs[g][k] = (uint32_t)k;
  }
  for (int k = 0; k < 3; k++) {
    m->face_uvs[f][k] = (uint32_t)k;
    if (uv && !add_uv(p, m, uv[k].x, uv[k].y, &m->face_uvs[f][k]))
      return false;
  }
  return true;
}

static bool add_triangle(zr_sdl_parser *p, struct zr_mesh *m,
                         const zr_vec3 v[3], const zr_vec3 *n,
                         const zr_vec3 *uv, const zr_texture *texture,
                         const zr_sdl_loc *loc);

bool zr__sdl_mesh_triangle(zr_sdl_parser *p, zr_object *o,
                           const zr_sdl_expr vertices[3],
                           const zr_sdl_loc vertex_locs[3],
                           const zr_sdl_expr *normals,
                           const zr_sdl_loc *normal_locs,
                           const zr_sdl_expr *uvs, const zr_sdl_loc *uv_locs,
                           const zr_texture *texture) {
  zr_vec3 v[3], n[3], uv[3];
  for (int k = 0; k < 3; k++) {
    if (!zr__sdl_want_vector(p, &vertices[k], &vertex_locs[k], &v[k]))
      return false;
    if (normals &&
        !zr__sdl_want_vector(p, &normals[k], &normal_locs[k], &n[k]))
      return false;
    if (uvs && !zr__sdl_want_vector(p, &uvs[k], &uv_locs[k], &uv[k]))
      return false;
  }
  return add_triangle(p, &build_of(o)->mesh, v, normals ? n : NULL,
                      uvs ? uv : NULL, texture, &vertex_locs[0]);
}

void zr__sdl_triangle_run(const double *corners, zr_vec3 out[3]) {
  for (int k = 0; k < 3; k++)
    out[k] = zr_v3(corners[3 * k], corners[3 * k + 1], corners[3 * k + 2]);
}

/* The corners as vertices where they lie: three doubles each, as a
   zr_vec3 is. */
_Static_assert(sizeof(zr_vec3) == 3 * sizeof(double),
               "a zr_vec3 is three doubles");

/*
 * A face of run corners (and normals, or NULL for a plain face) added
 * by index where the corners lie.  A mesh whose faces are all runs of
 * one file, one after another, takes the lexer's corner array as its
 * vertex array (mesh_build.borrowed), and for smooth runs the normal
 * array as its normals: run after run, the next face's corners (and
 * normals) are where the last face's end, so the mesh only counts them
 * and adds the face, whose normals are its corners' indices.  Returns
 * 1 when it did, 0 when the face must go through add_triangle - a plain
 * face among smooth ones, a uv or a texture before it, corners elsewhere
 * (another file, a run read again by a loop or macro) - whose first
 * vertex then copies the borrowed arrays (own_vertices, own_normals)
 * with the same values in the same order; -1 when out of memory.
 */
static int add_run_face(zr_sdl_parser *p, mesh_build *b,
                        const double *corners, const double *normals,
                        const zr_sdl_loc *loc) {
  struct zr_mesh *m = &b->mesh;
  const zr_vec3 *c = (const zr_vec3 *)(const void *)corners;
  const zr_vec3 *n = (const zr_vec3 *)(const void *)normals;
  /* The next face's corners follow the last's in the same file's array
     (another file's array could lie just after, in memory). */
  bool next = m->n_vertices == 0
                  ? m->n_faces == 0 && (!n || m->n_normals == 0)
                  : b->borrowed && b->borrowed_file == loc->file &&
                        c == m->vertices + m->n_vertices &&
                        (!n || (b->borrowed_normals &&
                                n == m->normals + m->n_normals));
  if (!next || m->face_uvs || m->face_textures || (!n && m->face_normals) ||
      m->n_faces > UINT32_MAX / 4)
    return 0;
  size_t f = m->n_faces, old_cap = m->cap_faces;
  if (!grow(p, (void **)&m->faces, &m->cap_faces, f, sizeof *m->faces) ||
      (n && !face_extra(p, &m->face_normals, old_cap, m->cap_faces, f, 0)))
    return -1;
  if (m->n_vertices == 0) {
    /* The tracer reads the vertices and normals only (zr_mesh's arrays
       are not const for the parser's sake). */
    m->vertices = (zr_vec3 *)(void *)corners;
    m->cap_vertices = 0;
    b->borrowed = true;
    b->borrowed_file = loc->file;
    if (n) {
      m->normals = (zr_vec3 *)(void *)normals;
      m->cap_normals = 0;
      b->borrowed_normals = true;
    }
  }
  uint32_t v = (uint32_t)m->n_vertices;
  for (int k = 0; k < 3; k++) {
    m->faces[f][k] = v + (uint32_t)k;
    if (n)
      m->face_normals[f][k] = v + (uint32_t)k;
  }
  m->n_vertices += 3;
  if (n)
    m->n_normals += 3;
  m->n_faces++;
  return 1;
}

/* A face of plain corners (add_run_face, else add_triangle). */
bool zr__sdl_mesh_triangle_run(zr_sdl_parser *p, zr_object *o,
                               const double *corners,
                               const zr_sdl_loc *loc) {
  int r = add_run_face(p, build_of(o), corners, NULL, loc);
  if (r)
    return r > 0;
  zr_vec3 v[3];
  zr__sdl_triangle_run(corners, v);
  return add_triangle(p, &build_of(o)->mesh, v, NULL, NULL, NULL, loc);
}

/* A face of a smooth_triangle's run, the same way. */
bool zr__sdl_mesh_smooth_triangle_run(zr_sdl_parser *p, zr_object *o,
                                      const zr_sdl_smooth_run *run,
                                      const zr_sdl_loc *loc) {
  int r = add_run_face(p, build_of(o), run->corners, run->normals, loc);
  if (r)
    return r > 0;
  const zr_vec3 *c = (const zr_vec3 *)(const void *)run->corners;
  const zr_vec3 *n = (const zr_vec3 *)(const void *)run->normals;
  zr_vec3 v[3], nv[3];
  for (int k = 0; k < 3; k++) {
    v[k] = c[k];
    nv[k] = n[k];
  }
  return add_triangle(p, &build_of(o)->mesh, v, nv, NULL, NULL, loc);
}

zr_object *zr__sdl_smooth_triangle_run(zr_sdl_parser *p,
                                       const zr_sdl_smooth_run *run,
                                       const zr_sdl_loc *loc) {
  zr_object *o = zr__sdl_mesh_new(p, false, loc);
  if (!o || !zr__sdl_mesh_smooth_triangle_run(p, o, run, loc) ||
      !zr__sdl_mesh_done(p, o, loc))
    return NULL;
  return o;
}

/* Adds a face of corners v, with corner normals n and uv coordinates
   uv when not NULL; loc is where "too many triangles" points. */
static bool add_triangle(zr_sdl_parser *p, struct zr_mesh *m,
                         const zr_vec3 v[3], const zr_vec3 *n,
                         const zr_vec3 *uv, const zr_texture *texture,
                         const zr_sdl_loc *loc) {
  const bool normals = n != NULL;
  if (m->n_faces > UINT32_MAX / 4) {
    zr__sdl_error(p, ZR_ELIMIT, loc, "too many triangles");
    return false;
  }
  size_t f = m->n_faces, old_cap = m->cap_faces;
  if (!grow(p, (void **)&m->faces, &m->cap_faces, f, sizeof *m->faces))
    return false;
  /* The optional arrays follow the faces' capacity. */
  bool first_smooth = normals && !m->face_normals;
  if ((normals || m->face_normals) &&
      !face_extra(p, &m->face_normals, old_cap, m->cap_faces, f, 0))
    return false;
  /* The flat faces before the first smooth one get their own normal at
     each corner, so every face then has three normal indices. */
  for (size_t g = 0; first_smooth && g < f; g++) {
    const uint32_t *vi = m->faces[g];
    zr_vec3 flat = zr_v3_cross(
        zr_v3_sub(m->vertices[vi[1]], m->vertices[vi[0]]),
        zr_v3_sub(m->vertices[vi[2]], m->vertices[vi[0]]));
    for (int k = 0; k < 3; k++)
      if (!add_normal(p, m, flat, &m->face_normals[g][k]))
        return false;
  }
  if (!face_uvs(p, m, f, old_cap, uv))
    return false;
  if ((texture || m->face_textures) &&
      !face_extra(p, (uint32_t(**)[3])&m->face_textures, old_cap,
                  m->cap_faces, f, (uint32_t)-1))
    return false;
  for (int k = 0; k < 3; k++) {
    if (!add_vertex(p, m, v[k], &m->faces[f][k]))
      return false;
    if (m->face_normals) {
      /* A flat face among smooth ones gets its own normal thrice. */
      zr_vec3 flat = zr_v3_cross(zr_v3_sub(v[1], v[0]),
                                 zr_v3_sub(v[2], v[0]));
      if (!add_normal(p, m, normals ? n[k] : flat, &m->face_normals[f][k]))
        return false;
    }
  }
  if (m->face_textures) {
    int32_t t = -1;
    if (texture && !texture_index(p, m, texture, &t))
      return false;
    m->face_textures[f][0] = m->face_textures[f][1] =
        m->face_textures[f][2] = t;
  }
  m->n_faces++;
  return true;
}

bool zr__sdl_mesh_inside_vector(zr_sdl_parser *p, zr_object *o,
                                const zr_sdl_expr *e,
                                const zr_sdl_loc *loc) {
  struct zr_mesh *m = &build_of(o)->mesh;
  zr_vec3 v;
  if (!zr__sdl_want_vector(p, e, loc, &v))
    return false;
  if (!(zr_v3_len(v) > 0.0)) {
    zr__sdl_error(p, ZR_ESCENE, loc, "the inside_vector is zero");
    return false;
  }
  m->has_inside = true;
  m->inside_vector = v;
  return true;
}

bool zr__sdl_mesh_done(zr_sdl_parser *p, zr_object *o,
                       const zr_sdl_loc *loc) {
  mesh_build *b = build_of(o);
  struct zr_mesh *m = &b->mesh;
  const char *what = b->mesh2 ? "mesh2" : "mesh";
  if (b->mesh2 && m->n_faces == 0) {
    zr__sdl_error(p, ZR_ESYNTAX, loc, "a mesh2 needs vertex_vectors and "
                  "face_indices");
    return false;
  }
  if (m->n_faces == 0) {
    zr__sdl_error(p, ZR_ESCENE, loc, "a %s needs at least one triangle",
                  what);
    return false;
  }
  /* normal_vectors without normal_indices: the faces' own indices pick
     the normals ("Mesh2"), which then must be one per vertex. */
  if (m->n_normals && !m->face_normals) {
    if (m->n_normals != m->n_vertices) {
      zr__sdl_error(p, ZR_ESCENE, loc, "mesh2 without normal_indices needs "
                    "one normal per vertex (%zu normals, %zu vertices)",
                    m->n_normals, m->n_vertices);
      return false;
    }
    m->face_normals = zr__sdl_alloc(p, m->n_faces * sizeof *m->faces);
    if (!m->face_normals)
      return false;
    memcpy(m->face_normals, m->faces, m->n_faces * sizeof *m->faces);
  }
  if (m->n_uvs && !m->face_uvs) {
    m->face_uvs = zr__sdl_alloc(p, m->n_faces * sizeof *m->faces);
    if (!m->face_uvs)
      return false;
    memcpy(m->face_uvs, m->faces, m->n_faces * sizeof *m->faces);
  }
  size_t bad = 0;
  /* With a team (zr_context_set_team) the members in step share the
     build; once they part, each builds alone for the rest of the
     parse. */
  bool team_on = p->ctx && p->ctx->team_parse;
  zr_status s = zr__mesh_build_team(m, &p->scene->arena,
                                    p->ctx ? p->ctx->threads : 1,
                                    p->ctx ? p->ctx->team : NULL, &team_on,
                                    &bad);
  if (p->ctx)
    p->ctx->team_parse = team_on;
  if (s == ZR_ESCENE) {
    zr__sdl_error(p, s, loc, "%s face %zu refers to a vertex, normal, uv "
                  "or texture that is not in its lists", what, bad);
    return false;
  }
  if (s != ZR_OK) {
    zr__sdl_error(p, s, loc, "cannot build the %s: %s", what,
                  zr_status_str(s));
    return false;
  }
  return true;
}

zr_object *zr__sdl_mesh_copy(zr_sdl_parser *p, const zr_object *o,
                             const zr_sdl_loc *loc) {
  if (o->kind != ZR_OBJ_MESH) {
    zr__sdl_error(p, ZR_ESCENE, loc, "only a mesh or mesh2 identifier can "
                  "start a mesh { } block");
    return NULL;
  }
  return zr__sdl_object_copy(p, o);
}

/* ---- mesh2 lists ---- */

static bool list_error(zr_sdl_parser *p, const zr_sdl_loc *loc,
                       const mesh_build *b, const char *fmt_tail) {
  zr__sdl_error(p, ZR_ESCENE, loc, "%s: %s", list_names[b->list],
                fmt_tail);
  return false;
}

/* Sets the list's count and allocates its arrays. */
static bool take_count(zr_sdl_parser *p, mesh_build *b, double count,
                       const zr_sdl_loc *loc) {
  struct zr_mesh *m = &b->mesh;
  if (!(count >= 0.0) || count != floor(count) || count > UINT32_MAX / 4)
    return list_error(p, loc, b, "the count must be a whole number");
  size_t n = (size_t)count, room = n ? n : 1;
  b->have_count = true;
  b->announced = n;
  b->got = 0;
  switch (b->list) {
  case ZR_SDL_M2_VERTICES:
    m->vertices = zr__sdl_alloc(p, room * sizeof *m->vertices);
    m->cap_vertices = n;
    return m->vertices != NULL;
  case ZR_SDL_M2_NORMALS:
    m->normals = zr__sdl_alloc(p, room * sizeof *m->normals);
    m->cap_normals = n;
    return m->normals != NULL;
  case ZR_SDL_M2_UVS:
    m->uvs = zr__sdl_alloc(p, room * sizeof *m->uvs);
    m->cap_uvs = n;
    return m->uvs != NULL;
  case ZR_SDL_M2_FACES:
    m->faces = zr__sdl_alloc(p, room * sizeof *m->faces);
    m->cap_faces = n;
    return m->faces != NULL;
  case ZR_SDL_M2_NORMAL_INDICES:
    m->face_normals = zr__sdl_alloc(p, room * sizeof *m->face_normals);
    return m->face_normals != NULL;
  case ZR_SDL_M2_UV_INDICES:
    m->face_uvs = zr__sdl_alloc(p, room * sizeof *m->face_uvs);
    return m->face_uvs != NULL;
  case ZR_SDL_M2_TEXTURES:
    m->textures = zr__sdl_alloc(p, room * sizeof *m->textures);
    return m->textures != NULL;
  }
  return true;
}

static bool want_index(zr_sdl_parser *p, const mesh_build *b, double v,
                       const zr_sdl_loc *loc, uint32_t *out) {
  if (!(v >= 0.0) || v >= 4294967295.0) {
    zr__sdl_error(p, ZR_ESCENE, loc, "%s: %g is not an index",
                  list_names[b->list], v);
    return false;
  }
  *out = (uint32_t)v;
  return true;
}

/* One vector of a list (x, y, z as written; uvs use x and y). */
static bool take_vector(zr_sdl_parser *p, mesh_build *b, zr_vec3 v,
                        const zr_sdl_loc *loc) {
  struct zr_mesh *m = &b->mesh;
  if (b->list == ZR_SDL_M2_FACES && b->texture_indices == 2)
    return list_error(p, loc, b, "a face has 1 or 3 texture indices, "
                      "not 2");
  if (b->got == b->announced) {
    zr__sdl_error(p, ZR_ESCENE, loc, "%s: more items than the %zu "
                  "announced", list_names[b->list], b->announced);
    return false;
  }
  size_t i = b->got++;
  uint32_t idx[3];
  switch (b->list) {
  case ZR_SDL_M2_VERTICES:
    m->vertices[m->n_vertices++] = v;
    return true;
  case ZR_SDL_M2_NORMALS:
    m->normals[m->n_normals++] = v;
    return true;
  case ZR_SDL_M2_UVS:
    m->uvs[m->n_uvs][0] = v.x;
    m->uvs[m->n_uvs++][1] = v.y;
    return true;
  default:
    break;
  }
  if (!want_index(p, b, v.x, loc, &idx[0]) ||
      !want_index(p, b, v.y, loc, &idx[1]) ||
      !want_index(p, b, v.z, loc, &idx[2]))
    return false;
  uint32_t(*rows)[3] = b->list == ZR_SDL_M2_FACES ? m->faces
                       : b->list == ZR_SDL_M2_NORMAL_INDICES
                           ? m->face_normals
                           : m->face_uvs;
  memcpy(rows[i], idx, sizeof idx);
  if (b->list == ZR_SDL_M2_FACES) {
    m->n_faces++;
    b->texture_indices = 0;
    if (m->face_textures)
      m->face_textures[i][0] = m->face_textures[i][1] =
          m->face_textures[i][2] = -1;
  }
  return true;
}

/* A float after a face: one of its texture indices. */
static bool take_texture_index(zr_sdl_parser *p, mesh_build *b, double v,
                               const zr_sdl_loc *loc) {
  struct zr_mesh *m = &b->mesh;
  if (b->got == 0 || b->texture_indices == 3)
    return list_error(p, loc, b, "expected a vector of three indices");
  if (!m->face_textures) {
    m->face_textures = zr__sdl_alloc(
        p, (b->announced ? b->announced : 1) * sizeof *m->face_textures);
    if (!m->face_textures)
      return false;
    for (size_t f = 0; f < b->announced; f++)
      m->face_textures[f][0] = m->face_textures[f][1] =
          m->face_textures[f][2] = -1;
  }
  uint32_t t;
  if (!want_index(p, b, v, loc, &t))
    return false;
  if (t > INT32_MAX)
    return list_error(p, loc, b, "texture index too large");
  int32_t *row = m->face_textures[b->got - 1];
  if (b->texture_indices == 0) {
    row[0] = row[1] = row[2] = (int32_t)t;
  } else {
    row[b->texture_indices] = (int32_t)t;
    if (b->texture_indices == 1 && !b->warned_blend) {
      b->warned_blend = true;
      zr__sdl_warning(p, loc, "three texture indices per face: zRcube "
                      "gives each point the texture of its nearest corner "
                      "instead of blending them");
    }
  }
  b->texture_indices++;
  return true;
}

bool zr__sdl_mesh2_item(zr_sdl_parser *p, zr_object *o,
                        const zr_sdl_expr *e, const zr_sdl_loc *loc) {
  mesh_build *b = build_of(o);
  if (!b->have_count) {
    double count;
    return zr__sdl_want_float(p, e, loc, &count) &&
           take_count(p, b, count, loc);
  }
  if (e->dim == 1 && b->list == ZR_SDL_M2_FACES)
    return take_texture_index(p, b, e->v[0], loc);
  if (b->list == ZR_SDL_M2_UVS) {
    if (e->dim > 2) {
      zr__sdl_error(p, ZR_ESYNTAX, loc, "uv_vectors: expected a 2-D "
                    "vector");
      return false;
    }
    double u = e->v[0], v = e->dim == 1 ? e->v[0] : e->v[1];
    return take_vector(p, b, zr_v3(u, v, 0), loc);
  }
  zr_vec3 v;
  return zr__sdl_want_vector(p, e, loc, &v) && take_vector(p, b, v, loc);
}

/* ---- the fast reader ---- */

typedef struct cursor {
  const zr_sdl_token *tokens;
  size_t pos, n;
} cursor;

static int kind_at(const cursor *c, size_t i) {
  return i < c->n ? c->tokens[i].kind : 0;
}

/* A number with optional signs at c->pos; advances past it. */
static bool signed_number(cursor *c, double *out) {
  double sign = 1.0;
  size_t i = c->pos;
  while (kind_at(c, i) == '-' || kind_at(c, i) == '+') {
    if (kind_at(c, i) == '-')
      sign = -sign;
    i++;
  }
  if (kind_at(c, i) != T_NUMBER)
    return false;
  *out = sign * c->tokens[i].v.num;
  c->pos = i + 1;
  return true;
}

/* Whether the token at i may follow a complete item (a run of items
   starts with a comma or a '<'). */
static bool item_end(const cursor *c, size_t i) {
  int k = kind_at(c, i);
  return k == ',' || k == '}' || k == '<' || k == ZR_SDL_NUMBER_LIST;
}

/* The items of a run the lexer kept as one token (numlist.c), read
   again from the file's bytes with the reader that found them. */
static bool number_list(zr_sdl_parser *p, mesh_build *b, int file,
                        const zr_sdl_numlist *list) {
  /* The reader looks past an item's end to see that it is complete:
     it reads up to the file's end, and stops after the run's items. */
  const zr_sdl_file *f = &p->files[file];
  zr_sdl_numreader r = {f->bytes, list->begin, f->size, list->line,
                        list->column, list->uv, true};
  for (size_t k = 0; k < list->n_items; k++) {
    double v[3];
    int dim;
    zr_sdl_loc loc = {file, 0, 0, 1};
    if (!zr__sdl_numlist_item(&r, v, &dim, &loc.line, &loc.column)) {
      zr__sdl_error(p, ZR_ESYNTAX, &loc, "%s: the lexer's run of items "
                    "does not read again", list_names[b->list]);
      return false;
    }
    if (!take_vector(p, b, zr_v3(v[0], v[1], v[2]), &loc))
      return false;
  }
  return true;
}

/* "<a, b[, c]>" of signed numbers; dim gets 2 or 3. */
static bool number_vector(cursor *c, double v[3], int *dim) {
  if (kind_at(c, c->pos) != '<')
    return false;
  c->pos++;
  int n = 0;
  for (;;) {
    if (n == 3 || !signed_number(c, &v[n]))
      return false;
    n++;
    if (kind_at(c, c->pos) != ',')
      break;
    c->pos++;
  }
  if (kind_at(c, c->pos) != '>' || n < 2)
    return false;
  c->pos++;
  if (n == 2)
    v[2] = 0.0;
  *dim = n;
  return true;
}

/* Reads plain items from the newest frame until one needs the grammar.
   False only after an error was reported. */
static bool fast_items(zr_sdl_parser *p, mesh_build *b) {
  zr_sdl_frame *fr = zr__sdl_top(p);
  const zr_sdl_file *f = &p->files[fr->file];
  cursor c = {f->tokens, fr->pos, f->n_tokens};
  if (!b->have_count) {
    double count;
    size_t start = c.pos;
    if (!signed_number(&c, &count) || !item_end(&c, c.pos))
      return true;
    zr_sdl_loc loc = zr__sdl_token_loc(fr->file, &c.tokens[start]);
    if (!take_count(p, b, count, &loc))
      return false;
    if (kind_at(&c, c.pos) == ',')
      c.pos++;
    fr->pos = c.pos;
  }
  bool faces = b->list == ZR_SDL_M2_FACES;
  for (;;) {
    if (kind_at(&c, c.pos) == ZR_SDL_NUMBER_LIST) {
      if (!number_list(p, b, fr->file, c.tokens[c.pos].v.list))
        return false;
      c.pos++;
      if (kind_at(&c, c.pos) == ',')
        c.pos++;
      fr->pos = c.pos;
      continue;
    }
    size_t start = c.pos;
    double v[3];
    int dim = 0;
    bool ok;
    if (kind_at(&c, c.pos) == '<') {
      ok = number_vector(&c, v, &dim) && item_end(&c, c.pos) &&
           (dim == 3 || b->list == ZR_SDL_M2_UVS);
    } else {
      ok = faces && signed_number(&c, &v[0]) && item_end(&c, c.pos);
    }
    if (!ok)
      break;
    zr_sdl_loc loc = zr__sdl_token_loc(fr->file, &c.tokens[start]);
    if (!(dim ? take_vector(p, b, zr_v3(v[0], v[1], v[2]), &loc)
              : take_texture_index(p, b, v[0], &loc)))
      return false;
    if (kind_at(&c, c.pos) == ',')
      c.pos++;
    fr->pos = c.pos;
  }
  return true;
}

bool zr__sdl_mesh2_open(zr_sdl_parser *p, zr_object *o,
                        zr_sdl_mesh2_list list, const zr_sdl_loc *loc,
                        bool fast) {
  mesh_build *b = build_of(o);
  if (b->lists_seen[list]) {
    zr__sdl_error(p, ZR_ESYNTAX, loc, "mesh2 has two %s",
                  list_names[list]);
    return false;
  }
  bool needs_faces =
      list == ZR_SDL_M2_NORMAL_INDICES || list == ZR_SDL_M2_UV_INDICES;
  if (needs_faces && !b->lists_seen[ZR_SDL_M2_FACES]) {
    zr__sdl_error(p, ZR_ESYNTAX, loc, "mesh2: %s must follow face_indices",
                  list_names[list]);
    return false;
  }
  b->lists_seen[list] = true;
  b->open = true;
  b->list = list;
  b->have_count = false;
  b->announced = b->got = 0;
  b->texture_indices = 0;
  if (fast && list != ZR_SDL_M2_TEXTURES)
    return fast_items(p, b);
  return true;
}

bool zr__sdl_mesh2_texture(zr_sdl_parser *p, zr_object *o,
                           const zr_texture *t, const zr_sdl_loc *loc) {
  mesh_build *b = build_of(o);
  if (!b->have_count)
    return list_error(p, loc, b, "expected the number of textures first");
  if (b->got == b->announced) {
    zr__sdl_error(p, ZR_ESCENE, loc, "texture_list: more items than the "
                  "%zu announced", b->announced);
    return false;
  }
  b->mesh.textures[b->got++] = t;
  b->mesh.n_textures = b->got;
  return true;
}

bool zr__sdl_mesh2_close(zr_sdl_parser *p, zr_object *o,
                         const zr_sdl_loc *loc) {
  mesh_build *b = build_of(o);
  b->open = false;
  if (!b->have_count)
    return list_error(p, loc, b, "expected the number of items first");
  if (b->got != b->announced) {
    zr__sdl_error(p, ZR_ESCENE, loc, "%s: %zu items given, %zu announced",
                  list_names[b->list], b->got, b->announced);
    return false;
  }
  if (b->list == ZR_SDL_M2_FACES && b->texture_indices == 2)
    return list_error(p, loc, b, "a face has 1 or 3 texture indices, "
                      "not 2");
  size_t faces = b->mesh.n_faces;
  if ((b->list == ZR_SDL_M2_NORMAL_INDICES ||
       b->list == ZR_SDL_M2_UV_INDICES) &&
      b->got != faces) {
    zr__sdl_error(p, ZR_ESCENE, loc, "%s: %zu given for %zu faces",
                  list_names[b->list], b->got, faces);
    return false;
  }
  return true;
}

zr_object *zr__sdl_smooth_triangle(zr_sdl_parser *p, const zr_sdl_loc *loc,
                                   const zr_sdl_expr e[6],
                                   const zr_sdl_loc locs[6]) {
  zr_object *o = zr__sdl_mesh_new(p, false, loc);
  if (!o)
    return NULL;
  zr_sdl_expr v[3] = {e[0], e[2], e[4]}, n[3] = {e[1], e[3], e[5]};
  zr_sdl_loc vl[3] = {locs[0], locs[2], locs[4]};
  zr_sdl_loc nl[3] = {locs[1], locs[3], locs[5]};
  if (!zr__sdl_mesh_triangle(p, o, v, vl, n, nl, NULL, NULL, NULL) ||
      !zr__sdl_mesh_done(p, o, loc))
    return NULL;
  return o;
}

/* ---- text ---- */

/* The fonts POV-Ray 3.7 builds in, by their 'internal' number. */
static const char *const internal_fonts[] = {"povlogo.ttf", "timrom.ttf",
                                             "cyrvetic.ttf", "crystal.ttf"};

/* Reads a font searched like an #include file: beside the including
   file, along the include paths, then in POV-Ray's include directory,
   where its fonts are installed, under the I/O restrictions.
   ZR_ENOTFOUND when it is nowhere; other failures reported at 'at'. */
static zr_status read_font(zr_sdl_parser *p, const char *name,
                           const zr_sdl_loc *at, char **bytes,
                           size_t *size) {
  const char *scene = p->files[zr__sdl_top(p)->file].path;
  const char *slash = strrchr(scene, '/');
  size_t n_dirs = p->ctx ? p->ctx->n_include_paths : 0;
  for (size_t i = 0; i <= n_dirs + 1; i++) {
    const char *dir = "";
    size_t dir_len = 0;
    if (name[0] == '/') {
      if (i > 0)
        break;
    } else if (i == 0) {
      dir = scene;
      dir_len = slash ? (size_t)(slash - scene) : 0;
    } else {
      dir = i <= n_dirs ? p->ctx->include_paths[i - 1]
                        : ZR_POVRAY_INCLUDE_DIR;
      dir_len = strlen(dir);
    }
    size_t len = dir_len + 1 + strlen(name) + 1;
    char *path = malloc(len);
    if (!path)
      return zr__sdl_error(p, ZR_ENOMEM, at, "out of memory");
    if (dir_len)
      snprintf(path, len, "%.*s/%s", (int)dir_len, dir, name);
    else
      snprintf(path, len, "%s", name);
    zr_status s = zr__sdl_read_file(p, path, name[0] != '/', at, "font",
                                   bytes, size);
    free(path);
    if (s != ZR_ENOTFOUND)
      return s;
  }
  return ZR_ENOTFOUND;
}

/* The outline pieces of the glyph being placed, collected by the font
   reader's callback. */
typedef struct text_build {
  zr_text_segment *segments;
  size_t n, cap;
  double scale, x, y; /* font units to text units, and the pen */
} text_build;

static bool add_segment(void *user, const double p0[2], const double c[2],
                        const double p1[2], bool line) {
  text_build *tb = user;
  if (tb->n == tb->cap) {
    size_t cap = tb->cap ? 2 * tb->cap : 256;
    zr_text_segment *q = realloc(tb->segments, cap * sizeof *q);
    if (!q)
      return false;
    tb->segments = q;
    tb->cap = cap;
  }
  zr_text_segment *sg = &tb->segments[tb->n++];
  const double *src[3] = {p0, c, p1};
  double *dst[3] = {sg->p0, sg->p1, sg->p2};
  for (int k = 0; k < 3; k++) {
    dst[k][0] = tb->x + src[k][0] * tb->scale;
    dst[k][1] = tb->y + src[k][1] * tb->scale;
  }
  sg->line = line;
  return true;
}

/* The next character of a UTF-8 string (a stray byte stands for
   itself, as in Latin-1). */
static uint32_t next_char(const unsigned char **s) {
  const unsigned char *c = *s;
  int extra = c[0] >= 0xF0 ? 3 : c[0] >= 0xE0 ? 2 : c[0] >= 0xC0 ? 1 : 0;
  uint32_t code = extra ? c[0] & (0x3F >> extra) : c[0];
  for (int i = 1; i <= extra; i++) {
    if ((c[i] & 0xC0) != 0x80) {
      *s = c + 1;
      return c[0];
    }
    code = code << 6 | (c[i] & 0x3F);
  }
  *s = c + 1 + extra;
  return code;
}

/* Lays the string out into tx (see the top of the file). */
static const char *layout(zr_sdl_parser *p, const zr_ttf *font,
                          const char *string, zr_vec3 offset,
                          struct zr_text *tx) {
  text_build tb = {NULL, 0, 0, 1.0 / font->units_per_em, 0.0, 0.0};
  size_t n_chars = strlen(string);
  zr_text_glyph *glyphs = malloc((n_chars ? n_chars : 1) * sizeof *glyphs);
  const char *err = glyphs ? NULL : "out of memory";
  size_t n_glyphs = 0;
  unsigned previous = 0;
  bool s_first = true, lead_blank = false;
  const unsigned char *s = (const unsigned char *)string;
  while (!err && *s) {
    unsigned g = zr__ttf_glyph(font, next_char(&s));
    if (n_glyphs > 0)
      tb.x += zr__ttf_kerning(font, previous, g) * tb.scale;
    size_t first = tb.n;
    err = zr__ttf_outline(font, g, add_segment, &tb);
    if (err)
      break;
    if (tb.n == first && s_first)
      lead_blank = true;
    s_first = false;
    if (tb.n > first) {
      zr_text_glyph *gl = &glyphs[n_glyphs++];
      gl->first = first;
      gl->n = tb.n - first;
      gl->lo[0] = gl->lo[1] = INFINITY;
      gl->hi[0] = gl->hi[1] = -INFINITY;
      /* The control points' hull holds each curve. */
      for (size_t i = first; i < tb.n; i++) {
        const double *pts[3] = {tb.segments[i].p0, tb.segments[i].p1,
                                tb.segments[i].p2};
        for (int k = 0; k < 3; k++)
          for (int a = 0; a < 2; a++) {
            gl->lo[a] = fmin(gl->lo[a], pts[k][a]);
            gl->hi[a] = fmax(gl->hi[a], pts[k][a]);
          }
      }
    }
    tb.x += zr__ttf_advance(font, g) * tb.scale + offset.x;
    tb.y += offset.y;
    previous = g;
  }
  /* "The text will start with the origin at the lower left, front of
     the first character": the first glyph's left edge goes to x = 0.
     A blank first character has its origin there, so leading spaces
     keep their width: POV-Ray 3.7 puts the A of " A" 0.26 further
     right than that of "A" in timrom.ttf (trace() along z). */
  if (!err && n_glyphs > 0 && !lead_blank) {
    double dx = glyphs[0].lo[0];
    for (size_t i = 0; i < tb.n; i++) {
      tb.segments[i].p0[0] -= dx;
      tb.segments[i].p1[0] -= dx;
      tb.segments[i].p2[0] -= dx;
    }
    for (size_t i = 0; i < n_glyphs; i++) {
      glyphs[i].lo[0] -= dx;
      glyphs[i].hi[0] -= dx;
    }
  }
  if (!err) {
    tx->segments = zr__sdl_alloc(p, (tb.n ? tb.n : 1) * sizeof *tb.segments);
    tx->glyphs = zr__sdl_alloc(p, (n_glyphs ? n_glyphs : 1) * sizeof *glyphs);
    if (!tx->segments || !tx->glyphs) {
      err = "out of memory";
    } else {
      if (tb.n)
        memcpy(tx->segments, tb.segments, tb.n * sizeof *tb.segments);
      if (n_glyphs)
        memcpy(tx->glyphs, glyphs, n_glyphs * sizeof *glyphs);
      tx->n_segments = tb.n;
      tx->n_glyphs = n_glyphs;
    }
  }
  free(tb.segments);
  free(glyphs);
  return err;
}

zr_object *zr__sdl_text(zr_sdl_parser *p, const zr_sdl_loc *loc,
                        const char *font_name, double internal_font,
                        const zr_sdl_loc *font_loc, const char *string,
                        const zr_sdl_expr *thickness,
                        const zr_sdl_loc *thickness_loc,
                        const zr_sdl_expr *offset,
                        const zr_sdl_loc *offset_loc) {
  double depth;
  zr_vec3 shift;
  if (!zr__sdl_want_float(p, thickness, thickness_loc, &depth) ||
      !zr__sdl_want_vector(p, offset, offset_loc, &shift))
    return NULL;
  if (shift.z != 0.0) {
    zr__sdl_error(p, ZR_ESCENE, offset_loc, "a text offset with a z "
                  "component is not supported yet");
    return NULL;
  }
  if (!font_name) {
    /* "An out of range Font_Number value will default to 0." */
    int k = internal_font >= 0 && internal_font < 4 ? (int)internal_font : 0;
    font_name = internal_fonts[k];
  }
  char *bytes = NULL;
  size_t size = 0;
  /* Like POV-Ray, which says "Cannot find file ..., even after trying
     to append file type extension": "cyrvetic" finds cyrvetic.ttf. */
  const char *with_ext = zr__sdl_concat(p, font_name, ".ttf");
  if (!with_ext)
    return NULL;
  zr_status fs = read_font(p, font_name, font_loc, &bytes, &size);
  if (fs == ZR_ENOTFOUND)
    fs = read_font(p, with_ext, font_loc, &bytes, &size);
  if (fs == ZR_ENOTFOUND)
    zr__sdl_error(p, ZR_ENOTFOUND, font_loc, "cannot find font '%s'",
                  font_name);
  if (fs != ZR_OK)
    return NULL;
  zr_ttf font;
  const char *err = zr__ttf_open(&font, (const uint8_t *)bytes, size);
  zr_object *o = NULL;
  struct zr_text *tx = NULL;
  if (!err) {
    o = zr__sdl_object_new(p, ZR_OBJ_TEXT, loc);
    tx = o ? zr__sdl_alloc(p, sizeof *tx) : NULL;
    err = tx ? layout(p, &font, string, shift, tx) : "out of memory";
  }
  free(bytes);
  if (err) {
    zr__sdl_error(p, ZR_ESCENE, font_loc, "cannot use font '%s': %s",
                  font_name, err);
    return NULL;
  }
  /* A thickness of zero still makes two caps; a negative one extrudes
     towards -z, which is the same solid moved. */
  tx->thickness = fabs(depth);
  tx->lo = zr_v3(INFINITY, INFINITY, 0.0);
  tx->hi = zr_v3(-INFINITY, -INFINITY, tx->thickness);
  for (size_t i = 0; i < tx->n_glyphs; i++) {
    tx->lo = zr_v3_min(tx->lo, zr_v3(tx->glyphs[i].lo[0],
                                     tx->glyphs[i].lo[1], 0.0));
    tx->hi = zr_v3_max(tx->hi, zr_v3(tx->glyphs[i].hi[0],
                                     tx->glyphs[i].hi[1], tx->thickness));
  }
  o->u.text.data = tx;
  return o;
}
