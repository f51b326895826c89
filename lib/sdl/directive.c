/*
 * directive.c - the directive engine between the token arrays and bison,
 * and the public entry points zr_scene_parse_file/_string.
 *
 * POV-Ray's language is a token stream rewritten by directives before the
 * grammar sees it (reference manual, "Language Directives").  This engine
 * is bison's yylex: it walks a stack of frames (the scene file, then each
 * #include in turn) over the files' token arrays and
 *   - runs #include "file": searched in the including file's directory,
 *     then the context's include paths (the CLI's +L), then POV-Ray's
 *     standard include directory; each file is read once (through the
 *     context's reader, so MPI ranks can serve files from memory) and
 *     lexed once, however often it is included; nesting is limited to
 *     ZR_SDL_MAX_INCLUDE_DEPTH levels;
 *   - runs #declare and #local through a nested parser (T_START_DECL),
 *     and hands the block directives (#if, #while, #for, #switch,
 *     #macro, #undef, #debug ...) to control.c;
 *   - runs #version and zRcube's #zfor (n) ... #zend, whose body is
 *     replayed from the token array n times with the float zr = 0..n-1
 *     (an inner loop's zr shadows the outer's until its #zend).  Their
 *     expressions are parsed by the grammar itself through a nested
 *     parser and a second start symbol;
 *   - turns an identifier into a typed token after looking it up, the
 *     newest #local scope first, then the global #declare table, or into
 *     a declaration name right after #declare/#local; a macro name
 *     becomes a macro call, an array name followed by '[' its element;
 *   - turns the built-in constants (clock, image_width, version ...) and
 *     defined(Name) into numbers;
 *   - stops at a reserved word outside the supported slice, naming it.
 * A directive's expression that has no closing token of its own (the
 * value of #version, an object after #declare) ends where the next token
 * cannot continue it: the engine then hands the grammar an end token,
 * as POV-Ray reads such input (see autoend_due below).
 * Messages carry the source line, a caret and the include and macro
 * call chain.
 */
#include "config.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/iopolicy.h"
#include "core/budget.h"
#include "core/strbuf.h"
#include "core/team.h"
#include "pov-parse.h"
#include "sdl/sdl.h"
#include "trace/prepare.h"

/* ---- diagnostics ---- */

/* Innermost include levels a message lists before it abbreviates. */
#define MAX_CHAIN_NOTES 6

/* The include and call chain of a place in file: "in macro X called
   from ..." or "in file included from ..." for each frame below the
   newest frame reading that file. */
static void chain_notes(const zr_sdl_parser *p, int file, zr_strbuf *sb) {
  size_t k = p->n_frames;
  while (k > 0 && p->frames[k - 1].file != file)
    k--;
  size_t listed = 0;
  for (size_t i = k; i-- > 1;) {
    if (listed == MAX_CHAIN_NOTES) {
      zr__strbuf_printf(&*sb, "(and %zu more levels of inclusion or "
                        "macro calls)\n", i);
      break;
    }
    const zr_sdl_loc *at = &p->frames[i].included_at;
    if (p->frames[i].macro)
      zr__strbuf_printf(sb, "in macro %s called from %s:%d:%d\n",
                        p->frames[i].macro->name, p->files[at->file].path,
                        at->line, at->column);
    else
      zr__strbuf_printf(sb, "in file included from %s:%d:%d\n",
                        p->files[at->file].path, at->line, at->column);
    listed++;
  }
}

static void vreport(zr_sdl_parser *p, zr_diag_level level, zr_status status,
                    const zr_sdl_loc *loc, const char *fmt, va_list ap) {
  zr_diag_place place;
  zr_strbuf notes;
  zr__strbuf_init(&notes);
  memset(&place, 0, sizeof place);
  bool placed = loc && loc->file >= 0 && (size_t)loc->file < p->n_files;
  if (placed) {
    zr_sdl_file *f = &p->files[loc->file];
    place.file = f->path;
    place.line = loc->line;
    place.column = loc->column;
    place.source_line = zr__sdl_file_line(f, loc->line,
                                          &place.source_line_len);
    place.caret_len = loc->length > 0 ? loc->length : 1;
    size_t start;
    if (loc->column >= 1 && zr__sdl_file_line_start(f, loc->line, &start)) {
      place.offset = start + (size_t)loc->column - 1;
      place.length = loc->length > 0 ? (size_t)loc->length : 0;
    }
    chain_notes(p, loc->file, &notes);
    place.notes = notes.len ? zr__strbuf_cstr(&notes) : NULL;
  }
  zr__vdiag(p->ctx, level, status, placed ? &place : NULL, fmt, ap);
  zr__strbuf_free(&notes);
}

zr_status zr__sdl_error(zr_sdl_parser *p, zr_status status,
                        const zr_sdl_loc *loc, const char *fmt, ...) {
  /* Only the first error is reported: the parse stops there, and what
     an aborting nested parse says next would only repeat it. */
  if (p->status != ZR_OK)
    return p->status;
  p->status = status;
  va_list ap;
  va_start(ap, fmt);
  vreport(p, ZR_DIAG_ERROR, status, loc, fmt, ap);
  va_end(ap);
  return status;
}

void zr__sdl_warning(zr_sdl_parser *p, const zr_sdl_loc *loc,
                     const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  vreport(p, ZR_DIAG_WARNING, ZR_OK, loc, fmt, ap);
  va_end(ap);
}

/* Progress and cancel every ZR_SDL_PROGRESS_TOKENS tokens the parse
   reads (replays of loops and macros included): false, with the error
   reported at the token, when the caller cancelled. */
static bool report_progress(zr_sdl_parser *p, const zr_sdl_loc *at) {
  if (zr__progress(p->ctx, ZR_PHASE_PARSE, p->tokens_read + p->work, 0) ==
      ZR_OK)
    return true;
  zr__sdl_error(p, ZR_ECANCELLED, at, "the parse was cancelled");
  return false;
}

bool zr__sdl_spend(zr_sdl_parser *p, const zr_sdl_loc *at,
                   const char *what) {
  unsigned long long limit = p->ctx ? p->ctx->work_limit : 0;
  ++p->work;
  /* Loops of simple #declares run without tokens reaching the
     grammar: their steps report progress too. */
  if ((p->work & (ZR_SDL_PROGRESS_TOKENS - 1)) == 0 &&
      !report_progress(p, at))
    return false;
  if (limit == 0 || p->work <= limit)
    return true;
  zr__sdl_error(p, ZR_ELIMIT, at,
                "the parse used up its work budget of %llu steps (each "
                "directive, macro call and loop pass is one) at %s: does "
                "the scene loop or recurse without end? (raise the budget "
                "with --max-work)", limit, what);
  return false;
}

void *zr__sdl_alloc(zr_sdl_parser *p, size_t size) {
  zr_arena *a = &p->scene->arena;
  a->over_budget = 0;
  void *m = zr__arena_alloc(a, size);
  if (!m)
    zr__sdl_alloc_failed(p, size);
  return m;
}

void *zr__sdl_alloc_raw(zr_sdl_parser *p, size_t size) {
  zr_arena *a = &p->scene->arena;
  a->over_budget = 0;
  void *m = zr__arena_alloc_raw(a, size);
  if (!m)
    zr__sdl_alloc_failed(p, size);
  return m;
}

void zr__sdl_alloc_failed(zr_sdl_parser *p, size_t size) {
  zr_arena *a = &p->scene->arena;
  /* Point at the token the grammar read last: the item being built. */
  zr_sdl_loc *at = p->last_loc.line > 0 ? &p->last_loc : NULL;
  if (a->over_budget) {
    char text[400];
    zr__sdl_error(p, ZR_ELIMIT, at, "%s",
                  zr__context_budget_text(p->ctx, size, "the scene", text,
                                          sizeof text));
  } else {
    zr__sdl_error(p, ZR_ENOMEM, at, "out of memory");
  }
}

