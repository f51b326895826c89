/*
 * options.c - the zrcube command line: POV-Ray's switches, POV-Ray's INI
 * options and GNU long options, parsed into a zr_cli_options.
 *
 * POV-Ray 3.7's reference, section 3.2 "Command-Line and INI-File
 * Options", is followed for what users of POV-Ray will type: switches
 * start with + (on) or - (off), their letters are case-insensitive, a value
 * follows the letters without a space (+W640, +A0.3, +Lpath), a bare name
 * is the scene and a name ending in .ini is a file of options.  Every
 * spelling of an option (+W640, --width=640, Width=640) goes through the
 * same setter, so they check values the same way.  Values are checked in
 * full: "+W12x" and "+W0" are errors rather than 12 or a default, because
 * a mistyped option silently ignored costs a whole render.  Options that
 * zrcube does not implement are refused by name instead of ignored; only
 * the display switches (+D, +P) are accepted and ignored, since zrcube
 * never opens a window.
 */
#include "options.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

/* What an option does, whatever its spelling. */
typedef enum opt_key {
  K_INPUT,
  K_OUTPUT,
  K_WIDTH,
  K_HEIGHT,
  K_AA_ON,        /* optional threshold */
  K_AA_OFF,       /* optional threshold, kept for later */
  K_AA_THRESHOLD, /* threshold only */
  K_AA_DEPTH,
  K_SAMPLING,
  K_JITTER_ON,    /* optional amount */
  K_JITTER_OFF,   /* optional amount, kept for later */
  K_JITTER_AMOUNT,
  K_THREADS,
  K_INCLUDE,
  K_VERBOSE,
  K_NOVERBOSE,
  K_QUIET,
  K_HELP,
  K_VERSION,
  K_PARSE_ONLY,
  K_LOOP_LIMIT,
  K_MEMORY_LIMIT,
  K_FILE_LIMIT,
  K_IGNORED,      /* display options: zrcube opens no window */
  K_OUTPUT_ON,    /* optional format */
  K_OUTPUT_OFF,   /* optional format, kept for later */
  K_FORMAT,
  K_BITS,
  K_RADIOSITY,
  K_BF_EPS,
  K_AREA_EPS,
  K_VIS_RAYS,
  K_UNIFORM,
  K_MAX_ITERATIONS,
  K_RESIDUAL,
  K_SHOOTING,
  K_ONE_SIDED,    /* optional on/off */
  K_RAD_ONLY,
  K_RAD_STATS,
  K_RAD_SAVE,
  K_RAD_LOAD,
  K_RAD_MESH,
  K_READ_PATH,
  K_WRITE_PATH,
  K_IO_RESTRICTIONS,
  K_GI,           /* --gi=auto|hierarchical|cache|path|off */
  K_NO_RADIOSITY, /* --no-radiosity, Radiosity=off */
  K_RADIOSITY_ON, /* Radiosity=on: the scene decides, as without it */
  K_QUALITY,      /* +Qn, Quality=n */
  K_GI_SAVE,
  K_GI_LOAD
} opt_key;

/* Where the option being applied came from, for messages. */
typedef struct arg_ctx {
  zr_cli_options *o;
  char *err;
  size_t err_size;
  const char *where; /* "file.ini:3: " or "" */
  const char *what;  /* the option as written: "+Wabc", "--width=abc" */
} arg_ctx;

static int fail(const arg_ctx *c, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

static int fail(const arg_ctx *c, const char *fmt, ...) {
  int n = snprintf(c->err, c->err_size, "zrcube: %s", c->where);
  if (n >= 0 && (size_t)n < c->err_size) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(c->err + n, c->err_size - (size_t)n, fmt, ap);
    va_end(ap);
  }
  return -1;
}

void zr__cli_init(zr_cli_options *o, const zr_render_params *defaults) {
  memset(o, 0, sizeof *o);
  o->params = *defaults;
  o->format = ZR_FORMAT_AUTO;
  o->write_output = 1;
  o->loop_limit = ZR_DEFAULT_WORK_LIMIT;
  o->file_limit = ZR_DEFAULT_FILE_LIMIT;
  /* The library's defaults are the command line's (issue 11). */
  zr_radiosity_params_init(&o->rad, NULL);
  o->gi = ZR_GI_AUTO;
  o->quality = 9;
}

void zr__cli_free(zr_cli_options *o) {
  if (!o)
    return;
  free(o->input);
  free(o->output);
  free(o->rad_save);
  free(o->rad_load);
  free(o->rad_mesh);
  free(o->gi_save);
  free(o->gi_load);
  for (size_t i = 0; i < o->n_include_paths; i++)
    free(o->include_paths[i]);
  free(o->include_paths);
  for (size_t i = 0; i < o->n_read_paths; i++)
    free(o->read_paths[i]);
  free(o->read_paths);
  for (size_t i = 0; i < o->n_write_paths; i++)
    free(o->write_paths[i]);
  free(o->write_paths);
  memset(o, 0, sizeof *o);
}

/* A size: digits, then an optional K, M, G or T (powers of 1024), with
   an optional "B" or "iB" after it ("512M", "2GiB", "1000000"). */
static int parse_size(const char *s, unsigned long long *out) {
  if (!s || !isdigit((unsigned char)*s))
    return -1;
  errno = 0;
  char *end;
  unsigned long long n = strtoull(s, &end, 10);
  if (errno)
    return -1;
  int shift = 0;
  switch (*end) {
  case 'k': case 'K': shift = 10; end++; break;
  case 'm': case 'M': shift = 20; end++; break;
  case 'g': case 'G': shift = 30; end++; break;
  case 't': case 'T': shift = 40; end++; break;
  default: break;
  }
  if (shift && *end == 'i')
    end++;
  if (*end == 'B' || *end == 'b')
    end++;
  if (*end || (shift && n > (~0ULL >> shift)))
    return -1;
  *out = n << shift;
  return 0;
}

/* A whole number from lo to hi and nothing else (no sign games, no
   trailing letters, no blanks). */
static int parse_int(const char *s, long lo, long hi, long *out) {
  if (!s || !*s || isspace((unsigned char)*s))
    return 0;
  errno = 0;
  char *end;
  long v = strtol(s, &end, 10);
  if (errno || *end || v < lo || v > hi)
    return 0;
  *out = v;
  return 1;
}

