/*
 * context.c - zr_context, status texts and compiler-style diagnostics.
 *
 * Messages follow the GNU convention that editors understand,
 * "file:line:column: error: message", then the include or macro chain,
 * then the source line with a caret under the column (see the Bison
 * manual's bistromathic example for the same layout).
 */
#include "core/context.h"

#include "config.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "core/iopolicy.h"
#include "core/budget.h"
#include "core/strbuf.h"

ZR_API const char *zr_status_str(zr_status status) {
  switch (status) {
#define ZR_STATUS_CASE_(name, value, text)                                 \
  case ZR_##name:                                                          \
    return text;
    ZR_STATUS_MAP(ZR_STATUS_CASE_)
#undef ZR_STATUS_CASE_
  }
  return "unknown status";
}

ZR_API const char *zr_version(void) { return ZR_VERSION_STRING; }

ZR_API zr_status zr_context_new(zr_context **out) {
  zr_context *ctx = calloc(1, sizeof *ctx);
  if (!ctx)
    return ZR_ENOMEM;
  ctx->work_limit = ZR_DEFAULT_WORK_LIMIT;
  ctx->file_limit = ZR_DEFAULT_FILE_LIMIT;
  ctx->png_level = ZR_DEFAULT_PNG_LEVEL;
  ctx->threads = 1;
  zr_context_set_accel(ctx, ZR_ACCEL_DEFAULT);
  zr_parse_options_init(&ctx->parse);
  ctx->budget = zr__budget_new(zr__budget_default_limit());
  if (!ctx->budget) {
    free(ctx);
    return ZR_ENOMEM;
  }
  *out = ctx;
  return ZR_OK;
}

ZR_API zr_status zr_context_set_accel(zr_context *ctx, zr_accel accel) {
  switch (accel) {
  case ZR_ACCEL_DEFAULT:
#ifdef ZR_HAVE_EMBREE
    ctx->accel = ZR_ACCEL_EMBREE;
#else
    ctx->accel = ZR_ACCEL_BUILTIN;
#endif
    return ZR_OK;
  case ZR_ACCEL_BUILTIN:
    ctx->accel = accel;
    return ZR_OK;
  case ZR_ACCEL_EMBREE:
#ifdef ZR_HAVE_EMBREE
    ctx->accel = accel;
    return ZR_OK;
#else
    return ZR_EUNSUPPORTED;
#endif
  }
  return ZR_EINVAL;
}

ZR_API zr_status zr_context_set_png_level(zr_context *ctx, int level) {
  if (level < 0 || level > 9)
    return ZR_EINVAL;
  ctx->png_level = level;
  return ZR_OK;
}

ZR_API void zr_context_set_threads(zr_context *ctx, int threads) {
  ctx->threads = threads < 1 ? 1 : threads;
}

ZR_API void zr_context_set_team(zr_context *ctx, const zr_team *team) {
  ctx->team = team;
}

ZR_API void zr_context_set_work_limit(zr_context *ctx,
                                      unsigned long long steps) {
  ctx->work_limit = steps;
}

ZR_API void zr_context_set_loop_limit(zr_context *ctx,
                                      unsigned long long iterations) {
  zr_context_set_work_limit(ctx, iterations);
}

ZR_API void zr_context_set_memory_limit(zr_context *ctx,
                                        unsigned long long bytes) {
  ctx->budget->limit = bytes > SIZE_MAX ? SIZE_MAX : (size_t)bytes;
}

ZR_API unsigned long long zr_context_memory_limit(const zr_context *ctx) {
  return ctx->budget->limit;
}

ZR_API unsigned long long zr_context_memory_peak(const zr_context *ctx) {
  return atomic_load(&ctx->budget->peak);
}

ZR_API void zr_context_set_file_limit(zr_context *ctx,
                                      unsigned long long bytes) {
  ctx->file_limit = bytes;
}