const char *zr__sdl_token_name(const char *name, char *buf, size_t size) {
  if (name[0] == '#' || zr__sdl_keyword_find(name, strlen(name)) ||
      strcmp(name, "<=") == 0 || strcmp(name, ">=") == 0 ||
      strcmp(name, "!=") == 0) {
    snprintf(buf, size, "'%s'", name);
    return buf;
  }
  return name;
}

/* ---- files and frames ---- */

static zr_sdl_frame *top(zr_sdl_parser *p) {
  return &p->frames[p->n_frames - 1];
}

zr_sdl_frame *zr__sdl_top(zr_sdl_parser *p) { return top(p); }

static zr_sdl_loc token_loc(int file, const zr_sdl_token *t) {
  zr_sdl_loc l = {file, t->line, t->column, t->length};
  return l;
}

zr_sdl_loc zr__sdl_token_loc(int file, const zr_sdl_token *t) {
  return token_loc(file, t);
}

const zr_sdl_token *zr__sdl_peek(zr_sdl_parser *p, size_t k) {
  const zr_sdl_frame *fr = top(p);
  const zr_sdl_file *f = &p->files[fr->file];
  size_t i = fr->pos + k;
  return &f->tokens[i < f->n_tokens ? i : f->n_tokens - 1];
}

zr_sdl_loc zr__sdl_peek_loc(zr_sdl_parser *p, size_t k) {
  return token_loc(top(p)->file, zr__sdl_peek(p, k));
}

/* Takes path and bytes, lexes them and appends the file; on a lexical
   error the file is kept (to quote its lines) and *err filled. */
static zr_status add_file(zr_sdl_parser *p, char *path, char *bytes,
                          size_t size, int *index, zr_sdl_loc *err_loc,
                          char *err, size_t err_size) {
  if (p->n_files == p->cap_files) {
    size_t cap = p->cap_files ? p->cap_files * 2 : 8;
    zr_sdl_file *files = realloc(p->files, cap * sizeof *files);
    if (!files) {
      free(path);
      free(bytes);
      snprintf(err, err_size, "out of memory");
      return ZR_ENOMEM;
    }
    p->files = files;
    p->cap_files = cap;
  }
  *index = (int)p->n_files;
  zr_sdl_file *f = &p->files[p->n_files++];
  zr_status s = zr__sdl_file_lex_scene(f, *index, path, bytes, size,
                                       p->ctx ? p->ctx->budget : NULL,
                                       &p->scene->arena, err_loc, err,
                                       err_size);
  if (s == ZR_OK || s == ZR_ESYNTAX) {
    f->scene_path = zr__arena_strdup(&p->scene->arena, f->path);
    if (!f->scene_path) {
      snprintf(err, err_size, "out of memory");
      return ZR_ENOMEM;
    }
  }
  return s;
}

bool zr__sdl_push_frame(zr_sdl_parser *p, int file, const zr_sdl_loc *at) {
  if (p->n_frames == p->cap_frames) {
    size_t cap = p->cap_frames ? p->cap_frames * 2 : 8;
    zr_sdl_frame *frames = realloc(p->frames, cap * sizeof *frames);
    if (!frames) {
      zr__sdl_error(p, ZR_ENOMEM, at, "out of memory");
      return false;
    }
    p->frames = frames;
    p->cap_frames = cap;
  }
  zr_sdl_frame *fr = &p->frames[p->n_frames++];
  memset(fr, 0, sizeof *fr);
  fr->file = file;
  if (at)
    fr->included_at = *at;
  return true;
}

void zr__sdl_pop_frame(zr_sdl_parser *p) {
  zr_sdl_frame *fr = top(p);
  if (fr->macro)
    p->macro_depth--;
  else if (p->n_frames > 1)
    p->include_depth--;
  zr__sdl_symtab_free(&fr->locals);
  free(fr->loops);
  free(fr->ctl);
  p->n_frames--;
}

/* The table #local writes to, and zr lives in, for a frame: the
   top-level file's locals are its globals (reference manual, "#local"). */
static zr_sdl_symtab *scope_of(zr_sdl_parser *p, size_t frame) {
  return frame == 0 ? &p->globals : &p->frames[frame].locals;
}

zr_sdl_symtab *zr__sdl_scope(zr_sdl_parser *p, size_t frame) {
  return scope_of(p, frame);
}

/* Follows a parameter passed by identifier to the caller's variable
   (which may itself be such a parameter).  NULL when it was #undef'ed. */
static zr_sdl_symbol *resolve(zr_sdl_parser *p, zr_sdl_symbol *s,
                              size_t *frame) {
  while (s && s->value.kind == ZR_SDL_ALIAS) {
    const zr_sdl_alias *a = s->value.ptr;
    if (a->frame >= p->n_frames)
      return NULL;
    if (frame)
      *frame = a->frame;
    s = zr__sdl_symtab_find(scope_of(p, a->frame), a->name);
  }
  return s;
}

/* #declare NAME where NAME is, innermost, a parameter passed by
   identifier: the caller's variable is the one to change, named now
   (POV-Ray 3.7: macros/macro2.pov turns its objects so). */
static void bind_alias(zr_sdl_parser *p, zr_sdl_decl_name *d) {
  zr_sdl_symbol *s = NULL;
  for (size_t i = p->n_frames; i-- > 1 && !s;)
    s = zr__sdl_symtab_find(&p->frames[i].locals, d->name);
  while (s && s->value.kind == ZR_SDL_ALIAS) {
    const zr_sdl_alias *a = s->value.ptr;
    if (a->frame >= p->n_frames)
      return;
    d->name = a->name;
    d->frame = (int)a->frame;
    d->bound = true;
    s = zr__sdl_symtab_find(scope_of(p, a->frame), a->name);
  }
}

zr_sdl_symbol *zr__sdl_lookup(zr_sdl_parser *p, const char *name,
                              size_t *frame) {
  for (size_t i = p->n_frames; i-- > 1;) {
    zr_sdl_symbol *s = zr__sdl_symtab_find(&p->frames[i].locals, name);
    if (s) {
      if (frame)
        *frame = i;
      return resolve(p, s, frame);
    }
  }
  if (frame)
    *frame = 0;
  return zr__sdl_symtab_find(&p->globals, name);
}

/* Assigns value to element name[index...] of an existing array. */
static bool define_element(zr_sdl_parser *p, const zr_sdl_decl_name *name,
                           const zr_sdl_value *value,
                           const zr_sdl_loc *loc) {
  zr_sdl_symbol *s = zr__sdl_lookup(p, name->name, NULL);
  if (!s) {
    zr__sdl_error(p, ZR_EUNDEFINED, loc, "undefined identifier '%s'",
                  name->name);
    return false;
  }
  if (s->value.kind != ZR_SDL_ARRAY) {
    zr__sdl_error(p, ZR_ESYNTAX, loc, "'%s' is not an array", name->name);
    return false;
  }
  zr_sdl_array *a = (zr_sdl_array *)s->value.ptr;
  zr_sdl_value *e = zr__sdl_array_at(p, name->name, a, name->index,
                                     name->n_index, loc);
  if (!e)
    return false;
  *e = *value;
  return true;
}