/* A finite real number and nothing else. */
static int parse_real(const char *s, double *out) {
  if (!s || !*s || isspace((unsigned char)*s))
    return 0;
  errno = 0;
  char *end;
  double v = strtod(s, &end);
  if (errno || *end || !isfinite(v))
    return 0;
  *out = v;
  return 1;
}

static int parse_bool(const char *s, int *out) {
  static const char *const yes[] = {"on", "true", "yes", "1"};
  static const char *const no[] = {"off", "false", "no", "0"};
  for (size_t i = 0; i < 4; i++) {
    if (!strcasecmp(s, yes[i])) {
      *out = 1;
      return 1;
    }
    if (!strcasecmp(s, no[i])) {
      *out = 0;
      return 1;
    }
  }
  return 0;
}

static int set_string(const arg_ctx *c, char **dst, const char *value) {
  char *copy = strdup(value);
  if (!copy)
    return fail(c, "out of memory");
  free(*dst);
  *dst = copy;
  return 0;
}

static int set_input(const arg_ctx *c, const char *value) {
  zr_cli_options *o = c->o;
  if (o->input && strcmp(o->input, value) != 0)
    return fail(c, "more than one scene file: '%s' and '%s'", o->input,
                value);
  return set_string(c, &o->input, value);
}

static int add_include(const arg_ctx *c, const char *dir) {
  zr_cli_options *o = c->o;
  /* POV-Ray counts a path given twice once. */
  for (size_t i = 0; i < o->n_include_paths; i++)
    if (!strcmp(o->include_paths[i], dir))
      return 0;
  char **paths = realloc(o->include_paths,
                         (o->n_include_paths + 1) * sizeof *paths);
  if (!paths)
    return fail(c, "out of memory");
  o->include_paths = paths;
  paths[o->n_include_paths] = strdup(dir);
  if (!paths[o->n_include_paths])
    return fail(c, "out of memory");
  o->n_include_paths++;
  return 0;
}

/* --read-path and --write-path: kept as given; the library resolves
   them (zr_context_add_read_path) on the rank that reads the files. */
static int add_dir(const arg_ctx *c, char ***dirs, size_t *n,
                   const char *dir) {
  if (!*dir)
    return fail(c, "'%s' needs a directory", c->what);
  char **grown = realloc(*dirs, (*n + 1) * sizeof *grown);
  if (!grown)
    return fail(c, "out of memory");
  *dirs = grown;
  grown[*n] = strdup(dir);
  if (!grown[*n])
    return fail(c, "out of memory");
  (*n)++;
  return 0;
}

/* POV-Ray's [File I/O Security] words, and on/off. */
static int set_io_restrictions(const arg_ctx *c, const char *value) {
  zr_cli_options *o = c->o;
  if (!strcasecmp(value, "restricted") || !strcasecmp(value, "on"))
    o->io_mode = ZR_IO_RESTRICTED;
  else if (!strcasecmp(value, "read-only"))
    o->io_mode = ZR_IO_READ_ONLY;
  else if (!strcasecmp(value, "none") || !strcasecmp(value, "off"))
    o->io_mode = ZR_IO_NONE;
  else
    return fail(c, "'%s': the I/O restrictions are 'restricted' (or "
                   "'on'), 'read-only' or 'none' (or 'off')", c->what);
  return 0;
}

static int set_side(const arg_ctx *c, const char *value, const char *name,
                    int *dst) {
  long v;
  if (!parse_int(value, 1, ZR_CLI_MAX_SIDE, &v))
    return fail(c, "'%s': %s must be a whole number from 1 to %d", c->what,
                name, ZR_CLI_MAX_SIDE);
  *dst = (int)v;
  return 0;
}

static int set_threshold(const arg_ctx *c, const char *value) {
  double v;
  if (!parse_real(value, &v) || v < 0)
    return fail(c, "'%s': the antialiasing threshold must be a number "
                   "from 0 up", c->what);
  c->o->params.aa_threshold = v;
  return 0;
}

/* POV-Ray: a jitter amount of 0 or less turns jitter off. */
static int set_jitter_amount(const arg_ctx *c, const char *value,
                             int turn_on) {
  double v;
  if (!parse_real(value, &v))
    return fail(c, "'%s': the jitter amount must be a number", c->what);
  if (v <= 0) {
    c->o->params.jitter = 0;
  } else {
    c->o->params.jitter_amount = v;
    if (turn_on)
      c->o->params.jitter = 1;
  }
  return 0;
}

static int set_bits(const arg_ctx *c, const char *value) {
  zr_cli_options *o = c->o;
  long bits;
  if (!parse_int(value, 1, 64, &bits))
    return fail(c, "'%s': bits per colour must be a whole number",
                c->what);
  if (bits != 8 && bits != 16)
    return fail(c, "'%s': only 8 and 16 bits per colour are supported",
                c->what);
  if (o->format == ZR_FORMAT_PPM && bits != 8)
    return fail(c, "'%s': PPM files are written with 8 bits per colour",
                c->what);
  if (o->format != ZR_FORMAT_PPM)
    o->format = bits == 16 ? ZR_FORMAT_PNG16 : ZR_FORMAT_PNG8;
  return 0;
}

/* The names of POV-Ray's other output types, to refuse them by name. */
static const char *pov_type_name(char type) {
  switch (toupper((unsigned char)type)) {
  case 'B':
    return "BMP";
  case 'C':
  case 'T':
    return "Targa";
  case 'E':
    return "OpenEXR";
  case 'H':
    return "Radiance HDR";
  case 'J':
    return "JPEG";
  case 'S':
    return "system-specific";
  default:
    return NULL;
  }
}

/* +F's value: a type letter, then optionally the bits per colour. */
static int set_format(const arg_ctx *c, const char *value) {
  zr_cli_options *o = c->o;
  char type = (char)toupper((unsigned char)value[0]);
  if (type == 'N') {
    o->format = ZR_FORMAT_PNG8;
  } else if (type == 'P') {
    o->format = ZR_FORMAT_PPM;
  } else if (pov_type_name(type)) {
    return fail(c, "'%s': %s output is not supported (use N for PNG, P "
                   "for PPM, or an output name ending in .pfm)",
                c->what, pov_type_name(type));
  } else {
    return fail(c, "'%s': unknown output file type '%c' (use N for PNG "
                   "or P for PPM)", c->what, value[0]);
  }
  return value[1] ? set_bits(c, value + 1) : 0;
}