const char *zr__context_budget_text(const zr_context *ctx, size_t bytes,
                                    const char *what, char *buf,
                                    size_t size) {
  char need[32], limit[32];
  snprintf(buf, size, "%s needs %s more, past the memory budget of %s "
           "(raise it with --memory-limit)", what,
           zr__budget_size_text(bytes, need, sizeof need),
           zr__budget_size_text(ctx ? ctx->budget->limit : 0, limit,
                                sizeof limit));
  return buf;
}

zr_status zr__context_over_budget(zr_context *ctx, size_t bytes,
                                  const zr_diag_place *place,
                                  const char *what) {
  char text[400];
  return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ELIMIT, place, "%s",
                  zr__context_budget_text(ctx, bytes, what, text,
                                          sizeof text));
}

ZR_API void zr_context_free(zr_context *ctx) {
  if (!ctx)
    return;
  for (size_t i = 0; i < ctx->n_include_paths; i++)
    free(ctx->include_paths[i]);
  free(ctx->include_paths);
  for (size_t i = 0; i < ctx->n_read_dirs; i++)
    free(ctx->read_dirs[i]);
  free(ctx->read_dirs);
  for (size_t i = 0; i < ctx->n_write_dirs; i++)
    free(ctx->write_dirs[i]);
  free(ctx->write_dirs);
  for (size_t i = 0; i < ctx->n_declared; i++)
    free(ctx->declared_names[i]);
  free(ctx->declared_names);
  free(ctx->declared_values);
  free(ctx->header_include);
  zr__budget_unref(ctx->budget);
  free(ctx);
}

ZR_API void zr_context_set_progress(zr_context *ctx, zr_progress_fn fn,
                                    void *user) {
  ctx->progress_fn = fn;
  ctx->progress_user = user;
}

ZR_API void zr_context_cancel(zr_context *ctx, int cancel) {
  if (ctx)
    atomic_store(&ctx->cancel, cancel != 0);
}

zr_status zr__params_take(void *out, size_t out_size, const void *in,
                          size_t min_size) {
  if (!in)
    return ZR_EINVAL;
  size_t size;
  memcpy(&size, in, sizeof size);
  if (size < min_size)
    return ZR_EINVAL;
  const unsigned char *bytes = in;
  for (size_t i = out_size; i < size; i++)
    if (bytes[i] != 0)
      return ZR_EINVAL;
  memcpy(out, in, size < out_size ? size : out_size);
  memcpy(out, &out_size, sizeof out_size);
  return ZR_OK;
}

bool zr__cancelled(zr_context *ctx) {
  return ctx && atomic_load_explicit(&ctx->cancel, memory_order_relaxed);
}

zr_status zr__progress(zr_context *ctx, zr_phase phase, uint64_t done,
                       uint64_t total) {
  if (!ctx)
    return ZR_OK;
  if (ctx->progress_fn) {
    zr_progress p = {phase, done, total};
    if (ctx->progress_fn(&p, ctx->progress_user) != 0)
      return ZR_ECANCELLED;
  }
  return zr__cancelled(ctx) ? ZR_ECANCELLED : ZR_OK;
}

ZR_API void zr_context_set_diag(zr_context *ctx, zr_diag_fn fn, void *user) {
  ctx->diag_fn = fn;
  ctx->diag_user = user;
}

ZR_API void zr_context_set_reader(zr_context *ctx, zr_read_fn fn,
                                  void *user) {
  ctx->read_fn = fn;
  ctx->read_user = user;
}

ZR_API zr_status zr_context_set_render_size(zr_context *ctx, int width,
                                            int height) {
  if (!ctx || width < 1 || height < 1)
    return ZR_EINVAL;
  ctx->render_width = width;
  ctx->render_height = height;
  return ZR_OK;
}

ZR_API void zr_parse_options_init(zr_parse_options *o) {
  memset(o, 0, sizeof *o);
  o->size = sizeof *o;
  o->version = 3.7;
}