bool zr__sdl_define(zr_sdl_parser *p, const zr_sdl_decl_name *name,
                    bool is_local, const zr_sdl_value *value,
                    const zr_sdl_loc *loc) {
  if (name->n_index > 0)
    return define_element(p, name, value, loc);
  size_t frame = (size_t)name->frame;
  if (frame >= p->n_frames)
    frame = p->n_frames - 1;
  zr_sdl_symtab *t = NULL;
  zr_sdl_symbol *s = NULL;
  if (!is_local && name->bound && (size_t)name->frame < p->n_frames) {
    t = scope_of(p, (size_t)name->frame);
    s = zr__sdl_symtab_find(t, name->name);
    if (s) {
      s->value = *value;
      return true;
    }
    if (zr__sdl_symtab_set(t, name->name, value) != ZR_OK) {
      zr__sdl_error(p, ZR_ENOMEM, loc, "out of memory");
      return false;
    }
    return true;
  }
  if (is_local) {
    t = scope_of(p, frame);
    s = zr__sdl_symtab_find(t, name->name);
  } else {
    /* #declare changes the innermost existing name, else makes a global
       one (reference manual, "Identifier Name Collisions"). */
    for (size_t i = p->n_frames; i-- > 1 && !s;) {
      t = &p->frames[i].locals;
      s = zr__sdl_symtab_find(t, name->name);
    }
    if (!s) {
      t = &p->globals;
      s = zr__sdl_symtab_find(t, name->name);
    }
  }
  if (s && s->value.kind == ZR_SDL_ALIAS) {
    /* A parameter passed by identifier: the caller's variable changes
       (and is made again if the macro #undef'ed it). */
    const zr_sdl_alias *a = NULL;
    while (s && s->value.kind == ZR_SDL_ALIAS) {
      a = s->value.ptr;
      if (a->frame >= p->n_frames)
        break;
      t = scope_of(p, a->frame);
      s = zr__sdl_symtab_find(t, a->name);
    }
    if (!s && a) {
      if (zr__sdl_symtab_set(t, a->name, value) != ZR_OK) {
        zr__sdl_error(p, ZR_ENOMEM, loc, "out of memory");
        return false;
      }
      return true;
    }
  }
  if (s) {
    s->value = *value;
    return true;
  }
  if (zr__sdl_symtab_set(t, name->name, value) != ZR_OK) {
    zr__sdl_error(p, ZR_ENOMEM, loc, "out of memory");
    return false;
  }
  return true;
}

/* ---- #include ---- */

static char *join_path(const char *dir, size_t dir_len, const char *name) {
  zr_strbuf sb;
  zr__strbuf_init(&sb);
  if (dir_len > 0) {
    zr__strbuf_append(&sb, dir, dir_len);
    if (dir[dir_len - 1] != '/')
      zr__strbuf_putc(&sb, '/');
  }
  zr__strbuf_puts(&sb, name);
  return zr__strbuf_take(&sb);
}

/*
 * Opens name as the #include at 'at' asks: returns the file's index, or
 * -1 after reporting.  Already read files are taken from the cache.
 */
static int open_include(zr_sdl_parser *p, const char *name,
                        const zr_sdl_loc *at, const zr_sdl_loc *directive,
                        const char *what) {
  const char *including = p->files[top(p)->file].path;
  const char *slash = strrchr(including, '/');
  size_t n_dirs = p->ctx ? p->ctx->n_include_paths : 0;
  for (size_t i = 0; i < n_dirs + 2; i++) {
    char *path;
    if (name[0] == '/') {
      if (i > 0)
        break;
      path = strdup(name);
    } else if (i == 0) {
      path = join_path(including, slash ? (size_t)(slash - including) : 0,
                       name);
    } else if (i <= n_dirs) {
      const char *dir = p->ctx->include_paths[i - 1];
      path = join_path(dir, strlen(dir), name);
    } else {
      path = join_path(ZR_POVRAY_INCLUDE_DIR, strlen(ZR_POVRAY_INCLUDE_DIR),
                       name);
    }
    if (!path) {
      zr__sdl_error(p, ZR_ENOMEM, at, "out of memory");
      return -1;
    }
    for (size_t k = 0; k < p->n_files; k++) {
      if (strcmp(p->files[k].path, path) == 0) {
        free(path);
        return (int)k;
      }
    }
    char *bytes = NULL;
    size_t size = 0;
    zr_status s = zr__sdl_read_file(p, path, name[0] != '/', at, what,
                                   &bytes, &size);
    if (s == ZR_ENOTFOUND) {
      free(path);
      continue;
    }
    if (s != ZR_OK) {
      free(path);
      return -1;
    }
    int index;
    zr_sdl_loc err_loc;
    char err[200];
    s = add_file(p, path, bytes, size, &index, &err_loc, err, sizeof err);
    if (s == ZR_ESYNTAX) {
      /* Point into the new file, with the chain through this #include. */
      if (zr__sdl_push_frame(p, index, directive))
        zr__sdl_error(p, s, &err_loc, "%s", err);
      return -1;
    }
    if (s != ZR_OK) {
      zr__sdl_error(p, s, at, "%s", err);
      return -1;
    }
    return index;
  }
  zr__sdl_error(p, ZR_ENOTFOUND, at, "cannot find %s '%s'", what, name);
  return -1;
}

zr_status zr__sdl_read_file(zr_sdl_parser *p, const char *path,
                            bool relative, const zr_sdl_loc *at,
                            const char *what, char **bytes, size_t *size) {
  char why[1024];
  zr_status s = zr__context_read_scene(p->ctx, path, p->scene_dir, relative,
                                       bytes, size, why, sizeof why);
  if (s == ZR_OK || s == ZR_ENOTFOUND)
    return s;
  if (why[0])
    return zr__sdl_error(p, s, at, "cannot read %s: %s", what, why);
  return zr__sdl_error(p, s, at, "cannot read %s '%s': %s", what, path,
                       zr_status_str(s));
}

int zr__sdl_open_data(zr_sdl_parser *p, const char *name,
                      const zr_sdl_loc *at) {
  return open_include(p, name, at, at, "data file");
}

static bool do_include(zr_sdl_parser *p, const zr_sdl_loc *directive) {
  zr_sdl_loc at = zr__sdl_peek_loc(p, 0);
  const char *name;
  if (zr__sdl_peek(p, 0)->kind == T_STRING) {
    name = zr__sdl_peek(p, 0)->v.str;
    top(p)->pos++;
  } else {
    /* "#include concat(Dir, Name)": any string expression. */
    if (zr__sdl_parse_nested(p, T_START_STRING) != ZR_OK)
      return false;
    name = p->nested_rvalue.ptr;
  }
  /* "#include "x.inc";": POV-Ray 3.7 reads the ';' (measured:
     tests/legacy/include_semicolon.pov). */
  if (zr__sdl_peek(p, 0)->kind == ';')
    top(p)->pos++;
  if (p->include_depth >= ZR_SDL_MAX_INCLUDE_DEPTH) {
    zr__sdl_error(p, ZR_ELIMIT, directive,
                  "#include nested more than %d levels deep "
                  "(does a file include itself?)",
                  ZR_SDL_MAX_INCLUDE_DEPTH);
    return false;
  }
  int file = open_include(p, name, &at, directive, "include file");
  if (file < 0 || !zr__sdl_push_frame(p, file, directive))
    return false;
  p->include_depth++;
  return true;
}

bool zr__sdl_file_exists(zr_sdl_parser *p, const char *name) {
  /* The places #include searches, in its order. */
  const char *including = p->files[top(p)->file].path;
  const char *slash = strrchr(including, '/');
  size_t n_dirs = p->ctx ? p->ctx->n_include_paths : 0;
  for (size_t i = 0; i < n_dirs + 2; i++) {
    char *path;
    if (name[0] == '/')
      path = i == 0 ? strdup(name) : NULL;
    else if (i == 0)
      path = join_path(including, slash ? (size_t)(slash - including) : 0,
                       name);
    else if (i <= n_dirs)
      path = join_path(p->ctx->include_paths[i - 1],
                       strlen(p->ctx->include_paths[i - 1]), name);
    else
      path = join_path(ZR_POVRAY_INCLUDE_DIR,
                       strlen(ZR_POVRAY_INCLUDE_DIR), name);
    if (!path)
      continue;
    /* A file the I/O restrictions refuse is not there for the scene:
       file_exists() tells nothing about the rest of the disk. */
    char *bytes = NULL;
    size_t size = 0;
    char why[512];
    zr_status s = zr__context_read_scene(p->ctx, path, p->scene_dir,
                                         name[0] != '/', &bytes, &size, why,
                                         sizeof why);
    free(path);
    free(bytes);
    if (s == ZR_OK)
      return true;
    if (s != ZR_ENOTFOUND)
      return false;
  }
  return false;
}

