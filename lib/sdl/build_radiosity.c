/*
 * build_radiosity.c - the radiosity settings of a scene: global_settings
 * { radiosity { ... } }, an object's radiosity { importance } and
 * no_radiosity, and zRcube's finish { energy P } (issue 4).
 *
 * POV-Ray 3.7's radiosity (reference manual r3_4, 3.4.4.3 "Radiosity")
 * is Ward's irradiance cache: count, error_bound, nearest_count,
 * pretrace_start and the rest tune how many hemisphere samples it takes
 * and how far it reuses them.  zRcube has no cache: its radiosity is
 * Hanrahan, Salzman and Aupperle's hierarchical method on the scene's
 * exact surfaces, solved once for every view over every bounce.  So:
 *
 *   - the block turns zRcube's radiosity on (as it turns POV-Ray's on);
 *   - brightness keeps its meaning: it scales the diffuse light that
 *     radiosity carries between surfaces;
 *   - recursion_limit would be a bounce limit, which the hierarchical
 *     solver cannot honour (it gathers over links to convergence, and
 *     refinement depends on the converged light): it is read and a
 *     warning names it;
 *   - the cache's own items (adc_bailout, always_sample, count,
 *     error_bound, gray_threshold, low_error_factor, max_sample,
 *     maximum_reuse, minimum_reuse, nearest_count, pretrace_start,
 *     pretrace_end) and the switches media, normal and subsurface are
 *     read, checked, and named in one warning per block;
 *   - POV-Ray 3.6's save_file and load_file get a warning pointing to
 *     --radiosity-save and --radiosity-load;
 *   - zRcube's own items set the solver's parameters, which the command
 *     line overrides: bf_bound (zr_radiosity_params.bf_eps), minimum_area
 *     (area_eps), visibility_count (visibility_rays), max_iterations and
 *     residual_bound (residual).
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
    {T_SUBSURFACE, "subsurface"},
    {T_RECURSION_LIMIT, "recursion_limit"},
};
#define N_IGNORED (sizeof ignored_items / sizeof ignored_items[0])

static const char *item_name(int kw) {
  for (size_t i = 0; i < N_IGNORED; i++)
    if (ignored_items[i].token == kw)
      return ignored_items[i].name;
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

/* zRcube's items: the value goes to the scene's settings. */
static bool own_item(zr_sdl_parser *p, int kw, double v,
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
  default: /* T_BRIGHTNESS */
    if (!(v >= 0.0 && isfinite(v))) {
      zr__sdl_error(p, ZR_ESCENE, loc,
                    "radiosity: brightness must be a number >= 0");
      return false;
    }
    r->brightness = v;
    return true;
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
    return own_item(p, kw, v, loc);
  /* POV-Ray's counts and the recursion limit are whole numbers >= 1;
     checked so a scene zRcube accepts is one POV-Ray accepts. */
  if ((kw == T_COUNT || kw == T_NEAREST_COUNT || kw == T_RECURSION_LIMIT)
      && (!whole(p, kw, v, 1, 1e9, loc) || !whole(p, kw, w, 1, 1e9, loc)))
    return false;
  p->radiosity_ignored |= 1u << bit;
  return true;
}

void zr__sdl_radiosity_file(zr_sdl_parser *p, int kw,
                            const zr_sdl_loc *loc) {
  zr__sdl_warning(p, loc, "radiosity: %s is ignored; zRcube saves and "
                  "loads its solution with --radiosity-save and "
                  "--radiosity-load", item_name(kw));
}

void zr__sdl_radiosity_end(zr_sdl_parser *p, const zr_sdl_loc *loc) {
  unsigned bits = p->radiosity_ignored;
  p->radiosity_ignored = 0;
  int limit = ignored_bit(T_RECURSION_LIMIT);
  if (bits & (1u << limit)) {
    zr__sdl_warning(p, loc, "radiosity: recursion_limit is ignored; "
                    "zRcube carries light over every bounce until "
                    "residual_bound is met");
    bits &= ~(1u << limit);
  }
  if (!bits)
    return;
  char list[512];
  size_t n = 0;
  list[0] = '\0';
  for (size_t i = 0; i < N_IGNORED; i++)
    if (bits & (1u << i)) {
      int w = snprintf(list + n, sizeof list - n, "%s%s", n ? ", " : "",
                       ignored_items[i].name);
      if (w > 0 && (size_t)w < sizeof list - n)
        n += (size_t)w;
    }
  zr__sdl_warning(p, loc, "radiosity: %s ignored: they tune POV-Ray's "
                  "irradiance cache, and zRcube's hierarchical radiosity "
                  "has its own settings (bf_bound, minimum_area, "
                  "visibility_count, max_iterations, residual_bound)",
                  list);
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
