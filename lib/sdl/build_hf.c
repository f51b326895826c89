/*
 * build_hf.c - the grammar's actions for the height field (POV-Ray 3.7
 * reference, "Height Field"); the tracer's side is
 * lib/trace/obj_height_field.c.
 *
 * The heights come from an image file (PNG, GIF, POT, TGA, PGM, PPM
 * or JPEG), read as numbers rather than
 * colours (lib/image/heights.c), or from a function sampled on a grid
 * of the resolution given.  The unscaled field spans 0 to 1 along x, y
 * and z.  Image column i lies at x = i / (W - 1) and image row j at
 * z = 1 - j / (H - 1), top row at the back; a function's sample at
 * x = i / (W - 1), y = j / (H - 1) is its image's pixel (i, j), clamped
 * to [0, 1].  Both were measured on POV-Ray 3.7's renderings.
 *
 * When the last item has been read the grid becomes a mesh: two
 * triangles per square of four samples, those wholly under the
 * water_level left out, with smooth normals from the grid's central
 * differences when smooth is given.  The mesh carries its own BVH, so
 * POV-Ray's hierarchy switch changes nothing and is only read.
 */
#include "sdl/build_iso.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "image/image.h"
#include "pov-parse.h"
#include "trace/obj_mesh.h"

/* The grid's largest side and size: a height field bigger than this is
   surely a mistake in the resolution. */
#define MAX_SIDE 65536
#define MAX_SAMPLES ((size_t)1 << 26)

/* A height field object holding a w x h grid (heights filled later). */
static zr_object *hf_new(zr_sdl_parser *p, const zr_sdl_loc *loc, int w,
                         int h, float **heights) {
  zr_object *o = zr__sdl_object_new(p, ZR_OBJ_HEIGHT_FIELD, loc);
  float *g = o ? zr__sdl_alloc(p, (size_t)w * (size_t)h * sizeof *g) : NULL;
  if (!g)
    return NULL;
  o->u.height_field.w = w;
  o->u.height_field.h = h;
  o->u.height_field.heights = g;
  *heights = g;
  return o;
}

/* The file's type from its name's extension, for a height_field without
   a type keyword; NULL when it is one zRcube reads. */
static const char *unreadable_type(const char *name) {
  static const char *const others[] = {"iff", "sys", "exr", "hdr"};
  const char *dot = strrchr(name, '.');
  if (!dot)
    return NULL;
  for (size_t i = 0; i < sizeof others / sizeof *others; i++)
    if (strcasecmp(dot + 1, others[i]) == 0)
      return others[i];
  return NULL;
}

zr_object *zr__sdl_height_field_image(zr_sdl_parser *p,
                                      const zr_sdl_loc *loc,
                                      const char *name,
                                      const zr_sdl_loc *name_loc, bool pot) {
  const char *type = pot ? NULL : unreadable_type(name);
  if (type) {
    zr__sdl_error(p, ZR_EUNSUPPORTED, name_loc,
                  "height_field: '%s' files are not supported yet (use "
                  "png, gif, pot, tga, bmp, tiff, pgm, ppm or jpeg)", type);
    return NULL;
  }
  char *path = NULL, *bytes = NULL;
  size_t size = 0;
  zr_status s = zr__sdl_read_image(p, name, name_loc, "height_field file",
                                   &path, &bytes, &size);
  if (s == ZR_ENOTFOUND)
    zr__sdl_error(p, ZR_ENOTFOUND, name_loc,
                  "height_field file '%s' not found", name);
  if (s != ZR_OK)
    return NULL;
  float *samples = NULL;
  int w = 0, h = 0;
  s = zr__image_decode_heights(p->ctx, path, pot, bytes, size, &samples, &w,
                               &h);
  free(bytes);
  free(path);
  if (s != ZR_OK) {
    zr__sdl_error(p, s, name_loc, "cannot use '%s' as a height_field",
                  name);
    return NULL;
  }
  if (w < 2 || h < 2) {
    free(samples);
    zr__sdl_error(p, ZR_ESCENE, name_loc,
                  "a height_field's image needs at least 2 x 2 pixels");
    return NULL;
  }
  float *g;
  zr_object *o = hf_new(p, loc, w, h, &g);
  if (o)
    for (int j = 0; j < h; j++) /* image row j at z = 1 - j / (h - 1) */
      memcpy(g + (size_t)(h - 1 - j) * w, samples + (size_t)j * w,
             (size_t)w * sizeof *g);
  free(samples);
  return o;
}