/* ---- nested parses, #declare, #version, #zfor, #zend ---- */

zr_status zr__sdl_parse_nested(zr_sdl_parser *p, int start_token) {
  if (p->nested_depth >= ZR_SDL_MAX_NESTED_PARSE) {
    zr_sdl_loc at = zr__sdl_peek_loc(p, 0);
    return zr__sdl_error(p, ZR_ELIMIT, &at,
                         "directives and macro calls nest more than %d "
                         "levels deep",
                         ZR_SDL_MAX_NESTED_PARSE);
  }
  /* The enclosing parse's end detection waits while this one runs. */
  zr_sdl_autoend saved = p->autoend;
  memset(&p->autoend, 0, sizeof p->autoend);
  if (start_token == T_START_DECL)
    p->autoend.token = T_DECL_END;
  else if (start_token == T_START_ARG)
    p->autoend.token = T_ARG_SEP;
  else if (start_token == T_START_VERSION)
    p->autoend.token = ';';
  p->start_token = start_token;
  p->nested_depth++;
  int r = zr__pov_parse(p);
  p->nested_depth--;
  p->start_token = 0;
  p->autoend = saved;
  if (r != 0 || p->status != ZR_OK) {
    if (p->status == ZR_OK)
      zr__sdl_error(p, ZR_ENOMEM, NULL, "out of memory");
    return p->status;
  }
  return ZR_OK;
}

zr_status zr__sdl_parse_expr(zr_sdl_parser *p, int start_token,
                             zr_sdl_expr *out) {
  zr_status s = zr__sdl_parse_nested(p, start_token);
  if (s == ZR_OK)
    *out = p->nested_value;
  return s;
}

/* Runs #declare or #local, with POV-Ray 3.7's "deprecated [once]
   ["message"]" before the name ("Deprecation Support"). */
static bool do_declare(zr_sdl_parser *p, int kind) {
  bool deprecated = false, once = false;
  const char *message = NULL;
  if (zr__sdl_peek(p, 0)->kind == T_DEPRECATED) {
    deprecated = true;
    top(p)->pos++;
    if (zr__sdl_peek(p, 0)->kind == T_ONCE) {
      once = true;
      top(p)->pos++;
    }
    if (zr__sdl_peek(p, 0)->kind == T_STRING) {
      message = zr__sdl_peek(p, 0)->v.str;
      top(p)->pos++;
    }
  }
  if (!deprecated && zr__sdl_fast_declare(p, kind == T_LOCAL))
    return p->status == ZR_OK;
  const zr_sdl_token *name = zr__sdl_peek(p, 0);
  p->want_decl_name = true;
  p->decl_local = kind == T_LOCAL;
  if (zr__sdl_parse_nested(p, T_START_DECL) != ZR_OK)
    return false;
  if (deprecated && name->kind == T_IDENTIFIER) {
    zr_sdl_symbol *s = zr__sdl_lookup(p, name->v.str, NULL);
    if (s) {
      s->deprecated = true;
      s->deprecated_once = once;
      s->warned = false;
      s->deprecated_message = message;
    }
  }
  return true;
}

static bool do_version(zr_sdl_parser *p, const zr_sdl_loc *directive) {
  zr_sdl_expr e;
  zr_status s = zr__sdl_parse_expr(p, T_START_VERSION, &e);
  p->version_given = true;
  p->scene->settings.version_given = true;
  if (s != ZR_OK || !zr__sdl_want_float(p, &e, directive, &p->version))
    return false;
  /* POV-Ray 3.7 refuses a scene that asks for a newer language, "Your
     scene file requires POV-Ray version 3.8 or later!"; it compares the
     version rounded to hundredths (3.70499 passes, 3.705 asks for 3.71:
     measured, tests/refused/version_38.pov). */
  double hundredths = floor(p->version * 100 + 0.5);
  if (hundredths > 370) {
    zr__sdl_error(p, ZR_EUNSUPPORTED, directive, "the scene needs POV-Ray "
                  "version %g or later; zRcube reads POV-Ray 3.7's "
                  "language", hundredths / 100);
    return false;
  }
  return true;
}

/* Tokens after which an expression may be complete. */
static bool ends_operand(int kind) {
  switch (kind) {
  case T_NUMBER: case T_FLOAT_ID: case T_VECTOR_ID: case T_COLOUR_ID:
  case T_PIGMENT_ID: case T_FINISH_ID: case T_TEXTURE_ID:
  case T_INTERIOR_ID: case T_OBJECT_ID: case T_STRING_ID: case T_ARRAY_ID:
  case T_FUNCTION_ID: case T_STRING:
  case T_NORMAL_ID: case T_COLOUR_MAP_ID: case T_MATERIAL_ID:
  case T_MEDIA_ID: case T_TRANSFORM_ID: case T_DENSITY_ID:
  /* function.c reads a function's body straight from the token array:
     the next token the engine hands out follows the whole function. */
  case T_FUNCTION:
  case ')': case '>': case ']': case '}':
  case T_X: case T_Y: case T_Z: case T_T: case T_U:
  case T_V: case T_PI: case T_TRUE: case T_FALSE: case T_YES: case T_NO:
  case T_ON: case T_OFF: case T_RED: case T_GREEN: case T_BLUE:
  case T_FILTER: case T_TRANSMIT: case T_GRAY:
    return true;
  default:
    return false;
  }
}

/* Tokens that may follow a complete operand inside an expression ('('
   after a function identifier: "#declare V = F(1);"). */
static bool continues(int kind) {
  switch (kind) {
  case '+': case '-': case '*': case '/': case '.': case ';': case '[':
  case '(':
  case '{': case '?': case ':': case '<': case '>': case '=': case '&':
  case '|': case T_LE: case T_GE: case T_NE:
  case T_RGB: case T_RGBF: case T_RGBT: case T_RGBFT: case T_RED:
  case T_SRGB: case T_SRGBF: case T_SRGBT: case T_SRGBFT:
  case T_GREEN: case T_BLUE: case T_FILTER: case T_TRANSMIT:
    return true;
  default:
    return false;
  }
}

/* Directives that close or continue a block: running them never starts
   anything new, so an expression may go on after them (a macro's value
   continues in its caller after the macro's #end). */
static bool closes_block(int kind) {
  return kind == T_END || kind == T_ELSE || kind == T_ELSEIF ||
         kind == T_BREAK || kind == T_CASE || kind == T_RANGE ||
         kind == T_ZEND;
}

static bool is_directive(int kind) {
  return (kind >= T_DECLARE && kind <= T_ZEND) ||
         (kind >= T_IF && kind <= T_DEFAULT);
}

/*
 * Whether the expression of the directive being parsed (the value of a
 * #declare or of #version) is complete before the next token, next.  It
 * is when no bracket is open, the last token could end an operand, and
 * next cannot continue it or starts another directive: POV-Ray accepts
 * "#version 3.7" without its ';' (and warns), and an object, texture or
 * array after #declare needs none.
 */
