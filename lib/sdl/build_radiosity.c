/*
 * build_radiosity.c - the radiosity settings of a scene: global_settings
 * { radiosity { ... } }, an object's radiosity { importance } and
 * no_radiosity, and zRcube's finish { energy P } (issue 4).
 *
 * POV-Ray 3.7's radiosity (reference manual r3_4, 3.4.4.3 "Radiosity")
 * is Ward's irradiance cache, which lib/gi/cache.c implements: count,
 * error_bound, nearest_count, pretrace_start and the rest are read,
 * checked against the ranges the manual gives and kept in the scene's
 * settings for zr_gi_params_init().  brightness also scales what the
 * hierarchical solver (lib/radiosity) carries between surfaces, and
 * zRcube's own items set that solver's parameters, which the command
 * line overrides: bf_bound (zr_radiosity_params.bf_eps), minimum_area
 * (area_eps), visibility_count (visibility_rays), max_iterations and
 * residual_bound (residual).  subsurface is read and named in a
 * warning (zRcube has no subsurface light transport).  save_file and
 * load_file (POV-Ray 3.6's spelling of what 3.7 moved to the command
 * line) name the irradiance cache's file: loaded before the pretrace,
 * written after it.
 *
 * finish { energy P } gives an emitter by its power instead of its
 * exitance, as the seed's energy keyword did: each object wearing the
 * finish emits P in all (per channel, in the scene's units of power),
 * spread evenly over the sides that emit, so its exitance is P / area;
 * lib/radiosity/mesh.c does the division, as only the solver knows the
 * area.  It adds to emission and lights nothing without radiosity.
 */
#include "config.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "pov-parse.h"
#include "sdl/sdl.h"

#define RADIOSITY (&p->scene->settings.radiosity)

/* The items zRcube reads but has no use for, one bit each, in the order
   the closing warning lists them. */
static const struct {
  int token;
  const char *name;
} ignored_items[] = {
    {T_SUBSURFACE, "subsurface"},
};
#define N_IGNORED (sizeof ignored_items / sizeof ignored_items[0])

/* POV-Ray's items the irradiance cache takes. */
static const struct {
  int token;
  const char *name;
} cache_items[] = {
    {T_ADC_BAILOUT, "adc_bailout"},
    {T_ALWAYS_SAMPLE, "always_sample"},
    {T_COUNT, "count"},
    {T_ERROR_BOUND, "error_bound"},
    {T_GRAY_THRESHOLD, "gray_threshold"},
    {T_LOW_ERROR_FACTOR, "low_error_factor"},
    {T_MAX_SAMPLE, "max_sample"},
    {T_MAXIMUM_REUSE, "maximum_reuse"},
    {T_MINIMUM_REUSE, "minimum_reuse"},
    {T_NEAREST_COUNT, "nearest_count"},
    {T_PRETRACE_START, "pretrace_start"},
    {T_PRETRACE_END, "pretrace_end"},
    {T_MEDIA, "media"},
    {T_NORMAL, "normal"},
    {T_RECURSION_LIMIT, "recursion_limit"},
};
#define N_CACHE (sizeof cache_items / sizeof cache_items[0])

static const char *item_name(int kw) {
  for (size_t i = 0; i < N_IGNORED; i++)
    if (ignored_items[i].token == kw)
      return ignored_items[i].name;
  for (size_t i = 0; i < N_CACHE; i++)
    if (cache_items[i].token == kw)
      return cache_items[i].name;
  switch (kw) {
  case T_BRIGHTNESS:
    return "brightness";
  case T_BF_BOUND:
    return "bf_bound";
  case T_MINIMUM_AREA:
    return "minimum_area";
  case T_VISIBILITY_COUNT:
    return "visibility_count";
  case T_MAX_ITERATIONS:
    return "max_iterations";
  case T_RESIDUAL_BOUND:
    return "residual_bound";
  case T_SAVE_FILE:
    return "save_file";
  case T_LOAD_FILE:
    return "load_file";
  default:
    return "?";
  }
}

static int ignored_bit(int kw) {
  for (size_t i = 0; i < N_IGNORED; i++)
    if (ignored_items[i].token == kw)
      return (int)i;
  return -1;
}

void zr__sdl_radiosity_begin(zr_sdl_parser *p) {
  /* A later block overrides an earlier one item by item, as a later
     global_settings does in POV-Ray. */
  if (!RADIOSITY->on)
    RADIOSITY->normal = RADIOSITY->media = RADIOSITY->always_sample = -1;
  RADIOSITY->on = true;
  p->radiosity_ignored = 0;
}

/* A whole number from lo to hi, or an error naming the item. */
static bool whole(zr_sdl_parser *p, int kw, double v, double lo, double hi,
                  const zr_sdl_loc *loc) {
  if (v >= lo && v <= hi && v == floor(v))
    return true;
  zr__sdl_error(p, ZR_ESCENE, loc,
                "radiosity: %s must be a whole number from %.0f to %.0f",
                item_name(kw), lo, hi);
  return false;
}

