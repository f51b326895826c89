/*
 * control.c - the block and message directives of the scene language:
 * #if #ifdef #ifndef #elseif #else #end, #while, #for, #switch #case
 * #range #break, #macro and macro calls, #undef, #debug #warning #error,
 * #default.
 *
 * They follow the reference manual's "Language Directives" (r3_3,
 * 3.3.2.6 to 3.3.2.8).  Each file's block directives were linked to their
 * partners when the file was lexed (tokens.c), so a false branch is
 * skipped in one jump and a loop goes back to its head by index: a
 * #while of a million iterations replays its token range without reading
 * or scanning anything again, and errors keep their true place.  The
 * blocks being run are a small stack in each frame (zr_sdl_ctl); a macro
 * call is a frame of its own whose table holds the parameters and the
 * macro's #local names, and whose #end returns to the caller.
 *
 * Semantics worth knowing:
 *   - #case compares within 1e-10; a true clause without #break falls
 *     through into the next #case, #range or #else whatever their
 *     conditions (what POV-Ray 3.7 does, measured: its manual says the
 *     next condition is evaluated); #else also runs when no clause was
 *     true;
 *   - #break leaves the innermost #switch, #while, #for or macro
 *     (POV-Ray 3.7), passing through any #if around it;
 *   - #for (I, Start, End [, Step]) keeps I in the current scope, runs
 *     while I <= End (I >= End for a negative step), within 1e-10, and
 *     leaves I at the first value past End;
 *   - a macro argument that is a lone identifier is passed by identifier:
 *     assigning the parameter changes the caller's variable; anything
 *     else is passed by value.  Parameters may be declared "optional";
 *   - macro calls nest at most ZR_SDL_MAX_MACRO_DEPTH deep, so runaway
 *     recursion ends in a message rather than a stack overflow.
 */
#include "config.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pov-parse.h"
#include "sdl/sdl.h"

#define NONE ((size_t)-1)
/* The reference manual's epsilon for #case and #for: "Numeric
   Expressions" (3.3.1.5) calls values within about 1.0e-10 of each other
   equal, and "Operators" (3.3.1.5.3) writes A = B as abs(A-B) < EPSILON. */
#define EPSILON 1e-10

static const zr_sdl_file *file_of(zr_sdl_parser *p) {
  return &p->files[zr__sdl_top(p)->file];
}

static const char *directive_name(int kind) {
  switch (kind) {
  case T_IF: return "#if";
  case T_IFDEF: return "#ifdef";
  case T_IFNDEF: return "#ifndef";
  case T_WHILE: return "#while";
  case T_FOR: return "#for";
  case T_SWITCH: return "#switch";
  case T_MACRO: return "#macro";
  case T_ELSE: return "#else";
  case T_ELSEIF: return "#elseif";
  case T_CASE: return "#case";
  case T_RANGE: return "#range";
  case T_BREAK: return "#break";
  default: return "#end";
  }
}

static bool unmatched(zr_sdl_parser *p, size_t open) {
  const zr_sdl_file *f = file_of(p);
  zr_sdl_loc at = zr__sdl_token_loc(zr__sdl_top(p)->file,
                                    &f->tokens[open]);
  zr__sdl_error(p, ZR_ESYNTAX, &at, "'%s' without a matching '#end'",
                directive_name(f->tokens[open].kind));
  return false;
}

/* The #end of the block whose directive is at i, or NONE. */
static size_t block_end(const zr_sdl_file *f, size_t i) {
  while (i != NONE && f->tokens[i].kind != T_END)
    i = zr__sdl_link(f, i);
  return i;
}

