/*
 * context.c - zr_context, status texts and compiler-style diagnostics.
 *
 * Messages follow the GNU convention that editors understand,
 * "file:line:column: error: message", then the include or macro chain,
 * then the source line with a caret under the column (see the Bison
 * manual's bistromathic example for the same layout).
 */
#include "core/context.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "core/iopolicy.h"
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
  ctx->loop_limit = ZR_DEFAULT_LOOP_LIMIT;
  *out = ctx;
  return ZR_OK;
}

ZR_API void zr_context_set_loop_limit(zr_context *ctx,
                                      unsigned long long iterations) {
  ctx->loop_limit = iterations;
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
  free(ctx);
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
               mode != ZR_IO_NONE))
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

/* Appends the quoted source line and a caret line under the column. */
static void append_quote(zr_strbuf *sb, const zr_diag_place *p) {
  size_t n = p->source_line_len;
  while (n > 0 && (p->source_line[n - 1] == '\n' ||
                   p->source_line[n - 1] == '\r'))
    n--;
  zr__strbuf_printf(sb, "%5d | %.*s\n      | ", p->line, (int)n,
                    p->source_line);
  /* Tabs are kept so the caret lines up under them in a terminal. */
  for (int i = 1; i < p->column && (size_t)(i - 1) < n; i++)
    zr__strbuf_putc(sb, p->source_line[i - 1] == '\t' ? '\t' : ' ');
  zr__strbuf_putc(sb, '^');
  for (int i = 1; i < p->caret_len; i++)
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
  if (level == ZR_DIAG_DEBUG) {
    zr__strbuf_puts(&text, zr__strbuf_cstr(&msg));
  } else {
    if (place && place->file)
      zr__strbuf_printf(&text, "%s:%d:%d: ", place->file, place->line,
                        place->column);
    zr__strbuf_printf(&text, "%s: %s\n", level_name(level),
                      zr__strbuf_cstr(&msg));
    if (place && place->notes)
      zr__strbuf_puts(&text, place->notes);
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
                 zr__strbuf_cstr(&msg),
                 zr__strbuf_cstr(&text)};
    ctx->diag_fn(&d, ctx->diag_user);
  }
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

zr_status zr__context_read(zr_context *ctx, const char *path, char **bytes,
                           size_t *size) {
  if (ctx && ctx->read_fn)
    return ctx->read_fn(path, bytes, size, ctx->read_user);
  char why[512];
  zr_status s = zr__io_read_named(path, bytes, size, why, sizeof why);
  if (s == ZR_EACCESS)
    zr__diag(ctx, ZR_DIAG_ERROR, s, NULL, "cannot read: %s", why);
  return observed(ctx, path, s, bytes, size);
}

zr_status zr__context_read_scene(zr_context *ctx, const char *path,
                                 const char *scene_dir, char **bytes,
                                 size_t *size, char *why, size_t why_size) {
  if (why_size)
    why[0] = '\0';
  if (ctx && ctx->read_fn)
    return ctx->read_fn(path, bytes, size, ctx->read_user);
  zr_status s = zr__io_read_scene(ctx, path, scene_dir, bytes, size, why,
                                  why_size);
  return observed(ctx, path, s, bytes, size);
}