static bool autoend_due(const zr_sdl_parser *p, int next) {
  const zr_sdl_autoend *a = &p->autoend;
  if (!a->token || a->depth > 0 || !a->operand || closes_block(next))
    return false;
  /* A macro argument ends by itself only after a block, where nothing
     can continue it, or before 'color' after a complete value, which
     starts the next argument: POV-Ray 3.7 runs t-o-k's
     FitHeightLineToPoints.pov, "ShowLine2D(..., 0.02 color rgbt <...>)"
     (tests/legacy/macro_arg_colour.pov); otherwise its ',' or ')' ends
     it. */
  if (a->token == T_ARG_SEP)
    return (a->last == '}' || next == T_COLOUR) && next != ',' &&
           next != ')' && next != 0 && next != T_TEXTURE &&
           !is_directive(next);
  if (next == 0)
    return p->n_frames == 1;
  if (is_directive(next))
    return true;
  if (a->token == ';' && next == '{')
    return true;
  /* "#declare T = texture { ... } texture { ... }" layers textures. */
  if (next == T_TEXTURE && a->last == '}')
    return false;
  /* A '(' after a block starts something new: shapes.inc's Text_Width
     declares "#local TO = text {...}" and goes on "(max_extent(TO).x". */
  if (next == '(' && a->last == '}')
    return true;
  return !continues(next);
}

static void track(zr_sdl_parser *p, int kind) {
  zr_sdl_autoend *a = &p->autoend;
  /* The runs of tokens.c: a sphere's stands for "sphere { centre,
     radius" and leaves its block open, a triangle's for the whole
     "triangle { ... }" (or "smooth_triangle { ... }"). */
  if (kind == T_SPHERE_RUN)
    kind = '{';
  if (kind == T_TRIANGLE_RUN || kind == T_SMOOTH_TRIANGLE_RUN) {
    a->operand = true;
    a->last = '}';
    return;
  }
  bool vector = kind == '<' && !a->operand;
  if (kind == '(' || kind == '[' || kind == '{' || vector) {
    if (a->depth < 64) {
      unsigned long long bit = 1ull << a->depth;
      a->angles = vector ? a->angles | bit : a->angles & ~bit;
    }
    a->depth++;
  } else if (kind == ')' || kind == ']' || kind == '}' ||
             (kind == '>' && a->depth > 0 && a->depth <= 64 &&
              (a->angles >> (a->depth - 1) & 1))) {
    if (a->depth > 0)
      a->depth--;
  } else if (kind == '>') {
    /* A comparison, not the end of a vector. */
    a->operand = false;
    a->last = kind;
    return;
  }
  /* red, filter ... end an operand only as ".red"; before a value they
     are colour items ("color red 1 green 0.5"). */
  bool item = kind == T_RED || kind == T_GREEN || kind == T_BLUE ||
              kind == T_FILTER || kind == T_TRANSMIT || kind == T_GRAY;
  a->operand = ends_operand(kind) && (!item || a->last == '.');
  a->last = kind;
}

static bool set_zr(zr_sdl_parser *p, zr_sdl_symtab *scope, double value) {
  zr_sdl_value v;
  memset(&v, 0, sizeof v);
  v.kind = ZR_SDL_FLOAT;
  v.num = zr__sdl_float(value);
  if (zr__sdl_symtab_set(scope, "zr", &v) != ZR_OK) {
    zr__sdl_error(p, ZR_ENOMEM, NULL, "out of memory");
    return false;
  }
  return true;
}

/* The index of the #zend closing a loop whose body starts at pos, or
   (size_t)-1 when there is none in the file. */
static size_t matching_zend(const zr_sdl_file *f, size_t pos) {
  int depth = 0;
  for (size_t i = pos; i < f->n_tokens; i++) {
    if (f->tokens[i].kind == T_ZFOR)
      depth++;
    else if (f->tokens[i].kind == T_ZEND && depth-- == 0)
      return i;
  }
  return (size_t)-1;
}

static bool do_zfor(zr_sdl_parser *p, const zr_sdl_loc *directive) {
  size_t frame = p->n_frames - 1;
  if (matching_zend(&p->files[top(p)->file], top(p)->pos) == (size_t)-1) {
    zr__sdl_error(p, ZR_ESYNTAX, directive,
                  "'#zfor' without a matching '#zend'");
    return false;
  }
  zr_sdl_expr e;
  double count;
  if (zr__sdl_parse_expr(p, T_START_PAREN, &e) != ZR_OK ||
      !zr__sdl_want_float(p, &e, directive, &count))
    return false;
  if (p->n_frames - 1 != frame) {
    zr__sdl_error(p, ZR_ESYNTAX, directive,
                  "the count of '#zfor' must be in the same file");
    return false;
  }
  if (!(count >= 0)) {
    zr__sdl_error(p, ZR_ESCENE, directive,
                  "the count of '#zfor' is negative (%g)", count);
    return false;
  }
  if (count > ZR_SDL_MAX_ZFOR) {
    zr__sdl_error(p, ZR_ELIMIT, directive,
                  "the count of '#zfor' is more than %d (%g)",
                  ZR_SDL_MAX_ZFOR, count);
    return false;
  }
  zr_sdl_frame *fr = top(p);
  size_t end = matching_zend(&p->files[fr->file], fr->pos);
  if ((long)count == 0) {
    fr->pos = end + 1;
    return true;
  }
  if (fr->n_loops == fr->cap_loops) {
    size_t cap = fr->cap_loops ? fr->cap_loops * 2 : 4;
    zr_sdl_loop *loops = realloc(fr->loops, cap * sizeof *loops);
    if (!loops) {
      zr__sdl_error(p, ZR_ENOMEM, directive, "out of memory");
      return false;
    }
    fr->loops = loops;
    fr->cap_loops = cap;
  }
  zr_sdl_loop *loop = &fr->loops[fr->n_loops++];
  memset(loop, 0, sizeof *loop);
  loop->start = fr->pos;
  loop->end = end;
  loop->count = (long)count;
  zr_sdl_symtab *scope = scope_of(p, frame);
  const zr_sdl_symbol *outer = zr__sdl_symtab_find(scope, "zr");
  if (outer) {
    loop->had_outer = true;
    loop->outer = outer->value;
  }
  return set_zr(p, scope, 0);
}

static bool do_zend(zr_sdl_parser *p, const zr_sdl_loc *directive) {
  zr_sdl_frame *fr = top(p);
  size_t frame = p->n_frames - 1;
  if (fr->n_loops == 0 || fr->loops[fr->n_loops - 1].end != fr->pos - 1) {
    zr__sdl_error(p, ZR_ESYNTAX, directive,
                  "'#zend' without a matching '#zfor'");
    return false;
  }
  zr_sdl_loop *loop = &fr->loops[fr->n_loops - 1];
  zr_sdl_symtab *scope = scope_of(p, frame);
  if (++loop->done < loop->count) {
    fr->pos = loop->start;
    return set_zr(p, scope, (double)loop->done);
  }
  /* The loop is over: an outer loop's zr (or an older zr) comes back. */
  if (loop->had_outer) {
    if (zr__sdl_symtab_set(scope, "zr", &loop->outer) != ZR_OK) {
      zr__sdl_error(p, ZR_ENOMEM, directive, "out of memory");
      return false;
    }
  } else {
    zr__sdl_symtab_remove(scope, "zr");
  }
  fr->n_loops--;
  return true;
}

/* ---- the token stream bison reads ---- */