static int set_sampling(const arg_ctx *c, const char *value) {
  long method;
  if (!parse_int(value, 1, 2, &method))
    return fail(c, "'%s': the sampling method must be 1 or 2", c->what);
  c->o->params.aa_method = (int)method;
  return 0;
}

/* Applies one option; value is NULL when none was written. */
/* --uniform=N: N x N elements on every surface, N a power of two (the
   library counts levels of splitting, 2^levels per side). */
static int set_uniform(const arg_ctx *c, const char *value) {
  long v;
  if (!parse_int(value, 2, 1024, &v) || (v & (v - 1)) != 0)
    return fail(c, "'%s': --uniform takes N for N x N elements per "
                   "surface, a power of two from 2 to 1024", c->what);
  int levels = 0;
  while ((1L << levels) < v)
    levels++;
  c->o->rad.uniform = levels;
  return 0;
}

/* The radiosity options; any of them turns radiosity on. */
static int apply_radiosity(const arg_ctx *c, opt_key key,
                           const char *value) {
  zr_cli_options *o = c->o;
  zr_radiosity_params *rp = &o->rad;
  double x;
  long v;
  o->radiosity = 1;
  /* Set before the value is checked: a bad value ends the run anyway. */
  o->rad_given |= key == K_BF_EPS           ? ZR_CLI_RAD_BF_EPS
                  : key == K_AREA_EPS       ? ZR_CLI_RAD_AREA_EPS
                  : key == K_VIS_RAYS       ? ZR_CLI_RAD_VIS_RAYS
                  : key == K_MAX_ITERATIONS ? ZR_CLI_RAD_MAX_ITERATIONS
                  : key == K_RESIDUAL       ? ZR_CLI_RAD_RESIDUAL
                                            : 0u;
  switch (key) {
  case K_BF_EPS:
    if (!parse_real(value, &x) || x < 0.0)
      return fail(c, "'%s': --bf-eps must be a number >= 0", c->what);
    rp->bf_eps = x;
    return 0;
  case K_AREA_EPS:
    if (!parse_real(value, &x) || !(x > 0.0 && x < 1.0))
      return fail(c, "'%s': --area-eps must be a number between 0 and 1 "
                     "(a fraction of the scene's surface area)", c->what);
    rp->area_eps = x;
    return 0;
  case K_VIS_RAYS:
    if (!parse_int(value, 1, 16, &v))
      return fail(c, "'%s': --vis-rays must be a whole number from 1 to "
                     "16", c->what);
    rp->visibility_rays = (int)v;
    return 0;
  case K_UNIFORM:
    return set_uniform(c, value);
  case K_MAX_ITERATIONS:
    if (!parse_int(value, 1, 100000000, &v))
      return fail(c, "'%s': --max-iterations must be a whole number from "
                     "1 to 100000000", c->what);
    rp->max_iterations = (int)v;
    return 0;
  case K_RESIDUAL:
    if (!parse_real(value, &x) || !(x > 0.0))
      return fail(c, "'%s': --residual must be a number > 0", c->what);
    rp->residual = x;
    return 0;
  case K_SHOOTING:
    rp->shooting = 1;
    return 0;
  case K_ONE_SIDED:
    if (!value) {
      rp->one_sided_emission = 1;
      return 0;
    }
    if (!parse_bool(value, &rp->one_sided_emission))
      return fail(c, "'%s': --one-sided-emission takes 0 or 1 (or on, "
                     "off)", c->what);
    return 0;
  case K_RAD_ONLY:
    o->params.radiosity_only = 1;
    return 0;
  case K_RAD_STATS:
    o->rad_stats = 1;
    return 0;
  case K_RAD_SAVE:
    return set_string(c, &o->rad_save, value);
  case K_RAD_LOAD:
    return set_string(c, &o->rad_load, value);
  case K_RAD_MESH:
    return set_string(c, &o->rad_mesh, value);
  default:
    return 0; /* K_RADIOSITY */
  }
}

void zr__cli_radiosity_params(const zr_cli_options *o, const zr_scene *scene,
                              zr_radiosity_params *out) {
  zr_radiosity_params sp;
  zr_radiosity_params_init(&sp, scene);
  *out = o->rad;
  unsigned g = o->rad_given;
  if (!(g & ZR_CLI_RAD_BF_EPS))
    out->bf_eps = sp.bf_eps;
  if (!(g & ZR_CLI_RAD_AREA_EPS))
    out->area_eps = sp.area_eps;
  if (!(g & ZR_CLI_RAD_VIS_RAYS))
    out->visibility_rays = sp.visibility_rays;
  if (!(g & ZR_CLI_RAD_MAX_ITERATIONS))
    out->max_iterations = sp.max_iterations;
  if (!(g & ZR_CLI_RAD_RESIDUAL))
    out->residual = sp.residual;
  out->brightness = sp.brightness;
}

zr_gi_method zr__cli_gi_asked(const zr_cli_options *o) {
  if (o->gi != ZR_GI_AUTO)
    return o->gi;
  if (o->quality <= 8)
    return ZR_GI_OFF;
  if (o->radiosity)
    return ZR_GI_HIERARCHICAL;
  return ZR_GI_AUTO;
}

/* --gi=MODEL; the last of --gi, --no-radiosity and Radiosity= wins. */
static int set_gi(const arg_ctx *c, const char *value) {
  static const zr_gi_method all[] = {ZR_GI_AUTO, ZR_GI_OFF,
                                     ZR_GI_HIERARCHICAL, ZR_GI_CACHE,
                                     ZR_GI_PATH};
  for (size_t i = 0; i < sizeof all / sizeof *all; i++)
    if (value && !strcmp(value, zr_gi_method_name(all[i]))) {
      if (all[i] == ZR_GI_PATH)
        return fail(c, "'%s': the path-traced reference is not built yet "
                       "(issue 11); use auto, hierarchical, cache or off",
                    c->what);
      c->o->gi = all[i];
      return 0;
    }
  return fail(c, "'%s': --gi takes auto, hierarchical, cache, path or "
                 "off", c->what);
}

static int set_quality(const arg_ctx *c, const char *value) {
  long v;
  if (!parse_int(value, 0, 11, &v))
    return fail(c, "'%s': the quality must be a whole number from 0 to "
                   "11", c->what);
  c->o->quality = (int)v;
  return 0;
}