static bool push_ctl(zr_sdl_parser *p, zr_sdl_ctl_kind kind, size_t open) {
  zr_sdl_frame *fr = zr__sdl_top(p);
  if (fr->n_ctl == fr->cap_ctl) {
    size_t cap = fr->cap_ctl ? fr->cap_ctl * 2 : 8;
    zr_sdl_ctl *ctl = realloc(fr->ctl, cap * sizeof *ctl);
    if (!ctl) {
      zr__sdl_error(p, ZR_ENOMEM, NULL, "out of memory");
      return false;
    }
    fr->ctl = ctl;
    fr->cap_ctl = cap;
  }
  zr_sdl_ctl *c = &fr->ctl[fr->n_ctl++];
  memset(c, 0, sizeof *c);
  c->kind = kind;
  c->open = open;
  return true;
}

static zr_sdl_ctl *top_ctl(zr_sdl_parser *p) {
  zr_sdl_frame *fr = zr__sdl_top(p);
  return fr->n_ctl ? &fr->ctl[fr->n_ctl - 1] : NULL;
}

static void pop_ctl(zr_sdl_parser *p) { zr__sdl_top(p)->n_ctl--; }

/* Continues after the #end at index end and closes the innermost block. */
static bool leave_block(zr_sdl_parser *p, size_t end) {
  zr__sdl_top(p)->pos = end + 1;
  pop_ctl(p);
  return true;
}

/* Parses "( expr )" at the current place as a float. */
static bool paren_float(zr_sdl_parser *p, const zr_sdl_loc *at,
                        double *out) {
  if (zr__sdl_fast_paren(p, out))
    return true;
  zr_sdl_expr e;
  return zr__sdl_parse_expr(p, T_START_PAREN, &e) == ZR_OK &&
         zr__sdl_want_float(p, &e, at, out);
}

static bool paren_truth(zr_sdl_parser *p, const zr_sdl_loc *at, bool *out) {
  double v;
  if (zr__sdl_fast_paren(p, &v)) {
    *out = fabs(v) > EPSILON;
    return true;
  }
  zr_sdl_expr e;
  return zr__sdl_parse_expr(p, T_START_PAREN, &e) == ZR_OK &&
         zr__sdl_truth(p, &e, at, out);
}

/* Reads an identifier token at the current place, or reports what was
   expected after the directive. */
const char *zr__sdl_read_name(zr_sdl_parser *p, const char *after) {
  const zr_sdl_token *t = zr__sdl_peek(p, 0);
  if (t->kind != T_IDENTIFIER) {
    zr_sdl_loc at = zr__sdl_peek_loc(p, 0);
    zr__sdl_error(p, ZR_ESYNTAX, &at, "expected an identifier after '%s'",
                  after);
    return NULL;
  }
  zr__sdl_top(p)->pos++;
  return t->v.str;
}

bool zr__sdl_expect(zr_sdl_parser *p, int kind, const char *what) {
  if (zr__sdl_peek(p, 0)->kind != kind) {
    zr_sdl_loc at = zr__sdl_peek_loc(p, 0);
    zr__sdl_error(p, ZR_ESYNTAX, &at, "expected %s", what);
    return false;
  }
  zr__sdl_top(p)->pos++;
  return true;
}

bool zr__sdl_read_defined(zr_sdl_parser *p, const zr_sdl_loc *at,
                          bool *out) {
  (void)at;
  if (!zr__sdl_expect(p, '(', "'(' before the identifier"))
    return false;
  zr_sdl_loc nl = zr__sdl_peek_loc(p, 0);
  const char *name = zr__sdl_read_name(p, "'('");
  if (!name)
    return false;
  const zr_sdl_symbol *s = zr__sdl_lookup(p, name, NULL);
  *out = s != NULL;
  if (s && s->value.kind == ZR_SDL_ARRAY &&
      zr__sdl_peek(p, 0)->kind == '[') {
    /* #ifdef (A[i]): whether that element was assigned. */
    const zr_sdl_array *a = s->value.ptr;
    int index[ZR_SDL_MAX_DIMS];
    int n = 0;
    while (zr__sdl_peek(p, 0)->kind == '[' && n < ZR_SDL_MAX_DIMS) {
      double v;
      if (zr__sdl_parse_nested(p, T_START_INDEX) != ZR_OK ||
          !zr__sdl_want_float(p, &p->nested_value, &nl, &v))
        return false;
      index[n++] = (int)floor(v);
    }
    bool set;
    if (!zr__sdl_array_get(p, name, a, index, n, &nl, &set))
      return false;
    *out = set;
  }
  return zr__sdl_expect(p, ')', "')' after the identifier");
}