const zr_fn *zr__sdl_height_field_fn_body(zr_sdl_parser *p,
                                          const zr_sdl_loc *brace) {
  /* The grammar has shifted the body's '{' and read nothing after it:
     step back onto it, so the compiler reads "{ ... }" whole. */
  zr_sdl_frame *fr = zr__sdl_top(p);
  const zr_sdl_file *f = &p->files[fr->file];
  if (fr->pos == 0 || fr->file != brace->file ||
      f->tokens[fr->pos - 1].kind != '{' ||
      f->tokens[fr->pos - 1].line != brace->line ||
      f->tokens[fr->pos - 1].column != brace->column) {
    zr__sdl_error(p, ZR_ESYNTAX, brace, "internal error: the parser "
                  "looked past the height_field function's '{'");
    return NULL;
  }
  fr->pos--;
  const zr_fn *fn = zr__sdl_function_parse(p, brace);
  /* The engine counted the '{' it handed out; the '}' it never saw. */
  if (fn && p->autoend.token && p->autoend.depth > 0)
    p->autoend.depth--;
  return fn;
}

zr_object *zr__sdl_height_field_function(zr_sdl_parser *p,
                                         const zr_sdl_loc *loc,
                                         const zr_sdl_expr size[2],
                                         const zr_sdl_loc size_loc[2],
                                         const zr_fn *fn,
                                         const zr_sdl_loc *fn_loc) {
  double n[2];
  for (int k = 0; k < 2; k++) {
    if (!zr__sdl_want_float(p, &size[k], &size_loc[k], &n[k]))
      return NULL;
    if (!(n[k] >= 2.0 && n[k] <= MAX_SIDE)) {
      zr__sdl_error(p, ZR_ESCENE, &size_loc[k],
                    "a height_field's resolution must be 2 to %d",
                    MAX_SIDE);
      return NULL;
    }
  }
  int w = (int)n[0], h = (int)n[1];
  if ((size_t)w * (size_t)h > MAX_SAMPLES) {
    zr__sdl_error(p, ZR_ELIMIT, &size_loc[0],
                  "a height_field of %d x %d samples is too large", w, h);
    return NULL;
  }
  const char *missing = zr__fn_unsupported(fn);
  if (missing) {
    zr__sdl_error(p, ZR_EUNSUPPORTED, fn_loc,
                  "the height_field's function uses %s, which is not "
                  "supported yet", missing);
    return NULL;
  }
  if (zr__fn_params(fn) > 3) {
    zr__sdl_error(p, ZR_ESCENE, fn_loc,
                  "a height_field's function takes x, y and z, not %d "
                  "parameters", zr__fn_params(fn));
    return NULL;
  }
  float *g;
  zr_object *o = hf_new(p, loc, w, h, &g);
  if (!o)
    return NULL;
  for (int j = 0; j < h; j++)
    for (int i = 0; i < w; i++) {
      double args[3] = {(double)i / (w - 1), (double)j / (h - 1), 0.0};
      double v = zr__fn_eval(fn, args);
      v = isfinite(v) ? fmin(fmax(v, 0.0), 1.0) : 0.0;
      g[(size_t)(h - 1 - j) * w + i] = (float)v;
    }
  return o;
}

bool zr__sdl_height_field_item(zr_sdl_parser *p, zr_object *o, int token,
                               const zr_sdl_expr *e, const zr_sdl_loc *at) {
  if (token == T_SMOOTH) {
    o->u.height_field.smooth = true;
    return true;
  }
  double v; /* T_WATER_LEVEL */
  if (!zr__sdl_want_float(p, e, at, &v))
    return false;
  o->u.height_field.water_level = v;
  return true;
}

