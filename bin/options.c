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

/* Where POV-Ray for Unix keeps the system's povray.ini (Debian's
   povray package; README.unix "INI files"). */
#ifndef ZR_POVRAY_SYSCONF_INI
#define ZR_POVRAY_SYSCONF_INI "/etc/povray/3.7/povray.ini"
#endif

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
  K_PNG_LEVEL,
  K_ACCEL,
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
  K_BOUNCES,
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
  K_COMPRESSION,  /* Compression=n: the JPEG quality */
  K_GI_SAVE,
  K_GI_LOAD,
  K_SPP,          /* --spp=N: the path tracer's samples per pixel */
  K_PATH_SEED,    /* --path-seed=N */
  /* Animation (reference 3.2.1). */
  K_CLOCK,
  K_INITIAL_FRAME,
  K_FINAL_FRAME,
  K_INITIAL_CLOCK,
  K_FINAL_CLOCK,
  K_CYCLIC_ON,
  K_CYCLIC_OFF,
  K_SUBSET_START,
  K_SUBSET_END,
  K_FRAME_STEP,
  K_FRAMES_PER_RANK, /* optional yes|no|auto */
  /* Partial renders and continuing (3.2.2.3, 3.2.2.5). */
  K_START_ROW,
  K_END_ROW,
  K_START_COL,
  K_END_COL,
  K_CONTINUE_ON,
  K_ALPHA_ON,     /* +UA, Output_Alpha=on */
  K_ALPHA_OFF,
  K_CONTINUE_OFF,
  K_STATE_INTERVAL,
  K_FILE_GAMMA,   /* File_Gamma=sRGB|G (3.2.4.7) */
  /* Scene parsing (3.2.5). */
  K_DECLARE,
  K_LANG_VERSION,
  K_HEADER,
  /* Text streams (3.2.7): console on and off, file; each for debug,
     fatal, render, statistics, warning and all five, in that order. */
  K_CONSOLE_ON,
  K_CONSOLE_OFF = K_CONSOLE_ON + ZR_CLI_STREAMS + 1,
  K_STREAM_FILE = K_CONSOLE_OFF + ZR_CLI_STREAMS + 1,
  K_WARNING_LEVEL = K_STREAM_FILE + ZR_CLI_STREAMS + 1,
  K_NOTE /* read, not acted on: a warning names it (o->notes) */
} opt_key;

/* Where the option being applied came from, for messages. */
typedef struct arg_ctx {
  zr_cli_options *o;
  char *err;
  size_t err_size;
  const char *where; /* "file.ini:3: " or "" */
  const char *what;  /* the option as written: "+Wabc", "--width=abc" */
  const char *why;   /* K_NOTE: why zrcube does not act on it */
  int depth;         /* INI files open (an INI names another) */
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
  o->ini_format = ZR_FORMAT_AUTO;
  o->write_output = 1;
  o->loop_limit = ZR_DEFAULT_WORK_LIMIT;
  o->file_limit = ZR_DEFAULT_FILE_LIMIT;
  o->png_level = ZR_DEFAULT_PNG_LEVEL;
  o->accel = ZR_ACCEL_DEFAULT;
  /* The library's defaults are the command line's (issue 11). */
  zr_radiosity_params_init(&o->rad, NULL);
  o->gi = ZR_GI_AUTO;
  o->quality = 9;
  o->initial_frame = 1;
  o->final_frame = 1;
  o->final_clock = 1;
  o->subset_start = o->subset_end = -1;
  o->frame_step = 1;
  o->frames_per_rank = -1;
  o->start_row = o->end_row = o->start_col = o->end_col = -1;
  o->state_interval = 10;
  for (int i = 0; i < ZR_CLI_STREAMS; i++)
    o->stream_console[i] = 1;
  o->spp = 64;
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
  for (size_t i = 0; i < o->n_declares; i++)
    free(o->declare_names[i]);
  free(o->declare_names);
  free(o->declare_values);
  for (int i = 0; i < ZR_CLI_STREAMS; i++)
    free(o->stream_file[i]);
  free(o->header_include);
  for (size_t i = 0; i < o->n_notes; i++)
    free(o->notes[i]);
  free(o->notes);
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
  else if (!strcasecmp(value, "strict"))
    o->io_mode = ZR_IO_STRICT;
  else
    return fail(c, "'%s': the I/O restrictions are 'restricted' (or "
                   "'on'), 'strict', 'read-only' or 'none' (or 'off')",
                c->what);
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
  if (o->format != ZR_FORMAT_PPM && o->format != ZR_FORMAT_PNG8 &&
      o->format != ZR_FORMAT_PNG16 && o->format != ZR_FORMAT_AUTO &&
      bits != 8)
    return fail(c, "'%s': only PNG files take 16 bits per colour",
                c->what);
  if (o->format != ZR_FORMAT_PPM && o->format != ZR_FORMAT_PNG8 &&
      o->format != ZR_FORMAT_PNG16 && o->format != ZR_FORMAT_AUTO)
    return 0; /* 8 bits: what TGA and JPEG store anyway */
  if (o->format != ZR_FORMAT_PPM)
    o->format = bits == 16 ? ZR_FORMAT_PNG16 : ZR_FORMAT_PNG8;
  return 0;
}

/* The names of POV-Ray's other output types, to refuse them by name. */
static const char *pov_type_name(char type) {
  switch (toupper((unsigned char)type)) {
  case 'E':
    return "OpenEXR";
  case 'S':
    return "system-specific";
  default:
    return NULL;
  }
}

static int add_note(const arg_ctx *c, const char *why);

