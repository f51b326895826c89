/*
 * fastexpr.c - a fast path for the simplest directive values: float
 * arithmetic on numbers and float identifiers.
 *
 * Loops spend most of their time in directives like "#while (I < N)" and
 * "#declare I = I + 1;", each of which would otherwise start a nested
 * bison parse.  When the tokens of such a value hold only numbers, float
 * identifiers, the built-in constants, parentheses, unary + and -, the
 * operators * / + -, one comparison (< <= = != >= >) and & |, this
 * evaluator computes it straight from the token array with the same
 * precedence and the same helpers as the grammar (zr__sdl_compare, the
 * reference manual's 1e-10 for equality and truth).  Anything else, and
 * any error (a division by zero, a missing ')'), makes it give up having
 * consumed and reported nothing: the grammar then parses the value as
 * before, and reports what is wrong with its usual message.
 */
#include "config.h"

#include <math.h>
#include <string.h>

#include "pov-parse.h"
#include "sdl/sdl.h"

/* Parentheses nest at most this deep on the fast path. */
#define MAX_DEPTH 32

typedef struct cursor {
  zr_sdl_parser *p;
  const zr_sdl_token *tokens;
  size_t pos, n;
  int depth;
} cursor;

static int peek(const cursor *c) {
  return c->pos < c->n ? c->tokens[c->pos].kind : 0;
}

static bool or_expr(cursor *c, double *out);

static bool primary(cursor *c, double *out) {
  const zr_sdl_token *t = &c->tokens[c->pos];
  switch (peek(c)) {
  case T_NUMBER:
    *out = t->v.num;
    c->pos++;
    return true;
  case T_IDENTIFIER: {
    const zr_sdl_symbol *s = zr__sdl_lookup(c->p, t->v.str, NULL);
    if (!s || s->value.kind != ZR_SDL_FLOAT || s->deprecated)
      return false;
    *out = s->value.num.v[0];
    c->pos++;
    return true;
  }
  case '(':
    if (c->depth >= MAX_DEPTH)
      return false;
    c->pos++;
    c->depth++;
    if (!or_expr(c, out) || peek(c) != ')')
      return false;
    c->depth--;
    c->pos++;
    return true;
  default:
    return false;
  }
}

static bool unary(cursor *c, double *out) {
  int sign = 1;
  while (peek(c) == '-' || peek(c) == '+') {
    if (peek(c) == '-')
      sign = -sign;
    c->pos++;
  }
  if (!primary(c, out))
    return false;
  /* ".x" and the like need the grammar. */
  if (peek(c) == '.')
    return false;
  *out *= sign;
  return true;
}

static bool term(cursor *c, double *out) {
  if (!unary(c, out))
    return false;
  while (peek(c) == '*' || peek(c) == '/') {
    int op = peek(c);
    double b;
    c->pos++;
    if (!unary(c, &b))
      return false;
    if (op == '/' && b == 0.0)
      return false;
    *out = op == '*' ? *out * b : *out / b;
  }
  return true;
}

static bool sum(cursor *c, double *out) {
  if (!term(c, out))
    return false;
  while (peek(c) == '+' || peek(c) == '-') {
    int op = peek(c);
    double b;
    c->pos++;
    if (!term(c, &b))
      return false;
    *out = op == '+' ? *out + b : *out - b;
  }
  return true;
}

static bool binary(cursor *c, int op, double a, double b, double *out) {
  zr_sdl_expr x = zr__sdl_float(a), y = zr__sdl_float(b), r;
  if (!zr__sdl_compare(c->p, op, &x, &y, NULL, &r))
    return false;
  *out = r.v[0];
  return true;
}

static bool relation(cursor *c, double *out) {
  if (!sum(c, out))
    return false;
  int op = peek(c);
  if (op != '<' && op != '>' && op != '=' && op != T_LE && op != T_GE &&
      op != T_NE)
    return true;
  double b;
  c->pos++;
  return sum(c, &b) && binary(c, op, *out, b, out);
}