/* ---- #if, #ifdef, #ifndef, #elseif, #else ---- */

/* Moves parsing to just after the linked directive at m of the block
   opened at open and returns that directive's token (its location in
   *tl); NULL, reported, when the chain ends without its #end. */
static const zr_sdl_token *enter_link(zr_sdl_parser *p, size_t open,
                                      size_t m, zr_sdl_loc *tl) {
  if (m == NONE) {
    unmatched(p, open);
    return NULL;
  }
  const zr_sdl_token *t = &file_of(p)->tokens[m];
  *tl = zr__sdl_token_loc(zr__sdl_top(p)->file, t);
  zr__sdl_top(p)->pos = m + 1;
  return t;
}

/* Goes on from the branch directive at m of an #if block whose
   condition (and any before m) was false. */
static bool next_branch(zr_sdl_parser *p, size_t open, size_t m) {
  for (;;) {
    zr_sdl_loc tl;
    const zr_sdl_token *t = enter_link(p, open, m, &tl);
    if (!t)
      return false;
    switch (t->kind) {
    case T_ELSEIF: {
      bool c;
      if (!paren_truth(p, &tl, &c))
        return false;
      if (c)
        return true;
      m = zr__sdl_link(file_of(p), m);
      break;
    }
    case T_ELSE:
      return true;
    case T_END:
      pop_ctl(p);
      return true;
    default:
      zr__sdl_error(p, ZR_ESYNTAX, &tl, "'%s' inside '#if'",
                    directive_name(t->kind));
      return false;
    }
  }
}

static bool do_if(zr_sdl_parser *p, const zr_sdl_token *t,
                  const zr_sdl_loc *at) {
  size_t open = zr__sdl_top(p)->pos - 1;
  bool c;
  if (t->kind == T_IF) {
    if (!paren_truth(p, at, &c))
      return false;
  } else {
    if (!zr__sdl_read_defined(p, at, &c))
      return false;
    if (t->kind == T_IFNDEF)
      c = !c;
  }
  if (!push_ctl(p, ZR_SDL_CTL_IF, open))
    return false;
  return c || next_branch(p, open, zr__sdl_link(file_of(p), open));
}

/* #else or #elseif reached while running the branch before it. */
static bool do_else(zr_sdl_parser *p, const zr_sdl_token *t,
                    const zr_sdl_loc *at) {
  zr_sdl_ctl *c = top_ctl(p);
  if (!c || (c->kind != ZR_SDL_CTL_IF &&
             !(c->kind == ZR_SDL_CTL_SWITCH && t->kind == T_ELSE))) {
    zr__sdl_error(p, ZR_ESYNTAX, at, "'%s' without a matching '#if'",
                  directive_name(t->kind));
    return false;
  }
  /* In a #switch a true clause falls through #else too (POV-Ray). */
  if (c->kind == ZR_SDL_CTL_SWITCH)
    return true;
  size_t end = block_end(file_of(p), zr__sdl_top(p)->pos - 1);
  if (end == NONE)
    return unmatched(p, c->open);
  return leave_block(p, end);
}

/* ---- #switch, #case, #range ---- */

/* Evaluates the clauses of the switch from the one at m on until one is
   true (parsing goes on in it) or the #end. */