static int apply(const arg_ctx *c, opt_key key, const char *value) {
  zr_cli_options *o = c->o;
  long v;
  switch (key) {
  case K_INPUT:
    return set_input(c, value);
  case K_OUTPUT:
    if (!strcmp(value, "-"))
      return fail(c, "'%s': writing the image to standard output is not "
                     "supported", c->what);
    return set_string(c, &o->output, value);
  case K_WIDTH:
    return set_side(c, value, "the width", &o->params.width);
  case K_HEIGHT:
    return set_side(c, value, "the height", &o->params.height);
  case K_AA_ON:
    o->params.antialias = 1;
    return value ? set_threshold(c, value) : 0;
  case K_AA_OFF:
    o->params.antialias = 0;
    return value ? set_threshold(c, value) : 0;
  case K_AA_THRESHOLD:
    return set_threshold(c, value);
  case K_AA_DEPTH:
    if (!parse_int(value, 1, ZR_CLI_MAX_AA_DEPTH, &v))
      return fail(c, "'%s': the antialiasing depth must be a whole number "
                     "from 1 to %d", c->what, ZR_CLI_MAX_AA_DEPTH);
    o->params.aa_depth = (int)v;
    return 0;
  case K_SAMPLING:
    return set_sampling(c, value);
  case K_JITTER_ON:
    o->params.jitter = 1;
    return value ? set_jitter_amount(c, value, 1) : 0;
  case K_JITTER_OFF:
    o->params.jitter = 0;
    return value ? set_jitter_amount(c, value, 0) : 0;
  case K_JITTER_AMOUNT:
    return set_jitter_amount(c, value, 0);
  case K_THREADS:
    if (!parse_int(value, 1, ZR_CLI_MAX_THREADS, &v))
      return fail(c, "'%s': the number of threads must be a whole number "
                     "from 1 to %d", c->what, ZR_CLI_MAX_THREADS);
    o->threads = (int)v;
    return 0;
  case K_INCLUDE:
    return add_include(c, value);
  case K_READ_PATH:
    return add_dir(c, &o->read_paths, &o->n_read_paths, value);
  case K_WRITE_PATH:
    return add_dir(c, &o->write_paths, &o->n_write_paths, value);
  case K_IO_RESTRICTIONS:
    return set_io_restrictions(c, value);
  case K_VERBOSE:
    o->verbose = 1;
    o->quiet = 0;
    return 0;
  case K_NOVERBOSE:
    o->verbose = 0;
    return 0;
  case K_QUIET:
    o->quiet = 1;
    o->verbose = 0;
    return 0;
  case K_HELP:
    o->help = 1;
    return 0;
  case K_VERSION:
    o->version = 1;
    return 0;
  case K_PARSE_ONLY:
    o->parse_only = 1;
    return 0;
  case K_LOOP_LIMIT: {
    /* strtoull would take "-1" as a huge number: digits only. */
    char *end = NULL;
    errno = 0;
    unsigned long long n = value && isdigit((unsigned char)*value)
                               ? strtoull(value, &end, 10) : 0;
    if (!end || *end || errno)
      return fail(c, "'%s': --max-work must be a whole number "
                     "(0: no limit)", c->what);
    o->loop_limit = n;
    return 0;
  }
  case K_MEMORY_LIMIT:
  case K_FILE_LIMIT: {
    unsigned long long n;
    if (parse_size(value, &n) < 0)
      return fail(c, "'%s': --%s must be a size in bytes, with an "
                     "optional K, M, G or T (binary units; 0: no limit)",
                  c->what, key == K_MEMORY_LIMIT ? "memory-limit"
                                                 : "max-file-size");
    if (key == K_MEMORY_LIMIT) {
      o->memory_limit = n;
      o->memory_limit_given = 1;
    } else {
      o->file_limit = n;
    }
    return 0;
  }
  case K_IGNORED:
    return 0;
  case K_OUTPUT_ON:
    o->write_output = 1;
    return value ? set_format(c, value) : 0;
  case K_OUTPUT_OFF:
    o->write_output = 0;
    return value ? set_format(c, value) : 0;
  case K_FORMAT:
    return set_format(c, value);
  case K_BITS:
    return set_bits(c, value);
  case K_RADIOSITY:
  case K_BF_EPS:
  case K_AREA_EPS:
  case K_VIS_RAYS:
  case K_UNIFORM:
  case K_MAX_ITERATIONS:
  case K_RESIDUAL:
  case K_SHOOTING:
  case K_ONE_SIDED:
  case K_RAD_ONLY:
  case K_RAD_STATS:
  case K_RAD_SAVE:
  case K_RAD_LOAD:
  case K_RAD_MESH:
    return apply_radiosity(c, key, value);
  case K_GI:
    return set_gi(c, value);
  case K_NO_RADIOSITY:
    o->gi = ZR_GI_OFF;
    return 0;
  case K_RADIOSITY_ON:
    if (o->gi == ZR_GI_OFF)
      o->gi = ZR_GI_AUTO;
    return 0;
  case K_QUALITY:
    return set_quality(c, value);
  case K_GI_SAVE:
    return set_string(c, &o->gi_save, value);
  case K_GI_LOAD:
    return set_string(c, &o->gi_load, value);
  }
  return fail(c, "'%s': internal error: unhandled option", c->what);
}

/* ---- POV-Ray switches: +X / -X ------------------------------------- */

/* How a switch takes its value. */
typedef enum value_rule {
  V_NONE,     /* nothing may follow the letters */
  V_OPTIONAL, /* +A or +A0.3 */
  V_REQUIRED, /* +W640 */
  V_ANY       /* anything follows and is ignored (+D0) */
} value_rule;

typedef struct pov_switch {
  const char *letters; /* longest first where one is a prefix of another */
  opt_key on;          /* after + */
  opt_key off;         /* after - */
  value_rule rule;
  const char *needs; /* what a missing value should have been */
} pov_switch;

