/*
 * build_media.c - participating media, interior_texture and photons
 * blocks as the grammar reads them (reference manual, "Media",
 * "Interior", "Atmospheric Media", "Interior Texture", "Photons").
 *
 * A media block starts from POV-Ray 3.7's defaults (the manual's table
 * in "Media", 3.4.8, and its note that 3.5 made method 3 with one
 * interval the default: method 3, one interval, aa_level 3,
 * aa_threshold 0.1, confidence 0.9, variance 1/128, ratio 0.9, jitter
 * 0; but samples 10, 10 where the table says 1, 1, because povray
 * renders a medium without "samples" exactly as with "samples 10, 10"
 * and not as with "samples 1, 1": bench/provenance/probe.py
 * media_defaults) or from a copy of a media
 * identifier, which must come first.  Every item but density and the
 * transformations overrides what was set before.  Densities are
 * pigments (a pattern with a colour_map, density_map or a block
 * pattern's list of densities, or a plain colour); a transformation
 * moves only the densities written before it, as the manual says.  An
 * interior's media list and the densities are copied before they change,
 * so that identifiers and objects never share a list that grows.
 *
 * An object's interior moves with the object: when its media have
 * densities, the object gets a copy of the interior whose densities
 * carry the object's transformations (lib/sdl/build.c calls
 * zr__sdl_interior_transform for every transform of an object).
 *
 * zRcube does not simulate photon mapping.  POV-Ray ignores objects'
 * and lights' photons { } blocks unless global_settings holds a photons
 * block, so those are read and dropped silently; the global block
 * itself draws one warning that caustics are not simulated.
 */
#include "config.h"

#include <stdlib.h>
#include <string.h>

#include "core/context.h"
#include "pov-parse.h"
#include "scene/df3.h"
#include "scene/texture.h"
#include "sdl/build_media.h"

zr_medium *zr__sdl_media_new(zr_sdl_parser *p, const zr_medium *from,
                             const zr_sdl_loc *loc) {
  zr_medium *m = zr__sdl_alloc(p, sizeof *m);
  if (!m)
    return NULL;
  if (from) {
    *m = *from;
  } else {
    memset(m, 0, sizeof *m);
    /* #version 3.5 and later: method 3, one interval, samples 10, 10;
       before, method 1 with 10 intervals of one sample.  Both measured:
       povray renders a medium without these items byte for byte as
       with them, under #version 3.7 and 3.1 (bench/provenance/probe.py
       media_defaults). */
    bool old = p->version < 3.5;
    m->method = old ? 1 : 3;
    m->intervals = old ? 10 : 1;
    m->min_samples = m->max_samples = old ? 1 : 10;
    m->confidence = 0.9;
    m->variance = 1.0 / 128.0;
    m->ratio = 0.9;
    m->aa_level = 3;
    m->aa_threshold = 0.1;
    m->scattering_type = ZR_SCATTER_ISOTROPIC;
    m->extinction = 1.0;
  }
  m->where.file = p->files[loc->file].scene_path;
  m->where.line = loc->line;
  m->where.column = loc->column;
  return m;
}

/* A whole number from lo to hi, or an error naming the item. */
static bool want_int(zr_sdl_parser *p, const zr_sdl_expr *e,
                     const zr_sdl_loc *loc, const char *what, int lo, int hi,
                     int *out) {
  double v;
  if (!zr__sdl_want_float(p, e, loc, &v))
    return false;
  if (!(v >= lo && v <= hi)) {
    if (hi == 1000000)
      zr__sdl_error(p, ZR_ESCENE, loc, "%s must be at least %d, not %g",
                    what, lo, v);
    else
      zr__sdl_error(p, ZR_ESCENE, loc, "%s must be from %d to %d, not %g",
                    what, lo, hi, v);
    return false;
  }
  *out = (int)v;
  return true;
}

bool zr__sdl_media_item(zr_sdl_parser *p, zr_medium *m, int token,
                        const zr_sdl_expr *e, const zr_sdl_loc *loc) {
  switch (token) {
  case T_METHOD:
    return want_int(p, e, loc, "media method", 1, 3, &m->method);
  case T_INTERVALS:
    return want_int(p, e, loc, "media intervals", 1, 1000000,
                    &m->intervals);
  case T_SAMPLES:
    if (!want_int(p, e, loc, "media samples", 1, 1000000, &m->min_samples))
      return false;
    m->max_samples = m->min_samples;
    return true;
  case T_AA_LEVEL:
    return want_int(p, e, loc, "aa_level", 1, 1000000, &m->aa_level);
  case T_ABSORPTION:
    return zr__sdl_want_rgb(p, e, loc, &m->absorption);
  case T_EMISSION:
    return zr__sdl_want_rgb(p, e, loc, &m->emission);
  case T_CONFIDENCE:
    if (!zr__sdl_want_float(p, e, loc, &m->confidence))
      return false;
    if (!(m->confidence >= 0.0 && m->confidence < 1.0)) {
      zr__sdl_error(p, ZR_ESCENE, loc, "media confidence must be at least "
                                       "0 and below 1, not %g",
                    m->confidence);
      return false;
    }
    return true;
  case T_VARIANCE:
    return zr__sdl_want_float(p, e, loc, &m->variance);
  case T_RATIO:
    return zr__sdl_want_float(p, e, loc, &m->ratio);
  case T_JITTER:
    return zr__sdl_want_float(p, e, loc, &m->jitter);
  default: /* T_AA_THRESHOLD */
    if (!zr__sdl_want_float(p, e, loc, &m->aa_threshold))
      return false;
    if (!(m->aa_threshold > 0.0)) {
      zr__sdl_error(p, ZR_ESCENE, loc, "aa_threshold must be above 0, "
                                       "not %g", m->aa_threshold);
      return false;
    }
    return true;
  }
}