static int identifier_token(zr_sdl_kind kind) {
  switch (kind) {
  case ZR_SDL_FLOAT: return T_FLOAT_ID;
  case ZR_SDL_VECTOR: return T_VECTOR_ID;
  case ZR_SDL_COLOUR: return T_COLOUR_ID;
  case ZR_SDL_PIGMENT: return T_PIGMENT_ID;
  case ZR_SDL_FINISH: return T_FINISH_ID;
  case ZR_SDL_TEXTURE: return T_TEXTURE_ID;
  case ZR_SDL_INTERIOR: return T_INTERIOR_ID;
  case ZR_SDL_FUNCTION: return T_FUNCTION_ID;
  case ZR_SDL_NORMAL: return T_NORMAL_ID;
  case ZR_SDL_COLOUR_MAP: return T_COLOUR_MAP_ID;
  case ZR_SDL_MATERIAL: return T_MATERIAL_ID;
  case ZR_SDL_SKY_SPHERE: return T_SKY_SPHERE_ID;
  case ZR_SDL_CAMERA: return T_CAMERA_ID;
  case ZR_SDL_LIGHT: return T_LIGHT_ID;
  case ZR_SDL_MEDIA: return T_MEDIA_ID;
  case ZR_SDL_DENSITY: return T_DENSITY_ID;
  case ZR_SDL_TRANSFORM: return T_TRANSFORM_ID;
  case ZR_SDL_STRING: return T_STRING_ID;
  case ZR_SDL_ARRAY: return T_ARRAY_ID;
  case ZR_SDL_SPLINE: return T_SPLINE_ID;
  default: return T_OBJECT_ID;
  }
}

static int deliver(zr_sdl_parser *p, int kind, const zr_sdl_lexval *val,
                   const zr_sdl_loc *loc, const char *text,
                   zr_sdl_lexval *out_val, zr_sdl_loc *out_loc) {
  p->last_loc = *loc;
  p->last_text = text;
  p->want_decl_name = false;
  if (p->autoend.token)
    track(p, kind);
  *out_val = *val;
  *out_loc = *loc;
  return kind;
}

/* The value of a built-in constant (reference manual, "Built-in Float
   Identifiers"): the render size, and the animation clock the caller
   set (zr_context_set_parse_options); for a still image POV-Ray 3.7
   gives 0 for all of clock, clock_delta, clock_on, frame_number,
   initial_clock, final_clock, initial_frame and final_frame (measured
   with povray 3.7.0), the defaults of zr_parse_options_init(). */
double zr__sdl_constant(const zr_sdl_parser *p, const char *name) {
  const zr_parse_options *a = &p->anim;
  if (strcmp(name, "clock") == 0)
    return p->clock;
  if (strcmp(name, "clock_delta") == 0)
    return a->clock_delta;
  if (strcmp(name, "clock_on") == 0)
    return a->clock_on;
  if (strcmp(name, "frame_number") == 0)
    return a->frame_number;
  if (strcmp(name, "initial_frame") == 0)
    return a->initial_frame;
  if (strcmp(name, "final_frame") == 0)
    return a->final_frame;
  if (strcmp(name, "initial_clock") == 0)
    return a->initial_clock;
  if (strcmp(name, "final_clock") == 0)
    return a->final_clock;
  if (strcmp(name, "image_width") == 0)
    return p->image_width;
  if (strcmp(name, "image_height") == 0)
    return p->image_height;
  if (strcmp(name, "version") == 0)
    return p->version;
  if (strcmp(name, "tau") == 0)
    return 2 * 3.14159265358979323846;
  return 0;
}

/*
 * An array name followed by '[': reads the indices (nested parses) and
 * returns the element, or NULL after an error.
 */
static const zr_sdl_value *array_element(zr_sdl_parser *p, const char *name,
                                         zr_sdl_array *a,
                                         const zr_sdl_loc *at) {
  int index[ZR_SDL_MAX_DIMS];
  int n = 0;
  size_t frames = p->n_frames;
  while (zr__sdl_peek(p, 0)->kind == '[' && n < a->n_dims) {
    zr_sdl_loc il = zr__sdl_peek_loc(p, 1);
    double v;
    if (zr__sdl_parse_nested(p, T_START_INDEX) != ZR_OK ||
        !zr__sdl_want_float(p, &p->nested_value, &il, &v))
      return NULL;
    if (p->n_frames != frames) {
      zr__sdl_error(p, ZR_ESYNTAX, at, "an array index must end in the "
                    "file or macro where it begins");
      return NULL;
    }
    index[n++] = (int)floor(v);
  }
  bool set;
  const zr_sdl_value *e = zr__sdl_array_get(p, name, a, index, n, at, &set);
  if (!e)
    return NULL;
  if (!set) {
    zr__sdl_error(p, ZR_EUNDEFINED, at,
                  "element of array '%s' used before it was assigned",
                  name);
    return NULL;
  }
  return e;
}

/*
 * "sphere { <x, y, z>, r texture { T } }", T a texture identifier, as
 * one token, T_SPHERE_TEXTURED (issue 13): the line of a sphere-heavy
 * file.  The T_SPHERE_RUN t (fr->pos already past it) is followed in
 * the token array by T_TEXTURE '{' T_IDENTIFIER '}' '}' on its line;
 * the grammar would take them one by one, and the engine would hand
 * them out as below: no directive, macro or end of file among them,
 * the identifier looked up in the same frames (nothing between the
 * sphere and it declares a name), progress counted for each.  So the
 * fused token is made only when the identifier is a texture that is
 * not deprecated (a warning would come earlier), when no #version or
 * #declare is waiting for its end (autoend) and when no name is being
 * declared.  The grammar's action makes the slow path's calls
 * (zr__sdl_sphere_textured).  On bench/peers.sh's sphereflake this
 * took 11.7 M of the parse's 64.5 M instructions away (callgrind,
 * --parse-only): bison's ten reductions and six shifts a sphere, and
 * five tokens through the engine.  Returns 1 with v filled in and the
 * frame moved past the tokens, 0 when the tokens are not that (nothing
 * changed), -1 after an error (a cancel seen by the progress report).
 */
static int sphere_textured(zr_sdl_parser *p, zr_sdl_frame *fr,
                           const zr_sdl_token *t, zr_sdl_lexval *v) {
  static const int kinds[5] = {T_TEXTURE, '{', T_IDENTIFIER, '}', '}'};
  if (p->autoend.token || p->want_decl_name ||
      (p->ctx && p->ctx->sdl_tokens_apart))
    return 0;
  const zr_sdl_token *u = t + 1; /* the token array ends with kind 0 */
  for (int i = 0; i < 5; i++)
    if (u[i].kind != kinds[i] || u[i].line != t->line)
      return 0;
  zr_sdl_symbol *s = zr__sdl_lookup(p, u[2].v.str, NULL);
  if (!s || s->deprecated || s->value.kind != ZR_SDL_TEXTURE)
    return 0;
  for (int i = 0; i < 5; i++) {
    zr_sdl_loc ul = token_loc(fr->file, &u[i]);
    if ((++p->tokens_read & (ZR_SDL_PROGRESS_TOKENS - 1)) == 0 &&
        !report_progress(p, &ul))
      return -1;
  }
  fr->pos += 5;
  v->sphere_tex.sphere = t->v.sphere;
  v->sphere_tex.texture = s->value.ptr;
  v->sphere_tex.texture_column = u[0].column;
  v->sphere_tex.texture_length = u[3].column + u[3].length - u[0].column;
  v->sphere_tex.length = u[4].column + u[4].length - t->column;
  return 1;
}

