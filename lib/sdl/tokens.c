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
 * partner.  The plain items of a mesh2 list, and the three plain
 * vectors of a triangle, become a single token whose bytes are read
 * later (numlist.c): they are the bulk of big files.
 */
#include "core/budget.h"
#include "config.h"

#include <ctype.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pov-parse.h"
#include "sdl/sdl.h"
#define YYSTYPE ZR__POV_STYPE
#define YYLTYPE zr_sdl_loc
#include "pov-scan.h"

/* A name spelled like the last one interned is that one: the names
   are never changed, and a sphere-heavy file names its texture on every
   line ("texture { Ball }": 7,381 copies of 16 bytes in bench/peers.sh's
   sphereflake, 29 fresh pages). */
const char *zr__sdl_lex_intern(zr_sdl_lexer *lx, const char *s, size_t n) {
  if (lx->last_name && lx->last_name_length == n &&
      memcmp(lx->last_name, s, n) == 0)
    return lx->last_name;
  char *copy = zr__arena_alloc_raw(&lx->file->strings, n + 1);
  if (!copy) {
    lx->failed = lx->out_of_memory = true;
    return NULL;
  }
  memcpy(copy, s, n);
  copy[n] = '\0';
  lx->last_name = copy;
  lx->last_name_length = n;
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

/* memchr, which the C library runs many bytes at a time: a big mesh2
   has millions of lines. */
static const char *next_newline(const zr_sdl_file *f, const char *from) {
  return memchr(from, '\n', (size_t)(f->bytes + f->size - from));
}

/* Counts the file's lines; the offsets of their starts wait for a
   message that quotes one (line_index): a file of 7,381 spheres' lines
   took 58 KB of fresh memory for them, which no clean parse reads. */
static zr_status index_lines(zr_sdl_file *f) {
  size_t n = 1;
  for (const char *c = f->bytes; c && (c = next_newline(f, c)); c++)
    n++;
  f->n_lines = n;
  return ZR_OK;
}

static bool line_index(zr_sdl_file *f) {
  if (f->line_starts)
    return true;
  size_t *starts = malloc(f->n_lines * sizeof *starts);
  if (!starts)
    return false;
  size_t n = 0;
  starts[n++] = 0;
  for (const char *c = f->bytes; c && n < f->n_lines &&
                                 (c = next_newline(f, c));
       c++)
    starts[n++] = (size_t)(c + 1 - f->bytes);
  f->line_starts = starts;
  return true;
}

bool zr__sdl_file_line_start(zr_sdl_file *f, int line, size_t *start) {
  if (line < 1 || (size_t)line > f->n_lines || !line_index(f))
    return false;
  *start = f->line_starts[line - 1];
  return true;
}

const char *zr__sdl_file_line(zr_sdl_file *f, int line, size_t *len) {
  size_t start;
  if (!zr__sdl_file_line_start(f, line, &start)) {
    *len = 0;
    return "";
  }
  size_t end = start;
  while (end < f->size && f->bytes[end] != '\n')
    end++;
  *len = end - start;
  return f->bytes + start;
}

static bool opens_block(int kind);
static bool continues_block(int kind);

static zr_status push_token(zr_sdl_file *f, size_t *cap,
                            const zr_sdl_token *t) {
  /* Counted here, where the kind is at hand, so that link_blocks need
     not read the whole array again when it has none. */
  f->block_tokens += opens_block(t->kind) || continues_block(t->kind);
  /* The budget is charged for the token array as it doubles from 256
     slots, each with a word for the block links made after it (far
     fewer in practice), whatever room the array has been given. */
  if (f->n_tokens == f->tokens_charged) {
    size_t slots = f->tokens_charged ? 2 * f->tokens_charged : 256;
    size_t more =
        (slots - f->tokens_charged) * (sizeof *f->tokens + sizeof(size_t));
    if (!zr__budget_charge(f->budget, more))
      return ZR_ELIMIT;
    if (f->budget)
      f->charged += more;
    f->tokens_charged = slots;
  }
  if (f->n_tokens == *cap) {
    size_t new_cap = *cap ? *cap * 2 : 256;
    /* Where the first 256 tokens, taken as a sample of the file's
       lines, say that the whole file holds a megabyte of tokens or
       more, the array takes twice that estimate at once, in huge pages
       (memory is taken as it is written): doubling from 256 touched the
       first megabyte in ~250 fresh 4 KiB pages (~14 us each here,
       core/arena.h) and copied the array at every step.
       bench/peers.sh's sphereflake (118,000 tokens, 2.8 MB; its header
       makes the sample sparser than the spheres' lines) took 1,257 page
       faults at 512^2, 1,050 so; its terrain (130,000 tokens) is no
       longer copied at all. */
    if (*cap == 256 && t->line > 0 && (size_t)t->line < f->n_lines &&
        f->n_lines / (size_t)t->line <= SIZE_MAX / 512 / sizeof *f->tokens) {
      size_t estimate = 512 * (f->n_lines / (size_t)t->line);
      if (estimate * sizeof *f->tokens >= ZR__HUGE_FROM)
        new_cap = estimate;
    }
    zr_sdl_token *tokens = zr__huge_grow(
        f->tokens, *cap * sizeof *tokens, new_cap * sizeof *tokens);
    if (!tokens)
      return ZR_ENOMEM;
    f->tokens = tokens;
    *cap = new_cap;
  }
  f->tokens[f->n_tokens++] = *t;
  return ZR_OK;
}

/*
 * The scanner's reads copy the file's bytes into its buffer.  After each
 * restart (every run below: a triangle, a sphere, a number list) the
 * scanner forgets what it had read ahead, so a read of its whole buffer
 * (8 KiB) for a triangle of ~100 bytes copied a terrain's 15 MB some 70
 * times over: 10% of its parse (perf, bench/parse.sh).  The first read
 * after a start copies READ_FIRST bytes and each next one twice as many,
 * up to what the scanner asks: a scanner matches the same tokens however
 * its input comes in pieces, and a long stretch of ordinary text still
 * reaches full reads after a handful.
 */
enum { READ_FIRST = 256 };

int zr__sdl_lex_input(zr_sdl_lexer *lx, char *buf, int max) {
  const zr_sdl_file *f = lx->file;
  size_t n = f->size - lx->read_pos;
  if (lx->read_size < READ_FIRST)
    lx->read_size = READ_FIRST;
  if (n > lx->read_size)
    n = lx->read_size;
  if (n > (size_t)max)
    n = (size_t)max;
  if (lx->read_size < (size_t)max)
    lx->read_size *= 2;
  memcpy(buf, f->bytes + lx->read_pos, n);
  lx->read_pos += n;
  return (int)n;
}

/* The mesh2 lists whose plain items may be read as one run. */
static bool number_list_keyword(int kind) {
  return kind == T_VERTEX_VECTORS || kind == T_NORMAL_VECTORS ||
         kind == T_UV_VECTORS || kind == T_FACE_INDICES ||
         kind == T_NORMAL_INDICES || kind == T_UV_INDICES;
}

/*
 * After "vertex_vectors { 1000" and the like, the plain items that
 * follow are read as one run (numlist.c) and kept as one token, and the
 * scanner goes on after them: a huge mesh2 then costs a few tokens, not
 * tens of millions.  The run's bytes stay in the file, where build_mesh.c
 * reads them again with the same reader.
 */
/*
 * The scanner's calls, each under the lexer's jmp_buf, so a fatal error
 * of the scanner (zr__sdl_lex_fatal: flex's own allocations failing)
 * comes back here as a failure rather than exit().  Nothing here is
 * changed between setjmp and longjmp, so no local needs volatile.
 */
static int scan_guarded(zr_sdl_lexer *lx, yyscan_t scanner,
                        ZR__POV_STYPE *value, zr_sdl_loc *loc) {
  if (setjmp(lx->fatal) != 0)
    return 0; /* lx->failed is set */
  return zr__scan_lex(value, loc, scanner);
}

/*
 * After a run the scanner must forget what it read ahead before it
 * reads again; the restart itself waits for the scanner's next call
 * (lex below, lx->restart).  Between the spheres of a sphere-heavy file
 * the lexer takes every word and brace itself (quick_token), so the
 * scanner was restarted once a sphere and never called before the next
 * restart: 1.4 M of bench/peers.sh's sphereflake's 75 M instructions
 * (callgrind), for nothing.  The restart reads nothing of the lexer's
 * state, so doing it later, just before the scanner reads, is the
 * same.
 */
static void restart_later(zr_sdl_lexer *lx) {
  lx->read_size = READ_FIRST;
  lx->fresh = true;
  lx->restart = true;
}

static bool restart_guarded(zr_sdl_lexer *lx, yyscan_t scanner) {
  lx->restart = false;
  if (setjmp(lx->fatal) != 0)
    return false;
  zr__scan_restart(NULL, scanner);
  return true;
}

_Noreturn void zr__sdl_lex_fatal(void *scanner, const char *msg) {
  zr_sdl_lexer *lx = zr__scan_get_extra(scanner);
  lx->failed = true;
  lx->out_of_memory = strstr(msg, "memory") != NULL;
  lx->error_at.line = lx->line;
  lx->error_at.column = lx->column;
  lx->error_at.length = 1;
  snprintf(lx->error, sizeof lx->error, "the scanner failed: %s", msg);
  longjmp(lx->fatal, 1);
}

static zr_status number_list(zr_sdl_file *f, size_t *cap,
                             zr_sdl_lexer *lx) {
  size_t n = f->n_tokens;
  if (n < 3 || f->tokens[n - 1].kind != T_NUMBER ||
      f->tokens[n - 2].kind != '{' ||
      !number_list_keyword(f->tokens[n - 3].kind))
    return ZR_OK;
  zr_sdl_numreader r = {f->bytes, lx->offset, f->size, lx->line,
                        lx->column, f->tokens[n - 3].kind == T_UV_VECTORS,
                        true};
  size_t items = 0;
  double v[3];
  int dim, line, column;
  while (zr__sdl_numlist_item(&r, v, &dim, &line, &column))
    items++;
  if (items == 0)
    return ZR_OK;
  zr_sdl_numlist *list = zr__arena_alloc(&f->strings, sizeof *list);
  if (!list)
    return ZR_ENOMEM;
  list->begin = lx->offset;
  list->end = r.pos;
  list->line = lx->line;
  list->column = lx->column;
  list->uv = r.uv;
  list->n_items = items;
  zr_sdl_token t;
  memset(&t, 0, sizeof t);
  t.kind = ZR_SDL_NUMBER_LIST;
  t.line = lx->line;
  t.column = lx->column;
  t.length = 1;
  t.v.list = list;
  zr_status status = push_token(f, cap, &t);
  /* The scanner forgets what it read ahead and goes on after the run. */
  lx->offset = lx->read_pos = r.pos;
  lx->line = r.line;
  lx->column = r.column;
  restart_later(lx);
  return status;
}

/* Moves the lexer past bytes [lx->offset, to) - blanks that the reader
   stopped before, and a closing '}' - counting lines and columns as the
   scanner does, and has the scanner start again there. */
static void resume_at(zr_sdl_lexer *lx, size_t to,
                      const zr_sdl_numreader *r) {
  lx->offset = r->pos;
  lx->line = r->line;
  lx->column = r->column;
  for (; lx->offset < to; lx->offset++) {
    if (lx->file->bytes[lx->offset] == '\n') {
      lx->line++;
      lx->column = 1;
    } else {
      lx->column++;
    }
  }
  lx->read_pos = lx->offset;
  restart_later(lx);
}

/* The token that stands for "KEYWORD { ..." in place of the keyword and
   the '{' the scanner gave: it keeps the keyword's place. */
static zr_sdl_token run_token(zr_sdl_file *f, int kind, const char *run) {
  zr_sdl_token t = f->tokens[f->n_tokens - 2];
  t.kind = kind;
  t.v.str = run;
  f->n_tokens -= 2;
  return t;
}

/*
 * "triangle { <a>, <b>, <c> }" with three plain vectors (the body of
 * most triangles in a big mesh) is kept as one token, T_TRIANGLE_RUN,
 * in place of the keyword, the braces and the 19 tokens of the vectors;
 * it holds the vectors' values (push_corner_run), which the grammar's
 * action takes as they are.  A terrain of 130,050 triangles then costs
 * one 24-byte token a triangle (issue 13: parse time and memory).
 * Any other body (a texture, a fourth vector, an expression, a comment)
 * stays as it was.  "smooth_triangle { <a>, <na>, <b>, <nb>, <c>, <nc> }"
 * is kept so too, as T_SMOOTH_TRIANGLE_RUN: 50 tokens a face made the
 * corpus' complexity.pov (16,869 of them in cedar.pov) lex and parse in
 * 0.3 s, two thirds of it growing and copying the token array.
 * A run followed, after blanks only, by another "triangle {" or
 * "smooth_triangle {" with a plain body is followed here too, without
 * the scanner: it would give the same keyword and '{' (a keyword is a
 * word of [a-zA-Z0-9_] that no such character follows, pov.l's IDENT),
 * and scanning them and starting again after each run was a fifth of a
 * terrain's parse (callgrind).
 */

/* The body of a run after its '{': n plain vectors (r moves past them)
   and blanks up to the '}', whose offset goes to *close. */
static bool run_body(const zr_sdl_file *f, zr_sdl_numreader *r, int n,
                     double v[6][3], size_t *close) {
  int dim, line, column;
  for (int k = 0; k < n; k++)
    if (!zr__sdl_numlist_item(r, v[k], &dim, &line, &column))
      return false;
  size_t end = r->pos;
  while (end < f->size && zr__sdl_is_blank(f->bytes[end]))
    end++;
  if (end >= f->size || f->bytes[end] != '}')
    return false;
  *close = end;
  return true;
}

/* A run token of kind at (line, column), the place of its keyword of
   length bytes, without its value. */
static zr_sdl_token run_at(int kind, int line, int column, int length) {
  zr_sdl_token t;
  memset(&t, 0, sizeof t);
  t.kind = kind;
  t.line = line;
  t.column = column;
  t.length = length;
  return t;
}

/* Appends three vectors (nine values) to one of the file's run arrays,
   which grows by doubling in corner_arena. */
static zr_status append_vectors(zr_sdl_file *f, double **array, size_t *n,
                                size_t *cap, const double *a,
                                const double *b, const double *c) {
  if (*n + 9 > *cap) {
    size_t grow = *cap ? 2 * *cap : 9 * 1024;
    if (grow > SIZE_MAX / sizeof(double))
      return ZR_ENOMEM;
    double *grown = zr__arena_grow(f->corner_arena, *array,
                                   *cap * sizeof(double),
                                   grow * sizeof(double));
    if (!grown)
      return f->corner_arena->over_budget ? ZR_ELIMIT : ZR_ENOMEM;
    *array = grown;
    *cap = grow;
  }
  memcpy(*array + *n, a, 3 * sizeof(double));
  memcpy(*array + *n + 3, b, 3 * sizeof(double));
  memcpy(*array + *n + 6, c, 3 * sizeof(double));
  *n += 9;
  return ZR_OK;
}

/*
 * A plain triangle's run keeps its corners: nine values appended to the
 * file's corner array, the token holding their index until the file is
 * lexed (the array grows) and a pointer to them after (fix_corners).
 * The parser's files keep them in the scene's arena, where a mesh made
 * of such runs takes them as its vertex array as they lie
 * (build_mesh.c): the grammar no longer reads the numbers a second time
 * (13% of the terrain's parse, perf) nor copies them (add_triangle).
 * (Session 11 kept the values beside the vertex array instead: that
 * saved the reading and cost as much in first touches of 10 MB more,
 * bench/results/mpi-n2-2026-12-03-s11.txt.)
 */
static zr_status push_corner_run(zr_sdl_file *f, size_t *cap, int line,
                                 int column, int length,
                                 double v[6][3]) {
  size_t at = f->n_corners;
  zr_status s = append_vectors(f, &f->corners, &f->n_corners,
                               &f->cap_corners, v[0], v[1], v[2]);
  if (s != ZR_OK)
    return s;
  zr_sdl_token t = run_at(T_TRIANGLE_RUN, line, column, length);
  t.v.corner = at;
  return push_token(f, cap, &t);
}

/*
 * A smooth_triangle's run (corner, normal, corner, normal, corner,
 * normal) keeps its corners in the same corner array, where plain runs'
 * and its own follow one another, and its normals in the file's normal
 * array; its token holds both indices.  A mesh of such runs takes the
 * two arrays as its vertices and normals where they lie (build_mesh.c),
 * as one of plain runs does: the grammar's action read the numbers a
 * second time (27% of the parse of a mesh of 130,050 smooth triangles,
 * perf) and add_triangle copied them.  Indices of 32 bits: a mesh holds
 * at most 2^30 faces (build_mesh.c), a file 477 million runs.
 */
static zr_status push_smooth_run(zr_sdl_file *f, size_t *cap, int line,
                                 int column, int length,
                                 double v[6][3]) {
  size_t corner = f->n_corners, normal = f->n_normals;
  if (corner > UINT32_MAX - 9 || normal > UINT32_MAX - 9)
    return ZR_ELIMIT;
  zr_status s = append_vectors(f, &f->corners, &f->n_corners,
                               &f->cap_corners, v[0], v[2], v[4]);
  if (s == ZR_OK)
    s = append_vectors(f, &f->normals, &f->n_normals, &f->cap_normals,
                       v[1], v[3], v[5]);
  if (s != ZR_OK)
    return s;
  zr_sdl_token t = run_at(T_SMOOTH_TRIANGLE_RUN, line, column, length);
  t.v.smooth.corner = (uint32_t)corner;
  t.v.smooth.normal = (uint32_t)normal;
  return push_token(f, cap, &t);
}

/* Once the corner array no longer moves: each run's index -> pointer. */
static void fix_corners(zr_sdl_file *f) {
  for (size_t i = 0; f->n_corners && i < f->n_tokens; i++)
    if (f->tokens[i].kind == T_TRIANGLE_RUN)
      f->tokens[i].v.corners = f->corners + f->tokens[i].v.corner;
}

static bool is_word_byte(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
         (c >= '0' && c <= '9') || c == '_';
}

/* Moves r over bytes [r->pos, to), counting lines and columns. */
static void move_to(zr_sdl_numreader *r, size_t to) {
  for (; r->pos < to; r->pos++) {
    if (r->bytes[r->pos] == '\n') {
      r->line++;
      r->column = 1;
    } else {
      r->column++;
    }
  }
}

/* After a run whose '}' is at close (r just past its vectors): the next
   run when blanks and then "triangle {" or "smooth_triangle {" with a
   plain body follow; r and *close move past it.  False, r and *close
   unchanged, otherwise. */
static zr_status next_run(zr_sdl_file *f, size_t *cap, zr_sdl_numreader *r,
                          size_t *close, bool *found) {
  static const struct {
    const char *word;
    int length, kind, vectors;
  } runs[] = {{"triangle", 8, T_TRIANGLE_RUN, 3},
              {"smooth_triangle", 15, T_SMOOTH_TRIANGLE_RUN, 6}};
  *found = false;
  zr_sdl_numreader q = *r;
  move_to(&q, *close + 1);
  size_t at = q.pos;
  while (at < f->size && zr__sdl_is_blank(f->bytes[at]))
    at++;
  move_to(&q, at);
  for (size_t i = 0; i < sizeof runs / sizeof *runs; i++) {
    size_t len = (size_t)runs[i].length;
    if (f->size - at <= len ||
        memcmp(f->bytes + at, runs[i].word, len) != 0 ||
        is_word_byte(f->bytes[at + len]))
      continue;
    int line = q.line, column = q.column;
    move_to(&q, at + len);
    size_t brace = q.pos;
    while (brace < f->size && zr__sdl_is_blank(f->bytes[brace]))
      brace++;
    if (brace >= f->size || f->bytes[brace] != '{')
      return ZR_OK;
    move_to(&q, brace + 1);
    double v[6][3];
    size_t end;
    if (!run_body(f, &q, runs[i].vectors, v, &end))
      return ZR_OK;
    zr_status status =
        runs[i].kind == T_TRIANGLE_RUN
            ? push_corner_run(f, cap, line, column, runs[i].length, v)
            : push_smooth_run(f, cap, line, column, runs[i].length, v);
    if (status != ZR_OK)
      return status;
    *r = q;
    *close = end;
    *found = true;
    return ZR_OK;
  }
  return ZR_OK;
}

static zr_status triangle_run(zr_sdl_file *f, size_t *cap,
                              zr_sdl_lexer *lx) {
  size_t n = f->n_tokens;
  if (n < 2 || f->tokens[n - 1].kind != '{' ||
      (f->tokens[n - 2].kind != T_TRIANGLE &&
       f->tokens[n - 2].kind != T_SMOOTH_TRIANGLE))
    return ZR_OK;
  bool smooth = f->tokens[n - 2].kind == T_SMOOTH_TRIANGLE;
  zr_sdl_numreader r = {f->bytes, lx->offset, f->size, lx->line,
                        lx->column, false, false};
  double v[6][3];
  size_t close;
  if (!run_body(f, &r, smooth ? 6 : 3, v, &close))
    return ZR_OK;
  /* The run stands where the keyword stood; the '{' goes. */
  zr_sdl_token keyword = f->tokens[n - 2];
  f->n_tokens -= 2;
  zr_status status =
      smooth ? push_smooth_run(f, cap, keyword.line, keyword.column,
                               keyword.length, v)
             : push_corner_run(f, cap, keyword.line, keyword.column,
                               keyword.length, v);
  for (bool more = true; status == ZR_OK && more;)
    status = next_run(f, cap, &r, &close, &more);
  resume_at(lx, close + 1, &r);
  return status;
}

/* Whether a keyword after a sphere's radius surely starts something
   else: not a blob component's strength, nor a colour item that an
   expression may go on with (directive.c, continues), nor a word the
   scanner reports. */
static bool ends_sphere(int token) {
  switch (token) {
  case T_STRENGTH: case T_UNSUPPORTED:
  case T_RGB: case T_RGBF: case T_RGBT: case T_RGBFT:
  case T_SRGB: case T_SRGBF: case T_SRGBT: case T_SRGBFT:
  case T_RED: case T_GREEN: case T_BLUE: case T_FILTER: case T_TRANSMIT:
  case T_GRAY:
    return false;
  default:
    return true;
  }
}

/*
 * "sphere { <x, y, z>, r" with plain numbers, followed by a keyword
 * (texture, pigment, scale ...) or the '}', is kept as one token,
 * T_SPHERE_RUN, in place of the keyword, the '{' and the 10 tokens of
 * the centre and radius; the sphere's modifiers and '}' follow as
 * tokens.  A sphere-heavy scene's token array is most of its parse
 * memory (issue 13: 17 tokens, 408 bytes, for "sphere { <x, y, z>, r
 * texture { T } }", now 7).  Only a keyword or '}' may follow, so the
 * radius is surely complete: an operator, a comma (a blob's strength),
 * an identifier (a macro could go on with an operator), a directive or
 * a comment leave the sphere to the scanner.  A value that is not
 * finite does too, so that the grammar reports it.
 */
static zr_status sphere_run(zr_sdl_file *f, size_t *cap,
                            zr_sdl_lexer *lx) {
  size_t n = f->n_tokens;
  if (n < 2 || f->tokens[n - 1].kind != '{' ||
      f->tokens[n - 2].kind != T_SPHERE)
    return ZR_OK;
  zr_sdl_numreader r = {f->bytes, lx->offset, f->size, lx->line,
                        lx->column, false, false};
  double v[4];
  if (!zr__sdl_numlist_sphere(&r, v))
    return ZR_OK;
  for (int k = 0; k < 4; k++)
    if (!isfinite(v[k]))
      return ZR_OK;
  size_t end = r.pos;
  while (end < f->size && zr__sdl_is_blank(f->bytes[end]))
    end++;
  if (end >= f->size)
    return ZR_OK;
  if (f->bytes[end] != '}') {
    size_t w = end;
    while (w < f->size && (isalnum((unsigned char)f->bytes[w]) ||
                           f->bytes[w] == '_'))
      w++;
    const zr_sdl_keyword *k = zr__sdl_keyword_find(f->bytes + end, w - end);
    if (w == end || !isalpha((unsigned char)f->bytes[end]) || !k ||
        !ends_sphere(k->token))
      return ZR_OK;
    /* The next token, which quick_token takes (a word of the file at
       an offset is always the same word). */
    lx->known_keyword = k;
    lx->known_at = end;
    lx->known_length = w - end;
  }
  /* The numbers go with the token (32 bytes a sphere in the file's
     arena): the grammar's action read them again from the bytes, 9% of
     bench/peers.sh's sphereflake's parse (8.8 M of 97 M instructions,
     callgrind). */
  double *values = zr__arena_alloc_raw(&f->strings, sizeof v);
  if (!values)
    return f->strings.over_budget ? ZR_ELIMIT : ZR_ENOMEM;
  memcpy(values, v, sizeof v);
  zr_sdl_token t = run_token(f, T_SPHERE_RUN, NULL);
  t.v.sphere = values;
  zr_status status = push_token(f, cap, &t);
  resume_at(lx, end, &r);
  return status;
}

/*
 * The scanner's work for the plain words and braces that follow a run,
 * done here.  After each run (a sphere's above) the scanner was started
 * again: it made a call to its restart function, read 256 bytes into
 * its buffer and matched "texture { T } }" and the next "sphere {" byte
 * by byte through its tables, counting lines and columns a byte at a
 * time, for every sphere of a sphere-heavy file.  While the scanner
 * holds nothing read ahead (lx->fresh: it was just started), a word or
 * a brace at the lexer's place is taken here instead, with the
 * scanner's rules for them (grammar/pov.l): blanks [ \t\r\n\f\v]
 * skipped, one column a byte and a line a newline; a word
 * [a-zA-Z_][a-zA-Z0-9_]* as long as it goes, a keyword when the table
 * has it, else an identifier interned in the file's arena; '{' and '}'
 * alone.  Anything else (a digit, '#', a quote, an operator, '/' that
 * may start a comment, the end of the file) is left to the scanner,
 * which starts reading at the lexer's place: the same tokens either way
 * (tests/test_lexer.c compares them on every scene and include file).
 * Returns 1 with *t filled, 0 when the scanner should take what
 * follows, -1 when interning failed (lx->failed).
 */
static int quick_token(zr_sdl_lexer *lx, zr_sdl_token *t) {
  const zr_sdl_file *f = lx->file;
  const char *b = f->bytes;
  size_t end = f->size;
  int line = lx->line, column = lx->column;
  size_t pos = zr__sdl_skip_blanks(b, lx->offset, end, &line, &column);
  /* The blanks are passed whatever comes next: the scanner would skip
     them the same way. */
  lx->offset = lx->read_pos = pos;
  lx->line = line;
  lx->column = column;
  if (pos == end)
    return 0;
  char c = b[pos];
  memset(t, 0, sizeof *t);
  t->line = line;
  t->column = column;
  if (c == '{' || c == '}') {
    t->kind = c;
    t->length = 1;
  } else if (lx->known_keyword && pos == lx->known_at) {
    t->kind = lx->known_keyword->token;
    t->v.str = lx->known_keyword->name;
    t->length = (int)lx->known_length;
  } else if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_') {
    size_t w = pos + 1;
    while (w < end && is_word_byte(b[w]))
      w++;
    size_t n = w - pos;
    if (n > INT_MAX / 2)
      return 0;
    const zr_sdl_keyword *k = zr__sdl_keyword_find(b + pos, n);
    if (k) {
      t->kind = k->token;
      t->v.str = k->name;
    } else {
      t->kind = T_IDENTIFIER;
      if (!(t->v.str = zr__sdl_lex_intern(lx, b + pos, n)))
        return -1;
    }
    t->length = (int)n;
  } else {
    return 0;
  }
  lx->offset = lx->read_pos = pos + (size_t)t->length;
  lx->column = column + t->length;
  return 1;
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
  /* Every token went through push_token, which counted the block
     directives: with none (a file of spheres or triangles) there is
     nothing to link.  Reading the 1.2 MB token array of bench/peers.sh's
     sphereflake once more for that took 8% of the samples of a
     --parse-only run (perf, cpu-clock: its first read after the array
     was cut to size). */
  if (f->block_tokens == 0) {
    f->links = malloc(sizeof *f->links);
    return f->links ? ZR_OK : ZR_ENOMEM;
  }
  /* Every directive that opens or continues a block may get a link. */
  size_t n = 0;
  for (size_t i = 0; i < f->n_tokens; i++)
    n += opens_block(f->tokens[i].kind) || continues_block(f->tokens[i].kind);
  f->links = malloc((n ? n : 1) * sizeof *f->links);
  /* open[] holds positions in links of the blocks still open. */
  size_t *open = malloc((n ? n : 1) * sizeof *open);
  if (!f->links || !open) {
    free(open);
    return ZR_ENOMEM;
  }
  size_t depth = 0;
  for (size_t i = 0; i < f->n_tokens; i++) {
    int kind = f->tokens[i].kind;
    if (opens_block(kind)) {
      f->links[f->n_links] = (struct zr_sdl_link){i, (size_t)-1};
      open[depth++] = f->n_links++;
    } else if (continues_block(kind)) {
      f->links[f->n_links] = (struct zr_sdl_link){i, (size_t)-1};
      if (depth > 0) {
        f->links[open[depth - 1]].to = i;
        open[depth - 1] = f->n_links;
      }
      f->n_links++;
    } else if (kind == T_END && depth > 0) {
      f->links[open[--depth]].to = i;
    }
  }
  free(open);
  return ZR_OK;
}