ZR_API zr_status zr_context_set_parse_options(zr_context *ctx,
                                              const zr_parse_options *o) {
  if (!ctx || !o || o->size < sizeof o->size)
    return ZR_EINVAL;
  /* The size rule: what the caller's struct holds, the rest default. */
  zr_parse_options copy;
  zr_parse_options_init(&copy);
  size_t n = o->size < sizeof copy ? o->size : sizeof copy;
  memcpy(&copy, o, n);
  copy.size = sizeof copy;
  if (!(copy.version > 0) || !isfinite(copy.version))
    return ZR_EINVAL;
  ctx->parse = copy;
  return ZR_OK;
}

ZR_API zr_status zr_context_set_header_include(zr_context *ctx,
                                               const char *path) {
  if (!ctx)
    return ZR_EINVAL;
  char *copy = NULL;
  if (path && !(copy = strdup(path)))
    return ZR_ENOMEM;
  free(ctx->header_include);
  ctx->header_include = copy;
  return ZR_OK;
}

static int is_identifier(const char *s) {
  if (!s || !(isalpha((unsigned char)*s) || *s == '_'))
    return 0;
  for (s++; *s; s++)
    if (!(isalnum((unsigned char)*s) || *s == '_'))
      return 0;
  return 1;
}

ZR_API zr_status zr_context_declare(zr_context *ctx, const char *name,
                                    double value) {
  if (!ctx || !is_identifier(name) || !isfinite(value))
    return ZR_EINVAL;
  for (size_t i = 0; i < ctx->n_declared; i++)
    if (!strcmp(ctx->declared_names[i], name)) {
      ctx->declared_values[i] = value;
      return ZR_OK;
    }
  size_t n = ctx->n_declared + 1;
  char **names = realloc(ctx->declared_names, n * sizeof *names);
  if (!names)
    return ZR_ENOMEM;
  ctx->declared_names = names;
  double *values = realloc(ctx->declared_values, n * sizeof *values);
  if (!values)
    return ZR_ENOMEM;
  ctx->declared_values = values;
  char *copy = strdup(name);
  if (!copy)
    return ZR_ENOMEM;
  names[ctx->n_declared] = copy;
  values[ctx->n_declared] = value;
  ctx->n_declared = n;
  return ZR_OK;
}

ZR_API zr_status zr_context_add_include_path(zr_context *ctx,
                                             const char *dir) {
  if (!ctx || !dir)
    return ZR_EINVAL;
  char **paths = realloc(ctx->include_paths,
                         (ctx->n_include_paths + 1) * sizeof *paths);
  if (!paths)
    return ZR_ENOMEM;
  ctx->include_paths = paths;
  paths[ctx->n_include_paths] = strdup(dir);
  if (!paths[ctx->n_include_paths])
    return ZR_ENOMEM;
  ctx->n_include_paths++;
  return ZR_OK;
}

ZR_API zr_status zr_context_set_io_restrictions(zr_context *ctx,
                                                zr_io_restrictions mode) {
  if (!ctx || (mode != ZR_IO_RESTRICTED && mode != ZR_IO_READ_ONLY &&
               mode != ZR_IO_NONE && mode != ZR_IO_STRICT))
    return ZR_EINVAL;
  ctx->io_mode = mode;
  return ZR_OK;
}

/* Resolves dir now (POV-Ray resolves its permitted paths once, from the
   working directory at start) and appends it to a list. */
static zr_status add_dir(char ***dirs, size_t *n, const char *dir) {
  char *real = realpath(dir, NULL);
  if (!real)
    return errno == ENOENT || errno == ENOTDIR ? ZR_ENOTFOUND : ZR_EIO;
  struct stat st;
  if (stat(real, &st) != 0 || !S_ISDIR(st.st_mode)) {
    free(real);
    return ZR_EINVAL;
  }
  char **grown = realloc(*dirs, (*n + 1) * sizeof *grown);
  if (!grown) {
    free(real);
    return ZR_ENOMEM;
  }
  *dirs = grown;
  grown[(*n)++] = real;
  return ZR_OK;
}