static bool next_clause(zr_sdl_parser *p, size_t m) {
  zr_sdl_ctl *sw = top_ctl(p);
  size_t open = sw->open;
  double value = sw->value;
  for (;;) {
    zr_sdl_loc tl;
    const zr_sdl_token *t = enter_link(p, open, m, &tl);
    if (!t)
      return false;
    switch (t->kind) {
    case T_CASE: {
      double v;
      if (!paren_float(p, &tl, &v))
        return false;
      if (fabs(v - value) < EPSILON)
        return true;
      break;
    }
    case T_RANGE: {
      if (zr__sdl_parse_nested(p, T_START_RANGE) != ZR_OK)
        return false;
      if (p->nested_list.v[0] <= value && value <= p->nested_list.v[1])
        return true;
      break;
    }
    case T_ELSE:
      return true;
    case T_END:
      pop_ctl(p);
      return true;
    default:
      zr__sdl_error(p, ZR_ESYNTAX, &tl, "'%s' inside '#switch'",
                    directive_name(t->kind));
      return false;
    }
    m = zr__sdl_link(file_of(p), m);
  }
}

static bool do_switch(zr_sdl_parser *p, const zr_sdl_loc *at) {
  size_t open = zr__sdl_top(p)->pos - 1;
  double value;
  if (!paren_float(p, at, &value) ||
      !push_ctl(p, ZR_SDL_CTL_SWITCH, open))
    return false;
  top_ctl(p)->value = value;
  return next_clause(p, zr__sdl_link(file_of(p), open));
}

/* #case or #range reached while running a true clause: parsing falls
   through into it whatever its condition, as POV-Ray 3.7 does (its
   manual says the condition is evaluated; the program does not look at
   it).  The condition is still read, to step over it. */
static bool do_case(zr_sdl_parser *p, const zr_sdl_token *t,
                    const zr_sdl_loc *at) {
  zr_sdl_ctl *c = top_ctl(p);
  if (!c || c->kind != ZR_SDL_CTL_SWITCH) {
    zr__sdl_error(p, ZR_ESYNTAX, at, "'%s' outside '#switch'",
                  directive_name(t->kind));
    return false;
  }
  double v;
  if (t->kind == T_CASE)
    return paren_float(p, at, &v);
  return zr__sdl_parse_nested(p, T_START_RANGE) == ZR_OK;
}

/* ---- #while, #for, #break, #end ---- */

static bool do_while(zr_sdl_parser *p, const zr_sdl_loc *at) {
  size_t open = zr__sdl_top(p)->pos - 1;
  size_t end = block_end(file_of(p), open);
  if (end == NONE)
    return unmatched(p, open);
  bool c;
  if (!paren_truth(p, at, &c))
    return false;
  if (!c) {
    zr__sdl_top(p)->pos = end + 1;
    return true;
  }
  return push_ctl(p, ZR_SDL_CTL_WHILE, open);
}

static bool set_counter(zr_sdl_parser *p, const char *var, double v) {
  zr_sdl_value value;
  memset(&value, 0, sizeof value);
  value.kind = ZR_SDL_FLOAT;
  value.num = zr__sdl_float(v);
  zr_sdl_symtab *scope = zr__sdl_scope(p, p->n_frames - 1);
  if (zr__sdl_symtab_set(scope, var, &value) != ZR_OK) {
    zr__sdl_error(p, ZR_ENOMEM, NULL, "out of memory");
    return false;
  }
  return true;
}

static bool for_continues(double v, double to, double step) {
  return step > 0 ? v <= to + EPSILON : v >= to - EPSILON;
}

static bool do_for(zr_sdl_parser *p, const zr_sdl_loc *at) {
  size_t open = zr__sdl_top(p)->pos - 1;
  size_t end = block_end(file_of(p), open);
  if (end == NONE)
    return unmatched(p, open);
  if (!zr__sdl_expect(p, '(', "'(' after '#for'"))
    return false;
  const char *var = zr__sdl_read_name(p, "'#for ('");
  if (!var || zr__sdl_parse_nested(p, T_START_FOR) != ZR_OK)
    return false;
  double start = p->nested_list.v[0], to = p->nested_list.v[1];
  double step = p->nested_list.n > 2 ? p->nested_list.v[2] : 1.0;
  if (step == 0) {
    zr__sdl_error(p, ZR_ESCENE, at, "the step of '#for' is zero");
    return false;
  }
  if (!set_counter(p, var, start))
    return false;
  if (!for_continues(start, to, step)) {
    zr__sdl_top(p)->pos = end + 1;
    return true;
  }
  if (!push_ctl(p, ZR_SDL_CTL_FOR, open))
    return false;
  zr_sdl_ctl *c = top_ctl(p);
  c->body = zr__sdl_top(p)->pos;
  c->var = var;
  c->to = to;
  c->step = step;
  return true;
}

