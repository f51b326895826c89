/*
 * context.h - the library context: diagnostics callback, file reader and
 * include paths.  No global state: everything a parse needs from its
 * caller is reached through a zr_context.
 */
#ifndef ZR_CORE_CONTEXT_H
#define ZR_CORE_CONTEXT_H

#include <stdarg.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "zrcube.h"

struct zr_context {
  zr_diag_fn diag_fn;
  void *diag_user;
  zr_read_fn read_fn;
  void *read_user;
  char **include_paths;
  size_t n_include_paths;
  int render_width, render_height; /* 0 until set: the parser's defaults */
  zr_parse_options parse;          /* clock, version (+MV) */
  char **declared_names;           /* zr_context_declare, in order */
  double *declared_values;
  size_t n_declared;
  char *header_include;            /* +HI, NULL: none */
  /* I/O restrictions (iopolicy.c): the mode and the folders added to the
     defaults, each resolved (realpath) when added. */
  zr_io_restrictions io_mode;
  char **read_dirs;
  size_t n_read_dirs;
  char **write_dirs;
  size_t n_write_dirs;
  zr_read_observer_fn observer_fn;
  void *observer_user;
  unsigned long long work_limit;   /* parse steps; 0: none */
  unsigned long long file_limit;   /* bytes of one file read; 0: none */
  int no_scene_writes;             /* zr_context_set_scene_writes(0) */
  int png_level;                   /* zlib level of PNG output, 0 to 9 */
  int threads;                     /* a parse's threads, at least 1 */
  /* Tests only: the engine hands the grammar every token as it is, no
     T_SPHERE_TEXTURED (lib/sdl/directive.c), to compare the paths. */
  int sdl_tokens_apart;
  /* zr_context_set_team: the members that parse together, NULL alone;
     team_parse is 1 while a parse goes on with them in step (lib/sdl's
     zr__sdl_team_*), 0 once they have parted or before a parse. */
  const zr_team *team;
  int team_parse;
  zr_accel accel;                  /* meshes' backend, never DEFAULT */
  struct zr_budget *budget;        /* the run's memory (core/budget.h) */
  char last_error[1024];
  unsigned errors;   /* errors reported so far */
  unsigned warnings; /* warnings reported so far */
  zr_progress_fn progress_fn; /* zr_context_set_progress */
  void *progress_user;
  atomic_int cancel;          /* zr_context_cancel: any thread, signals */
};

/*
 * Copies a caller's parameter struct that starts with its size (the
 * public *_params structs) into out, which holds the library's
 * defaults: the members in->size covers replace them.  ZR_EINVAL when
 * in is NULL, its size is below min_size (the struct's first release)
 * or it is larger than out_size with bytes past out_size that are not
 * zero (members this library does not know were set).
 */
zr_status zr__params_take(void *out, size_t out_size, const void *in,
                          size_t min_size);

/* Whether ctx (may be NULL) was cancelled with zr_context_cancel(). */
bool zr__cancelled(zr_context *ctx);

/*
 * Tells ctx's progress callback (ctx may be NULL) where a call is.
 * Returns ZR_ECANCELLED when the callback asks to stop or ctx was
 * cancelled, else ZR_OK.  The caller serialises the calls.
 */
zr_status zr__progress(zr_context *ctx, zr_phase phase, uint64_t done,
                       uint64_t total);

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
  /* Byte offset of line:column in the file and the bytes pointed at
     (zr_diag.offset and .length); 0 when not known. */
  size_t offset;
  size_t length;
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

/*
 * Reads a whole file the caller named (the scene file given to
 * zr_scene_parse_file, an image given to zr_image_read) through the
 * context's reader, or the library's own (iopolicy.c: regular files
 * only, not confined to folders).  The bytes end in a NUL that *size
 * does not count.  A file larger than the context's file limit gives
 * ZR_ELIMIT.
 */
zr_status zr__context_read(zr_context *ctx, const char *path, char **bytes,
                           size_t *size);
/* Why a read failed with status s, for "cannot read 'x': ..." messages:
   the file limit and the option that raises it for ZR_ELIMIT. */
const char *zr__context_read_error(const zr_context *ctx, zr_status s,
                                   char *buf, size_t size);
/* The message for what (a noun phrase: "the 4000x4000 image 'a.png'")
   needing bytes past the context's memory budget, in buf: the budget
   and the option that raises it. */
const char *zr__context_budget_text(const zr_context *ctx, size_t bytes,
                                    const char *what, char *buf,
                                    size_t size);
/* Reports that message as an error at place (may be NULL); returns
   ZR_ELIMIT. */
zr_status zr__context_over_budget(zr_context *ctx, size_t bytes,
                                  const zr_diag_place *place,
                                  const char *what);

/*
 * Reads a whole file a scene named, under the context's I/O restrictions
 * (zrcube.h); scene_dir is the resolved folder of the main scene file
 * (NULL when the scene is a string).  ZR_ENOTFOUND when the file does
 * not exist (a search goes on to its next place); ZR_EACCESS when it is
 * refused, with the reason in why (which never quotes the file).
 * relative: the scene named the file by a relative name (path is that
 * name joined to the folder it was searched from), which
 * ZR_IO_RESTRICTED lets it read wherever it leads.
 */
zr_status zr__context_read_scene(zr_context *ctx, const char *path,
                                 const char *scene_dir, bool relative,
                                 char **bytes, size_t *size, char *why,
                                 size_t why_size);

#endif /* ZR_CORE_CONTEXT_H */
