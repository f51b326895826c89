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
 * The samples are kept as read (8 or 16-bit codes, floats for a
 * function) with a block hierarchy over them; the tracer makes the
 * triangles from them where a ray needs them, so POV-Ray's hierarchy
 * switch changes nothing and is only read.
 */
#include "sdl/build_iso.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "image/image.h"
#include "pov-parse.h"
#include "trace/obj_isosurface.h"

/* The grid's largest side and size: a height field bigger than this is
   surely a mistake in the resolution. */
#define MAX_SIDE 65536
#define MAX_SAMPLES ((size_t)1 << 26)

/* A height field object over w x h samples (image order, of bits 8,
   16 or 32 = float), with the block hierarchy the tracer walks. */
static zr_object *hf_new(zr_sdl_parser *p, const zr_sdl_loc *loc,
                         const void *samples, int bits, int w, int h) {
  zr_object *o = zr__sdl_object_new(p, ZR_OBJ_HEIGHT_FIELD, loc);
  if (!o)
    return NULL;
  o->u.height_field.w = w;
  o->u.height_field.h = h;
  zr_arena *arena = &p->scene->arena;
  arena->over_budget = 0;
  zr_status s = zr__height_field_grid(arena, samples, bits, w, h,
                                      &o->u.height_field.grid);
  if (s != ZR_OK) {
    if (arena->over_budget) {
      char text[400];
      zr__sdl_error(p, ZR_ELIMIT, loc, "%s",
                    zr__context_budget_text(p->ctx, (size_t)w * (size_t)h / 32, "the height_field",
                                            text, sizeof text));
    } else {
      zr__sdl_error(p, s, loc, "cannot build the height_field: %s",
                    zr_status_str(s));
    }
    return NULL;
  }
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
  zr_height_codes codes;
  s = zr__image_decode_height_codes(p->ctx, path, pot, bytes, size,
                                    &p->scene->arena, &codes);
  free(bytes);
  free(path);
  if (s != ZR_OK) {
    zr__sdl_error(p, s, name_loc, "cannot use '%s' as a height_field",
                  name);
    return NULL;
  }
  if (codes.width < 2 || codes.height < 2) {
    zr__sdl_error(p, ZR_ESCENE, name_loc,
                  "a height_field's image needs at least 2 x 2 pixels");
    return NULL;
  }
  /* Image row j lies at z = 1 - j / (h - 1): the samples are kept in
     the file's order. */
  return hf_new(p, loc, codes.codes, codes.bits, codes.width, codes.height);
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
  /* The function's sample (i, j) is image pixel (i, j), row j, kept as
     a 16-bit code, the value times 65535 rounded down, as POV-Ray 3.7
     keeps it: its height_field of function 5, 5 { 100.3/65535 } and of
     { 100.7/65535 } both stand at 100/65535 (trace() through #debug),
     and the smooth normals (obj_height_field.c) are made from the codes. */
  uint16_t *g = zr__sdl_alloc(p, (size_t)w * (size_t)h * sizeof *g);
  if (!g)
    return NULL;
  for (int j = 0; j < h; j++)
    for (int i = 0; i < w; i++) {
      double args[3] = {(double)i / (w - 1), (double)j / (h - 1), 0.0};
      double v = zr__fn_eval(fn, args);
      v = isfinite(v) ? fmin(fmax(v, 0.0), 1.0) : 0.0;
      g[(size_t)j * w + i] = (uint16_t)floor(v * 65535.0);
    }
  return hf_new(p, loc, g, 16, w, h);
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

bool zr__sdl_height_field_done(zr_sdl_parser *p, zr_object *o,
                               const zr_sdl_loc *loc) {
  /* Everything was made with the samples: the tracer derives the
     triangles from them (lib/trace/obj_height_field.c). */
  (void)p;
  (void)loc;
  return o->u.height_field.grid != NULL;
}