/* The height at grid point (i, j), clamped to the grid. */
static double sample(const zr_object *o, int i, int j) {
  int w = o->u.height_field.w, h = o->u.height_field.h;
  i = i < 0 ? 0 : i >= w ? w - 1 : i;
  j = j < 0 ? 0 : j >= h ? h - 1 : j;
  return o->u.height_field.heights[(size_t)j * w + i];
}

static bool add_face(struct zr_mesh *m, uint32_t a, uint32_t b,
                     uint32_t c) {
  size_t f = m->n_faces++;
  m->faces[f][0] = a;
  m->faces[f][1] = b;
  m->faces[f][2] = c;
  if (m->face_normals) {
    m->face_normals[f][0] = a;
    m->face_normals[f][1] = b;
    m->face_normals[f][2] = c;
  }
  return true;
}

bool zr__sdl_height_field_done(zr_sdl_parser *p, zr_object *o,
                               const zr_sdl_loc *loc) {
  int w = o->u.height_field.w, h = o->u.height_field.h;
  bool smooth = o->u.height_field.smooth;
  double water = o->u.height_field.water_level;
  size_t nv = (size_t)w * (size_t)h;
  size_t nf = 2 * (size_t)(w - 1) * (size_t)(h - 1);
  struct zr_mesh *m = zr__sdl_alloc(p, sizeof *m);
  if (!m)
    return false;
  memset(m, 0, sizeof *m);
  m->vertices = zr__sdl_alloc(p, nv * sizeof *m->vertices);
  m->faces = zr__sdl_alloc(p, nf * sizeof *m->faces);
  if (smooth) {
    m->normals = zr__sdl_alloc(p, nv * sizeof *m->normals);
    m->face_normals = zr__sdl_alloc(p, nf * sizeof *m->face_normals);
  }
  if (!m->vertices || !m->faces ||
      (smooth && (!m->normals || !m->face_normals)))
    return false;
  double dx = 1.0 / (w - 1), dz = 1.0 / (h - 1);
  for (int j = 0; j < h; j++)
    for (int i = 0; i < w; i++) {
      size_t k = (size_t)j * w + i;
      m->vertices[k] = zr_v3(i * dx, sample(o, i, j), j * dz);
      if (smooth) {
        /* Central differences, one-sided at the edges. */
        int i0 = i > 0 ? i - 1 : i, i1 = i < w - 1 ? i + 1 : i;
        int j0 = j > 0 ? j - 1 : j, j1 = j < h - 1 ? j + 1 : j;
        double sx = (sample(o, i1, j) - sample(o, i0, j)) / ((i1 - i0) * dx);
        double sz = (sample(o, i, j1) - sample(o, i, j0)) / ((j1 - j0) * dz);
        m->normals[k] = zr_v3(-sx, 1.0, -sz);
      }
    }
  m->n_vertices = m->cap_vertices = nv;
  m->n_normals = m->cap_normals = smooth ? nv : 0;
  m->cap_faces = nf;
  /* Each square's diagonal runs from (i + 1, j) to (i, j + 1)
     (zr__height_field_height() interpolates the same way); both
     triangles are wound so that their normals point up. */
  for (int j = 0; j + 1 < h; j++)
    for (int i = 0; i + 1 < w; i++) {
      uint32_t a = (uint32_t)((size_t)j * w + i), b = a + 1;
      uint32_t c = a + (uint32_t)w, d = c + 1;
      double ya = m->vertices[a].y, yb = m->vertices[b].y;
      double yc = m->vertices[c].y, yd = m->vertices[d].y;
      if (!(ya < water && yb < water && yc < water))
        add_face(m, a, c, b);
      if (!(yb < water && yc < water && yd < water))
        add_face(m, b, c, d);
    }
  size_t bad = 0;
  zr_status s = zr__mesh_build(m, &p->scene->arena, &bad);
  if (s != ZR_OK) {
    zr__sdl_error(p, s, loc, "cannot build the height_field: %s",
                  zr_status_str(s));
    return false;
  }
  o->u.height_field.data = m;
  return true;
}