/* A number in (lo, hi] (lo_open) or [lo, hi], or an error naming the
   item and the range the manual gives. */
static bool in_range(zr_sdl_parser *p, int kw, double v, double lo,
                     double hi, bool lo_open, const zr_sdl_loc *loc) {
  if ((lo_open ? v > lo : v >= lo) && v <= hi)
    return true;
  zr__sdl_error(p, ZR_ESCENE, loc, "radiosity: %s must be %s %g and at "
                "most %g", item_name(kw), lo_open ? "above" : "at least",
                lo, hi);
  return false;
}

/* POV-Ray's items, for the irradiance cache (lib/gi/cache.c); the
   ranges are the manual's (count, nearest_count up to 20,
   recursion_limit up to 20, pretrace sizes in (0, 1]). */
static bool cache_item(zr_sdl_parser *p, int kw, double v, double w,
                       const zr_sdl_loc *loc) {
  zr_radiosity_settings *r = RADIOSITY;
  switch (kw) {
  case T_COUNT:
    if (!whole(p, kw, v, 1, 1e6, loc) || !whole(p, kw, w, 1, 1e6, loc))
      return false;
    r->count = (int)v;
    r->count_pool = (int)w; /* 1 when no second value: none */
    return true;
  case T_NEAREST_COUNT:
    if (!whole(p, kw, v, 1, 20, loc) || !whole(p, kw, w, 1, 20, loc))
      return false;
    r->nearest_count = (int)v;
    r->nearest_count_max = (int)w;
    return true;
  case T_RECURSION_LIMIT:
    if (!whole(p, kw, v, 1, 20, loc))
      return false;
    r->recursion_limit = (int)v;
    return true;
  case T_ERROR_BOUND:
    if (!in_range(p, kw, v, 0.0, 1e6, true, loc))
      return false;
    r->error_bound = v;
    return true;
  case T_LOW_ERROR_FACTOR:
    if (!in_range(p, kw, v, 0.0, 1.0, true, loc))
      return false;
    r->low_error_factor = v;
    return true;
  case T_GRAY_THRESHOLD:
    if (!in_range(p, kw, v, 0.0, 1.0, false, loc))
      return false;
    r->gray_threshold = v;
    r->gray_given = true;
    return true;
  case T_MINIMUM_REUSE:
    if (!in_range(p, kw, v, 0.0, 1.0, false, loc))
      return false;
    r->minimum_reuse = v;
    return true;
  case T_MAXIMUM_REUSE:
    if (!in_range(p, kw, v, 0.0, 1e6, true, loc))
      return false;
    r->maximum_reuse = v;
    return true;
  case T_PRETRACE_START:
  case T_PRETRACE_END:
    if (!in_range(p, kw, v, 0.0, 1.0, true, loc))
      return false;
    *(kw == T_PRETRACE_START ? &r->pretrace_start : &r->pretrace_end) = v;
    return true;
  case T_ADC_BAILOUT:
    if (!in_range(p, kw, v, 0.0, 1.0, false, loc))
      return false;
    r->adc_bailout = v;
    r->adc_given = true;
    return true;
  case T_MAX_SAMPLE:
    r->max_sample = v; /* not positive: no limit, as the manual says */
    r->max_sample_given = true;
    return true;
  case T_MEDIA:
    r->media = v != 0.0;
    return true;
  case T_NORMAL:
    r->normal = v != 0.0;
    return true;
  default: /* T_ALWAYS_SAMPLE */
    r->always_sample = v != 0.0;
    return true;
  }
}

/* zRcube's items: the value goes to the scene's settings. */
static bool own_item(zr_sdl_parser *p, int kw, double v, double w,
                     const zr_sdl_loc *loc) {
  zr_radiosity_settings *r = RADIOSITY;
  switch (kw) {
  case T_BF_BOUND:
    if (!(v > 0.0 && isfinite(v))) {
      zr__sdl_error(p, ZR_ESCENE, loc,
                    "radiosity: bf_bound must be a number > 0 (a fraction "
                    "of the scene's emitted power)");
      return false;
    }
    r->bf_eps = v;
    return true;
  case T_MINIMUM_AREA:
    if (!(v > 0.0 && v < 1.0)) {
      zr__sdl_error(p, ZR_ESCENE, loc,
                    "radiosity: minimum_area must be between 0 and 1 (a "
                    "fraction of the scene's surface area)");
      return false;
    }
    r->area_eps = v;
    return true;
  case T_VISIBILITY_COUNT:
    if (!whole(p, kw, v, 1, 16, loc))
      return false;
    r->visibility_rays = (int)v;
    return true;
  case T_MAX_ITERATIONS:
    if (!whole(p, kw, v, 1, 100000000, loc))
      return false;
    r->max_iterations = (int)v;
    return true;
  case T_RESIDUAL_BOUND:
    if (!(v > 0.0 && isfinite(v))) {
      zr__sdl_error(p, ZR_ESCENE, loc,
                    "radiosity: residual_bound must be a number > 0 (a "
                    "fraction of the scene's emitted power)");
      return false;
    }
    r->residual = v;
    return true;
  case T_BRIGHTNESS:
    if (!(v >= 0.0 && isfinite(v))) {
      zr__sdl_error(p, ZR_ESCENE, loc,
                    "radiosity: brightness must be a number >= 0");
      return false;
    }
    r->brightness = v;
    return true;
  default:
    return cache_item(p, kw, v, w, loc);
  }
}

