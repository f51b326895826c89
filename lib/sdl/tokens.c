/*
 * tokens.c - lexing a whole file into an array of tokens.
 *
 * Each scene or include file is read once and run through the flex
 * scanner (grammar/pov.l) once; the directive engine then walks the
 * array, and a #zfor loop replays a range of it without reading or
 * scanning again.  Every token keeps its line and column, and the file
 * keeps its bytes and line starts, so any message can quote the source
 * line under its caret however the tokens were reached (the layout of
 * GCC and of Bison's bistromathic example).  The block directives (#if
 * ... #else ... #end, #while ... #end, #macro ... #end) are linked to
 * each other once here, so skipping and looping jump straight to their
 * partner.
 */
#include "config.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pov-parse.h"
#include "sdl/sdl.h"
#define YYSTYPE ZR__POV_STYPE
#define YYLTYPE zr_sdl_loc
#include "pov-scan.h"

const char *zr__sdl_lex_intern(zr_sdl_lexer *lx, const char *s, size_t n) {
  char *copy = zr__arena_alloc(&lx->file->strings, n + 1);
  if (!copy) {
    lx->failed = lx->out_of_memory = true;
    return NULL;
  }
  memcpy(copy, s, n);
  copy[n] = '\0';
  return copy;
}

/* The escapes POV-Ray knows in strings ("String Literals"). */
static char unescape(char c) {
  switch (c) {
  case 'a': return '\a';
  case 'b': return '\b';
  case 'f': return '\f';
  case 'n': return '\n';
  case 'r': return '\r';
  case 't': return '\t';
  case 'v': return '\v';
  default: return c; /* \\ \" \' */
  }
}

const char *zr__sdl_lex_string(zr_sdl_lexer *lx, const char *s, size_t n) {
  char *out = zr__arena_alloc(&lx->file->strings, n + 1);
  if (!out) {
    lx->failed = lx->out_of_memory = true;
    return NULL;
  }
  size_t j = 0;
  for (size_t i = 0; i < n; i++)
    out[j++] = s[i] == '\\' && i + 1 < n ? unescape(s[++i]) : s[i];
  out[j] = '\0';
  return out;
}

void zr__sdl_lex_fail(zr_sdl_lexer *lx, const zr_sdl_loc *at,
                      const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(lx->error, sizeof lx->error, fmt, ap);
  va_end(ap);
  lx->failed = true;
  lx->error_at = *at;
}

static zr_status index_lines(zr_sdl_file *f) {
  size_t n = 1;
  for (size_t i = 0; i < f->size; i++)
    n += f->bytes[i] == '\n';
  f->line_starts = malloc(n * sizeof *f->line_starts);
  if (!f->line_starts)
    return ZR_ENOMEM;
  f->line_starts[0] = 0;
  f->n_lines = 1;
  for (size_t i = 0; i < f->size; i++)
    if (f->bytes[i] == '\n')
      f->line_starts[f->n_lines++] = i + 1;
  return ZR_OK;
}

const char *zr__sdl_file_line(const zr_sdl_file *f, int line, size_t *len) {
  if (line < 1 || (size_t)line > f->n_lines) {
    *len = 0;
    return "";
  }
  size_t start = f->line_starts[line - 1];
  size_t end = start;
  while (end < f->size && f->bytes[end] != '\n')
    end++;
  *len = end - start;
  return f->bytes + start;
}

static zr_status push_token(zr_sdl_file *f, size_t *cap,
                            const zr_sdl_token *t) {
  if (f->n_tokens == *cap) {
    size_t new_cap = *cap ? *cap * 2 : 256;
    zr_sdl_token *tokens = realloc(f->tokens, new_cap * sizeof *tokens);
    if (!tokens)
      return ZR_ENOMEM;
    f->tokens = tokens;
    *cap = new_cap;
  }
  f->tokens[f->n_tokens++] = *t;
  return ZR_OK;
}

static bool opens_block(int kind) {
  return kind == T_IF || kind == T_IFDEF || kind == T_IFNDEF ||
         kind == T_WHILE || kind == T_FOR || kind == T_SWITCH ||
         kind == T_MACRO;
}