static const pov_switch pov_switches[] = {
    {"WT", K_THREADS, K_THREADS, V_REQUIRED, "a number of threads, as in +WT4"},
    {"W", K_WIDTH, K_WIDTH, V_REQUIRED, "a width, as in +W640"},
    {"H", K_HEIGHT, K_HEIGHT, V_REQUIRED, "a height, as in +H480"},
    {"I", K_INPUT, K_INPUT, V_REQUIRED, "a file name, as in +Iscene.pov"},
    {"O", K_OUTPUT, K_OUTPUT, V_REQUIRED, "a file name, as in +Oimage.png"},
    {"L", K_INCLUDE, K_INCLUDE, V_REQUIRED, "a directory, as in +Linclude"},
    {"AM", K_SAMPLING, K_SAMPLING, V_REQUIRED, "a method, as in +AM1"},
    {"A", K_AA_ON, K_AA_OFF, V_OPTIONAL, NULL},
    {"R", K_AA_DEPTH, K_AA_DEPTH, V_REQUIRED, "a depth, as in +R3"},
    {"J", K_JITTER_ON, K_JITTER_OFF, V_OPTIONAL, NULL},
    {"F", K_OUTPUT_ON, K_OUTPUT_OFF, V_OPTIONAL, NULL},
    {"V", K_VERBOSE, K_NOVERBOSE, V_NONE, NULL},
    {"D", K_IGNORED, K_IGNORED, V_ANY, NULL},
    {"P", K_IGNORED, K_IGNORED, V_NONE, NULL},
    {"Q", K_QUALITY, K_QUALITY, V_REQUIRED, "a quality, as in +Q9"},
};

static int parse_switch(arg_ctx *c, const char *arg) {
  int plus = arg[0] == '+';
  const char *body = arg + 1;
  /* GNU habits that do not clash with POV-Ray's letters. */
  if (!strcmp(body, "?") || !strcmp(arg, "-h"))
    return apply(c, K_HELP, NULL);
  if (!strcmp(arg, "-v"))
    return apply(c, K_VERBOSE, NULL);
  if (!strcmp(arg, "-q"))
    return apply(c, K_QUIET, NULL);
  /* Before +A, which would take "G2.2" for its threshold. */
  if (!strncasecmp(body, "AG", 2))
    return fail(c, "'%s': the antialiasing gamma (+AG) is not supported",
                arg);
  for (size_t i = 0; i < sizeof pov_switches / sizeof *pov_switches; i++) {
    const pov_switch *sw = &pov_switches[i];
    size_t n = strlen(sw->letters);
    if (strncasecmp(body, sw->letters, n) != 0)
      continue;
    const char *value = body + n;
    opt_key key = plus ? sw->on : sw->off;
    switch (sw->rule) {
    case V_NONE:
      if (*value)
        break; /* +Vx: not this switch; an unknown one */
      return apply(c, key, NULL);
    case V_OPTIONAL:
      return apply(c, key, *value ? value : NULL);
    case V_REQUIRED:
      if (!*value)
        return fail(c, "'%s' needs %s", arg, sw->needs);
      return apply(c, key, value);
    case V_ANY:
      return apply(c, key, NULL);
    }
    break;
  }
  return fail(c, "unknown option '%s' (try 'zrcube --help')", arg);
}

/* ---- GNU long options: --name, --name=value, --name value ---------- */

typedef enum long_rule { L_NONE, L_OPTIONAL, L_REQUIRED } long_rule;

typedef struct long_option {
  const char *name;
  opt_key key;
  long_rule rule;
} long_option;

static const long_option long_options[] = {
    {"input", K_INPUT, L_REQUIRED},
    {"output", K_OUTPUT, L_REQUIRED},
    {"width", K_WIDTH, L_REQUIRED},
    {"height", K_HEIGHT, L_REQUIRED},
    {"antialias", K_AA_ON, L_OPTIONAL},
    {"no-antialias", K_AA_OFF, L_NONE},
    {"aa-depth", K_AA_DEPTH, L_REQUIRED},
    {"jitter", K_JITTER_ON, L_OPTIONAL},
    {"no-jitter", K_JITTER_OFF, L_NONE},
    {"threads", K_THREADS, L_REQUIRED},
    {"include-path", K_INCLUDE, L_REQUIRED},
    {"verbose", K_VERBOSE, L_NONE},
    {"quiet", K_QUIET, L_NONE},
    {"help", K_HELP, L_NONE},
    {"version", K_VERSION, L_NONE},
    {"parse-only", K_PARSE_ONLY, L_NONE},
    {"max-loop-iterations", K_LOOP_LIMIT, L_REQUIRED},
    {"max-work", K_LOOP_LIMIT, L_REQUIRED},
    {"memory-limit", K_MEMORY_LIMIT, L_REQUIRED},
    {"max-file-size", K_FILE_LIMIT, L_REQUIRED},
    {"radiosity", K_RADIOSITY, L_NONE},
    {"bf-eps", K_BF_EPS, L_REQUIRED},
    {"area-eps", K_AREA_EPS, L_REQUIRED},
    {"vis-rays", K_VIS_RAYS, L_REQUIRED},
    {"uniform", K_UNIFORM, L_REQUIRED},
    {"max-iterations", K_MAX_ITERATIONS, L_REQUIRED},
    {"residual", K_RESIDUAL, L_REQUIRED},
    {"shooting", K_SHOOTING, L_NONE},
    {"one-sided-emission", K_ONE_SIDED, L_OPTIONAL},
    {"radiosity-only", K_RAD_ONLY, L_NONE},
    {"radiosity-stats", K_RAD_STATS, L_NONE},
    {"radiosity-save", K_RAD_SAVE, L_REQUIRED},
    {"radiosity-load", K_RAD_LOAD, L_REQUIRED},
    {"radiosity-mesh", K_RAD_MESH, L_REQUIRED},
    {"read-path", K_READ_PATH, L_REQUIRED},
    {"write-path", K_WRITE_PATH, L_REQUIRED},
    {"io-restrictions", K_IO_RESTRICTIONS, L_REQUIRED},
    {"gi", K_GI, L_REQUIRED},
    {"no-radiosity", K_NO_RADIOSITY, L_NONE},
    {"quality", K_QUALITY, L_REQUIRED},
    {"gi-save", K_GI_SAVE, L_REQUIRED},
    {"gi-load", K_GI_LOAD, L_REQUIRED},
};