int zr__sdl_next(zr_sdl_lexval *val, zr_sdl_loc *loc, zr_sdl_parser *p) {
  zr_sdl_lexval v;
  memset(&v, 0, sizeof v);
  if (p->start_token) {
    int kind = p->start_token;
    p->start_token = 0;
    *val = v;
    *loc = p->last_loc;
    return kind;
  }
  for (;;) {
    if (p->status != ZR_OK)
      return ZR__POV_error;
    zr_sdl_frame *fr = top(p);
    const zr_sdl_token *t = &p->files[fr->file].tokens[fr->pos];
    zr_sdl_loc tl = token_loc(fr->file, t);
    if (autoend_due(p, t->kind)) {
      int end = p->autoend.token;
      if (end == ';')
        zr__sdl_warning(p, &p->last_loc, "'#version' should end with ';'");
      p->autoend.token = 0;
      return deliver(p, end, &v, &p->last_loc, NULL, val, loc);
    }
    if (t->kind == 0) {
      if (!zr__sdl_check_blocks(p))
        return ZR__POV_error;
      if (p->n_frames > 1) {
        zr__sdl_pop_frame(p);
        continue;
      }
      return deliver(p, 0, &v, &tl, NULL, val, loc);
    }
    fr->pos++;
    if ((++p->tokens_read & (ZR_SDL_PROGRESS_TOKENS - 1)) == 0 &&
        !report_progress(p, &tl))
      return ZR__POV_error;
    if (is_directive(t->kind)) {
      char what[48];
      snprintf(what, sizeof what, "'%s'", zr__sdl_kind_name(t->kind));
      if (!zr__sdl_spend(p, &tl, what))
        return ZR__POV_error;
    }
    switch (t->kind) {
    case T_INCLUDE:
      if (!do_include(p, &tl))
        return ZR__POV_error;
      continue;
    case T_DECLARE:
    case T_LOCAL:
      /* "declare" without '#' (POV-Ray 2.x-3.0 syntax, which 3.7
         accepts; measured: tests/legacy/declare.pov). */
      if (t->kind == T_DECLARE && t->length == 7)
        zr__sdl_warning(p, &tl, "Should have '#' before 'declare'.");
      if (!do_declare(p, t->kind))
        return ZR__POV_error;
      continue;
    case T_VERSION:
      if (!do_version(p, &tl))
        return ZR__POV_error;
      continue;
    case T_ZFOR:
      if (!do_zfor(p, &tl))
        return ZR__POV_error;
      continue;
    case T_ZEND:
      if (!do_zend(p, &tl))
        return ZR__POV_error;
      continue;
    case T_UNSUPPORTED:
      zr__sdl_error(p, ZR_EUNSUPPORTED, &tl, "'%s' is not supported yet",
                    t->v.str);
      return ZR__POV_error;
    case T_BAD_CHAR: {
      /* The scanner's token for a character no token begins with
         (grammar/pov.l): the error waits until the scene reaches it. */
      int c = (unsigned char)t->v.str[0];
      if (c >= 32 && c < 127)
        zr__sdl_error(p, ZR_ESYNTAX, &tl, "unexpected character '%c'", c);
      else
        zr__sdl_error(p, ZR_ESYNTAX, &tl, "unexpected byte 0x%02x", c);
      return ZR__POV_error;
    }
    case ZR_SDL_NUMBER_LIST:
      /* mesh2's fast reader takes these runs after the list's count
         (build_mesh.c); nothing else should meet one. */
      zr__sdl_error(p, ZR_ESYNTAX, &tl, "these mesh2 items cannot be "
                    "read here");
      return ZR__POV_error;
    case T_CONSTANT:
      v.num = zr__sdl_constant(p, t->v.str);
      return deliver(p, T_NUMBER, &v, &tl, NULL, val, loc);
    case T_DEFINED: {
      bool defined;
      if (!zr__sdl_read_defined(p, &tl, &defined))
        return ZR__POV_error;
      v.num = defined ? 1 : 0;
      return deliver(p, T_NUMBER, &v, &tl, NULL, val, loc);
    }
    case T_NUMBER:
      v.num = t->v.num;
      return deliver(p, t->kind, &v, &tl, NULL, val, loc);
    case T_SPHERE_RUN: {
      int fused = sphere_textured(p, fr, t, &v);
      if (fused < 0)
        return ZR__POV_error;
      if (fused == 0) {
        v.sphere = t->v.sphere;
        return deliver(p, t->kind, &v, &tl, NULL, val, loc);
      }
      int kind = deliver(p, T_SPHERE_TEXTURED, &v, &tl, NULL, val, loc);
      /* The last token the slow path hands out is the sphere's '}'. */
      p->last_loc = token_loc(fr->file, t + 5);
      return kind;
    }
    case T_TRIANGLE_RUN:
      v.corners = t->v.corners;
      return deliver(p, t->kind, &v, &tl, NULL, val, loc);
    case T_SMOOTH_TRIANGLE_RUN: {
      const zr_sdl_file *f = &p->files[fr->file];
      v.smooth.corners = f->corners + t->v.smooth.corner;
      v.smooth.normals = f->normals + t->v.smooth.normal;
      return deliver(p, t->kind, &v, &tl, NULL, val, loc);
    }
    case T_IDENTIFIER:
      break;
    default:
      if (is_directive(t->kind)) {
        if (!zr__sdl_run_directive(p, t, &tl))
          return ZR__POV_error;
        continue;
      }
      v.str = t->v.str;
      return deliver(p, t->kind, &v, &tl, NULL, val, loc);
    }
    if (p->want_decl_name) {
      v.decl.name = t->v.str;
      v.decl.frame = (int)(p->n_frames - 1);
      v.decl.local = p->decl_local;
      v.decl.bound = false;
      if (!p->decl_local)
        bind_alias(p, &v.decl);
      return deliver(p, T_DECL_NAME, &v, &tl, t->v.str, val, loc);
    }
    zr_sdl_symbol *s = zr__sdl_lookup(p, t->v.str, NULL);
    if (!s) {
      zr__sdl_error(p, ZR_EUNDEFINED, &tl, "undefined identifier '%s'",
                    t->v.str);
      return ZR__POV_error;
    }
    if (s->deprecated && !(s->deprecated_once && s->warned)) {
      s->warned = true;
      if (s->deprecated_message)
        zr__sdl_warning(p, &tl, "%s", s->deprecated_message);
      else
        zr__sdl_warning(p, &tl, "identifier %s was declared deprecated",
                        t->v.str);
    }
    if (s->value.kind == ZR_SDL_MACRO) {
      if (!zr__sdl_call_macro(p, s->value.ptr, &tl))
        return ZR__POV_error;
      continue;
    }
    v.value = s->value;
    /* An element may be an array itself ("array[2]{array[3]{...}, ...}"),
       indexed in turn: "C[i][j]", as POV-Ray 3.7 reads it (watchduck's
       permutohedron scenes; tests/refused/array_of_arrays.pov). */
    while (v.value.kind == ZR_SDL_ARRAY && zr__sdl_peek(p, 0)->kind == '[') {
      const zr_sdl_value *e = array_element(
          p, t->v.str, (zr_sdl_array *)v.value.ptr, &tl);
      if (!e)
        return ZR__POV_error;
      v.value = *e;
      if (v.value.kind == ZR_SDL_MACRO || v.value.kind == ZR_SDL_ALIAS) {
        zr__sdl_error(p, ZR_ESYNTAX, &tl, "an array element cannot be a "
                      "macro");
        return ZR__POV_error;
      }
    }
    return deliver(p, identifier_token(v.value.kind), &v, &tl, t->v.str,
                   val, loc);
  }
}

/* ---- entry points ---- */

static void parser_free(zr_sdl_parser *p) {
  while (p->n_frames > 0)
    zr__sdl_pop_frame(p);
  free(p->frames);
  free(p->image_pixels);
  free(p->image_sizes);
  free(p->image_codes);
  for (size_t i = 0; i < p->n_files; i++)
    zr__sdl_file_free(&p->files[i]);
  free(p->files);
  free(p->init);
  free(p->scene_dir);
  zr__sdl_close_files(p);
  zr__sdl_symtab_free(&p->globals);
}

/* The caller's header include (POV-Ray's Include_Header, +HI): read
   as if the scene's first line were #include "header", found where
   #include looks. */
static bool push_header(zr_sdl_parser *p) {
  if (!p->ctx || !p->ctx->header_include)
    return true;
  int file = open_include(p, p->ctx->header_include, NULL, NULL,
                          "header include file");
  if (file < 0 || !zr__sdl_push_frame(p, file, NULL))
    return false;
  p->include_depth++;
  return true;
}

