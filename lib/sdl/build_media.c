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
 * photons { } blocks are read here into the scene's settings, the
 * lights and the objects (zr_photon_object); lib/trace/photons.c shoots
 * and gathers the photons.  POV-Ray ignores objects' and lights' blocks
 * unless global_settings holds one, and so does the tracer.
 */
#include "config.h"

#include <math.h>
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

/* ---- photons { } blocks ("Photons") ---- */

zr_sdl_photons *zr__sdl_photons_new(zr_sdl_parser *p) {
  zr_sdl_photons *ph = zr__sdl_alloc(p, sizeof *ph);
  if (!ph)
    return NULL;
  memset(ph, 0, sizeof *ph);
  zr_settings defaults;
  zr__settings_init(&defaults);
  ph->global = defaults.photons;
  return ph;
}

static const char *photon_kw_name(int kw) {
  switch (kw) {
  case T_TARGET: return "target";
  case T_REFRACTION: return "refraction";
  case T_REFLECTION: return "reflection";
  case T_COLLECT: return "collect";
  case T_PASS_THROUGH: return "pass_through";
  case T_AREA_LIGHT: return "area_light";
  case T_SPACING: return "spacing";
  case T_COUNT: return "count";
  case T_GATHER: return "gather";
  case T_MEDIA: return "media";
  case T_JITTER: return "jitter";
  case T_RADIUS: return "radius";
  case T_MAX_TRACE_LEVEL: return "max_trace_level";
  case T_ADC_BAILOUT: return "adc_bailout";
  case T_AUTOSTOP: return "autostop";
  case T_EXPAND_THRESHOLDS: return "expand_thresholds";
  default: return "photons item";
  }
}

/* The item's numbers: at least min and at most max of them. */
static bool photon_count(zr_sdl_parser *p, int kw,
                         const zr_sdl_photon_args *a, int min, int max,
                         const zr_sdl_loc *loc) {
  int n = a ? a->n + (a->skip_first ? 1 : 0) : 0;
  if (n >= min && n <= max && !(a && a->skip_first && kw != T_RADIUS))
    return true;
  zr__sdl_error(p, ZR_ESYNTAX, loc,
                "'%s' in photons { } takes %s%d number%s", photon_kw_name(kw),
                min == max ? "" : "up to ", max, max == 1 ? "" : "s");
  return false;
}

static bool photon_positive(zr_sdl_parser *p, int kw, double v,
                            bool zero_ok, const zr_sdl_loc *loc) {
  if (isfinite(v) && (v > 0.0 || (zero_ok && v == 0.0)))
    return true;
  zr__sdl_error(p, ZR_EINVAL, loc, "'%s' in photons { } must be %s, not %g",
                photon_kw_name(kw), zero_ok ? "0 or more" : "above 0", v);
  return false;
}