/* Counts one more pass of a loop body against the work budget, so that
   a loop whose condition never changes ends. */
static bool count_iteration(zr_sdl_parser *p, size_t open) {
  const zr_sdl_file *f = file_of(p);
  zr_sdl_loc at = zr__sdl_token_loc(zr__sdl_top(p)->file,
                                    &f->tokens[open]);
  char what[48];
  snprintf(what, sizeof what, "a pass of '%s'",
           directive_name(f->tokens[open].kind));
  return zr__sdl_spend(p, &at, what);
}

/* The #end of a #for: the next value of the counter, or the way out. */
static bool for_end(zr_sdl_parser *p, size_t end, const zr_sdl_loc *at) {
  zr_sdl_ctl *c = top_ctl(p);
  zr_sdl_symtab *scope = zr__sdl_scope(p, p->n_frames - 1);
  const zr_sdl_symbol *s = zr__sdl_symtab_find(scope, c->var);
  if (!s || s->value.kind != ZR_SDL_FLOAT) {
    zr__sdl_error(p, ZR_ESCENE, at,
                  "the counter '%s' of '#for' is no longer a local float",
                  c->var);
    return false;
  }
  double v = s->value.num.v[0] + c->step;
  size_t body = c->body;
  bool again = for_continues(v, c->to, c->step);
  if (!set_counter(p, c->var, v))
    return false;
  if (!again)
    return leave_block(p, end);
  zr__sdl_top(p)->pos = body;
  return count_iteration(p, c->open);
}

static bool do_end(zr_sdl_parser *p, const zr_sdl_loc *at) {
  zr_sdl_frame *fr = zr__sdl_top(p);
  size_t end = fr->pos - 1;
  zr_sdl_ctl *c = top_ctl(p);
  if (!c) {
    if (fr->macro && end == fr->macro->end) {
      zr__sdl_pop_frame(p);
      return true;
    }
    zr__sdl_error(p, ZR_ESYNTAX, at, "'#end' without a matching '#if', "
                  "'#while', '#for', '#switch' or '#macro'");
    return false;
  }
  switch (c->kind) {
  case ZR_SDL_CTL_WHILE: {
    /* Back to the condition, whose tokens are read again from the
       array: a loop costs no lexing. */
    size_t open = c->open;
    fr->pos = open + 1;
    bool again;
    zr_sdl_loc wl = zr__sdl_token_loc(fr->file, &file_of(p)->tokens[open]);
    if (!paren_truth(p, &wl, &again))
      return false;
    if (again)
      return count_iteration(p, open);
    return leave_block(p, end);
  }
  case ZR_SDL_CTL_FOR:
    return for_end(p, end, at);
  default:
    pop_ctl(p);
    return true;
  }
}

static bool do_break(zr_sdl_parser *p, const zr_sdl_loc *at) {
  for (;;) {
    zr_sdl_frame *fr = zr__sdl_top(p);
    zr_sdl_ctl *c = top_ctl(p);
    if (!c) {
      if (fr->macro) {
        zr__sdl_pop_frame(p);
        return true;
      }
      zr__sdl_error(p, ZR_ESYNTAX, at, "'#break' outside '#switch', "
                    "'#while', '#for' or a macro");
      return false;
    }
    if (c->kind == ZR_SDL_CTL_IF) {
      pop_ctl(p);
      continue;
    }
    size_t end = block_end(file_of(p), c->open);
    if (end == NONE)
      return unmatched(p, c->open);
    return leave_block(p, end);
  }
}