/* +F's value: a type letter, then optionally the bits per colour. */
static int set_format(const arg_ctx *c, const char *value) {
  zr_cli_options *o = c->o;
  char type = (char)toupper((unsigned char)value[0]);
  if (type == 'N') {
    o->format = ZR_FORMAT_PNG8;
  } else if (type == 'P') {
    o->format = ZR_FORMAT_PPM;
  } else if (type == 'J') {
    /* The digits after +FJ are bits per colour, as after every type
       letter; povray 3.7 ignores them for JPEG (measured: +FJ, +FJ2 and
       +FJ100 write the same bytes) and takes the quality from
       Compression= alone. */
    o->format = ZR_FORMAT_JPEG;
    if (!value[1])
      return 0;
    long bits;
    if (!parse_int(value + 1, 0, 1000000, &bits))
      return fail(c, "'%s': bits per colour must be a whole number",
                  c->what);
    return add_note(c, "ignored: JPEG files take no bits per colour (set "
                       "the JPEG quality with Compression=N)");
  } else if (type == 'B') {
    o->format = ZR_FORMAT_BMP;
    if (value[1])
      return set_bits(c, value + 1);
    return 0;
  } else if (type == 'T' || type == 'C' || type == 'H' ||
             (type == 'E' && zr_image_format_supported(ZR_FORMAT_EXR))) {
    o->format = type == 'T'   ? ZR_FORMAT_TGA
                : type == 'C' ? ZR_FORMAT_TGA_RLE
                : type == 'H' ? ZR_FORMAT_HDR
                              : ZR_FORMAT_EXR;
    if (value[1] && (type == 'H' || type == 'E'))
      return fail(c, "'%s': %s files hold floats; they take no bits per "
                     "colour", c->what, type == 'H' ? "HDR" : "OpenEXR");
  } else if (type == 'E') {
    return fail(c, "'%s': OpenEXR output is not supported: this zrcube "
                   "was built without OpenEXR", c->what);
  } else if (pov_type_name(type)) {
    return fail(c, "'%s': %s output is not supported (use N for PNG, J "
                   "for JPEG, T or C for Targa, B for BMP, H for HDR, E "
                   "for OpenEXR, P for PPM, or an output name ending in "
                   ".pfm)",
                c->what, pov_type_name(type));
  } else {
    return fail(c, "'%s': unknown output file type '%c' (use N for PNG, "
                   "J for JPEG, T or C for Targa, B for BMP, H for HDR, E "
                   "for OpenEXR or P for PPM)", c->what, value[0]);
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

/* The radiosity options; any of them but --bounces turns radiosity on. */
static int apply_radiosity(const arg_ctx *c, opt_key key,
                           const char *value) {
  zr_cli_options *o = c->o;
  zr_radiosity_params *rp = &o->rad;
  double x;
  long v;
  /* --bounces applies where the solver is used and chooses nothing. */
  if (key != K_BOUNCES)
    o->radiosity = 1;
  /* Set before the value is checked: a bad value ends the run anyway. */
  o->rad_given |= key == K_BF_EPS           ? ZR_CLI_RAD_BF_EPS
                  : key == K_AREA_EPS       ? ZR_CLI_RAD_AREA_EPS
                  : key == K_VIS_RAYS       ? ZR_CLI_RAD_VIS_RAYS
                  : key == K_MAX_ITERATIONS ? ZR_CLI_RAD_MAX_ITERATIONS
                  : key == K_RESIDUAL       ? ZR_CLI_RAD_RESIDUAL
                  : key == K_BOUNCES        ? ZR_CLI_RAD_BOUNCES
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
  case K_BOUNCES:
    if (value && strcmp(value, "all") == 0) {
      rp->bounces = 0;
      return 0;
    }
    if (!parse_int(value, 1, 1000000, &v))
      return fail(c, "'%s': --bounces takes all or a whole number from 1 "
                     "to 1000000", c->what);
    rp->bounces = (int)v;
    return 0;
  case K_SHOOTING:
    rp->shooting = 1;
    return 0;
  case K_ONE_SIDED:
    if (!value) {
      rp->one_sided_emission = 1;
      return 0;
    }
    if (strcmp(value, "open") == 0) {
      rp->one_sided_emission = 2;
      return 0;
    }
    if (!parse_bool(value, &rp->one_sided_emission))
      return fail(c, "'%s': --one-sided-emission takes 0 or 1 (or on, "
                     "off), or open", c->what);
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
  if (!(g & ZR_CLI_RAD_BOUNCES))
    out->bounces = sp.bounces;
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
  c->o->params.quality = (int)v; /* shadows, rays, media (zrcube(1)) */
  return 0;
}

/* A message for the caller to print as a warning after parsing: a key
   zrcube reads but does not act on. */
static int add_note(const arg_ctx *c, const char *why) {
  zr_cli_options *o = c->o;
  size_t n = strlen(c->where) + strlen(c->what) + strlen(why) + 8;
  char *text = malloc(n);
  char **grown = realloc(o->notes, (o->n_notes + 1) * sizeof *grown);
  if (!text || !grown) {
    free(text);
    if (grown)
      o->notes = grown;
    return fail(c, "out of memory");
  }
  snprintf(text, n, "%s'%s': %s", c->where, c->what, why);
  o->notes = grown;
  o->notes[o->n_notes++] = text;
  return 0;
}

static int set_frame(const arg_ctx *c, const char *value, long *out,
                     int *given) {
  long v;
  if (!parse_int(value, -1000000000L, 1000000000L, &v))
    return fail(c, "'%s': a frame number must be a whole number",
                c->what);
  *out = v;
  if (given)
    *given = 1;
  return 0;
}

static int set_clock_value(const arg_ctx *c, const char *value,
                           double *out) {
  if (!parse_real(value, out))
    return fail(c, "'%s': the clock must be a number", c->what);
  return 0;
}

/* A subset frame, a row or a column: a fraction when below 1 (0.n), a
   1-based number otherwise (reference 3.2.1.3 and 3.2.2.3). */
static int set_position(const arg_ctx *c, const char *value, double *out,
                        const char *what) {
  double v;
  if (!parse_real(value, &v) || v < 0 || (v >= 1 && v != floor(v)))
    return fail(c, "'%s': the %s must be a whole number from 1, or a "
                   "fraction from 0.0 to 1.0", c->what, what);
  *out = v;
  return 0;
}

/* Declare=NAME=VALUE: a float the scene sees as if #declared first. */
static int add_declare(const arg_ctx *c, const char *value) {
  zr_cli_options *o = c->o;
  const char *eq = strchr(value, '=');
  const char *p = value;
  if (isalpha((unsigned char)*p) || *p == '_')
    for (p++; isalnum((unsigned char)*p) || *p == '_'; p++)
      ;
  const char *name_end = p;
  while (p < (eq ? eq : p) && isspace((unsigned char)*p))
    p++;
  double v;
  const char *num = eq ? eq + 1 : "";
  while (isspace((unsigned char)*num))
    num++;
  if (!eq || name_end == value || p != eq || !parse_real(num, &v))
    return fail(c, "'%s': expected Declare=IDENTIFIER=FLOAT, as in "
                   "Declare=MyValue=24", c->what);
  size_t len = (size_t)(name_end - value);
  for (size_t i = 0; i < o->n_declares; i++)
    if (strlen(o->declare_names[i]) == len &&
        !strncmp(o->declare_names[i], value, len)) {
      o->declare_values[i] = v;
      return 0;
    }
  char **names = realloc(o->declare_names,
                         (o->n_declares + 1) * sizeof *names);
  if (!names)
    return fail(c, "out of memory");
  o->declare_names = names;
  double *values = realloc(o->declare_values,
                           (o->n_declares + 1) * sizeof *values);
  if (!values)
    return fail(c, "out of memory");
  o->declare_values = values;
  names[o->n_declares] = strndup(value, len);
  if (!names[o->n_declares])
    return fail(c, "out of memory");
  values[o->n_declares++] = v;
  return 0;
}

/* POV-Ray's default file of each stream (reference 3.2.7.3). */
static const char *const stream_default_file[ZR_CLI_STREAMS + 1] = {
    "DEBUG.OUT", "FATAL.OUT", "RENDER.OUT", "STATS.OUT", "WARNING.OUT",
    "ALLTEXT.OUT"};

/* Stream i (ZR_CLI_STREAMS: all five) to a file: a name, or true for
   the default name, or false for none. */
static int set_stream_file(const arg_ctx *c, int i, const char *value) {
  zr_cli_options *o = c->o;
  int on = 1;
  const char *name = value;
  if (parse_bool(value, &on))
    name = on ? stream_default_file[i] : NULL;
  int first = i == ZR_CLI_STREAMS ? 0 : i;
  int last = i == ZR_CLI_STREAMS ? ZR_CLI_STREAMS - 1 : i;
  for (int k = first; k <= last; k++) {
    free(o->stream_file[k]);
    o->stream_file[k] = NULL;
    if (name && !(o->stream_file[k] = strdup(name)))
      return fail(c, "out of memory");
  }
  return 0;
}

static int set_console(const arg_ctx *c, int i, int on) {
  int first = i == ZR_CLI_STREAMS ? 0 : i;
  int last = i == ZR_CLI_STREAMS ? ZR_CLI_STREAMS - 1 : i;
  for (int k = first; k <= last; k++)
    c->o->stream_console[k] = on;
  return 0;
}

static int apply_more(const arg_ctx *c, opt_key key, const char *value) {
  zr_cli_options *o = c->o;
  long v;
  double d;
  if (key >= K_CONSOLE_ON && key <= K_CONSOLE_ON + ZR_CLI_STREAMS) {
    int i = (int)(key - K_CONSOLE_ON);
    set_console(c, i, 1);
    return value ? set_stream_file(c, i, value) : 0;
  }
  if (key >= K_CONSOLE_OFF && key <= K_CONSOLE_OFF + ZR_CLI_STREAMS) {
    int i = (int)(key - K_CONSOLE_OFF);
    set_console(c, i, 0);
    return value ? set_stream_file(c, i, value) : 0;
  }
  if (key >= K_STREAM_FILE && key <= K_STREAM_FILE + ZR_CLI_STREAMS)
    return set_stream_file(c, (int)(key - K_STREAM_FILE), value);
  switch (key) {
  case K_CLOCK:
    o->clock_given = 1;
    return set_clock_value(c, value, &o->clock);
  case K_INITIAL_FRAME:
    return set_frame(c, value, &o->initial_frame, &o->initial_frame_given);
  case K_FINAL_FRAME:
    return set_frame(c, value, &o->final_frame, &o->final_frame_given);
  case K_INITIAL_CLOCK:
    return set_clock_value(c, value, &o->initial_clock);
  case K_FINAL_CLOCK:
    return set_clock_value(c, value, &o->final_clock);
  case K_CYCLIC_ON:
  case K_CYCLIC_OFF:
    o->cyclic = key == K_CYCLIC_ON;
    return 0;
  case K_SUBSET_START:
    return set_position(c, value, &o->subset_start, "subset frame");
  case K_SUBSET_END:
    return set_position(c, value, &o->subset_end, "subset frame");
  case K_FRAME_STEP:
    if (!parse_int(value, 1, 1000000000L, &v))
      return fail(c, "'%s': the frame step must be a whole number from 1",
                  c->what);
    o->frame_step = v;
    return 0;
  case K_FRAMES_PER_RANK: {
    int on;
    if (!value)
      o->frames_per_rank = 1;
    else if (!strcasecmp(value, "auto"))
      o->frames_per_rank = -1;
    else if (parse_bool(value, &on))
      o->frames_per_rank = on;
    else
      return fail(c, "'%s': --frames-per-rank takes yes, no or auto",
                  c->what);
    return 0;
  }
  case K_START_ROW:
    return set_position(c, value, &o->start_row, "row");
  case K_END_ROW:
    return set_position(c, value, &o->end_row, "row");
  case K_START_COL:
    return set_position(c, value, &o->start_col, "column");
  case K_END_COL:
    return set_position(c, value, &o->end_col, "column");
  case K_CONTINUE_ON:
  case K_CONTINUE_OFF:
    o->continue_trace = key == K_CONTINUE_ON;
    return 0;
  case K_ALPHA_ON:
  case K_ALPHA_OFF:
    o->params.alpha = key == K_ALPHA_ON;
    return 0;
  case K_STATE_INTERVAL:
    if (!parse_real(value, &d) || d < 0)
      return fail(c, "'%s': --state-interval takes seconds (0: after "
                     "every band of rows)", c->what);
    o->state_interval = d;
    return 0;
  case K_DECLARE:
    return add_declare(c, value);
  case K_LANG_VERSION:
    if (!parse_real(value, &d) || d < 1 || d > 3.8)
      return fail(c, "'%s': the language version must be a number from "
                     "1.0 to 3.7", c->what);
    o->lang_version = d;
    return 0;
  case K_HEADER:
    return set_string(c, &o->header_include, value);
  case K_WARNING_LEVEL:
    if (!parse_int(value, 0, 10, &v))
      return fail(c, "'%s': the warning level must be a whole number "
                     "from 0 to 10", c->what);
    /* Level 0 turns all warnings off; zrcube has no classes of
       warnings to tell the others apart. */
    if (v == 0)
      set_console(c, ZR_CLI_STREAM_WARNING, 0);
    return 0;
  case K_NOTE:
    return add_note(c, c->why ? c->why : "ignored");
  default:
    break;
  }
  return fail(c, "'%s': internal error: unhandled option", c->what);
}

static int apply(const arg_ctx *c, opt_key key, const char *value) {
  zr_cli_options *o = c->o;
  long v;
  switch (key) {
  case K_INPUT:
    return set_input(c, value);
  case K_OUTPUT:
    /* +O- : the image goes to standard output (reference 3.2.4.2). */
    o->to_stdout = !strcmp(value, "-");
    if (o->to_stdout) {
      free(o->output);
      o->output = NULL;
      return 0;
    }
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
  case K_PNG_LEVEL:
    if (!value || value[0] < '0' || value[0] > '9' || value[1])
      return fail(c, "'%s': --png-level must be 0 to 9", c->what);
    o->png_level = value[0] - '0';
    return 0;
  case K_ACCEL:
    if (value && !strcmp(value, "builtin"))
      o->accel = ZR_ACCEL_BUILTIN;
    else if (value && !strcmp(value, "embree"))
      o->accel = ZR_ACCEL_EMBREE;
    else
      return fail(c, "'%s': --accel must be builtin or embree", c->what);
    return 0;
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
  case K_BOUNCES:
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
  case K_COMPRESSION: {
    /* POV-Ray 3.7 reference, "Output File Type": 0 to 100, 0 and 1 the
       default (85), values outside clipped to that range. */
    long q;
    if (!parse_int(value, -1000000, 1000000, &q))
      return fail(c, "'%s': the JPEG quality must be a whole number, as "
                     "in Compression=90", c->what);
    o->jpeg_quality = q < 0 ? 0 : q > 100 ? 100 : (int)q;
    return 0;
  }
  case K_FILE_GAMMA: {
    /* "File Gamma": sRGB or a display gamma to pre-correct for; a
       legacy scene ignores it (zr_scene_file_gamma). */
    double g;
    if (value && !strcasecmp(value, "srgb"))
      o->file_gamma = 0.0;
    else if (parse_real(value, &g) && g > 0.0)
      o->file_gamma = g;
    else
      return fail(c, "'%s': the file gamma must be sRGB or a positive "
                     "number, as in File_Gamma=2.2", c->what);
    return 0;
  }
  case K_GI_SAVE:
    return set_string(c, &o->gi_save, value);
  case K_GI_LOAD:
    return set_string(c, &o->gi_load, value);
  case K_SPP:
  case K_PATH_SEED: {
    char *end = NULL;
    errno = 0;
    unsigned long n = value && isdigit((unsigned char)*value)
                          ? strtoul(value, &end, 10) : 0;
    if (key == K_SPP) {
      if (!end || *end || errno || n < 1 || n > (1ul << 24))
        return fail(c, "'%s': --spp must be a whole number from 1 to "
                       "16777216", c->what);
      o->spp = (int)n;
    } else {
      if (!end || *end || errno || n > 0xfffffffful)
        return fail(c, "'%s': --path-seed must be a whole number from 0 "
                       "to 4294967295", c->what);
      o->path_seed = (uint32_t)n;
    }
    return 0;
  }
  default:
    break;
  }
  return apply_more(c, key, value);
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
  const char *needs; /* what a missing value should have been; for
                        K_NOTE, why zrcube does not act on it */
} pov_switch;

#define STREAM_SWITCH(l, i)                                              \
  {l, (opt_key)(K_CONSOLE_ON + (i)), (opt_key)(K_CONSOLE_OFF + (i)),     \
   V_OPTIONAL, NULL}

/*
 * POV-Ray's switches (reference 3.2), matched on their letters with the
 * longest family first, as POV-Ray tells +HIfile.inc (a header include)
 * from +H480 and +WT2 from +W640: a switch is its letters, then its
 * value.  Switches for work zrcube does differently are read and named
 * in a warning (K_NOTE) rather than refused, because stock INI files
 * carry them; those that only tune speed or memory (+B, +MB, +X ...)
 * are read and ignored silently.
 */
static const pov_switch pov_switches[] = {
    {"WT", K_THREADS, K_THREADS, V_REQUIRED, "a number of threads, as in +WT4"},
    {"WL", K_WARNING_LEVEL, K_WARNING_LEVEL, V_REQUIRED,
     "a warning level, as in +WL10"},
    {"W", K_WIDTH, K_WIDTH, V_REQUIRED, "a width, as in +W640"},
    {"HI", K_HEADER, K_HEADER, V_REQUIRED,
     "a file name, as in +HIheader.inc"},
    {"H", K_HEIGHT, K_HEIGHT, V_REQUIRED, "a height, as in +H480"},
    {"I", K_INPUT, K_INPUT, V_REQUIRED, "a file name, as in +Iscene.pov"},
    {"O", K_OUTPUT, K_OUTPUT, V_REQUIRED, "a file name, as in +Oimage.png"},
    {"L", K_INCLUDE, K_INCLUDE, V_REQUIRED, "a directory, as in +Linclude"},
    {"AM", K_SAMPLING, K_SAMPLING, V_REQUIRED, "a method, as in +AM1"},
    {"A", K_AA_ON, K_AA_OFF, V_OPTIONAL, NULL},
    {"RVP", K_IGNORED, K_IGNORED, V_NONE, NULL},
    {"RP", K_IGNORED, K_IGNORED, V_ANY, NULL},
    {"RS", K_IGNORED, K_IGNORED, V_ANY, NULL},
    {"R", K_AA_DEPTH, K_AA_DEPTH, V_REQUIRED, "a depth, as in +R3"},
    {"J", K_JITTER_ON, K_JITTER_OFF, V_OPTIONAL, NULL},
    {"F", K_OUTPUT_ON, K_OUTPUT_OFF, V_OPTIONAL, NULL},
    {"V", K_VERBOSE, K_NOVERBOSE, V_NONE, NULL},
    {"D", K_IGNORED, K_IGNORED, V_ANY, NULL},
    {"P", K_IGNORED, K_IGNORED, V_NONE, NULL},
    {"Q", K_QUALITY, K_QUALITY, V_REQUIRED, "a quality, as in +Q9"},
    {"KFI", K_INITIAL_FRAME, K_INITIAL_FRAME, V_REQUIRED,
     "a frame number, as in +KFI1"},
    {"KFF", K_FINAL_FRAME, K_FINAL_FRAME, V_REQUIRED,
     "a frame number, as in +KFF10"},
    {"KI", K_INITIAL_CLOCK, K_INITIAL_CLOCK, V_REQUIRED,
     "a clock value, as in +KI0.0"},
    {"KF", K_FINAL_CLOCK, K_FINAL_CLOCK, V_REQUIRED,
     "a clock value, as in +KF1.0"},
    {"KC", K_CYCLIC_ON, K_CYCLIC_OFF, V_NONE, NULL},
    {"K", K_CLOCK, K_CLOCK, V_REQUIRED, "a clock value, as in +K0.5"},
    {"SR", K_START_ROW, K_START_ROW, V_REQUIRED, "a row, as in +SR10"},
    {"SC", K_START_COL, K_START_COL, V_REQUIRED, "a column, as in +SC10"},
    {"SF", K_SUBSET_START, K_SUBSET_START, V_REQUIRED,
     "a frame, as in +SF5"},
    {"STP", K_FRAME_STEP, K_FRAME_STEP, V_REQUIRED, "a step, as in +STP2"},
    {"SP", K_NOTE, K_NOTE, V_ANY,
     "ignored: zrcube shows no mosaic preview"},
    {"SU", K_IGNORED, K_IGNORED, V_NONE, NULL},
    {"ER", K_END_ROW, K_END_ROW, V_REQUIRED, "a row, as in +ER100"},
    {"EC", K_END_COL, K_END_COL, V_REQUIRED, "a column, as in +EC100"},
    {"EF", K_SUBSET_END, K_SUBSET_END, V_REQUIRED, "a frame, as in +EF10"},
    {"EP", K_NOTE, K_NOTE, V_ANY, "ignored: zrcube shows no mosaic preview"},
    {"C", K_CONTINUE_ON, K_CONTINUE_OFF, V_NONE, NULL},
    STREAM_SWITCH("GD", ZR_CLI_STREAM_DEBUG),
    STREAM_SWITCH("GF", ZR_CLI_STREAM_FATAL),
    STREAM_SWITCH("GR", ZR_CLI_STREAM_RENDER),
    STREAM_SWITCH("GS", ZR_CLI_STREAM_STATISTICS),
    STREAM_SWITCH("GW", ZR_CLI_STREAM_WARNING),
    STREAM_SWITCH("GA", ZR_CLI_STREAMS),
    {"GI", K_NOTE, K_NOTE, V_ANY,
     "ignored: zrcube does not write INI files (Create_Ini)"},
    {"GP", K_IGNORED, K_IGNORED, V_NONE, NULL},
    {"MV", K_LANG_VERSION, K_LANG_VERSION, V_REQUIRED,
     "a version, as in +MV3.7"},
    {"MB", K_IGNORED, K_IGNORED, V_ANY, NULL},
    {"MI", K_IGNORED, K_IGNORED, V_ANY, NULL},
    {"UA", K_ALPHA_ON, K_ALPHA_OFF, V_NONE, NULL},
    {"UD", K_NOTE, K_NOTE, V_NONE, "ignored: zrcube does not dither"},
    {"UF", K_NOTE, K_NOTE, V_NONE,
     "ignored: field rendering is not supported"},
    {"UO", K_NOTE, K_NOTE, V_NONE,
     "ignored: field rendering is not supported"},
    {"UL", K_IGNORED, K_IGNORED, V_NONE, NULL},
    {"UV", K_IGNORED, K_IGNORED, V_NONE, NULL},
    {"UR", K_IGNORED, K_IGNORED, V_NONE, NULL},
    {"X", K_IGNORED, K_IGNORED, V_ANY, NULL},
    {"BS", K_IGNORED, K_IGNORED, V_ANY, NULL},
    {"B", K_IGNORED, K_IGNORED, V_ANY, NULL},
};

static const char *unquote(const char *value, char *buf, size_t size);

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
    char buf[4096];
    const char *value = unquote(body + n, buf, sizeof buf);
    opt_key key = plus ? sw->on : sw->off;
    arg_ctx sub = *c;
    sub.why = sw->needs;
    switch (sw->rule) {
    case V_NONE:
      if (*value)
        break; /* +Vx: not this switch; an unknown one */
      return apply(&sub, key, NULL);
    case V_OPTIONAL:
      return apply(&sub, key, *value ? value : NULL);
    case V_REQUIRED:
      if (!*value)
        return fail(c, "'%s' needs %s", arg, sw->needs);
      return apply(&sub, key, value);
    case V_ANY:
      return apply(&sub, key, NULL);
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
    {"png-level", K_PNG_LEVEL, L_REQUIRED},
    {"accel", K_ACCEL, L_REQUIRED},
    {"radiosity", K_RADIOSITY, L_NONE},
    {"bf-eps", K_BF_EPS, L_REQUIRED},
    {"area-eps", K_AREA_EPS, L_REQUIRED},
    {"vis-rays", K_VIS_RAYS, L_REQUIRED},
    {"uniform", K_UNIFORM, L_REQUIRED},
    {"max-iterations", K_MAX_ITERATIONS, L_REQUIRED},
    {"residual", K_RESIDUAL, L_REQUIRED},
    {"bounces", K_BOUNCES, L_REQUIRED},
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
    {"frames-per-rank", K_FRAMES_PER_RANK, L_OPTIONAL},
    {"state-interval", K_STATE_INTERVAL, L_REQUIRED},
    {"declare", K_DECLARE, L_REQUIRED},
    {"spp", K_SPP, L_REQUIRED},
    {"path-seed", K_PATH_SEED, L_REQUIRED},
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
  const char *why; /* K_NOTE: why zrcube does not act on the key */
} ini_option;

#define STREAM_KEYS(console, file, i)                                     \
  {console, (opt_key)(K_CONSOLE_ON + (i)), 1,                            \
   (opt_key)(K_CONSOLE_OFF + (i)), NULL},                                \
  {file, (opt_key)(K_STREAM_FILE + (i)), 0,                              \
   (opt_key)(K_STREAM_FILE + (i)), NULL}

/* Keys read and named in a warning: zrcube works otherwise, and the
   picture may differ from POV-Ray's.  Keys that only tune speed,
   memory or the user interface (bounding, block sizes, abort tests) are
   read and ignored silently (K_IGNORED), like the display options. */
#define NOTE(name, why) {name, K_NOTE, 0, K_NOTE, why}
#define SHELL_NOTE(name)                                                  \
  NOTE(name, "ignored: zrcube runs no shell commands (reference 3.2.6)")

static const ini_option ini_options[] = {
    {"Input_File_Name", K_INPUT, 0, K_INPUT, NULL},
    {"Output_File_Name", K_OUTPUT, 0, K_OUTPUT, NULL},
    {"Width", K_WIDTH, 0, K_WIDTH, NULL},
    {"Height", K_HEIGHT, 0, K_HEIGHT, NULL},
    {"Antialias", K_AA_ON, 1, K_AA_OFF, NULL},
    {"Antialias_Threshold", K_AA_THRESHOLD, 0, K_AA_THRESHOLD, NULL},
    {"Antialias_Depth", K_AA_DEPTH, 0, K_AA_DEPTH, NULL},
    {"Sampling_Method", K_SAMPLING, 0, K_SAMPLING, NULL},
    {"Jitter", K_JITTER_ON, 1, K_JITTER_OFF, NULL},
    {"Jitter_Amount", K_JITTER_AMOUNT, 0, K_JITTER_AMOUNT, NULL},
    {"Work_Threads", K_THREADS, 0, K_THREADS, NULL},
    {"Library_Path", K_INCLUDE, 0, K_INCLUDE, NULL},
    {"Verbose", K_VERBOSE, 1, K_NOVERBOSE, NULL},
    {"Display", K_IGNORED, 1, K_IGNORED, NULL},
    {"Pause_When_Done", K_IGNORED, 1, K_IGNORED, NULL},
    {"Output_To_File", K_OUTPUT_ON, 1, K_OUTPUT_OFF, NULL},
    {"Output_File_Type", K_FORMAT, 0, K_FORMAT, NULL},
    {"Bits_Per_Color", K_BITS, 0, K_BITS, NULL},
    {"Compression", K_COMPRESSION, 0, K_COMPRESSION, NULL},
    /* zrcube's own keys for what POV-Ray 3.7 sets in povray.conf
       ([Permitted Paths] read= and read+write=, [File I/O Security]);
       the plural spellings are accepted too. */
    {"Read_Path", K_READ_PATH, 0, K_READ_PATH, NULL},
    {"Read_Paths", K_READ_PATH, 0, K_READ_PATH, NULL},
    {"Write_Path", K_WRITE_PATH, 0, K_WRITE_PATH, NULL},
    {"Write_Paths", K_WRITE_PATH, 0, K_WRITE_PATH, NULL},
    {"IO_Restrictions", K_IO_RESTRICTIONS, 0, K_IO_RESTRICTIONS, NULL},
    {"Quality", K_QUALITY, 0, K_QUALITY, NULL},
    {"Radiosity", K_RADIOSITY_ON, 1, K_NO_RADIOSITY, NULL},
    /* Animation (3.2.1). */
    {"Clock", K_CLOCK, 0, K_CLOCK, NULL},
    {"Initial_Frame", K_INITIAL_FRAME, 0, K_INITIAL_FRAME, NULL},
    {"Final_Frame", K_FINAL_FRAME, 0, K_FINAL_FRAME, NULL},
    {"Initial_Clock", K_INITIAL_CLOCK, 0, K_INITIAL_CLOCK, NULL},
    {"Final_Clock", K_FINAL_CLOCK, 0, K_FINAL_CLOCK, NULL},
    {"Cyclic_Animation", K_CYCLIC_ON, 1, K_CYCLIC_OFF, NULL},
    {"Subset_Start_Frame", K_SUBSET_START, 0, K_SUBSET_START, NULL},
    {"Subset_End_Frame", K_SUBSET_END, 0, K_SUBSET_END, NULL},
    {"Frame_Step", K_FRAME_STEP, 0, K_FRAME_STEP, NULL},
    NOTE("Field_Render", "ignored: field rendering is not supported"),
    NOTE("Odd_Field", "ignored: field rendering is not supported"),
    NOTE("Clockless_Animation",
         "ignored: every frame is parsed with its own clock"),
    NOTE("Real_Time_Raytracing",
         "ignored: zrcube shows no window to play frames in"),
    /* Partial output and continuing (3.2.2). */
    {"Start_Row", K_START_ROW, 0, K_START_ROW, NULL},
    {"End_Row", K_END_ROW, 0, K_END_ROW, NULL},
    {"Start_Column", K_START_COL, 0, K_START_COL, NULL},
    {"End_Column", K_END_COL, 0, K_END_COL, NULL},
    {"Continue_Trace", K_CONTINUE_ON, 1, K_CONTINUE_OFF, NULL},
    NOTE("Create_Ini", "ignored: zrcube does not write INI files"),
    {"Test_Abort", K_IGNORED, 0, K_IGNORED, NULL},
    {"Test_Abort_Count", K_IGNORED, 0, K_IGNORED, NULL},
    {"Max_Image_Buffer_Memory", K_IGNORED, 0, K_IGNORED, NULL},
    /* Display (3.2.3): zrcube opens no window. */
    {"Video_Mode", K_IGNORED, 0, K_IGNORED, NULL},
    {"Palette", K_IGNORED, 0, K_IGNORED, NULL},
    {"Display_Gamma", K_IGNORED, 0, K_IGNORED, NULL},
    {"Preview_Start_Size", K_IGNORED, 0, K_IGNORED, NULL},
    {"Preview_End_Size", K_IGNORED, 0, K_IGNORED, NULL},
    {"Draw_Vistas", K_IGNORED, 0, K_IGNORED, NULL},
    /* File output (3.2.4). */
    {"Output_Alpha", K_ALPHA_ON, 1, K_ALPHA_OFF, NULL},
    NOTE("Dither", "ignored: zrcube does not dither"),
    NOTE("Dither_Method", "ignored: zrcube does not dither"),
    {"File_Gamma", K_FILE_GAMMA, 0, K_FILE_GAMMA, NULL},
    NOTE("Grayscale_Output", "ignored: the image is written in colour"),
    NOTE("Histogram_Type", "ignored: POV-Ray 3.7 has no histogram"),
    NOTE("Histogram_Name", "ignored: POV-Ray 3.7 has no histogram"),
    NOTE("Histogram_Grid_Size", "ignored: POV-Ray 3.7 has no histogram"),
    /* Scene parsing (3.2.5). */
    {"Declare", K_DECLARE, 0, K_DECLARE, NULL},
    {"Version", K_LANG_VERSION, 0, K_LANG_VERSION, NULL},
    {"Include_Header", K_HEADER, 0, K_HEADER, NULL},
    /* Shell commands (3.2.6). */
    SHELL_NOTE("Pre_Scene_Command"),
    SHELL_NOTE("Pre_Frame_Command"),
    SHELL_NOTE("Post_Scene_Command"),
    SHELL_NOTE("Post_Frame_Command"),
    SHELL_NOTE("User_Abort_Command"),
    SHELL_NOTE("Fatal_Error_Command"),
    SHELL_NOTE("Pre_Scene_Return"),
    SHELL_NOTE("Pre_Frame_Return"),
    SHELL_NOTE("Post_Scene_Return"),
    SHELL_NOTE("Post_Frame_Return"),
    SHELL_NOTE("User_Abort_Return"),
    SHELL_NOTE("Fatal_Error_Return"),
    /* Text streams (3.2.7). */
    STREAM_KEYS("Debug_Console", "Debug_File", ZR_CLI_STREAM_DEBUG),
    STREAM_KEYS("Fatal_Console", "Fatal_File", ZR_CLI_STREAM_FATAL),
    STREAM_KEYS("Render_Console", "Render_File", ZR_CLI_STREAM_RENDER),
    STREAM_KEYS("Statistic_Console", "Statistic_File",
                ZR_CLI_STREAM_STATISTICS),
    STREAM_KEYS("Warning_Console", "Warning_File", ZR_CLI_STREAM_WARNING),
    STREAM_KEYS("All_Console", "All_File", ZR_CLI_STREAMS),
    {"Append_File", K_IGNORED, 0, K_IGNORED, NULL},
    {"Warning_Level", K_WARNING_LEVEL, 0, K_WARNING_LEVEL, NULL},
    /* Tracing (3.2.8). */
    {"Render_Block_Size", K_IGNORED, 0, K_IGNORED, NULL},
    {"Render_Pattern", K_IGNORED, 0, K_IGNORED, NULL},
    {"Render_Block_Step", K_IGNORED, 0, K_IGNORED, NULL},
    {"Bounding", K_IGNORED, 0, K_IGNORED, NULL},
    {"Bounding_Method", K_IGNORED, 0, K_IGNORED, NULL},
    {"Bounding_Threshold", K_IGNORED, 0, K_IGNORED, NULL},
    {"Light_Buffer", K_IGNORED, 0, K_IGNORED, NULL},
    {"Vista_Buffer", K_IGNORED, 0, K_IGNORED, NULL},
    {"Remove_Bounds", K_IGNORED, 0, K_IGNORED, NULL},
    {"Split_Unions", K_IGNORED, 0, K_IGNORED, NULL},
    NOTE("Antialias_Gamma", "ignored: antialiasing compares colours in "
                            "the working space"),
    /* Radiosity (3.2.9). */
    {"High_Reproducibility", K_IGNORED, 0, K_IGNORED, NULL},
    {"Radiosity_Vain_Pretrace", K_IGNORED, 0, K_IGNORED, NULL},
    NOTE("Radiosity_File_Name", "ignored: use --gi-save=FILE or "
                                "--gi-load=FILE"),
    NOTE("Radiosity_From_File", "ignored: use --gi-load=FILE"),
    NOTE("Radiosity_To_File", "ignored: use --gi-save=FILE"),
};

/* A value as written: POV-Ray lets a value be quoted
   (Library_Path="/usr/share/povray-3.7"); the quotes go. */
static const char *unquote(const char *value, char *buf, size_t size) {
  size_t n = strlen(value);
  if (n >= 2 && (value[0] == '"' || value[0] == '\'') &&
      value[n - 1] == value[0] && n - 2 < size) {
    memcpy(buf, value + 1, n - 2);
    buf[n - 2] = '\0';
    return buf;
  }
  return value;
}

/* arg is "Key=Value"; POV-Ray's keys are case-insensitive.  A key
   zrcube does not know is named in a warning when it comes from an INI
   file (POV-Ray's files carry keys of other versions and platforms),
   and refused on the command line, where it is most likely a typo. */
static int parse_ini_option(arg_ctx *c, const char *arg) {
  const char *eq = strchr(arg, '=');
  size_t len = (size_t)(eq - arg);
  while (len > 0 && isspace((unsigned char)arg[len - 1]))
    len--;
  const char *value = eq + 1;
  while (isspace((unsigned char)*value))
    value++;
  char buf[4096];
  value = unquote(value, buf, sizeof buf);
  for (size_t i = 0; i < sizeof ini_options / sizeof *ini_options; i++) {
    const ini_option *io = &ini_options[i];
    if (strlen(io->name) != len || strncasecmp(arg, io->name, len) != 0)
      continue;
    arg_ctx sub = *c;
    sub.why = io->why;
    if (io->key == K_NOTE)
      return apply(&sub, K_NOTE, NULL);
    if (!*value) {
      /* POV-Ray's stock files leave some keys empty (Pre_Frame_Command=
         in pngflc.ini): nothing to set. */
      if (*c->where)
        return 0;
      return fail(c, "'%s' needs a value", arg);
    }
    if (io->boolean) {
      int on;
      if (!parse_bool(value, &on))
        return fail(c, "'%s': expected on or off", arg);
      return apply(&sub, on ? io->key : io->off, NULL);
    }
    return apply(&sub, io->key, value);
  }
  if (*c->where) {
    arg_ctx sub = *c;
    sub.why = "unknown key, ignored";
    return apply(&sub, K_NOTE, NULL);
  }
  return fail(c, "unknown option '%.*s' (try 'zrcube --help')", (int)len,
              arg);
}

static int parse_word(arg_ctx *c, const char *word, const char *next);

static int has_suffix(const char *s, const char *suffix) {
  size_t n = strlen(s), m = strlen(suffix);
  return n >= m && !strcasecmp(s + n - m, suffix);
}

/* POV-Ray reads INI files nested up to ten deep (user's guide 2.2.8.2). */
#define MAX_INI_DEPTH 10

/*
 * The file an INI name refers to: the name as given, with ".ini" added
 * when it has no extension, in the working directory or else in one of
 * the library paths given so far (POV-Ray for Unix's own povray.ini
 * lists its ini folder there).  malloc'ed, or NULL when none exists.
 */
static char *find_ini(const zr_cli_options *o, const char *name) {
  const char *slash = strrchr(name, '/');
  const char *dot = strrchr(slash ? slash : name, '.');
  size_t n = strlen(name) + 5;
  char *file = malloc(n);
  if (!file)
    return NULL;
  snprintf(file, n, "%s%s", name, dot ? "" : ".ini");
  struct stat st;
  if (stat(file, &st) == 0 && S_ISREG(st.st_mode))
    return file;
  if (name[0] != '/')
    for (size_t i = 0; i < o->n_include_paths; i++) {
      size_t m = strlen(o->include_paths[i]) + strlen(file) + 2;
      char *there = malloc(m);
      if (!there)
        break;
      snprintf(there, m, "%s/%s", o->include_paths[i], file);
      if (stat(there, &st) == 0 && S_ISREG(st.st_mode)) {
        free(file);
        return there;
      }
      free(there);
    }
  free(file);
  return NULL;
}

/* Splits "file.ini[Section]" into the name and the section; *section
   is NULL without brackets.  name is modified in place. */
static void split_section(char *name, char **section) {
  *section = NULL;
  size_t n = strlen(name);
  char *open = strchr(name, '[');
  if (open && n > 0 && name[n - 1] == ']') {
    name[n - 1] = '\0';
    *open = '\0';
    *section = open + 1;
  }
}

/* The same label, ignoring case and the blanks around it. */
static int same_label(const char *a, const char *b) {
  while (isspace((unsigned char)*a))
    a++;
  while (isspace((unsigned char)*b))
    b++;
  size_t na = strlen(a), nb = strlen(b);
  while (na > 0 && isspace((unsigned char)a[na - 1]))
    na--;
  while (nb > 0 && isspace((unsigned char)b[nb - 1]))
    nb--;
  return na == nb && strncasecmp(a, b, na) == 0;
}

static int parse_ini_line(arg_ctx *c, char *s);

/*
 * Reads an INI file (user's guide 2.2.8.2): one option per line
 * (Key=Value, or switches separated by blanks, or the name of another
 * INI file), ';' starts a comment.  Without a section, only the lines
 * before the first [label] are read; with one, only the lines after
 * that label up to the next label.  Labels ignore case.
 */
static int parse_ini_file(arg_ctx *c, const char *spec) {
  char *name = strdup(spec);
  if (!name)
    return fail(c, "out of memory");
  char *section;
  split_section(name, &section);
  if (c->depth >= MAX_INI_DEPTH) {
    int rc = fail(c, "'%s': INI files nested more than %d deep", name,
                  MAX_INI_DEPTH);
    free(name);
    return rc;
  }
  char *path = find_ini(c->o, name);
  FILE *f = path ? fopen(path, "r") : NULL;
  if (!f) {
    int rc = fail(c, "cannot open INI file '%s': %s", name,
                  strerror(path ? errno : ENOENT));
    free(path);
    free(name);
    return rc;
  }
  c->o->ini_read++;
  char line[4096];
  int lineno = 0, rc = 0, reading = section == NULL, found = !section;
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
    if (*s == '[') {
      char *close = strchr(s, ']');
      if (close)
        *close = '\0';
      reading = section && same_label(s + 1, section);
      found |= reading;
      continue;
    }
    if (!reading)
      continue;
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
    sub.depth = c->depth + 1;
    rc = parse_ini_line(&sub, s);
    free(where);
  }
  fclose(f);
  if (rc == 0 && !found)
    rc = fail(c, "INI file '%s' has no section [%s]", path, section);
  free(path);
  free(name);
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

/* One line of an INI file, blanks trimmed. */
static int parse_ini_line(arg_ctx *c, char *s) {
  if (*s == '+' || *s == '-') {
    /* A line may hold several switches separated by blanks. */
    for (char *tok = strtok(s, " \t"); tok; tok = strtok(NULL, " \t")) {
      c->what = tok;
      if (parse_word(c, tok, NULL) < 0)
        return -1;
    }
    return 0;
  }
  if (is_ini_option(s))
    return parse_ini_option(c, s);
  /* A name alone on its line is another INI file. */
  return parse_ini_file(c, s);
}

/* A bare word of the command line names an INI file when it ends in
   .ini or .ini[Section], or has no extension and NAME.ini exists (as
   "povray res[Med]" or "povray myopts"); otherwise it is the scene. */
static int names_ini(const zr_cli_options *o, const char *word) {
  char *name = strdup(word);
  if (!name)
    return 0;
  char *section;
  split_section(name, &section);
  int yes = has_suffix(name, ".ini");
  if (!yes) {
    const char *slash = strrchr(name, '/');
    struct stat st;
    if (!strchr(slash ? slash : name, '.') && stat(name, &st) != 0) {
      char *found = find_ini(o, name);
      yes = found != NULL;
      free(found);
    }
  }
  free(name);
  return yes;
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
  if (names_ini(c->o, word))
    return parse_ini_file(c, word);
  return set_input(c, word);
}

int zr__cli_parse(zr_cli_options *o, int argc, char **argv, char *err,
                  size_t err_size) {
  arg_ctx c = {o, err, err_size, "", "", NULL, 0};
  if (err_size)
    err[0] = '\0';
  /* "+H alone is a help switch if it is the only switch on the command
     line" (reference 3.2.7.5). */
  if (argc == 2 && (!strcasecmp(argv[1], "+H") || !strcasecmp(argv[1], "-H")))
    return apply(&c, K_HELP, NULL);
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
  case ZR_FORMAT_JPEG:
    return ".jpg";
  case ZR_FORMAT_TGA:
  case ZR_FORMAT_TGA_RLE:
    return ".tga";
  case ZR_FORMAT_HDR:
    return ".hdr";
  case ZR_FORMAT_EXR:
    return ".exr";
  case ZR_FORMAT_BMP:
    return ".bmp";
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
  if (!strcasecmp(ext, ".jpg") || !strcasecmp(ext, ".jpeg"))
    return ZR_FORMAT_JPEG;
  if (!strcasecmp(ext, ".tga"))
    return ZR_FORMAT_TGA;
  if (!strcasecmp(ext, ".hdr"))
    return ZR_FORMAT_HDR;
  if (!strcasecmp(ext, ".exr") && zr_image_format_supported(ZR_FORMAT_EXR))
    return ZR_FORMAT_EXR;
  if (!strcasecmp(ext, ".bmp"))
    return ZR_FORMAT_BMP;
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
  arg_ctx c = {(zr_cli_options *)o, err, err_size, "", "", NULL, 0};
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
      fmt = o->ini_format != ZR_FORMAT_AUTO ? o->ini_format : ZR_FORMAT_PNG8;
    name = default_name(out, o->input, format_extension(fmt));
  } else {
    if (same_file(out, o->input))
      return fail(&c, "refusing to overwrite the scene file '%s' with the "
                      "image", o->input);
    const char *ext = extension_of(out);
    zr_image_format by_name = format_of_extension(ext);
    if (fmt == ZR_FORMAT_AUTO && *ext && by_name == ZR_FORMAT_AUTO)
      return fail(&c, "cannot write '%s': the output name must end in "
                      ".png, .jpg, .tga, .bmp, .hdr, .exr, .ppm or .pfm (or "
                      "give the type with +F)", out);
    if (fmt == ZR_FORMAT_AUTO)
      fmt = by_name != ZR_FORMAT_AUTO        ? by_name
             : o->ini_format != ZR_FORMAT_AUTO ? o->ini_format
                                               : ZR_FORMAT_PNG8;
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
  arg_ctx c = {(zr_cli_options *)o, err, err_size, "", "", NULL, 0};
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
      "  +O<file>, --output=FILE      the image: .png, .jpg, .tga, .bmp,\n"
      "                               .hdr, .exr, .ppm or .pfm by its\n"
      "                               extension (default: SCENE.png here);\n"
      "                               a directory puts SCENE.png in it, a\n"
      "                               name without extension gets .png\n"
      "  +FN, +FN16, +FP              PNG (8 or 16 bit) or PPM output\n"
      "  +FJ, +FT, +FC, +FB, +FH, +FE JPEG, Targa (C: run-length\n"
      "                               encoded), BMP, Radiance HDR,\n"
      "                               OpenEXR output\n"
      "  Compression=N                JPEG quality 2..100 (0, 1: 85)\n"
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
      "  --png-level=N                PNG compression, 0 (none) to 9\n"
      "                               (smallest); default 1\n"
      "  --accel=builtin|embree       what finds the triangles of meshes:\n"
      "                               zRcube's hierarchy or Embree's\n"
      "                               (builds configured --with-embree,\n"
      "                               where it is the default)\n"
      "  --read-path=DIR              let scenes read below DIR too\n"
      "  --write-path=DIR             let scenes write below DIR too\n"
      "  --io-restrictions=MODE       restricted (default: scenes read\n"
      "                               what they name by relative names,\n"
      "                               absolute names below their folder,\n"
      "                               the working directory and the\n"
      "                               include paths, and write below the\n"
      "                               working directory), strict (relative\n"
      "                               names confined too), read-only or\n"
      "                               none\n"
      "  +D, -D, +P, -P               accepted and ignored (no display)\n"
      "  +K<c>, Clock=C               the clock of a still image\n"
      "  +KFF<n>, +KFI<n>             animate frames initial..final, each\n"
      "                               to a numbered image (out01.png..)\n"
      "  +KI<c>, +KF<c>, +KC          the clock range, cyclic animation\n"
      "  +SF<n>, +EF<n>, +STP<n>      render a subset of the frames\n"
      "  --frames-per-rank[=yes|no|auto]  whole frames to MPI ranks\n"
      "  +SR, +ER, +SC, +EC           render only rows/columns (1-based or\n"
      "                               fractions); the rest is black\n"
      "  +C, -C                       continue an interrupted render from\n"
      "                               its state file (IMAGE.zrstate)\n"
      "  --state-interval=SECONDS     how often the state file is written\n"
      "  +O-                          the image on standard output\n"
      "  Declare=NAME=VALUE           a float the scene sees, declared\n"
      "  +HI<file>, +MV<v>            header include, language version\n"
      "  +GD +GF +GR +GS +GW +GA[file]  text streams on (+) or off (-) the\n"
      "                               console, copied to FILE\n"
      "  +Q<n>, Quality=N             0..11 (default 9): below 9 no media\n"
      "                               or radiosity, 8 no reflection, 6 no\n"
      "                               refraction, 5 hard area shadows, 4\n"
      "                               no shadows\n"
      "  FILE.ini[Section]            read options from an INI file\n"
      "                               (povray.ini is read first: $POVINI)\n"
      "\n"
      "Radiosity (hierarchical, on the exact surfaces; any of these turns\n"
      "it on):\n"
      "  --gi=MODEL                   global illumination: auto (default:\n"
      "                               by the scene, see zrcube(1)),\n"
      "                               hierarchical, cache, path (the\n"
      "                               path-traced reference) or off\n"
      "  --spp=N                      path: samples per pixel (64),\n"
      "                               written after 1, 2, 4 ... of them\n"
      "  --path-seed=N                path: another set of samples (0)\n"
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
      "  --bounces=N|all              bounces of light shown (default:\n"
      "                               the radiosity block's\n"
      "                               recursion_limit; all without one)\n"
      "  --shooting                   progressive shooting, not gathering\n"
      "  --one-sided-emission[=0|1|open]  1: emit from the front only;\n"
      "                               0: both sides; open (default): the\n"
      "                               sides light gets away from\n"
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

/* ---- animation frames, partial renders, povray.ini ---------------- */

/* A subset frame as given (+SF, +EF): a fraction of the frames when
   below 1, else a frame number.  The fraction counts frames from the
   initial one: with Initial_Frame=1 and 10 frames, 0.5 is frame 5 and
   0.7 frame 7, as povray 3.7.0 renders them (measured; for other
   initial frames povray clamps the result to the initial frame, which
   the manual's "fraction of the whole animation" does not say, so
   zrcube keeps the proportion). */
static long subset_frame(double v, long first, long count) {
  if (v < 1)
    return first - 1 + (long)floor(v * (double)count);
  return (long)v;
}

int zr__cli_frames(const zr_cli_options *o, zr_cli_frame **frames,
                   size_t *n, int *digits, char *err, size_t err_size) {
  arg_ctx c = {(zr_cli_options *)o, err, err_size, "", "", NULL, 0};
  *frames = NULL;
  *n = 0;
  *digits = 0;
  zr_parse_options base;
  zr_parse_options_init(&base);
  if (o->lang_version > 0)
    base.version = o->lang_version;
  if (!o->initial_frame_given && !o->final_frame_given) {
    /* A still: +K sets the clock and clock_on, the frame values stay 0
       (measured with povray 3.7.0: +K0.5 gives clock_on 1). */
    *frames = malloc(sizeof **frames);
    if (!*frames)
      return fail(&c, "out of memory");
    (*frames)[0].number = 0;
    (*frames)[0].clock = base;
    if (o->clock_given) {
      (*frames)[0].clock.clock = o->clock;
      (*frames)[0].clock.clock_on = 1;
    }
    *n = 1;
    return 0;
  }
  /* The internal loop (reference 3.2.1.2).  Measured with povray 3.7.0:
     a negative initial frame counts as 0; a final frame before the
     initial one (or none) is the initial one; +KC counts one frame more
     for the clock (final_frame reads final + 1, clock_delta is the
     clock range over that many steps) but renders the same frames. */
  long first = o->initial_frame < 0 ? 0 : o->initial_frame;
  long last = o->final_frame_given ? o->final_frame : first;
  if (last < first)
    last = first;
  long clock_last = o->cyclic ? last + 1 : last;
  long count = last - first + 1;
  double delta = clock_last > first
                     ? (o->final_clock - o->initial_clock) /
                           (double)(clock_last - first)
                     : 0; /* povray 3.7.0 gives NaN: one frame has no step */
  long from = first, to = last;
  if (o->subset_start >= 0)
    from = subset_frame(o->subset_start, first, count);
  if (o->subset_end >= 0)
    to = subset_frame(o->subset_end, first, count);
  if (from < first)
    from = first;
  if (from > last)
    return fail(&c, "the subset starts at frame %ld, after the final "
                    "frame %ld", from, last);
  if (to > last)
    to = last;
  if (to < from)
    to = from; /* povray 3.7.0 renders the start frame alone */
  size_t total = (size_t)((to - from) / o->frame_step + 1);
  *frames = calloc(total, sizeof **frames);
  if (!*frames)
    return fail(&c, "out of memory");
  for (size_t i = 0; i < total; i++) {
    long f = from + (long)i * o->frame_step;
    zr_cli_frame *fr = &(*frames)[i];
    fr->number = f;
    fr->clock = base;
    fr->clock.clock_on = 1;
    fr->clock.frame_number = (int)f;
    fr->clock.initial_frame = (int)first;
    fr->clock.final_frame = (int)clock_last;
    fr->clock.initial_clock = o->initial_clock;
    fr->clock.final_clock = o->final_clock;
    fr->clock.clock_delta = delta;
    fr->clock.clock = o->initial_clock + (double)(f - first) * delta;
  }
  *n = total;
  /* The frame number's width is the final frame's: +KFF10 writes
     out01.png .. out10.png, +KFF100 out001.png .. (reference 3.2.1.2). */
  int d = 1;
  for (long v = last; v >= 10; v /= 10)
    d++;
  *digits = d;
  return 0;
}

char *zr__cli_frame_name(const char *path, long number, int digits) {
  const char *slash = strrchr(path, '/');
  const char *dot = strrchr(slash ? slash + 1 : path, '.');
  size_t stem = dot ? (size_t)(dot - path) : strlen(path);
  size_t n = strlen(path) + (size_t)digits + 24;
  char *name = malloc(n);
  if (name)
    snprintf(name, n, "%.*s%0*ld%s", (int)stem, path, digits, number,
             dot ? dot : "");
  return name;
}

/* One end of the window on a side of size pixels: a fraction is a
   boundary at floor(v * size); a number n is pixel n (1-based).
   Measured with povray 3.7.0 on 10 rows: +SR0.25 +ER0.55 and +SR3
   +ER5 both render rows 3 to 5. */
static int window_start(double v, int size) {
  return v < 1 ? (int)floor(v * size) : (int)v - 1;
}
static int window_end(double v, int size) {
  return v < 1 ? (int)floor(v * size) : (int)v;
}

int zr__cli_window(const zr_cli_options *o, int *row0, int *row1,
                   int *col0, int *col1, char *err, size_t err_size) {
  arg_ctx c = {(zr_cli_options *)o, err, err_size, "", "", NULL, 0};
  int w = o->params.width, h = o->params.height;
  *row0 = o->start_row >= 0 ? window_start(o->start_row, h) : 0;
  *row1 = o->end_row >= 0 ? window_end(o->end_row, h) : h;
  *col0 = o->start_col >= 0 ? window_start(o->start_col, w) : 0;
  *col1 = o->end_col >= 0 ? window_end(o->end_col, w) : w;
  if (*row1 > h)
    *row1 = h;
  if (*col1 > w)
    *col1 = w;
  if (*row0 >= h || *col0 >= w)
    return fail(&c, "the partial render starts outside the %dx%d image "
                    "(+SR/+SC are 1-based, or fractions below 1)", w, h);
  if (*row1 <= *row0 || *col1 <= *col0)
    return fail(&c, "the partial render holds no pixel: rows %d to %d, "
                    "columns %d to %d", *row0 + 1, *row1, *col0 + 1,
                *col1);
  return 0;
}

/*
 * Reads the default povray.ini.  Its Output_File_Type (Debian's says N8)
 * is kept aside: an output name whose extension names a type
 * (+Oimage.pfm) is written in that type, as zrcube(1) says, where
 * POV-Ray would write PNG bytes under that name; +F on the command line
 * or in a scene's ini still wins over the extension.
 */
static int default_ini(arg_ctx *c, const char *path) {
  zr_image_format before = c->o->format;
  int rc = parse_ini_file(c, path);
  if (c->o->format != before) {
    c->o->ini_format = c->o->format;
    c->o->format = before;
  }
  return rc;
}

int zr__cli_read_povray_ini(zr_cli_options *o, char *err, size_t err_size) {
  arg_ctx c = {o, err, err_size, "", "", NULL, 0};
  const char *env = getenv("POVINI");
  if (env && !*env)
    return 0;
  if (env) {
    /* POV-Ray for Unix falls through to the next place when $POVINI
       names no file it can read. */
    struct stat st;
    if (stat(env, &st) == 0 && S_ISREG(st.st_mode))
      return default_ini(&c, env);
  }
  const char *home = getenv("HOME");
  char user[4096], rc_file[4096];
  snprintf(user, sizeof user, "%s/.povray/3.7/povray.ini",
           home ? home : "");
  snprintf(rc_file, sizeof rc_file, "%s/.povrayrc", home ? home : "");
  const char *places[] = {"povray.ini", home ? user : NULL,
                          ZR_POVRAY_SYSCONF_INI, home ? rc_file : NULL};
  for (size_t i = 0; i < sizeof places / sizeof *places; i++) {
    struct stat st;
    if (places[i] && stat(places[i], &st) == 0 && S_ISREG(st.st_mode)) {
      /* An explicit path: a file named "povray.ini" is not searched for
         in the library paths. */
      char spec[4200];
      snprintf(spec, sizeof spec, "%s%s",
               strchr(places[i], '/') ? "" : "./", places[i]);
      return default_ini(&c, spec);
    }
  }
  return 0;
}