/* Returns how many extra arguments it used (0 or 1), or -1 on failure. */
static int parse_long(arg_ctx *c, const char *arg, const char *next) {
  const char *name = arg + 2;
  const char *eq = strchr(name, '=');
  size_t len = eq ? (size_t)(eq - name) : strlen(name);
  for (size_t i = 0; i < sizeof long_options / sizeof *long_options; i++) {
    const long_option *lo = &long_options[i];
    if (strlen(lo->name) != len || strncmp(name, lo->name, len) != 0)
      continue;
    switch (lo->rule) {
    case L_NONE:
      if (eq)
        return fail(c, "'%s': --%s takes no value", arg, lo->name);
      return apply(c, lo->key, NULL);
    case L_OPTIONAL:
      return apply(c, lo->key, eq ? eq + 1 : NULL);
    case L_REQUIRED:
      if (eq)
        return apply(c, lo->key, eq + 1);
      if (!next)
        return fail(c, "'%s' needs a value", arg);
      {
        /* Messages quote "--width=abc" for "--width abc" too. */
        size_t n = strlen(arg) + strlen(next) + 2;
        char *what = malloc(n);
        if (!what)
          return fail(c, "out of memory");
        snprintf(what, n, "%s=%s", arg, next);
        arg_ctx sub = *c;
        sub.what = what;
        int rc = apply(&sub, lo->key, next);
        free(what);
        return rc < 0 ? -1 : 1;
      }
    }
  }
  return fail(c, "unknown option '%.*s' (try 'zrcube --help')",
              (int)(len + 2), arg);
}

/* ---- INI options: Key=Value ---------------------------------------- */

typedef struct ini_option {
  const char *name;
  opt_key key;   /* with a value */
  int boolean;   /* 1: on/off selects between key and off */
  opt_key off;
} ini_option;

static const ini_option ini_options[] = {
    {"Input_File_Name", K_INPUT, 0, K_INPUT},
    {"Output_File_Name", K_OUTPUT, 0, K_OUTPUT},
    {"Width", K_WIDTH, 0, K_WIDTH},
    {"Height", K_HEIGHT, 0, K_HEIGHT},
    {"Antialias", K_AA_ON, 1, K_AA_OFF},
    {"Antialias_Threshold", K_AA_THRESHOLD, 0, K_AA_THRESHOLD},
    {"Antialias_Depth", K_AA_DEPTH, 0, K_AA_DEPTH},
    {"Sampling_Method", K_SAMPLING, 0, K_SAMPLING},
    {"Jitter", K_JITTER_ON, 1, K_JITTER_OFF},
    {"Jitter_Amount", K_JITTER_AMOUNT, 0, K_JITTER_AMOUNT},
    {"Work_Threads", K_THREADS, 0, K_THREADS},
    {"Library_Path", K_INCLUDE, 0, K_INCLUDE},
    {"Verbose", K_VERBOSE, 1, K_NOVERBOSE},
    {"Display", K_IGNORED, 1, K_IGNORED},
    {"Pause_When_Done", K_IGNORED, 1, K_IGNORED},
    {"Output_To_File", K_OUTPUT_ON, 1, K_OUTPUT_OFF},
    {"Output_File_Type", K_FORMAT, 0, K_FORMAT},
    {"Bits_Per_Color", K_BITS, 0, K_BITS},
    /* zrcube's own keys for what POV-Ray 3.7 sets in povray.conf
       ([Permitted Paths] read= and read+write=, [File I/O Security]);
       the plural spellings are accepted too. */
    {"Read_Path", K_READ_PATH, 0, K_READ_PATH},
    {"Read_Paths", K_READ_PATH, 0, K_READ_PATH},
    {"Write_Path", K_WRITE_PATH, 0, K_WRITE_PATH},
    {"Write_Paths", K_WRITE_PATH, 0, K_WRITE_PATH},
    {"IO_Restrictions", K_IO_RESTRICTIONS, 0, K_IO_RESTRICTIONS},
    {"Quality", K_QUALITY, 0, K_QUALITY},
    {"Radiosity", K_RADIOSITY_ON, 1, K_NO_RADIOSITY},
};

/* arg is "Key=Value"; POV-Ray's keys are case-insensitive. */
static int parse_ini_option(arg_ctx *c, const char *arg) {
  const char *eq = strchr(arg, '=');
  size_t len = (size_t)(eq - arg);
  while (len > 0 && isspace((unsigned char)arg[len - 1]))
    len--;
  const char *value = eq + 1;
  while (isspace((unsigned char)*value))
    value++;
  for (size_t i = 0; i < sizeof ini_options / sizeof *ini_options; i++) {
    const ini_option *io = &ini_options[i];
    if (strlen(io->name) != len || strncasecmp(arg, io->name, len) != 0)
      continue;
    if (!*value)
      return fail(c, "'%s' needs a value", arg);
    if (io->boolean) {
      int on;
      if (!parse_bool(value, &on))
        return fail(c, "'%s': expected on or off", arg);
      return apply(c, on ? io->key : io->off, NULL);
    }
    return apply(c, io->key, value);
  }
  return fail(c, "unknown option '%.*s' (try 'zrcube --help')", (int)len,
              arg);
}

static int parse_word(arg_ctx *c, const char *word, const char *next);

static int has_suffix(const char *s, const char *suffix) {
  size_t n = strlen(s), m = strlen(suffix);
  return n >= m && !strcasecmp(s + n - m, suffix);
}

/*
 * Reads an INI file: one option per line (Key=Value or switches), ';'
 * starts a comment.  As POV-Ray does without a [section] request, only
 * the lines before the first [section] header are read.
 */
static int parse_ini_file(arg_ctx *c, const char *path) {
  FILE *f = fopen(path, "r");
  if (!f)
    return fail(c, "cannot open '%s': %s", path, strerror(errno));
  char line[4096];
  int lineno = 0, rc = 0;
  while (rc == 0 && fgets(line, sizeof line, f)) {
    lineno++;
    char *semi = strchr(line, ';');
    if (semi)
      *semi = '\0';
    char *s = line;
    while (isspace((unsigned char)*s))
      s++;
    size_t n = strlen(s);
    while (n > 0 && isspace((unsigned char)s[n - 1]))
      s[--n] = '\0';
    if (!*s)
      continue;
    if (*s == '[')
      break;
    size_t where_size = strlen(path) + 32;
    char *where = malloc(where_size);
    if (!where) {
      rc = fail(c, "out of memory");
      break;
    }
    snprintf(where, where_size, "%s:%d: ", path, lineno);
    arg_ctx sub = *c;
    sub.where = where;
    sub.what = s;
    if (*s == '+' || *s == '-') {
      /* A line may hold several switches separated by blanks. */
      for (char *tok = strtok(s, " \t"); tok && rc == 0;
           tok = strtok(NULL, " \t")) {
        sub.what = tok;
        rc = parse_word(&sub, tok, NULL) < 0 ? -1 : 0;
      }
    } else {
      rc = parse_word(&sub, s, NULL) < 0 ? -1 : 0;
    }
    free(where);
  }
  fclose(f);
  return rc;
}