bool zr__sdl_check_blocks(zr_sdl_parser *p) {
  zr_sdl_ctl *c = top_ctl(p);
  return !c || unmatched(p, c->open);
}

/* ---- #macro and macro calls ---- */

static bool do_macro(zr_sdl_parser *p, const zr_sdl_loc *at) {
  size_t open = zr__sdl_top(p)->pos - 1;
  size_t end = block_end(file_of(p), open);
  if (end == NONE)
    return unmatched(p, open);
  zr_sdl_loc nl = zr__sdl_peek_loc(p, 0);
  const char *name = zr__sdl_read_name(p, "'#macro'");
  if (!name || !zr__sdl_expect(p, '(', "'(' after the macro's name"))
    return false;
  zr_sdl_macro *m = zr__sdl_alloc(p, sizeof *m);
  if (!m)
    return false;
  memset(m, 0, sizeof *m);
  m->name = name;
  m->file = zr__sdl_top(p)->file;
  m->end = end;
  /* The parameters: at most as many as tokens before the ')'. */
  size_t cap = 0;
  while (zr__sdl_peek(p, cap)->kind != ')' &&
         zr__sdl_peek(p, cap)->kind != 0)
    cap++;
  m->params = zr__sdl_alloc(p, (cap + 1) * sizeof *m->params);
  m->optional = zr__sdl_alloc(p, (cap + 1) * sizeof *m->optional);
  if (!m->params || !m->optional)
    return false;
  if (zr__sdl_peek(p, 0)->kind != ')') {
    for (;;) {
      const zr_sdl_token *t = zr__sdl_peek(p, 0);
      bool optional = t->kind == T_IDENTIFIER &&
                      strcmp(t->v.str, "optional") == 0 &&
                      zr__sdl_peek(p, 1)->kind == T_IDENTIFIER;
      if (optional)
        zr__sdl_top(p)->pos++;
      const char *param = zr__sdl_read_name(p, m->n_params ? "','" : "'('");
      if (!param)
        return false;
      m->optional[m->n_params] = optional;
      m->params[m->n_params++] = param;
      /* POV-Ray takes a parameter list with a comma missing between
         two names or after the last one (shapes3.inc has both). */
      if (zr__sdl_peek(p, 0)->kind == T_IDENTIFIER)
        continue;
      if (zr__sdl_peek(p, 0)->kind != ',')
        break;
      zr__sdl_top(p)->pos++;
      if (zr__sdl_peek(p, 0)->kind == ')')
        break;
    }
  }
  if (!zr__sdl_expect(p, ')', "',' or ')' in the macro's parameters"))
    return false;
  m->body = zr__sdl_top(p)->pos;
  if (m->body > end) {
    zr__sdl_error(p, ZR_ESYNTAX, at, "'#macro' without a body");
    return false;
  }
  /* Macros are global, whatever the scope they are defined in. */
  zr_sdl_value v;
  memset(&v, 0, sizeof v);
  v.kind = ZR_SDL_MACRO;
  v.ptr = m;
  if (zr__sdl_symtab_set(&p->globals, name, &v) != ZR_OK) {
    zr__sdl_error(p, ZR_ENOMEM, &nl, "out of memory");
    return false;
  }
  zr__sdl_top(p)->pos = end + 1;
  return true;
}