bool zr__sdl_media_samples(zr_sdl_parser *p, zr_medium *m,
                           const zr_sdl_expr *lo, const zr_sdl_loc *lo_loc,
                           const zr_sdl_expr *hi, const zr_sdl_loc *hi_loc) {
  if (!want_int(p, lo, lo_loc, "media samples", 1, 1000000,
                &m->min_samples) ||
      !want_int(p, hi, hi_loc, "media samples", 1, 1000000,
                &m->max_samples))
    return false;
  if (m->max_samples < m->min_samples) {
    zr__sdl_error(p, ZR_ESCENE, hi_loc, "the most media samples (%d) must "
                  "not be fewer than the least (%d)", m->max_samples,
                  m->min_samples);
    return false;
  }
  return true;
}

bool zr__sdl_media_scattering(zr_sdl_parser *p, zr_medium *m,
                              const zr_sdl_expr *type,
                              const zr_sdl_loc *type_loc,
                              const zr_sdl_expr *colour,
                              const zr_sdl_loc *colour_loc) {
  double t;
  if (!zr__sdl_want_float(p, type, type_loc, &t))
    return false;
  /* povray warns about an unknown type and scatters isotropically. */
  if (t >= 1 && t < 6) {
    m->scattering_type = (zr_scattering_kind)(int)t;
  } else {
    zr__sdl_warning(p, type_loc, "unknown scattering type %g: isotropic "
                                 "scattering (1) is used", t);
    m->scattering_type = ZR_SCATTER_ISOTROPIC;
  }
  return zr__sdl_want_rgb(p, colour, colour_loc, &m->scattering);
}

bool zr__sdl_media_eccentricity(zr_sdl_parser *p, zr_medium *m,
                                const zr_sdl_expr *e,
                                const zr_sdl_loc *loc) {
  if (m->scattering_type != ZR_SCATTER_HENYEY_GREENSTEIN) {
    zr__sdl_error(p, ZR_ESCENE, loc, "eccentricity is only for scattering "
                                     "type 5 (Henyey-Greenstein)");
    return false;
  }
  return zr__sdl_want_float(p, e, loc, &m->eccentricity);
}

bool zr__sdl_media_density(zr_sdl_parser *p, zr_medium *m,
                           const zr_pigment *density) {
  const zr_pigment **list =
      zr__sdl_alloc(p, (m->n_density + 1) * sizeof *list);
  if (!list)
    return false;
  if (m->n_density)
    memcpy(list, m->density, m->n_density * sizeof *list);
  list[m->n_density] = density;
  m->density = list;
  m->n_density++;
  return true;
}

bool zr__sdl_media_transform(zr_sdl_parser *p, zr_medium *m,
                             const zr_transform *t) {
  if (m->n_density == 0)
    return true; /* the manual: no densities, no effect */
  const zr_pigment **list = zr__sdl_alloc(p, m->n_density * sizeof *list);
  if (!list)
    return false;
  for (size_t i = 0; i < m->n_density; i++) {
    zr_pigment *d = zr__sdl_pigment_new(p, m->density[i]);
    if (!d || !zr__sdl_pigment_transform(p, d, t))
      return false;
    list[i] = d;
  }
  m->density = list;
  return true;
}

/* list with m appended, as a new array. */
static const zr_medium *const *append(zr_sdl_parser *p,
                                      const zr_medium *const *list,
                                      size_t n, const zr_medium *m) {
  const zr_medium **out = zr__sdl_alloc(p, (n + 1) * sizeof *out);
  if (!out)
    return NULL;
  if (n)
    memcpy(out, list, n * sizeof *out);
  out[n] = m;
  return out;
}

bool zr__sdl_interior_media(zr_sdl_parser *p, zr_interior *in,
                            const zr_medium *m) {
  const zr_medium *const *list = append(p, in->media, in->n_media, m);
  if (!list)
    return false;
  in->media = list;
  in->n_media++;
  return true;
}