/* Key=Value with a key made of letters, digits and underscores (so a
   file name holding '=' is still a file name). */
static int is_ini_option(const char *word) {
  const char *p = word;
  while (isalnum((unsigned char)*p) || *p == '_')
    p++;
  while (p > word && (*p == ' ' || *p == '\t'))
    p++;
  return p > word && *p == '=';
}

/* One word of the command line; returns extra words used, or -1. */
static int parse_word(arg_ctx *c, const char *word, const char *next) {
  c->what = word;
  if (word[0] == '-' && word[1] == '-' && word[2])
    return parse_long(c, word, next);
  if ((word[0] == '+' || word[0] == '-') && word[1])
    return parse_switch(c, word);
  if (is_ini_option(word))
    return parse_ini_option(c, word);
  if (has_suffix(word, ".ini"))
    return parse_ini_file(c, word);
  return set_input(c, word);
}

int zr__cli_parse(zr_cli_options *o, int argc, char **argv, char *err,
                  size_t err_size) {
  arg_ctx c = {o, err, err_size, "", ""};
  if (err_size)
    err[0] = '\0';
  int only_files = 0;
  for (int i = 1; i < argc; i++) {
    if (only_files) {
      c.what = argv[i];
      if (set_input(&c, argv[i]) < 0)
        return -1;
      continue;
    }
    if (!strcmp(argv[i], "--")) {
      only_files = 1;
      continue;
    }
    int used = parse_word(&c, argv[i], i + 1 < argc ? argv[i + 1] : NULL);
    if (used < 0)
      return -1;
    i += used;
  }
  return 0;
}

/* ---- the image file name ------------------------------------------- */

static const char *format_extension(zr_image_format format) {
  switch (format) {
  case ZR_FORMAT_PPM:
    return ".ppm";
  case ZR_FORMAT_PFM:
    return ".pfm";
  default:
    return ".png";
  }
}

/* The extension of a file name's last component ("" when none). */
static const char *extension_of(const char *path) {
  const char *base = strrchr(path, '/');
  base = base ? base + 1 : path;
  const char *dot = strrchr(base, '.');
  return dot && dot != base ? dot : "";
}

static zr_image_format format_of_extension(const char *ext) {
  if (!strcasecmp(ext, ".png"))
    return ZR_FORMAT_PNG8;
  if (!strcasecmp(ext, ".ppm"))
    return ZR_FORMAT_PPM;
  if (!strcasecmp(ext, ".pfm"))
    return ZR_FORMAT_PFM;
  return ZR_FORMAT_AUTO;
}

/* dir (may be NULL or end in '/') + the scene's base name + ext. */
static char *default_name(const char *dir, const char *input,
                          const char *ext) {
  const char *base = strrchr(input, '/');
  base = base ? base + 1 : input;
  size_t stem = strlen(base) - strlen(extension_of(base));
  size_t dir_len = dir ? strlen(dir) : 0;
  int slash = dir_len > 0 && dir[dir_len - 1] != '/';
  size_t n = dir_len + (size_t)slash + stem + strlen(ext) + 1;
  char *name = malloc(n);
  if (name)
    snprintf(name, n, "%s%s%.*s%s", dir ? dir : "", slash ? "/" : "",
             (int)stem, base, ext);
  return name;
}

/* path + ext, malloc'ed. */
static char *with_extension(const char *path, const char *ext) {
  size_t n = strlen(path) + strlen(ext) + 1;
  char *name = malloc(n);
  if (name)
    snprintf(name, n, "%s%s", path, ext);
  return name;
}

static const char *kind_of(mode_t mode) {
  return S_ISDIR(mode)    ? "a directory"
         : S_ISCHR(mode)  ? "a character device"
         : S_ISBLK(mode)  ? "a block device"
         : S_ISFIFO(mode) ? "a FIFO"
         : S_ISSOCK(mode) ? "a socket"
                          : "not a regular file";
}

static int same_file(const char *a, const char *b) {
  if (!strcmp(a, b))
    return 1;
  struct stat sa, sb;
  return stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev &&
         sa.st_ino == sb.st_ino;
}

int zr__cli_output_path(const zr_cli_options *o, char **path,
                        zr_image_format *format, char *err,
                        size_t err_size) {
  arg_ctx c = {(zr_cli_options *)o, err, err_size, "", ""};
  *path = NULL;
  if (!o->input)
    return fail(&c, "no scene file given (try 'zrcube --help')");
  zr_image_format fmt = o->format;
  char *name;
  struct stat st;
  const char *out = o->output;
  size_t out_len = out ? strlen(out) : 0;
  /* A device, FIFO or socket is never an image file: writing next to
     it under another name would surprise as much as writing into it. */
  if (out && stat(out, &st) == 0 && !S_ISDIR(st.st_mode) &&
      !S_ISREG(st.st_mode))
    return fail(&c, "cannot write the image to '%s': it is %s, not a "
                    "regular file or a directory", out, kind_of(st.st_mode));
  if (!out || (out_len > 0 && out[out_len - 1] == '/') ||
      (stat(out, &st) == 0 && S_ISDIR(st.st_mode))) {
    /* POV-Ray: no name, or a directory, means the scene's base name. */
    if (fmt == ZR_FORMAT_AUTO)
      fmt = ZR_FORMAT_PNG8;
    name = default_name(out, o->input, format_extension(fmt));
  } else {
    if (same_file(out, o->input))
      return fail(&c, "refusing to overwrite the scene file '%s' with the "
                      "image", o->input);
    const char *ext = extension_of(out);
    zr_image_format by_name = format_of_extension(ext);
    if (fmt == ZR_FORMAT_AUTO && *ext && by_name == ZR_FORMAT_AUTO)
      return fail(&c, "cannot write '%s': the output name must end in "
                      ".png, .ppm or .pfm (or give the type with +FN or "
                      "+FP)", out);
    if (fmt == ZR_FORMAT_AUTO)
      fmt = by_name == ZR_FORMAT_AUTO ? ZR_FORMAT_PNG8 : by_name;
    /* As POV-Ray does, a name without an extension gets the type's, in
       the folder the name gives (+Odir/abc writes dir/abc.png). */
    name = *ext ? strdup(out) : with_extension(out, format_extension(fmt));
  }
  if (!name)
    return fail(&c, "out of memory");
  if (stat(name, &st) == 0 && !S_ISREG(st.st_mode)) {
    fail(&c, "cannot write the image to '%s': it is %s, not a regular "
             "file", name, kind_of(st.st_mode));
    free(name);
    return -1;
  }
  if (same_file(name, o->input)) {
    fail(&c, "refusing to overwrite the scene file '%s' with the image",
         o->input);
    free(name);
    return -1;
  }
  *path = name;
  *format = fmt;
  return 0;
}