bool zr__sdl_photons_item(zr_sdl_parser *p, zr_sdl_photons *ph, int kw,
                          const zr_sdl_photon_args *a,
                          const zr_sdl_loc *loc) {
  const double *v = a ? a->v : NULL;
  bool on = !a || fabs(v[0]) >= 1e-10; /* a flag alone means on */
  zr_photon_settings *g = &ph->global;
  bool object_item = false, global_item = true;
  switch (kw) {
  case T_TARGET:
    if (!photon_count(p, kw, a, 0, 1, loc))
      return false;
    ph->has_target = true;
    ph->obj.target = true;
    ph->obj.spacing = a ? v[0] : 1.0;
    if (a && !photon_positive(p, kw, v[0], false, loc))
      return false;
    object_item = true, global_item = false;
    break;
  case T_REFRACTION:
  case T_REFLECTION:
    if (!photon_count(p, kw, a, 1, 1, loc))
      return false;
    if (kw == T_REFRACTION)
      ph->has_refraction = true, ph->refraction = on;
    else
      ph->has_reflection = true, ph->reflection = on;
    global_item = false; /* objects and lights */
    break;
  case T_COLLECT:
    if (!photon_count(p, kw, a, 1, 1, loc))
      return false;
    ph->has_collect = true, ph->collect = on;
    object_item = true, global_item = false;
    break;
  case T_PASS_THROUGH:
    if (!photon_count(p, kw, a, 0, 1, loc))
      return false;
    ph->has_pass_through = true, ph->pass_through = on;
    object_item = true, global_item = false;
    break;
  case T_AREA_LIGHT:
    if (!photon_count(p, kw, a, 0, 1, loc))
      return false;
    ph->has_area_light = true, ph->area_light = on;
    global_item = false;
    break;
  case T_SPACING:
    if (!photon_count(p, kw, a, 1, 1, loc) ||
        !photon_positive(p, kw, v[0], false, loc))
      return false;
    g->spacing = v[0], ph->has_spacing = true;
    break;
  case T_COUNT:
    if (!photon_count(p, kw, a, 1, 1, loc) ||
        !photon_positive(p, kw, v[0], false, loc))
      return false;
    g->count = v[0], ph->has_count = true;
    break;
  case T_GATHER:
    if (!photon_count(p, kw, a, 2, 2, loc) ||
        !photon_positive(p, kw, v[0], false, loc) ||
        !photon_positive(p, kw, v[1], false, loc))
      return false;
    if (v[0] > v[1] || v[1] > 1e6) {
      zr__sdl_error(p, ZR_EINVAL, loc,
                    "'gather %g, %g': the minimum must not exceed the "
                    "maximum, at most 1e6",
                    v[0], v[1]);
      return false;
    }
    g->gather_min = (int)v[0];
    g->gather_max = (int)v[1];
    break;
  case T_MEDIA:
    /* media MAX_STEPS [, FACTOR]: a whole number of steps (0 turns
       media photons off, the default) and a spacing factor above 0. */
    if (!photon_count(p, kw, a, 1, 2, loc))
      return false;
    if (!isfinite(v[0]) || v[0] < 0.0 || v[0] != floor(v[0]) ||
        v[0] > 1e6) {
      zr__sdl_error(p, ZR_EINVAL, loc,
                    "'media' in photons { } takes a whole number of steps "
                    "from 0 to 1e6, not %g",
                    v[0]);
      return false;
    }
    if (a->n > 1 && !(isfinite(v[1]) && v[1] > 0.0)) {
      zr__sdl_error(p, ZR_EINVAL, loc,
                    "'media %g, %g': the spacing factor must be above 0",
                    v[0], v[1]);
      return false;
    }
    g->media_steps = (int)v[0];
    g->media_factor = a->n > 1 ? v[1] : 1.0;
    ph->has_media = v[0] > 0.0;
    ph->media_loc = *loc;
    break;
  case T_JITTER:
    if (!photon_count(p, kw, a, 1, 1, loc) ||
        !photon_positive(p, kw, v[0], true, loc))
      return false;
    g->jitter = v[0];
    break;
  case T_RADIUS: {
    int n = a ? a->n + (a->skip_first ? 1 : 0) : 0;
    if (!photon_count(p, kw, a, 1, 4, loc))
      return false;
    int first = a->skip_first ? 1 : 0;
    for (int i = 0; i < a->n; i++) {
      int slot = first + i;
      if (!photon_positive(p, kw, v[i], true, loc))
        return false;
      if (slot == 0)
        g->radius = v[i];
      else if (slot == 1)
        g->radius_multiplier = v[i] > 0.0 ? v[i] : 1.0;
      else if (slot == 2)
        g->media_radius = v[i];
      else
        g->media_radius_multiplier = v[i] > 0.0 ? v[i] : 1.0;
    }
    (void)n;
    break;
  }
  case T_MAX_TRACE_LEVEL:
    if (!photon_count(p, kw, a, 1, 1, loc) ||
        !photon_positive(p, kw, v[0], false, loc))
      return false;
    g->max_trace_level = v[0] > 256 ? 256 : (int)v[0];
    break;
  case T_ADC_BAILOUT:
    if (!photon_count(p, kw, a, 1, 1, loc) ||
        !photon_positive(p, kw, v[0], true, loc))
      return false;
    g->adc_bailout = v[0];
    break;
  case T_AUTOSTOP:
    if (!photon_count(p, kw, a, 1, 1, loc) ||
        !photon_positive(p, kw, v[0], true, loc))
      return false;
    g->autostop = v[0];
    break;
  case T_EXPAND_THRESHOLDS:
    if (!photon_count(p, kw, a, 2, 2, loc) ||
        !photon_positive(p, kw, v[0], true, loc) ||
        !photon_positive(p, kw, v[1], true, loc))
      return false;
    g->expand_increase = v[0];
    g->expand_min = v[1] > 1e6 ? 1000000 : (int)v[1];
    break;
  default:
    break;
  }
  if (object_item && !ph->any_object_item)
    ph->any_object_item = true, ph->first_object_item = *loc,
    ph->first_object_kw = kw;
  if (global_item && !ph->any_global_item)
    ph->any_global_item = true, ph->first_global_item = *loc,
    ph->first_global_kw = kw;
  return true;
}