static bool and_expr(cursor *c, double *out) {
  if (!relation(c, out))
    return false;
  while (peek(c) == '&') {
    double b;
    c->pos++;
    if (!relation(c, &b) || !binary(c, '&', *out, b, out))
      return false;
  }
  return true;
}

static bool or_expr(cursor *c, double *out) {
  if (!and_expr(c, out))
    return false;
  while (peek(c) == '|') {
    double b;
    c->pos++;
    if (!and_expr(c, &b) || !binary(c, '|', *out, b, out))
      return false;
  }
  return true;
}

/* Evaluates the tokens from the newest frame's position + skip up to a
   token of kind 'until'; on success *end is the index after it. */
static bool evaluate(zr_sdl_parser *p, size_t skip, int until, size_t *end,
                     double *out) {
  const zr_sdl_frame *fr = zr__sdl_top(p);
  const zr_sdl_file *f = &p->files[fr->file];
  cursor c = {p, f->tokens, fr->pos + skip, f->n_tokens, 0};
  if (!or_expr(&c, out) || peek(&c) != until || !isfinite(*out))
    return false;
  *end = c.pos + 1;
  return true;
}

bool zr__sdl_fast_paren(zr_sdl_parser *p, double *out) {
  size_t end;
  if (zr__sdl_peek(p, 0)->kind != '(' || !evaluate(p, 1, ')', &end, out))
    return false;
  zr__sdl_top(p)->pos = end;
  return true;
}

/* A vector literal "<e, e [, e...]>" of 2 to 5 float expressions (no
   comparisons inside, as in the grammar's vector lists). */
static bool vector(cursor *c, zr_sdl_expr *out) {
  if (peek(c) != '<')
    return false;
  c->pos++;
  memset(out, 0, sizeof *out);
  for (;;) {
    if (out->dim == 5 || !sum(c, &out->v[out->dim]))
      return false;
    out->dim++;
    if (peek(c) != ',')
      break;
    c->pos++;
  }
  if (peek(c) != '>' || out->dim < 2)
    return false;
  c->pos++;
  return true;
}

bool zr__sdl_fast_argument(zr_sdl_parser *p, zr_sdl_value *value,
                           int *end) {
  const zr_sdl_frame *fr = zr__sdl_top(p);
  const zr_sdl_file *f = &p->files[fr->file];
  cursor c = {p, f->tokens, fr->pos, f->n_tokens, 0};
  memset(value, 0, sizeof *value);
  if (peek(&c) == '<') {
    if (!vector(&c, &value->num))
      return false;
    for (int i = 0; i < value->num.dim; i++)
      if (!isfinite(value->num.v[i]))
        return false;
    value->kind = value->num.dim == 5 ? ZR_SDL_COLOUR : ZR_SDL_VECTOR;
  } else {
    double v;
    if (!or_expr(&c, &v) || !isfinite(v))
      return false;
    value->kind = ZR_SDL_FLOAT;
    value->num = zr__sdl_float(v);
  }
  if (peek(&c) != ',' && peek(&c) != ')')
    return false;
  *end = peek(&c);
  zr__sdl_top(p)->pos = c.pos + 1;
  return true;
}

bool zr__sdl_fast_declare(zr_sdl_parser *p, bool is_local) {
  const zr_sdl_token *name = zr__sdl_peek(p, 0);
  if (name->kind != T_IDENTIFIER || zr__sdl_peek(p, 1)->kind != '=')
    return false;
  double v;
  size_t end;
  if (!evaluate(p, 2, ';', &end, &v))
    return false;
  zr_sdl_decl_name decl;
  memset(&decl, 0, sizeof decl);
  decl.name = name->v.str;
  decl.frame = (int)(p->n_frames - 1);
  decl.local = is_local;
  zr_sdl_value value;
  memset(&value, 0, sizeof value);
  value.kind = ZR_SDL_FLOAT;
  value.num = zr__sdl_float(v);
  zr_sdl_loc at = zr__sdl_peek_loc(p, 0);
  zr__sdl_top(p)->pos = end;
  return zr__sdl_define(p, &decl, is_local, &value, &at);
}