/* The caller's zr_context_declare() floats, as "#declare name = value;"
   before the scene's first line (POV-Ray's Declare=IDENTIFIER=FLOAT). */
static bool declare_from_context(zr_sdl_parser *p) {
  if (!p->ctx)
    return true;
  for (size_t i = 0; i < p->ctx->n_declared; i++) {
    zr_sdl_value v;
    memset(&v, 0, sizeof v);
    v.kind = ZR_SDL_FLOAT;
    v.num.dim = 1;
    v.num.v[0] = p->ctx->declared_values[i];
    if (zr__sdl_symtab_set(&p->globals, p->ctx->declared_names[i], &v) !=
        ZR_OK) {
      zr__sdl_error(p, ZR_ENOMEM, NULL, "out of memory");
      return false;
    }
  }
  return true;
}

/* A scene file this big fills many blocks of the scene's arena with
   what it describes: 256 KiB of "sphere { <x, y, z>, r texture { T }
   }" lines are ~3,600 spheres, 0.5 MB of objects. */
enum { SCENE_FILE_BIG = 256 * 1024 };

static zr_status parse(zr_context *ctx, char *path, char *bytes, size_t size,
                       bool from_disk, zr_scene **out) {
  if (zr__cancelled(ctx)) {
    free(path);
    free(bytes);
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ECANCELLED, NULL,
                    "the parse was cancelled");
  }
  zr_sdl_parser p;
  memset(&p, 0, sizeof p);
  p.ctx = ctx;
  p.version = 3.7;
  p.image_width = ctx && ctx->render_width ? ctx->render_width : 320;
  p.image_height = ctx && ctx->render_height ? ctx->render_height : 240;
  if (ctx)
    p.anim = ctx->parse;
  else
    zr_parse_options_init(&p.anim);
  p.clock = p.anim.clock;
  p.version = p.anim.version;
  p.scene = zr__scene_new();
  if (!p.scene) {
    free(path);
    free(bytes);
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "out of memory");
  }
  if (from_disk)
    p.scene_dir = zr__io_scene_dir(path);
  /* The scene's arena (arrays, objects, textures) is charged to the
     run's memory budget; the scene keeps the budget alive. */
  if (ctx)
    p.scene->arena.budget = zr__budget_ref(ctx->budget);
  /* A big scene file makes a big scene: its arena's blocks are filled
     in at once (zr__mem_populate), not a page at a time as objects
     reach them.  bench/peers.sh's sphereflake (518 KB, 7,381 spheres)
     faulted 256 pages for the arena's first megabyte one by one. */
  if (size >= SCENE_FILE_BIG)
    p.scene->arena.populate = true;
  int index;
  zr_sdl_loc err_loc;
  char err[200];
  zr_status s = add_file(&p, path, bytes, size, &index, &err_loc, err,
                         sizeof err);
  if (s != ZR_OK)
    zr__sdl_error(&p, s, s == ZR_ESYNTAX ? &err_loc : NULL, "%s", err);
  else if (declare_from_context(&p) && zr__sdl_push_frame(&p, index, NULL) &&
           push_header(&p)) {
    p.start_token = T_START_SCENE;
    if (zr__pov_parse(&p) != 0 && p.status == ZR_OK)
      zr__sdl_error(&p, ZR_ENOMEM, NULL, "out of memory");
  }
  s = p.status;
  p.scene->settings.version = p.version;
  /* A legacy scene (no #version at all, or one below 3.7 in force at
     the end) without assumed_gamma has gamma correction turned off
     ("Gamma in Legacy Scenes"): POV-Ray 3.7 writes rgb v seen with
     ambient 1 as the code 255 v whatever File_Gamma says (0.002, 0.01,
     0.05, 0.3 as 1, 3, 13, 77), as sRGB(v) after "#version 3.7;" or
     "#include \"colors.inc\"" (which sets and restores the version),
     and as sRGB(v) with assumed_gamma 1 in a #version 3.6 scene
     (bench/conform/legacy_gamma_probe.py).  We work in the display's
     gamma, 2.2, and write with file gamma 2.2: the codes are the
     colours, and image_maps decoded to linear light come back to their
     codes. */
  if (!p.scene->settings.assumed_gamma_given &&
      (!p.version_given || p.version < 3.7 - 1e-9)) {
    p.scene->settings.assumed_gamma = 2.2;
    p.scene->settings.gamma_correction_off = true;
  }
  if (s == ZR_OK)
    zr__sdl_images_to_working_gamma(
        &p, p.scene->settings.assumed_gamma,
        p.scene->settings.gamma_correction_off);
  p.scene->parse_steps = p.work;
  parser_free(&p);
  if (s == ZR_OK)
    s = zr__scene_finish(p.scene, ctx);
  if (s != ZR_OK) {
    zr_scene_free(p.scene);
    return s;
  }
  *out = p.scene;
  return ZR_OK;
}

static zr_status parse_file(zr_context *ctx, const char *path,
                            zr_scene **out) {
  if (!out)
    return ZR_EINVAL;
  *out = NULL;
  if (!path)
    return ZR_EINVAL;
  char *bytes = NULL;
  size_t size = 0;
  zr_status s = zr__context_read(ctx, path, &bytes, &size);
  if (s == ZR_EACCESS)
    return s; /* zr__context_read said why */
  if (s != ZR_OK) {
    char why[160];
    return zr__diag(ctx, ZR_DIAG_ERROR, s, NULL,
                    "cannot open scene file '%s': %s", path,
                    zr__context_read_error(ctx, s, why, sizeof why));
  }
  char *copy = strdup(path);
  if (!copy) {
    free(bytes);
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "out of memory");
  }
  return parse(ctx, copy, bytes, size, true, out);
}

static zr_status parse_string(zr_context *ctx, const char *name,
                              const char *text, size_t size,
                              zr_scene **out) {
  if (!out)
    return ZR_EINVAL;
  *out = NULL;
  if (!text && size > 0)
    return ZR_EINVAL;
  char *copy = strdup(name ? name : "<string>");
  char *bytes = malloc(size + 1);
  if (!copy || !bytes) {
    free(copy);
    free(bytes);
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "out of memory");
  }
  if (size > 0)
    memcpy(bytes, text, size);
  bytes[size] = '\0';
  return parse(ctx, copy, bytes, size, false, out);
}

/*
 * A parse with a team (zr_context_set_team) keeps its members in step:
 * every exchange of the parse (a large mesh's hierarchy, obj_mesh.c) is
 * preceded by zr__team_same_key with a key naming its data, and the
 * parse ends with one more call of key ZR__TEAM_KEY_DONE, on every path
 * out, failures included.  Members that parse the same bytes make the
 * same calls; a member that read other bytes, or stopped early, meets
 * the others in a call whose keys differ, and from there each goes on
 * alone without another call, so none is left waiting.
 */
static void team_begin(zr_context *ctx) {
  if (ctx)
    ctx->team_parse = zr__team_size(ctx->team) > 1;
}

static void team_end(zr_context *ctx) {
  if (ctx && ctx->team_parse)
    (void)zr__team_same_key(ctx->team, ZR_OK, ZR__TEAM_KEY_DONE);
  if (ctx)
    ctx->team_parse = 0;
}

ZR_API zr_status zr_scene_parse_file(zr_context *ctx, const char *path,
                                     zr_scene **out) {
  team_begin(ctx);
  zr_status s = parse_file(ctx, path, out);
  team_end(ctx);
  return s;
}

ZR_API zr_status zr_scene_parse_string(zr_context *ctx, const char *name,
                                       const char *text, size_t size,
                                       zr_scene **out) {
  team_begin(ctx);
  zr_status s = parse_string(ctx, name, text, size, out);
  team_end(ctx);
  return s;
}