ZR_API zr_status zr_context_add_read_path(zr_context *ctx, const char *dir) {
  if (!ctx || !dir)
    return ZR_EINVAL;
  return add_dir(&ctx->read_dirs, &ctx->n_read_dirs, dir);
}

ZR_API zr_status zr_context_add_write_path(zr_context *ctx,
                                           const char *dir) {
  if (!ctx || !dir)
    return ZR_EINVAL;
  return add_dir(&ctx->write_dirs, &ctx->n_write_dirs, dir);
}

ZR_API void zr_context_set_read_observer(zr_context *ctx,
                                         zr_read_observer_fn fn,
                                         void *user) {
  ctx->observer_fn = fn;
  ctx->observer_user = user;
}

ZR_API void zr_context_set_scene_writes(zr_context *ctx, int enabled) {
  if (ctx)
    ctx->no_scene_writes = !enabled;
}

ZR_API const char *zr_context_last_error(const zr_context *ctx) {
  return ctx ? ctx->last_error : "";
}

static const char *level_name(zr_diag_level level) {
  switch (level) {
  case ZR_DIAG_ERROR:
    return "error";
  case ZR_DIAG_WARNING:
    return "warning";
  case ZR_DIAG_NOTE:
    return "note";
  case ZR_DIAG_DEBUG:
    return "debug";
  }
  return "error";
}

/*
 * Terminal safety: text from a scene (a name, a string, a source line,
 * a file name) may hold control bytes, and an escape sequence echoed in
 * a message would act on the user's terminal.  Messages show C0 and C1
 * controls, DEL and bytes that are not UTF-8 as \xNN; tabs stay (the
 * caret lines up under them) and so do newlines where a message has
 * lines of its own.
 */

/* The length of the UTF-8 sequence at s (n bytes left) that is safe to
   print as it is: 1 to 4, or 0 for a byte that must be escaped. */
static size_t printable_len(const unsigned char *s, size_t n) {
  unsigned c = s[0];
  if (c == '\t')
    return 1;
  if (c < 0x20 || c == 0x7f)
    return 0;
  if (c < 0x80)
    return 1;
  size_t len = c >= 0xc2 && c <= 0xdf   ? 2
               : c >= 0xe0 && c <= 0xef ? 3
               : c >= 0xf0 && c <= 0xf4 ? 4
                                        : 0;
  if (len == 0 || len > n)
    return 0;
  for (size_t i = 1; i < len; i++)
    if ((s[i] & 0xc0) != 0x80)
      return 0;
  unsigned cp = len == 2 ? (c & 0x1f) << 6 | (s[1] & 0x3f)
              : len == 3 ? (c & 0x0f) << 12 | (s[1] & 0x3f) << 6 |
                               (s[2] & 0x3f)
                         : (c & 0x07) << 18 | (s[1] & 0x3f) << 12 |
                               (s[2] & 0x3f) << 6 | (s[3] & 0x3f);
  /* Overlong forms, surrogates, beyond U+10FFFF, and the C1 controls
     (U+0080 to U+009F: CSI among them) are escaped. */
  if ((len == 3 && cp < 0x800) || (len == 4 && cp < 0x10000) ||
      (cp >= 0xd800 && cp <= 0xdfff) || cp > 0x10ffff ||
      (cp >= 0x80 && cp <= 0x9f))
    return 0;
  return len;
}

/* Appends n bytes of s with control bytes escaped; keep_newlines keeps
   '\n' as it is. */
static void put_escaped(zr_strbuf *sb, const char *s, size_t n,
                        bool keep_newlines) {
  const unsigned char *u = (const unsigned char *)s;
  size_t i = 0;
  while (i < n) {
    size_t len = printable_len(u + i, n - i);
    if (len == 0 && keep_newlines && u[i] == '\n')
      len = 1;
    if (len > 0) {
      zr__strbuf_append(sb, s + i, len);
      i += len;
    } else {
      zr__strbuf_printf(sb, "\\x%02x", u[i]);
      i++;
    }
  }
}

static void puts_escaped(zr_strbuf *sb, const char *s, bool keep_newlines) {
  put_escaped(sb, s, strlen(s), keep_newlines);
}