bool zr__sdl_atmosphere_media(zr_sdl_parser *p, const zr_medium *m) {
  zr_settings *s = &p->scene->settings;
  const zr_medium *const *list = append(p, s->media, s->n_media, m);
  if (!list)
    return false;
  s->media = list;
  s->n_media++;
  return true;
}

const zr_interior *zr__sdl_interior_transform(zr_sdl_parser *p,
                                              const zr_interior *in,
                                              const zr_transform *t) {
  bool placed = false;
  for (size_t i = 0; in && i < in->n_media; i++)
    placed = placed || in->media[i]->n_density > 0;
  if (!placed)
    return in;
  zr_interior *copy = zr__sdl_interior_new(p, in);
  const zr_medium **list =
      copy ? zr__sdl_alloc(p, in->n_media * sizeof *list) : NULL;
  if (!list)
    return NULL;
  for (size_t i = 0; i < in->n_media; i++) {
    zr_medium *m = zr__sdl_alloc(p, sizeof *m);
    if (!m)
      return NULL;
    *m = *in->media[i];
    if (!zr__sdl_media_transform(p, m, t))
      return NULL;
    list[i] = m;
  }
  copy->media = list;
  return copy;
}

void zr__sdl_interior_texture(zr_object *o, const zr_texture *tx) {
  o->interior_texture = tx;
  if (zr__is_csg(o->kind))
    for (size_t i = 0; i < o->u.csg.n_children; i++)
      if (!o->u.csg.children[i]->interior_texture)
        zr__sdl_interior_texture(o->u.csg.children[i], tx);
}

/* The df3 file name (searched like an image_map's), decoded; NULL after
   an error. */
static const zr_density_file *load_df3(zr_sdl_parser *p, const char *name,
                                       const zr_sdl_loc *loc) {
  char *path = NULL, *bytes = NULL;
  size_t size = 0;
  zr_status s = zr__sdl_read_image(p, name, loc, "density_file", &path,
                                   &bytes, &size);
  if (s == ZR_ENOTFOUND)
    zr__sdl_error(p, ZR_ENOTFOUND, loc, "density_file '%s' not found",
                  name);
  if (s != ZR_OK)
    return NULL;
  free(path);
  zr_density_file *d = zr__sdl_alloc(p, sizeof *d);
  if (s == ZR_OK && d) {
    memset(d, 0, sizeof *d);
    s = zr__df3_decode((const unsigned char *)bytes, size,
                       &p->scene->arena, d);
  }
  free(bytes);
  if (s != ZR_OK || !d) {
    zr__sdl_error(p, s == ZR_OK ? ZR_ENOMEM : s, loc,
                  "cannot use '%s' as a df3 density_file", name);
    return NULL;
  }
  return d;
}

bool zr__sdl_density_file(zr_sdl_parser *p, zr_pigment *pg,
                          const char *name, const zr_sdl_loc *loc) {
  const zr_density_file *d = load_df3(p, name, loc);
  if (!d)
    return false;
  zr__pigment_set_pattern(pg, ZR_PAT_DENSITY_FILE);
  pg->pattern.density_file = d;
  return true;
}

bool zr__sdl_normal_density_file(zr_sdl_parser *p, zr_normal *nm,
                                 const char *name, const zr_sdl_expr *amount,
                                 const zr_sdl_loc *loc) {
  const zr_density_file *d = load_df3(p, name, loc);
  if (!d || !zr__sdl_normal_pattern(p, nm, ZR_PAT_DENSITY_FILE, amount,
                                    loc))
    return false;
  nm->pattern.density_file = d;
  return true;
}

bool zr__sdl_density_interpolate(zr_sdl_parser *p, zr_pattern *pt,
                                 const zr_sdl_expr *e,
                                 const zr_sdl_loc *loc) {
  double v;
  if (!zr__sdl_want_float(p, e, loc, &v))
    return false;
  const zr_density_file *d = pt->density_file;
  if (pt->kind != ZR_PAT_DENSITY_FILE || !d) {
    zr__sdl_error(p, ZR_ESYNTAX, loc, "'interpolate' here belongs to a "
                                      "density_file, which must come "
                                      "first");
    return false;
  }
  if (v == 2)
    zr__sdl_warning(p, loc, "tricubic interpolation (2) of a density_file "
                            "is not supported: trilinear (1) is used");
  zr_density_file *copy = zr__sdl_alloc(p, sizeof *copy);
  if (!copy)
    return false;
  *copy = *d;
  copy->interpolate = v != 0 ? 1 : 0;
  pt->density_file = copy;
  return true;
}

void zr__sdl_photons_global(zr_sdl_parser *p, const zr_sdl_loc *loc) {
  zr__sdl_warning(p, loc, "'photons' is not simulated: zRcube renders "
                          "without photon mapping, so there are no "
                          "caustics");
}