bool zr__sdl_photons_file(zr_sdl_parser *p, zr_sdl_photons *ph, bool save,
                          const zr_sdl_loc *loc) {
  if (save)
    ph->has_save = true;
  else
    ph->has_load = true;
  ph->file_loc = *loc;
  if (!ph->any_global_item)
    ph->any_global_item = true, ph->first_global_item = *loc,
    ph->first_global_kw = 0;
  (void)p;
  return true;
}

/* An item that does not belong in this block. */
static bool photons_misplaced(zr_sdl_parser *p, const zr_sdl_loc *loc,
                              int kw, const char *where,
                              const char *belongs) {
  zr__sdl_error(p, ZR_ESYNTAX, loc,
                "'%s' does not belong in %s photons { } (it belongs in "
                "%s)",
                kw ? photon_kw_name(kw) : "save_file/load_file", where,
                belongs);
  return false;
}

bool zr__sdl_photons_global(zr_sdl_parser *p, const zr_sdl_photons *ph,
                            const zr_sdl_loc *loc) {
  if (ph->any_object_item)
    return photons_misplaced(p, &ph->first_object_item,
                             ph->first_object_kw, "global_settings'",
                             "an object's");
  if (ph->has_refraction || ph->has_reflection || ph->has_area_light)
    return photons_misplaced(p, loc,
                             ph->has_refraction   ? T_REFRACTION
                             : ph->has_reflection ? T_REFLECTION
                                                  : T_AREA_LIGHT,
                             "global_settings'", "an object's or a light's");
  if (!ph->has_spacing && !ph->has_count && !ph->has_load) {
    zr__sdl_error(p, ZR_ESYNTAX, loc,
                  "global_settings' photons { } needs 'spacing' or "
                  "'count'");
    return false;
  }
  zr_photon_settings *g = &p->scene->settings.photons;
  *g = ph->global;
  if (!ph->has_spacing)
    g->spacing = 0.0;
  if (!ph->has_count || ph->has_spacing)
    g->count = 0.0;
  g->on = true;
  if (ph->has_load || ph->has_save)
    zr__sdl_warning(p, &ph->file_loc,
                    "photon maps are not saved or loaded: the photons are "
                    "shot anew");
  return true;
}

bool zr__sdl_photons_light(zr_sdl_parser *p, zr_light *l,
                           const zr_sdl_photons *ph, const zr_sdl_loc *loc) {
  if (ph->any_object_item && !ph->has_area_light)
    return photons_misplaced(p, &ph->first_object_item,
                             ph->first_object_kw, "a light's",
                             "an object's");
  if (ph->any_global_item)
    return photons_misplaced(p, &ph->first_global_item,
                             ph->first_global_kw, "a light's",
                             "global_settings'");
  if (ph->has_refraction)
    l->photon_refraction = ph->refraction;
  if (ph->has_reflection)
    l->photon_reflection = ph->reflection;
  if (ph->has_area_light) {
    l->photon_area = ph->area_light;
    if (ph->area_light)
      zr__sdl_warning(p, loc,
                      "photons { area_light }: photons leave from the "
                      "light's centre, as without it");
  }
  return true;
}

/* The block applied to o, and pushed into a CSG's parts. */
static bool photons_apply(zr_sdl_parser *p, zr_object *o,
                          const zr_sdl_photons *ph) {
  zr_photon_object *po = zr__sdl_alloc(p, sizeof *po);
  if (!po)
    return false;
  if (o->photons) {
    *po = *o->photons;
  } else {
    memset(po, 0, sizeof *po);
    po->spacing = 1.0;
    po->collect = true;
    po->pass_through = o->no_shadow;
  }
  if (ph->has_target)
    po->target = true, po->spacing = ph->obj.spacing;
  if (ph->has_refraction)
    po->refraction = ph->refraction, po->refraction_set = true;
  if (ph->has_reflection)
    po->reflection = ph->reflection, po->reflection_set = true;
  if (ph->has_collect)
    po->collect = ph->collect;
  if (ph->has_pass_through)
    po->pass_through = ph->pass_through;
  o->photons = po;
  if (zr__is_csg(o->kind))
    for (size_t i = 0; i < o->u.csg.n_children; i++)
      if (!photons_apply(p, o->u.csg.children[i], ph))
        return false;
  return true;
}

bool zr__sdl_photons_object(zr_sdl_parser *p, zr_object *o,
                            const zr_sdl_photons *ph) {
  if (ph->any_global_item)
    return photons_misplaced(p, &ph->first_global_item,
                             ph->first_global_kw, "an object's",
                             "global_settings'");
  if (ph->has_area_light)
    return photons_misplaced(p, &ph->first_object_item, T_AREA_LIGHT,
                             "an object's", "a light's");
  return photons_apply(p, o, ph);
}