size_t zr__sdl_link(const zr_sdl_file *f, size_t i) {
  size_t lo = 0, hi = f->n_links;
  while (lo < hi) {
    size_t mid = lo + (hi - lo) / 2;
    if (f->links[mid].from < i)
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo < f->n_links && f->links[lo].from == i ? f->links[lo].to
                                                   : (size_t)-1;
}

zr_status zr__sdl_file_lex(zr_sdl_file *f, int file_index, char *path,
                           char *bytes, size_t size, zr_sdl_loc *err_loc,
                           char *err, size_t err_size) {
  return zr__sdl_file_lex_budget(f, file_index, path, bytes, size, NULL,
                                 err_loc, err, err_size);
}

static zr_status lex(zr_sdl_file *f, int file_index, char *path,
                     char *bytes, size_t size, struct zr_budget *budget,
                     zr_arena *corner_arena, bool scanner_only,
                     zr_sdl_loc *err_loc, char *err, size_t err_size);

zr_status zr__sdl_file_lex_budget(zr_sdl_file *f, int file_index,
                                  char *path, char *bytes, size_t size,
                                  struct zr_budget *budget,
                                  zr_sdl_loc *err_loc, char *err,
                                  size_t err_size) {
  return lex(f, file_index, path, bytes, size, budget, NULL, false, err_loc,
             err, err_size);
}

zr_status zr__sdl_file_lex_scene(zr_sdl_file *f, int file_index, char *path,
                                 char *bytes, size_t size,
                                 struct zr_budget *budget,
                                 zr_arena *corner_arena, zr_sdl_loc *err_loc,
                                 char *err, size_t err_size) {
  return lex(f, file_index, path, bytes, size, budget, corner_arena, false,
             err_loc, err, err_size);
}

zr_status zr__sdl_file_lex_scanner_only(zr_sdl_file *f, int file_index,
                                        char *path, char *bytes,
                                        size_t size, zr_sdl_loc *err_loc,
                                        char *err, size_t err_size) {
  return lex(f, file_index, path, bytes, size, NULL, NULL, true, err_loc,
             err, err_size);
}

static zr_status lex(zr_sdl_file *f, int file_index, char *path,
                     char *bytes, size_t size, struct zr_budget *budget,
                     zr_arena *corner_arena, bool scanner_only,
                     zr_sdl_loc *err_loc, char *err, size_t err_size) {
  memset(f, 0, sizeof *f);
  f->path = path;
  f->bytes = bytes;
  f->size = size;
  zr__arena_init(&f->strings);
  f->corner_arena = corner_arena ? corner_arena : &f->strings;
  f->strings.budget = budget;
  /* A big file's strings arena holds its spheres' numbers (sphere_run),
     32 bytes each: its blocks are filled in at once (core/arena.h). */
  f->strings.populate = size >= 256 * 1024;
  f->budget = budget;
  if (!zr__budget_charge(budget, size)) {
    snprintf(err, err_size, "the file's %zu bytes do not fit in the "
             "memory budget (raise it with --memory-limit)", size);
    return ZR_ELIMIT;
  }
  if (budget)
    f->charged = size;
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
  /* A UTF-8 byte order mark is not part of the scene.  The scanner
     reads the bytes through zr__sdl_lex_input(). */
  size_t skip = size >= 3 && memcmp(bytes, "\xEF\xBB\xBF", 3) == 0 ? 3 : 0;
  lx.offset = lx.read_pos = skip;
  zr_status status = ZR_OK;
  size_t cap = 0;
  lx.fresh = true; /* the scanner has read nothing yet */
  lx.scanner_only = scanner_only;
  while (status == ZR_OK) {
    zr_sdl_token t;
    int quick = lx.fresh && !lx.scanner_only ? quick_token(&lx, &t) : 0;
    if (quick == 0 && lx.restart && !restart_guarded(&lx, scanner)) {
      status = ZR_ENOMEM;
      break;
    }
    if (quick == 0) {
      ZR__POV_STYPE value;
      zr_sdl_loc loc;
      memset(&value, 0, sizeof value);
      lx.fresh = false;
      int kind = scan_guarded(&lx, scanner, &value, &loc);
      memset(&t, 0, sizeof t);
      t.kind = kind;
      t.line = loc.line;
      t.column = loc.column;
      t.length = loc.length;
      if (kind == T_NUMBER)
        t.v.num = value.num;
      else
        t.v.str = value.str;
    }
    if (lx.failed) {
      status = !lx.out_of_memory         ? ZR_ESYNTAX
               : f->strings.over_budget ? ZR_ELIMIT
                                        : ZR_ENOMEM;
      break;
    }
    int kind = t.kind;
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
    if (status == ZR_OK && kind == T_NUMBER)
      status = number_list(f, &cap, &lx);
    else if (status == ZR_OK && kind == '{') {
      status = triangle_run(f, &cap, &lx);
      if (status == ZR_OK)
        status = sphere_run(f, &cap, &lx);
    }
  }
  zr__scan_lex_destroy(scanner);
  if (status == ZR_OK && f->strings.over_budget)
    status = ZR_ELIMIT;
  if (status == ZR_OK && f->n_tokens < cap) {
    /* The array doubled as it grew: give back what is left over. */
    zr_sdl_token *fit = realloc(f->tokens, f->n_tokens * sizeof *fit);
    if (fit)
      f->tokens = fit;
  }
  if (status == ZR_OK)
    status = link_blocks(f);
  if (status == ZR_OK)
    fix_corners(f);
  if (status == ZR_ESYNTAX) {
    *err_loc = lx.error_at;
    err_loc->file = file_index;
    snprintf(err, err_size, "%s", lx.error);
  } else if (status == ZR_ENOMEM) {
    snprintf(err, err_size, "out of memory");
  } else if (status == ZR_ELIMIT) {
    snprintf(err, err_size, "the tokens of '%s' do not fit in the memory "
             "budget (raise it with --memory-limit)", path);
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
  zr__budget_release(f->budget, f->charged);
  memset(f, 0, sizeof *f);
}