/* One actual parameter: by identifier when it is a lone defined name. */
static bool read_argument(zr_sdl_parser *p, zr_sdl_value *value,
                          int *end) {
  const zr_sdl_token *t = zr__sdl_peek(p, 0);
  int after = zr__sdl_peek(p, 1)->kind;
  if (t->kind == T_IDENTIFIER && (after == ',' || after == ')')) {
    size_t frame;
    const zr_sdl_symbol *s = zr__sdl_lookup(p, t->v.str, &frame);
    if (!s) {
      zr_sdl_loc at = zr__sdl_peek_loc(p, 0);
      zr__sdl_error(p, ZR_EUNDEFINED, &at, "undefined identifier '%s'",
                    t->v.str);
      return false;
    }
    if (s->value.kind != ZR_SDL_MACRO) {
      /* The variable itself: a parameter passed on by identifier again
         names its caller's variable, whose name may differ. */
      zr_sdl_alias *a = zr__sdl_alloc(p, sizeof *a);
      if (!a || !(a->name = zr__sdl_strdup(p, s->name, strlen(s->name))))
        return false;
      a->frame = frame;
      memset(value, 0, sizeof *value);
      value->kind = ZR_SDL_ALIAS;
      value->ptr = a;
      zr__sdl_top(p)->pos += 2;
      *end = after;
      return true;
    }
  }
  if (zr__sdl_fast_argument(p, value, end))
    return true;
  size_t frames = p->n_frames;
  if (zr__sdl_parse_nested(p, T_START_ARG) != ZR_OK)
    return false;
  if (p->n_frames != frames) {
    zr_sdl_loc at = zr__sdl_peek_loc(p, 0);
    zr__sdl_error(p, ZR_ESYNTAX, &at, "a macro argument must end in the "
                  "file or macro where it begins");
    return false;
  }
  *value = p->nested_rvalue;
  *end = p->nested_end;
  return true;
}

bool zr__sdl_call_macro(zr_sdl_parser *p, const zr_sdl_macro *m,
                        const zr_sdl_loc *at) {
  char what[96];
  snprintf(what, sizeof what, "a call of macro '%.60s'", m->name);
  if (!zr__sdl_spend(p, at, what))
    return false;
  if (p->macro_depth >= ZR_SDL_MAX_MACRO_DEPTH) {
    zr__sdl_error(p, ZR_ELIMIT, at, "macro calls nested more than %d "
                  "deep (does '%s' call itself without end?)",
                  ZR_SDL_MAX_MACRO_DEPTH, m->name);
    return false;
  }
  if (zr__sdl_peek(p, 0)->kind != '(') {
    zr_sdl_loc l = zr__sdl_peek_loc(p, 0);
    zr__sdl_error(p, ZR_ESYNTAX, &l, "expected '(' after macro name '%s'",
                  m->name);
    return false;
  }
  zr__sdl_top(p)->pos++;
  zr_sdl_value *args = calloc((size_t)m->n_params + 1, sizeof *args);
  if (!args) {
    zr__sdl_error(p, ZR_ENOMEM, at, "out of memory");
    return false;
  }
  int n = 0;
  bool ok = true;
  if (zr__sdl_peek(p, 0)->kind == ')') {
    zr__sdl_top(p)->pos++;
  } else {
    for (;;) {
      int end;
      zr_sdl_value v;
      if (!read_argument(p, &v, &end)) {
        ok = false;
        break;
      }
      if (n < m->n_params)
        args[n] = v;
      n++;
      if (end == ')')
        break;
    }
  }
  int needed = m->n_params;
  while (needed > 0 && m->optional[needed - 1] && needed > n)
    needed--;
  if (ok && (n < needed || n > m->n_params)) {
    zr__sdl_error(p, ZR_ESYNTAX, at, "macro '%s' takes %d argument%s, "
                  "not %d", m->name, m->n_params,
                  m->n_params == 1 ? "" : "s", n);
    ok = false;
  }
  if (ok && zr__sdl_push_frame(p, m->file, at)) {
    zr_sdl_frame *fr = zr__sdl_top(p);
    fr->macro = m;
    fr->pos = m->body;
    p->macro_depth++;
    for (int i = 0; i < n && ok; i++) {
      if (zr__sdl_symtab_set(&fr->locals, m->params[i], &args[i]) !=
          ZR_OK) {
        zr__sdl_error(p, ZR_ENOMEM, at, "out of memory");
        ok = false;
      }
    }
  } else {
    ok = false;
  }
  free(args);
  return ok;
}