static bool continues_block(int kind) {
  return kind == T_ELSE || kind == T_ELSEIF || kind == T_CASE ||
         kind == T_RANGE;
}

/*
 * Links each block directive to the next one of its block (see links in
 * sdl.h), so that skipping a false #if branch or leaving a loop is one
 * step whatever the body holds.  Directives that do not pair up keep
 * (size_t)-1; the engine reports them when it runs them.
 */
static zr_status link_blocks(zr_sdl_file *f) {
  f->links = malloc((f->n_tokens ? f->n_tokens : 1) * sizeof *f->links);
  size_t *open = malloc((f->n_tokens ? f->n_tokens : 1) * sizeof *open);
  if (!f->links || !open) {
    free(open);
    return ZR_ENOMEM;
  }
  size_t depth = 0;
  for (size_t i = 0; i < f->n_tokens; i++) {
    int kind = f->tokens[i].kind;
    f->links[i] = (size_t)-1;
    if (opens_block(kind)) {
      open[depth++] = i;
    } else if (continues_block(kind) && depth > 0) {
      f->links[open[depth - 1]] = i;
      open[depth - 1] = i;
    } else if (kind == T_END && depth > 0) {
      f->links[open[--depth]] = i;
    }
  }
  free(open);
  return ZR_OK;
}

zr_status zr__sdl_file_lex(zr_sdl_file *f, int file_index, char *path,
                           char *bytes, size_t size, zr_sdl_loc *err_loc,
                           char *err, size_t err_size) {
  memset(f, 0, sizeof *f);
  f->path = path;
  f->bytes = bytes;
  f->size = size;
  zr__arena_init(&f->strings);
  if (index_lines(f) != ZR_OK)
    return ZR_ENOMEM;

  zr_sdl_lexer lx;
  memset(&lx, 0, sizeof lx);
  lx.file = f;
  lx.line = 1;
  lx.column = 1;
  yyscan_t scanner;
  if (zr__scan_lex_init_extra(&lx, &scanner) != 0)
    return ZR_ENOMEM;
  /* A UTF-8 byte order mark is not part of the scene. */
  size_t skip = size >= 3 && memcmp(bytes, "\xEF\xBB\xBF", 3) == 0 ? 3 : 0;
  YY_BUFFER_STATE buffer =
      zr__scan__scan_bytes(bytes + skip, (int)(size - skip), scanner);
  zr_status status = buffer ? ZR_OK : ZR_ENOMEM;
  size_t cap = 0;
  while (status == ZR_OK) {
    ZR__POV_STYPE value;
    zr_sdl_loc loc;
    memset(&value, 0, sizeof value);
    int kind = zr__scan_lex(&value, &loc, scanner);
    if (lx.failed) {
      status = lx.out_of_memory ? ZR_ENOMEM : ZR_ESYNTAX;
      break;
    }
    zr_sdl_token t;
    memset(&t, 0, sizeof t);
    t.kind = kind;
    t.line = loc.line;
    t.column = loc.column;
    t.length = loc.length;
    if (kind == T_NUMBER)
      t.v.num = value.num;
    else
      t.v.str = value.str;
    if (kind == 0) {
      /* The end of the file is a token too: it carries the place where
         "unexpected end of file" points. */
      t.line = lx.line;
      t.column = lx.column;
      t.length = 1;
    }
    status = push_token(f, &cap, &t);
    if (kind == 0)
      break;
  }
  if (buffer)
    zr__scan__delete_buffer(buffer, scanner);
  zr__scan_lex_destroy(scanner);
  if (status == ZR_OK)
    status = link_blocks(f);
  if (status == ZR_ESYNTAX) {
    *err_loc = lx.error_at;
    err_loc->file = file_index;
    snprintf(err, err_size, "%s", lx.error);
  } else if (status == ZR_ENOMEM) {
    snprintf(err, err_size, "out of memory");
  }
  return status;
}

void zr__sdl_file_free(zr_sdl_file *f) {
  if (!f)
    return;
  free(f->path);
  free(f->bytes);
  free(f->line_starts);
  free(f->tokens);
  free(f->links);
  zr__arena_free(&f->strings);
  memset(f, 0, sizeof *f);
}