int zr__cli_check_size(const zr_cli_options *o, char *err,
                       size_t err_size) {
  arg_ctx c = {(zr_cli_options *)o, err, err_size, "", ""};
  unsigned long long w = (unsigned long long)o->params.width;
  unsigned long long h = (unsigned long long)o->params.height;
  if (w * h > (unsigned long long)ZR_IMAGE_MAX_PIXELS)
    return fail(&c, "an image of %llux%llu is %llu pixels, more than the "
                    "limit of %llu (2^27) pixels; make +W or +H smaller",
                w, h, w * h, (unsigned long long)ZR_IMAGE_MAX_PIXELS);
  return 0;
}

const char *zr__cli_usage(void) {
  return
      "Usage: zrcube [OPTION]... SCENE.pov\n"
      "       mpirun -n N zrcube [OPTION]... SCENE.pov\n"
      "Render a POV-Ray 3.7 scene to an image, on one process or on all\n"
      "processes of an MPI job.  Options take POV-Ray's form (+W640,\n"
      "letters in any case), its INI form (Width=640) or GNU's\n"
      "(--width=640); files ending in .ini hold more options.\n"
      "\n"
      "  +I<file>, --input=FILE       the scene (or give it as an argument)\n"
      "  +O<file>, --output=FILE      the image: .png, .ppm or .pfm by its\n"
      "                               extension (default: SCENE.png here);\n"
      "                               a directory puts SCENE.png in it, a\n"
      "                               name without extension gets .png\n"
      "  +FN, +FN16, +FP              PNG (8 or 16 bit) or PPM output\n"
      "  -F                           render without writing an image\n"
      "  +W<n>, --width=N             image width in pixels (default 320)\n"
      "  +H<n>, --height=N            image height in pixels (default 240);\n"
      "                               at most 65535 a side and 2^27\n"
      "                               (134217728) pixels in all\n"
      "  +A[t], --antialias[=T]       antialias, threshold T (default 0.3)\n"
      "  -A, --no-antialias           no antialiasing (default)\n"
      "  +R<n>, --aa-depth=N          n*n samples per antialiased pixel\n"
      "                               (1 to 9, default 3)\n"
      "  +J[a], --jitter[=A]          jitter supersamples by A (default 1)\n"
      "  -J, --no-jitter              no jitter (default)\n"
      "  +L<dir>, --include-path=DIR  search DIR for #include files\n"
      "                               (repeatable, searched in order)\n"
      "  +WT<n>, --threads=N          threads per process (default: the\n"
      "                               processors of the host shared among\n"
      "                               its processes)\n"
      "  +V, -v, --verbose            print render statistics\n"
      "  -V                           no statistics (default)\n"
      "  -q, --quiet                  no progress line and no warnings\n"
      "  --parse-only                 parse the scene, print what it holds\n"
      "                               and the parse time, render nothing\n"
      "  --max-work=N                 stop a parse after N steps (each\n"
      "                               directive, macro call and loop pass\n"
      "                               is one; default 200000000; 0: no\n"
      "                               limit); --max-loop-iterations=N is\n"
      "                               the older name\n"
      "  --memory-limit=SIZE          the run's memory budget (K, M, G, T:\n"
      "                               binary units; default half of\n"
      "                               physical memory; 0: no limit)\n"
      "  --max-file-size=SIZE         the largest file a scene may read\n"
      "                               (default 1G; 0: no limit)\n"
      "  --read-path=DIR              let scenes read below DIR too\n"
      "  --write-path=DIR             let scenes write below DIR too\n"
      "  --io-restrictions=MODE       restricted (default: scenes read\n"
      "                               below their folder, the working\n"
      "                               directory and the include paths and\n"
      "                               write below the working directory),\n"
      "                               read-only or none\n"
      "  +D, -D, +P, -P               accepted and ignored (no display)\n"
      "\n"
      "Radiosity (hierarchical, on the exact surfaces; any of these turns\n"
      "it on):\n"
      "  --gi=MODEL                   global illumination: auto (default:\n"
      "                               by the scene, see zrcube(1)),\n"
      "                               hierarchical, cache or off\n"
      "  --no-radiosity, +Q8          no global illumination (classic\n"
      "                               ambient; +Q0 to +Q8, Radiosity=off)\n"
      "  --gi-save=FILE               save the irradiance cache\n"
      "  --gi-load=FILE               start from a saved irradiance cache\n"
      "  --radiosity                  solve diffuse interreflection from\n"
      "                               emitting surfaces and light sources,\n"
      "                               then render with it\n"
      "  --bf-eps=X                   refinement threshold, a fraction of\n"
      "                               the emitted and light sources'\n"
      "                               power (default 1e-4)\n"
      "  --area-eps=X                 smallest element, a fraction of the\n"
      "                               total area (default 1e-4)\n"
      "  --vis-rays=K                 K x K rays per link's visibility (4)\n"
      "  --uniform=N                  N x N elements per surface, no\n"
      "                               refinement (N a power of two)\n"
      "  --max-iterations=N           sweeps or shots at most (1000)\n"
      "  --residual=X                 stop below this change (1e-6)\n"
      "  --shooting                   progressive shooting, not gathering\n"
      "  --one-sided-emission[=0|1]   emit from the front side only\n"
      "                               (default 1; 0 as POV-Ray shows it)\n"
      "  --radiosity-only             show the solution alone\n"
      "  --radiosity-stats            key=value statistics on stderr\n"
      "  --radiosity-save=FILE        save the solution\n"
      "  --radiosity-load=FILE        render with a saved solution\n"
      "  --radiosity-mesh=FILE        also write the solution's mesh:\n"
      "                               elements flat, edges drawn over\n"
      "\n"
      "  -h, --help                   show this help and exit\n"
      "  --version                    show the version and exit\n"
      "\n"
      "Exit status: 0 on success, 1 when the scene cannot be read, parsed\n"
      "or rendered or the image cannot be written, 2 for a command line\n"
      "error.  See zrcube(1).\n";
}
