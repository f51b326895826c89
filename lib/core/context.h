/*
 * context.h - the library context: diagnostics callback, file reader and
 * include paths.  No global state: everything a parse needs from its
 * caller is reached through a zr_context.
 */
#ifndef ZR_CORE_CONTEXT_H
#define ZR_CORE_CONTEXT_H

#include <stdarg.h>
#include <stddef.h>

#include "zrcube.h"

struct zr_context {
  zr_diag_fn diag_fn;
  void *diag_user;
  zr_read_fn read_fn;
  void *read_user;
  char **include_paths;
  size_t n_include_paths;
  int render_width, render_height; /* 0 until set: the parser's defaults */
  unsigned long long loop_limit;   /* 0: none */
  char last_error[1024];
  unsigned errors;   /* errors reported so far */
  unsigned warnings; /* warnings reported so far */
};

/*
 * Where a diagnostic points.  source_line is the text of that line (no
 * newline needed; NULL to omit the quote and caret).  notes are extra
 * lines printed after the first, such as "in file included from a.pov:3".
 */
typedef struct zr_diag_place {
  const char *file;
  int line;
  int column;
  const char *source_line;
  size_t source_line_len;
  int caret_len; /* columns to underline with ~ after the ^; 0 for none */
  const char *notes; /* "in file included from ...\n..." or NULL */
} zr_diag_place;

/*
 * Formats and delivers a diagnostic through ctx (which may be NULL); for
 * errors also records ctx->last_error.  Returns status so callers can
 * write "return zr__diag(...)".
 */
zr_status zr__diag(zr_context *ctx, zr_diag_level level, zr_status status,
                   const zr_diag_place *place, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
zr_status zr__vdiag(zr_context *ctx, zr_diag_level level, zr_status status,
                    const zr_diag_place *place, const char *fmt, va_list ap);

/* Reads a whole file through the context's reader (stdio by default). */
zr_status zr__context_read(zr_context *ctx, const char *path, char **bytes,
                           size_t *size);

#endif /* ZR_CORE_CONTEXT_H */