/* ---- #undef, #debug, #warning, #error ---- */

static bool do_undef(zr_sdl_parser *p, const zr_sdl_loc *at) {
  zr_sdl_loc nl = zr__sdl_peek_loc(p, 0);
  const char *name = zr__sdl_read_name(p, "'#undef'");
  if (!name)
    return false;
  (void)at;
  /* The most local, most recent version goes ("Destroying
     Identifiers"); a parameter passed by identifier goes itself. */
  for (size_t i = p->n_frames; i-- > 0;) {
    zr_sdl_symtab *t = zr__sdl_scope(p, i);
    if (zr__sdl_symtab_find(t, name)) {
      zr__sdl_symtab_remove(t, name);
      return true;
    }
  }
  zr__sdl_warning(p, &nl, "'#undef' of '%s', which is not defined", name);
  return true;
}

static bool do_message(zr_sdl_parser *p, int kind, const zr_sdl_loc *at) {
  if (zr__sdl_parse_nested(p, T_START_STRING) != ZR_OK)
    return false;
  const char *text = p->nested_rvalue.ptr;
  if (kind == T_DEBUG) {
    zr__diag(p->ctx, ZR_DIAG_DEBUG, ZR_OK, NULL, "%s", text);
    return true;
  }
  /* Messages end their own line: a trailing newline is the stream's. */
  int len = (int)strlen(text);
  if (len > 0 && text[len - 1] == '\n')
    len--;
  if (kind == T_WARNING) {
    zr__sdl_warning(p, at, "%.*s", len, text);
    return true;
  }
  zr__sdl_error(p, ZR_ESCENE, at, "%.*s", len, text);
  return false;
}

/* ---- #default ---- */

bool zr__sdl_set_default(zr_sdl_parser *p, const zr_texture *texture,
                         const zr_pigment *pigment,
                         const zr_finish *finish) {
  const zr_texture *old = p->scene->default_texture;
  zr_texture *t = zr__sdl_texture_new(p, texture ? texture : old);
  if (!t)
    return false;
  if (pigment)
    t->pigment = pigment;
  if (finish)
    t->finish = finish;
  /* The scene applies its default texture when it is finished; objects
     made before this #default keep the one in force when they were made
     ("The #default Directive": it affects what follows). */
  for (size_t i = 0; i < p->scene->n_objects; i++)
    if (!p->scene->objects[i]->texture)
      p->scene->objects[i]->texture = old;
  p->scene->default_texture = t;
  p->default_changed = true;
  return true;
}

bool zr__sdl_run_directive(zr_sdl_parser *p, const zr_sdl_token *t,
                           const zr_sdl_loc *at) {
  switch (t->kind) {
  case T_IF:
  case T_IFDEF:
  case T_IFNDEF:
    return do_if(p, t, at);
  case T_ELSE:
  case T_ELSEIF:
    return do_else(p, t, at);
  case T_SWITCH:
    return do_switch(p, at);
  case T_CASE:
  case T_RANGE:
    return do_case(p, t, at);
  case T_WHILE:
    return do_while(p, at);
  case T_FOR:
    return do_for(p, at);
  case T_END:
    return do_end(p, at);
  case T_BREAK:
    return do_break(p, at);
  case T_MACRO:
    return do_macro(p, at);
  case T_UNDEF:
    return do_undef(p, at);
  case T_DEBUG:
  case T_WARNING:
  case T_ERROR:
    return do_message(p, t->kind, at);
  case T_DEFAULT:
    return zr__sdl_parse_nested(p, T_START_DEFAULT) == ZR_OK;
  case T_FOPEN:
  case T_FCLOSE:
  case T_READ:
  case T_WRITE:
    return zr__sdl_run_file_directive(p, t->kind, at);
  default:
    zr__sdl_error(p, ZR_EUNSUPPORTED, at, "'%s' is not supported yet",
                  t->v.str);
    return false;
  }
}