/* How much of a long line a quote shows on each side of the column, and
   the most of a message's own text shown: a 10 MB line gives a bounded
   message. */
enum { QUOTE_BEFORE = 70, QUOTE_AFTER = 70, MESSAGE_MAX = 2048 };

/* Appends the quoted source line and a caret line under the column.  A
   long line is cut around the column with "..." on the cut sides; the
   caret line gets one blank for each column shown before the caret, so
   escapes and UTF-8 characters keep it aligned. */
static void append_quote(zr_strbuf *sb, const zr_diag_place *p) {
  const unsigned char *line = (const unsigned char *)p->source_line;
  size_t n = p->source_line_len;
  while (n > 0 && (line[n - 1] == '\n' || line[n - 1] == '\r'))
    n--;
  size_t col = p->column > 1 ? (size_t)p->column - 1 : 0;
  if (col > n)
    col = n;
  size_t from = 0, to = n;
  if (col > QUOTE_BEFORE) {
    from = col - QUOTE_BEFORE;
    while (from < col && (line[from] & 0xc0) == 0x80)
      from++;
  }
  if (n - col > QUOTE_AFTER) {
    to = col + QUOTE_AFTER;
    while (to > col && (line[to] & 0xc0) == 0x80)
      to--;
  }
  zr_strbuf caret;
  zr__strbuf_init(&caret);
  zr__strbuf_printf(sb, "%5d | ", p->line);
  if (from > 0) {
    zr__strbuf_puts(sb, "...");
    zr__strbuf_puts(&caret, "   ");
  }
  size_t i = from;
  while (i < to) {
    size_t len = printable_len(line + i, to - i);
    size_t width = len ? 1 : 4;
    if (len)
      zr__strbuf_append(sb, (const char *)line + i, len);
    else
      zr__strbuf_printf(sb, "\\x%02x", line[i]);
    /* Tabs are kept so the caret lines up under them in a terminal. */
    for (size_t w = 0; i < col && w < width; w++)
      zr__strbuf_putc(&caret, line[i] == '\t' ? '\t' : ' ');
    i += len ? len : 1;
  }
  if (to < n)
    zr__strbuf_puts(sb, "...");
  zr__strbuf_printf(sb, "\n      | %s^", zr__strbuf_cstr(&caret));
  zr__strbuf_free(&caret);
  int tildes = p->caret_len;
  if (tildes > QUOTE_AFTER)
    tildes = QUOTE_AFTER;
  for (int k = 1; k < tildes; k++)
    zr__strbuf_putc(sb, '~');
  zr__strbuf_putc(sb, '\n');
}

zr_status zr__vdiag(zr_context *ctx, zr_diag_level level, zr_status status,
                    const zr_diag_place *place, const char *fmt,
                    va_list ap) {
  if (!ctx)
    return status;
  if (level == ZR_DIAG_ERROR)
    ctx->errors++;
  else if (level == ZR_DIAG_WARNING)
    ctx->warnings++;
  zr_strbuf msg, text;
  zr__strbuf_init(&msg);
  zr__strbuf_init(&text);
  zr__strbuf_vprintf(&msg, fmt, ap);
  /* What the message shows: control bytes escaped, and for errors and
     warnings at most MESSAGE_MAX bytes of it.  #debug text is the
     scene's own output: its newlines and tabs stay, escape sequences do
     not reach the terminal. */
  zr_strbuf shown;
  zr__strbuf_init(&shown);
  const char *m = zr__strbuf_cstr(&msg);
  size_t mlen = strlen(m);
  bool cut = level != ZR_DIAG_DEBUG && mlen > MESSAGE_MAX;
  put_escaped(&shown, m, cut ? MESSAGE_MAX : mlen, true);
  if (cut)
    zr__strbuf_puts(&shown, "...");
  if (level == ZR_DIAG_DEBUG) {
    zr__strbuf_puts(&text, zr__strbuf_cstr(&shown));
  } else {
    if (place && place->file) {
      puts_escaped(&text, place->file, false);
      zr__strbuf_printf(&text, ":%d:%d: ", place->line, place->column);
    }
    zr__strbuf_printf(&text, "%s: %s\n", level_name(level),
                      zr__strbuf_cstr(&shown));
    if (place && place->notes)
      puts_escaped(&text, place->notes, true);
    if (place && place->source_line && place->line > 0)
      append_quote(&text, place);
  }
  if (level == ZR_DIAG_ERROR)
    snprintf(ctx->last_error, sizeof ctx->last_error, "%s",
             zr__strbuf_cstr(&text));
  if (ctx->diag_fn) {
    zr_diag d = {level,
                 status,
                 place ? place->file : NULL,
                 place ? place->line : 0,
                 place ? place->column : 0,
                 zr__strbuf_cstr(&shown),
                 zr__strbuf_cstr(&text),
                 place ? place->offset : 0,
                 place ? place->length : 0};
    ctx->diag_fn(&d, ctx->diag_user);
  }
  zr__strbuf_free(&shown);
  zr__strbuf_free(&msg);
  zr__strbuf_free(&text);
  return status;
}

