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
 *   - runs #version and zRcube's #zfor (n) ... #zend, whose body is
 *     replayed from the token array n times with the float zr = 0..n-1
 *     (an inner loop's zr shadows the outer's until its #zend).  Their
 *     expressions are parsed by the grammar itself through a nested
 *     parser and a second start symbol;
 *   - turns an identifier into a typed token after looking it up, the
 *     newest #local scope first, then the global #declare table, or into
 *     a declaration name right after #declare/#local;
 *   - stops at a reserved word outside the supported slice, naming it.
 * Messages carry the source line, a caret and the include chain.
 */
#include "config.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/strbuf.h"
#include "pov-parse.h"
#include "sdl/sdl.h"

/* ---- diagnostics ---- */

/* Innermost include levels a message lists before it abbreviates. */
#define MAX_CHAIN_NOTES 6

/* The include chain of a place in file: "in file included from ..." for
   each frame below the newest frame reading that file. */
static void chain_notes(const zr_sdl_parser *p, int file, zr_strbuf *sb) {
  size_t k = p->n_frames;
  while (k > 0 && p->frames[k - 1].file != file)
    k--;
  size_t listed = 0;
  for (size_t i = k; i-- > 1;) {
    if (listed == MAX_CHAIN_NOTES) {
      zr__strbuf_printf(&*sb, "(and %zu more levels of inclusion)\n", i);
      break;
    }
    const zr_sdl_loc *at = &p->frames[i].included_at;
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
    const zr_sdl_file *f = &p->files[loc->file];
    place.file = f->path;
    place.line = loc->line;
    place.column = loc->column;
    place.source_line = zr__sdl_file_line(f, loc->line,
                                          &place.source_line_len);
    place.caret_len = loc->length > 0 ? loc->length : 1;
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

void *zr__sdl_alloc(zr_sdl_parser *p, size_t size) {
  void *m = zr__arena_alloc(&p->scene->arena, size);
  if (!m)
    zr__sdl_error(p, ZR_ENOMEM, NULL, "out of memory");
  return m;
}

const char *zr__sdl_token_name(const char *name, char *buf, size_t size) {
  if (name[0] == '#' || zr__sdl_keyword_find(name, strlen(name))) {
    snprintf(buf, size, "'%s'", name);
    return buf;
  }
  return name;
}

/* ---- files and frames ---- */

static zr_sdl_frame *top(zr_sdl_parser *p) {
  return &p->frames[p->n_frames - 1];
}

static zr_sdl_loc token_loc(int file, const zr_sdl_token *t) {
  zr_sdl_loc l = {file, t->line, t->column, t->length};
  return l;
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
  zr_status s = zr__sdl_file_lex(f, *index, path, bytes, size, err_loc, err,
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

static bool push_frame(zr_sdl_parser *p, int file, const zr_sdl_loc *at) {
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

static void pop_frame(zr_sdl_parser *p) {
  zr_sdl_frame *fr = top(p);
  zr__sdl_symtab_free(&fr->locals);
  free(fr->loops);
  p->n_frames--;
}

/* The table #local writes to, and zr lives in, for a frame: the
   top-level file's locals are its globals (reference manual, "#local"). */
static zr_sdl_symtab *scope_of(zr_sdl_parser *p, size_t frame) {
  return frame == 0 ? &p->globals : &p->frames[frame].locals;
}

static const zr_sdl_symbol *lookup(zr_sdl_parser *p, const char *name) {
  for (size_t i = p->n_frames; i-- > 1;) {
    zr_sdl_symbol *s = zr__sdl_symtab_find(&p->frames[i].locals, name);
    if (s)
      return s;
  }
  return zr__sdl_symtab_find(&p->globals, name);
}

bool zr__sdl_define(zr_sdl_parser *p, const zr_sdl_decl_name *name,
                    bool is_local, const zr_sdl_value *value,
                    const zr_sdl_loc *loc) {
  size_t frame = (size_t)name->frame;
  if (frame >= p->n_frames)
    frame = p->n_frames - 1;
  zr_sdl_symtab *t = is_local ? scope_of(p, frame) : &p->globals;
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
                        const zr_sdl_loc *at, const zr_sdl_loc *directive) {
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
    zr_status s = zr__context_read(p->ctx, path, &bytes, &size);
    if (s == ZR_ENOTFOUND) {
      free(path);
      continue;
    }
    if (s != ZR_OK) {
      zr__sdl_error(p, s, at, "cannot read include file '%s': %s", path,
                    zr_status_str(s));
      free(path);
      return -1;
    }
    int index;
    zr_sdl_loc err_loc;
    char err[200];
    s = add_file(p, path, bytes, size, &index, &err_loc, err, sizeof err);
    if (s == ZR_ESYNTAX) {
      /* Point into the new file, with the chain through this #include. */
      if (push_frame(p, index, directive))
        zr__sdl_error(p, s, &err_loc, "%s", err);
      return -1;
    }
    if (s != ZR_OK) {
      zr__sdl_error(p, s, at, "%s", err);
      return -1;
    }
    return index;
  }
  zr__sdl_error(p, ZR_ENOTFOUND, at, "cannot find include file '%s'", name);
  return -1;
}

static bool do_include(zr_sdl_parser *p, const zr_sdl_loc *directive) {
  zr_sdl_frame *fr = top(p);
  const zr_sdl_token *t = &p->files[fr->file].tokens[fr->pos];
  zr_sdl_loc at = token_loc(fr->file, t);
  if (t->kind != T_STRING) {
    zr__sdl_error(p, ZR_ESYNTAX, &at,
                  "expected a file name in quotes after '#include'");
    return false;
  }
  fr->pos++;
  if (p->n_frames > ZR_SDL_MAX_INCLUDE_DEPTH) {
    zr__sdl_error(p, ZR_ELIMIT, directive,
                  "#include nested more than %d levels deep "
                  "(does a file include itself?)",
                  ZR_SDL_MAX_INCLUDE_DEPTH);
    return false;
  }
  int file = open_include(p, t->v.str, &at, directive);
  return file >= 0 && push_frame(p, file, directive);
}

/* ---- #version, #zfor, #zend ---- */

zr_status zr__sdl_parse_expr(zr_sdl_parser *p, int start_token,
                             zr_sdl_expr *out) {
  p->start_token = start_token;
  int r = zr__pov_parse(p);
  p->start_token = 0;
  if (r != 0 || p->status != ZR_OK) {
    if (p->status == ZR_OK)
      zr__sdl_error(p, ZR_ENOMEM, NULL, "out of memory");
    return p->status;
  }
  *out = p->nested_value;
  return ZR_OK;
}

static bool do_version(zr_sdl_parser *p, const zr_sdl_loc *directive) {
  zr_sdl_expr e;
  p->in_version = true;
  p->version_depth = 0;
  p->version_operand = false;
  zr_status s = zr__sdl_parse_expr(p, T_START_VERSION, &e);
  p->in_version = false;
  return s == ZR_OK && zr__sdl_want_float(p, &e, directive, &p->version);
}

/* Tokens after which an expression may be complete. */
static bool ends_operand(int kind) {
  switch (kind) {
  case T_NUMBER: case T_FLOAT_ID: case T_VECTOR_ID: case T_COLOUR_ID:
  case ')': case '>': case T_X: case T_Y: case T_Z: case T_T: case T_U:
  case T_V: case T_PI: case T_TRUE: case T_FALSE: case T_YES: case T_NO:
  case T_ON: case T_OFF: case T_RED: case T_GREEN: case T_BLUE:
  case T_FILTER: case T_TRANSMIT: case T_GRAY:
    return true;
  default:
    return false;
  }
}

/*
 * POV-Ray accepts "#version 3.7" without its ';' and warns.  The nested
 * parser's rule ends in ';' (so it never reads past the directive); when
 * the expression is complete and the next token cannot continue it, the
 * engine supplies the ';'.
 */
static bool version_needs_semicolon(const zr_sdl_parser *p, int next) {
  if (!p->in_version || p->version_depth > 0 || !p->version_operand)
    return false;
  return next != '+' && next != '-' && next != '*' && next != '/' &&
         next != '.' && next != ';';
}

static void track_version(zr_sdl_parser *p, int kind) {
  if (kind == '(' || kind == '<')
    p->version_depth++;
  else if (kind == ')' || kind == '>')
    p->version_depth--;
  p->version_operand = ends_operand(kind);
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
  default: return T_OBJECT_ID;
  }
}

static int deliver(zr_sdl_parser *p, int kind, const zr_sdl_lexval *val,
                   const zr_sdl_loc *loc, const char *text,
                   zr_sdl_lexval *out_val, zr_sdl_loc *out_loc) {
  p->last_loc = *loc;
  p->last_text = text;
  p->want_decl_name = kind == T_DECLARE || kind == T_LOCAL;
  if (p->in_version)
    track_version(p, kind);
  *out_val = *val;
  *out_loc = *loc;
  return kind;
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
    if (version_needs_semicolon(p, t->kind)) {
      zr__sdl_warning(p, &p->last_loc, "'#version' should end with ';'");
      p->in_version = false;
      return deliver(p, ';', &v, &p->last_loc, NULL, val, loc);
    }
    if (t->kind == 0) {
      if (p->n_frames > 1) {
        pop_frame(p);
        continue;
      }
      return deliver(p, 0, &v, &tl, NULL, val, loc);
    }
    fr->pos++;
    switch (t->kind) {
    case T_INCLUDE:
      if (!do_include(p, &tl))
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
    case T_NUMBER:
      v.num = t->v.num;
      return deliver(p, t->kind, &v, &tl, NULL, val, loc);
    case T_IDENTIFIER:
      break;
    default:
      v.str = t->v.str;
      return deliver(p, t->kind, &v, &tl, NULL, val, loc);
    }
    if (p->want_decl_name) {
      v.decl.name = t->v.str;
      v.decl.frame = (int)(p->n_frames - 1);
      return deliver(p, T_DECL_NAME, &v, &tl, t->v.str, val, loc);
    }
    const zr_sdl_symbol *s = lookup(p, t->v.str);
    if (!s) {
      zr__sdl_error(p, ZR_EUNDEFINED, &tl, "undefined identifier '%s'",
                    t->v.str);
      return ZR__POV_error;
    }
    v.value = s->value;
    return deliver(p, identifier_token(s->value.kind), &v, &tl, t->v.str,
                   val, loc);
  }
}

/* ---- entry points ---- */

static void parser_free(zr_sdl_parser *p) {
  while (p->n_frames > 0)
    pop_frame(p);
  free(p->frames);
  for (size_t i = 0; i < p->n_files; i++)
    zr__sdl_file_free(&p->files[i]);
  free(p->files);
  zr__sdl_symtab_free(&p->globals);
}

static zr_status parse(zr_context *ctx, char *path, char *bytes, size_t size,
                       zr_scene **out) {
  zr_sdl_parser p;
  memset(&p, 0, sizeof p);
  p.ctx = ctx;
  p.version = 3.7;
  p.scene = zr__scene_new();
  if (!p.scene) {
    free(path);
    free(bytes);
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "out of memory");
  }
  int index;
  zr_sdl_loc err_loc;
  char err[200];
  zr_status s = add_file(&p, path, bytes, size, &index, &err_loc, err,
                         sizeof err);
  if (s != ZR_OK)
    zr__sdl_error(&p, s, s == ZR_ESYNTAX ? &err_loc : NULL, "%s", err);
  else if (push_frame(&p, index, NULL)) {
    p.start_token = T_START_SCENE;
    if (zr__pov_parse(&p) != 0 && p.status == ZR_OK)
      zr__sdl_error(&p, ZR_ENOMEM, NULL, "out of memory");
  }
  s = p.status;
  p.scene->settings.version = p.version;
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

ZR_API zr_status zr_scene_parse_file(zr_context *ctx, const char *path,
                                     zr_scene **out) {
  if (!out)
    return ZR_EINVAL;
  *out = NULL;
  if (!path)
    return ZR_EINVAL;
  char *bytes = NULL;
  size_t size = 0;
  zr_status s = zr__context_read(ctx, path, &bytes, &size);
  if (s != ZR_OK)
    return zr__diag(ctx, ZR_DIAG_ERROR, s, NULL,
                    "cannot open scene file '%s': %s", path,
                    zr_status_str(s));
  char *copy = strdup(path);
  if (!copy) {
    free(bytes);
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "out of memory");
  }
  return parse(ctx, copy, bytes, size, out);
}

ZR_API zr_status zr_scene_parse_string(zr_context *ctx, const char *name,
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
  return parse(ctx, copy, bytes, size, out);
}