bool zr__sdl_radiosity_item(zr_sdl_parser *p, int kw, const zr_sdl_expr *a,
                            const zr_sdl_expr *b, const zr_sdl_loc *loc) {
  bool is_switch = kw == T_ALWAYS_SAMPLE || kw == T_MEDIA ||
                   kw == T_NORMAL || kw == T_SUBSURFACE;
  bool two = kw == T_COUNT || kw == T_NEAREST_COUNT;
  double v = 1.0, w = 1.0;
  if (!a && !is_switch) {
    zr__sdl_error(p, ZR_ESYNTAX, loc, "radiosity: %s needs a value",
                  item_name(kw));
    return false;
  }
  if (b && !two) {
    zr__sdl_error(p, ZR_ESYNTAX, loc, "radiosity: %s takes one value",
                  item_name(kw));
    return false;
  }
  if ((a && !zr__sdl_want_float(p, a, loc, &v)) ||
      (b && !zr__sdl_want_float(p, b, loc, &w)))
    return false;
  if (!isfinite(v) || !isfinite(w)) {
    zr__sdl_error(p, ZR_ESCENE, loc, "radiosity: %s must be a finite "
                  "number", item_name(kw));
    return false;
  }
  int bit = ignored_bit(kw);
  if (bit < 0)
    return own_item(p, kw, v, b ? w : (kw == T_NEAREST_COUNT ? v : 1.0),
                    loc);
  p->radiosity_ignored |= 1u << bit;
  return true;
}

bool zr__sdl_radiosity_file(zr_sdl_parser *p, int kw, const char *name,
                            const zr_sdl_loc *loc) {
  if (!name || !*name) {
    zr__sdl_error(p, ZR_ESCENE, loc, "radiosity: %s needs a file name",
                  item_name(kw));
    return false;
  }
  char *copy = zr__arena_strdup(&p->scene->arena, name);
  if (!copy) {
    zr__sdl_error(p, ZR_ENOMEM, loc, "out of memory");
    return false;
  }
  if (kw == T_SAVE_FILE)
    RADIOSITY->save_file = copy;
  else
    RADIOSITY->load_file = copy;
  return true;
}

void zr__sdl_radiosity_end(zr_sdl_parser *p, const zr_sdl_loc *loc) {
  zr_radiosity_settings *r = RADIOSITY;
  if (r->minimum_reuse > 0.0 && r->maximum_reuse > 0.0 &&
      r->minimum_reuse >= r->maximum_reuse)
    zr__sdl_warning(p, loc, "radiosity: minimum_reuse %g is not below "
                    "maximum_reuse %g; the cache uses maximum_reuse for "
                    "both", r->minimum_reuse, r->maximum_reuse);
  unsigned bits = p->radiosity_ignored;
  p->radiosity_ignored = 0;
  if (bits & 1u)
    zr__sdl_warning(p, loc, "radiosity: subsurface ignored: zRcube has no "
                    "subsurface light transport");
}

void zr__sdl_radiosity_object(zr_sdl_parser *p, int kw,
                              const zr_sdl_loc *loc) {
  unsigned bit = kw == T_NO_RADIOSITY ? 1u : 2u;
  if (p->radiosity_object_warned & bit)
    return;
  p->radiosity_object_warned |= bit;
  if (kw == T_NO_RADIOSITY)
    zr__sdl_warning(p, loc, "no_radiosity is ignored (warned once): in "
                    "zRcube's radiosity every surface takes part");
  else
    zr__sdl_warning(p, loc, "an object's radiosity { importance } is "
                    "ignored (warned once): zRcube's radiosity refines "
                    "where light is, not by object");
}

bool zr__sdl_finish_energy(zr_sdl_parser *p, zr_finish *f,
                           const zr_sdl_expr *e, const zr_sdl_loc *loc) {
  zr_rgb P;
  if (!zr__sdl_want_rgb(p, e, loc, &P))
    return false;
  if (!(P.r >= 0.0 && P.g >= 0.0 && P.b >= 0.0 && isfinite(P.r) &&
        isfinite(P.g) && isfinite(P.b))) {
    zr__sdl_error(p, ZR_ESCENE, loc,
                  "energy must be a power >= 0 in every channel");
    return false;
  }
  f->energy = P;
  return true;
}