zr_status zr__diag(zr_context *ctx, zr_diag_level level, zr_status status,
                   const zr_diag_place *place, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  zr_status s = zr__vdiag(ctx, level, status, place, fmt, ap);
  va_end(ap);
  return s;
}

/* Hands what the library's own reader read to the observer. */
static zr_status observed(zr_context *ctx, const char *path, zr_status s,
                          char **bytes, size_t *size) {
  if (s != ZR_OK || !ctx || !ctx->observer_fn)
    return s;
  s = ctx->observer_fn(path, *bytes, *size, ctx->observer_user);
  if (s != ZR_OK) {
    free(*bytes);
    *bytes = NULL;
  }
  return s;
}

/* A reader of the caller's own is held to the file size limit too. */
static zr_status caller_read(zr_context *ctx, const char *path,
                             unsigned long long limit, char **bytes,
                             size_t *size) {
  zr_status s = ctx->read_fn(path, bytes, size, ctx->read_user);
  if (s == ZR_OK && limit && *size > limit) {
    free(*bytes);
    *bytes = NULL;
    return ZR_ELIMIT;
  }
  return s;
}

zr_status zr__context_read(zr_context *ctx, const char *path, char **bytes,
                           size_t *size) {
  unsigned long long limit = ctx ? ctx->file_limit : ZR_DEFAULT_FILE_LIMIT;
  if (ctx && ctx->read_fn)
    return caller_read(ctx, path, limit, bytes, size);
  char why[512];
  zr_status s = zr__io_read_named_max(path, limit, bytes, size, why,
                                      sizeof why);
  if (s == ZR_EACCESS)
    zr__diag(ctx, ZR_DIAG_ERROR, s, NULL, "cannot read: %s", why);
  return observed(ctx, path, s, bytes, size);
}

zr_status zr__context_read_scene(zr_context *ctx, const char *path,
                                 const char *scene_dir, bool relative,
                                 char **bytes, size_t *size, char *why,
                                 size_t why_size) {
  if (why_size)
    why[0] = '\0';
  if (ctx && ctx->read_fn)
    return caller_read(ctx, path, ctx->file_limit, bytes, size);
  zr_status s = zr__io_read_scene(ctx, path, scene_dir, relative, bytes,
                                  size, why, why_size);
  return observed(ctx, path, s, bytes, size);
}

const char *zr__context_read_error(const zr_context *ctx, zr_status s,
                                   char *buf, size_t size) {
  if (s != ZR_ELIMIT)
    return zr_status_str(s);
  char limit[32];
  snprintf(buf, size, "it is larger than the file size limit of %s "
           "(raise it with --max-file-size)",
           zr__budget_size_text(ctx ? (size_t)ctx->file_limit
                                    : (size_t)ZR_DEFAULT_FILE_LIMIT,
                                limit, sizeof limit));
  return buf;
}
