/*
 * function.c - user-defined functions: the compiler.
 *
 * POV-Ray evaluates `function { ... }` bodies while rendering (patterns,
 * isosurfaces) and while parsing (`#declare V = F(3);`), so a body is
 * compiled once, when it is declared, into bytecode for a small stack
 * machine over doubles (lib/fn/code.h), and evaluated many times by the
 * machine in lib/fn/vm.c, which sits below the scene model and the
 * tracer that call it (README, "Layering").  The language is the
 * one the reference manual gives in 3.3.1.8 "Function": | lowest, then &,
 * one relational operator (< <= = != >= >), + -, * /, unary signs, and
 * the float functions it lists (abs ... tanh, min and max with any number
 * of arguments, select with 3 or 4, sum and prod with their iteration
 * variable).  POV-Ray 3.7 itself rejects ^ and ?: inside functions (we
 * checked with povray 3.7.0), and so do we, with a message saying so.
 *
 * What a name means is settled at compile time: a parameter (x y z, or
 * u v, which the manual makes synonyms of x y; or the declared list), a
 * sum/prod counter, a declared float (its value is captured now, as in
 * POV-Ray), a declared vector's component (V.x), or a declared function,
 * which becomes a call.  Functions cannot recurse (a name is declared
 * after its body is compiled), but chains of calls are limited to
 * ZR_FN_MAX_DEPTH, as POV-Ray documents, so runaway input cannot blow the
 * C stack.  Each function records how many doubles an evaluation needs,
 * callees included, so the machine never allocates.
 *
 * The body is read straight from the token array of the file being read
 * (the grammar hands over right after the 'function' keyword, before it
 * looks ahead), because parameter names must not be looked up as
 * declared identifiers the way the directive engine does for bison.
 *
 * The compiler folds operations on constants and fuses an operator with
 * a lone right operand (x*y is two instructions, not three).
 *
 * `internal(n)` bodies (functions.inc) map n to a routine of
 * lib/fn/internal.c.  Any n still compiles, so functions.inc parses,
 * but a function that uses one not implemented reports it by name and
 * number when it is called (zr__fn_unsupported() tells later users the
 * same).
 *
 * function { pattern { ... } } and function { pigment { ... } } are read
 * by the grammar (a nested parse) and become one instruction that
 * evaluates the pattern's value or the pigment's colour at (x, y, z)
 * ("Function Pattern") through a callback stored with the pigment
 * (zr_fn_extern), as the machine knows no pigments; another body uses a
 * pigment function as
 * F(x, y, z).red (or .x, .gray ...), one channel of the colour.
 * function { spline { ... } } and function { S } (S a declared spline)
 * are functions of one parameter whose value in a scene is the spline's
 * vector (lib/sdl/spline.c); another body takes one component,
 * F(t).y, which one OP_SPLINE evaluates.  function { transform { ... } }
 * is a function of x, y, z whose value in a scene is the point moved by
 * the transform (transforms.inc's vtransform), and F(x, y, z).y in a
 * body, one OP_XFORM.
 */
#include "config.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fn/code.h"
#include "pov-parse.h"
#include "scene/pattern.h"
#include "scene/texture.h"
#include "sdl/function.h"
#include "sdl/spline.h"


/* ---- what bodies reach outside the machine (zr_fn_extern) ---- */

/* A pattern or pigment function's value at the point at[0..2]. */
static double pigment_extern(const void *what, int channel,
                             const double *at) {
  const zr_pigment *pg = what;
  zr_vec3 p = zr_v3(at[0], at[1], at[2]);
  if (channel == TEXTURE_PATTERN)
    return zr__pigment_pattern_value(pg, p);
  zr_colour c = zr__pigment_eval(pg, p);
  switch (channel) {
  case 0: return c.r;
  case 1: return c.g;
  case 2: return c.b;
  case 3: return c.f;
  case 4: return c.t;
  case TEXTURE_HF: /* .hf: the manual's (Red + Green/255) * 0.996093,
                      which povray 3.7 follows (tests/legacy/pigment_hf.pov) */
    return (c.r + c.g / 255.0) * 0.996093;
  default: /* .gray: the manual's weights (2.3.3.3.7) */
    return 0.297 * c.r + 0.589 * c.g + 0.114 * c.b;
  }
}

/* Component `which` of a spline at the parameter at[0]. */
static double spline_extern(const void *what, int which, const double *at) {
  double v[5];
  zr__sdl_spline_eval(what, -1, at[0], v);
  return v[which];
}

/* ---- the compiler ---- */

/* The most sum/prod loops one body may nest (POV-Ray documents 56). */
#define MAX_COUNTERS 56

typedef struct compiler {
  zr_sdl_parser *p;
  int file;
  const zr_sdl_file *f;
  size_t pos;
  /* Names of the slots: parameters, then live sum/prod counters (a
     counter's limit sits in the slot after it, unnamed). */
  const char *names[ZR_FN_MAX_PARAMS + 2 * MAX_COUNTERS];
  int n_params, n_live, n_slots;
  insn *code;
  size_t n_code, cap_code;
  double *consts;
  size_t n_consts, cap_consts;
  const zr_fn **callees;
  size_t n_callees, cap_callees;
  /* Pigments and splines, with the routines that evaluate them. */
  zr_fn_extern *externs;
  size_t n_externs, cap_externs;
  const zr_transform **transforms;
  size_t n_transforms, cap_transforms;
  int texture_kind;
  int height, max_height; /* operand stack depth now and at most */
  int need_calls;         /* the deepest a call reaches above base */
  int depth;
  int nesting; /* of unary(), which every operand goes through */
  const char *unsupported;
  bool failed;
} compiler;

static const zr_sdl_token *tok(const compiler *c) {
  return &c->f->tokens[c->pos];
}

static zr_sdl_loc loc_of(const compiler *c, const zr_sdl_token *t) {
  zr_sdl_loc l = {c->file, t->line, t->column, t->length};
  return l;
}

static bool is_char(const zr_sdl_token *t, int ch) { return t->kind == ch; }

/* A reserved word's spelling (keyword or directive), else NULL. */
static const char *word_of(const zr_sdl_token *t) {
  if (t->kind < 256 || t->kind == T_NUMBER || t->kind == T_STRING ||
      t->kind == T_IDENTIFIER || t->kind == T_TRIANGLE_RUN ||
      t->kind == T_SMOOTH_TRIANGLE_RUN ||
      t->kind == T_SPHERE_RUN || t->kind == ZR_SDL_NUMBER_LIST)
    return NULL; /* runs of plain items point into the file's bytes */
  return t->v.str; /* NULL for "<=" and the like */
}

static bool is_word(const zr_sdl_token *t, const char *w) {
  const char *s = word_of(t);
  return s && strcmp(s, w) == 0;
}

/* Whether t is a directive (its spelling keeps the '#'). */
static bool is_directive(const zr_sdl_token *t) {
  const char *s = word_of(t);
  return s && s[0] == '#';
}

/* What messages call a token. */
static void describe(const zr_sdl_token *t, char *buf, size_t size) {
  if (t->kind == 0)
    snprintf(buf, size, "end of file");
  else if (t->kind == T_NUMBER)
    snprintf(buf, size, "number");
  else if (t->kind == T_STRING)
    snprintf(buf, size, "string");
  else if (t->kind == T_IDENTIFIER)
    snprintf(buf, size, "'%s'", t->v.str);
  else if (t->kind == T_TRIANGLE_RUN)
    snprintf(buf, size, "'triangle'");
  else if (t->kind == T_SMOOTH_TRIANGLE_RUN)
    snprintf(buf, size, "'smooth_triangle'");
  else if (t->kind == T_SPHERE_RUN)
    snprintf(buf, size, "'sphere'");
  else if (t->kind == ZR_SDL_NUMBER_LIST)
    snprintf(buf, size, "vectors");
  else if (t->kind >= 256 && t->v.str)
    snprintf(buf, size, "'%s'", t->v.str);
  else if (t->kind >= 256)
    snprintf(buf, size, "an operator");
  else
    snprintf(buf, size, "'%c'", t->kind);
}

static bool fail_at(compiler *c, const zr_sdl_token *t, zr_status s,
                    const char *fmt, ...) __attribute__((format(printf, 4, 5)));

static bool fail_at(compiler *c, const zr_sdl_token *t, zr_status s,
                    const char *fmt, ...) {
  char msg[256];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  zr_sdl_loc l = loc_of(c, t);
  zr__sdl_error(c->p, s, &l, "%s", msg);
  c->failed = true;
  return false;
}

/* "expected X in function, got Y" at the current token. */
static bool expected(compiler *c, const char *what) {
  char got[96];
  describe(tok(c), got, sizeof got);
  return fail_at(c, tok(c), ZR_ESYNTAX, "expected %s in function, got %s",
                 what, got);
}

static bool accept(compiler *c, int ch) {
  if (!is_char(tok(c), ch))
    return false;
  c->pos++;
  return true;
}

static bool want(compiler *c, int ch, const char *what) {
  return accept(c, ch) || expected(c, what);
}

static bool oom(compiler *c) {
  zr__sdl_error(c->p, ZR_ENOMEM, NULL, "out of memory");
  c->failed = true;
  return false;
}

static bool grow(compiler *c, void **items, size_t *cap, size_t n,
                 size_t size) {
  if (n < *cap)
    return true;
  size_t new_cap = *cap ? *cap * 2 : 32;
  void *m = realloc(*items, new_cap * size);
  if (!m)
    return oom(c);
  *items = m;
  *cap = new_cap;
  return true;
}

/* Appends an instruction that moves the operand stack by delta. */
static bool emit(compiler *c, op o, int32_t arg, int32_t n, int delta) {
  if (!grow(c, (void **)&c->code, &c->cap_code, c->n_code, sizeof *c->code))
    return false;
  insn i = {(uint8_t)o, arg, n};
  c->code[c->n_code++] = i;
  c->height += delta;
  if (c->height > c->max_height)
    c->max_height = c->height;
  return true;
}

static bool emit_const(compiler *c, double v) {
  if (!grow(c, (void **)&c->consts, &c->cap_consts, c->n_consts,
            sizeof *c->consts))
    return false;
  c->consts[c->n_consts] = v;
  return emit(c, OP_CONST, (int32_t)c->n_consts++, 0, 1);
}

/* Folds an operator whose operands are the last constants emitted, so
   "2*pi/360" costs one push at render time: the operator runs once now
   on the machine itself, its operands loaded from slots. */
static bool fold(compiler *c, op o, int arity, size_t first_pc) {
  double mem[8];
  insn prog[6];
  for (int k = 0; k < arity; k++) {
    mem[k] = c->consts[c->code[first_pc + (size_t)k].arg];
    insn load = {OP_LOAD, k, 0};
    prog[k] = load;
  }
  insn apply = {(uint8_t)o, 0, arity}, ret = {OP_RETURN, 0, 0};
  prog[arity] = apply;
  prog[arity + 1] = ret;
  zr_fn tmp;
  memset(&tmp, 0, sizeof tmp);
  tmp.n_slots = arity;
  tmp.n_code = (size_t)arity + 2;
  tmp.code = prog;
  double v = zr__fn_run(&tmp, mem);
  c->n_code = first_pc;
  c->n_consts -= (size_t)arity;
  c->height -= arity;
  return emit_const(c, v);
}

/* Emits an operator taking arity operands pushed from first_pc on. */
static bool emit_op(compiler *c, op o, int arity, size_t first_pc) {
  if (c->n_code - first_pc == (size_t)arity && arity <= 4) {
    bool all_const = true;
    for (int k = 0; k < arity; k++)
      all_const &= c->code[first_pc + (size_t)k].op == OP_CONST;
    /* Constants are appended in order, so the folded ones are the last
       'arity' of the pool and can be dropped. */
    if (all_const && c->code[first_pc].arg ==
                         (int32_t)(c->n_consts - (size_t)arity))
      return fold(c, o, arity, first_pc);
  }
  return emit(c, o, 0, arity, 1 - arity);
}

/* A binary operator whose right operand was compiled from right_pc on:
   folded when both are constants, fused with a lone load of the right
   operand, else the plain stack form. */
static bool emit_binary(compiler *c, op o, size_t first_pc, size_t right_pc) {
  if (c->n_code - first_pc == 2 && c->code[first_pc].op == OP_CONST &&
      c->code[right_pc].op == OP_CONST)
    return emit_op(c, o, 2, first_pc);
  if (c->n_code - right_pc == 1 && (o == OP_ADD || o == OP_SUB ||
                                    o == OP_MUL || o == OP_DIV)) {
    insn *last = &c->code[right_pc];
    int k = o - OP_ADD;
    if (last->op == OP_LOAD || last->op == OP_CONST) {
      last->op = (uint8_t)((last->op == OP_LOAD ? OP_ADD_S : OP_ADD_K) + k);
      c->height--; /* the load no longer pushes */
      return true;
    }
  }
  return emit(c, o, 0, 2, -1);
}

static bool expr(compiler *c);

/* ---- names ---- */

/* The slot a name denotes: counters newest first, then parameters. */
static int slot_of(const compiler *c, const char *name) {
  for (int i = c->n_live; i-- > 0;) {
    int s = c->n_params + 2 * i;
    if (strcmp(c->names[s], name) == 0)
      return s;
  }
  for (int i = 0; i < c->n_params; i++)
    if (strcmp(c->names[i], name) == 0)
      return i;
  return -1;
}

/* x and u, y and v are the same parameter (manual, "Declaring
   User-Defined Float Functions"). */
static const char *canonical(const char *name) {
  if (strcmp(name, "u") == 0)
    return "x";
  if (strcmp(name, "v") == 0)
    return "y";
  return name;
}

/* ---- built-in float functions ---- */

typedef struct builtin {
  const char *name;
  op o;
  int min_args, max_args; /* max 0: any number (min and max) */
} builtin;

static const builtin builtins[] = {
    {"abs", OP_ABS, 1, 1},         {"acos", OP_ACOS, 1, 1},
    {"acosh", OP_ACOSH, 1, 1},     {"asin", OP_ASIN, 1, 1},
    {"asinh", OP_ASINH, 1, 1},     {"atan", OP_ATAN, 1, 1},
    {"atan2", OP_ATAN2, 2, 2},     {"atanh", OP_ATANH, 1, 1},
    {"ceil", OP_CEIL, 1, 1},       {"cos", OP_COS, 1, 1},
    {"cosh", OP_COSH, 1, 1},       {"degrees", OP_DEGREES, 1, 1},
    {"exp", OP_EXP, 1, 1},         {"floor", OP_FLOOR, 1, 1},
    {"int", OP_INT, 1, 1},         {"ln", OP_LN, 1, 1},
    {"log", OP_LOG, 1, 1},         {"max", OP_MAX, 2, 0},
    {"min", OP_MIN, 2, 0},         {"mod", OP_MOD, 2, 2},
    {"pow", OP_POW, 2, 2},         {"radians", OP_RADIANS, 1, 1},
    {"select", OP_SELECT3, 3, 4},  {"sin", OP_SIN, 1, 1},
    {"sinh", OP_SINH, 1, 1},       {"sqrt", OP_SQRT, 1, 1},
    {"tan", OP_TAN, 1, 1},         {"tanh", OP_TANH, 1, 1},
};

static const builtin *builtin_find(const char *name) {
  for (size_t i = 0; i < sizeof builtins / sizeof builtins[0]; i++)
    if (strcmp(builtins[i].name, name) == 0)
      return &builtins[i];
  return NULL;
}

/* "(a, b, ...)": compiles the arguments, returns their count or -1. */
static int arguments(compiler *c) {
  if (!want(c, '(', "'('"))
    return -1;
  int n = 0;
  do {
    if (n == ZR_FN_MAX_PARAMS) {
      fail_at(c, tok(c), ZR_ELIMIT, "more than 56 arguments in function");
      return -1;
    }
    if (!expr(c))
      return -1;
    n++;
  } while (accept(c, ','));
  return want(c, ')', "',' or ')'") ? n : -1;
}

static bool call_builtin(compiler *c, const builtin *b,
                         const zr_sdl_token *name) {
  size_t first = c->n_code;
  int n = arguments(c);
  if (n < 0)
    return false;
  if (n < b->min_args || (b->max_args && n > b->max_args)) {
    char counts[64];
    if (b->max_args == 0)
      snprintf(counts, sizeof counts, "at least %d arguments", b->min_args);
    else if (b->min_args == b->max_args)
      snprintf(counts, sizeof counts, "%d argument%s", b->min_args,
               b->min_args == 1 ? "" : "s");
    else
      snprintf(counts, sizeof counts, "%d or %d arguments", b->min_args,
               b->max_args);
    return fail_at(c, name, ZR_ESYNTAX, "'%s' takes %s", b->name, counts);
  }
  if (b->max_args == 0) { /* min and max fold pairwise */
    for (int k = 1; k < n; k++)
      if (!emit(c, b->o, 0, 2, -1))
        return false;
    return true;
  }
  op o = b->o == OP_SELECT3 && n == 4 ? OP_SELECT4 : b->o;
  return emit_op(c, o, n, first);
}

/* Adds the cost of calling 'callee' with n arguments now on the stack. */
static bool note_call(compiler *c, const zr_fn *callee, int n,
                      const zr_sdl_token *name) {
  if (callee->depth + 1 > ZR_FN_MAX_DEPTH)
    return fail_at(c, name, ZR_ELIMIT,
                   "functions nested more than %d calls deep",
                   ZR_FN_MAX_DEPTH);
  if (callee->depth + 1 > c->depth)
    c->depth = callee->depth + 1;
  /* The callee's parameters start where its arguments are. */
  int reach = c->height - n + callee->need;
  if (reach > c->need_calls)
    c->need_calls = reach;
  if (callee->unsupported && !c->unsupported)
    c->unsupported = callee->unsupported;
  return true;
}

static bool call_function(compiler *c, const zr_fn *callee,
                          const zr_sdl_token *name) {
  int n = arguments(c);
  if (n < 0)
    return false;
  if (n != callee->n_params) {
    char msg[96];
    snprintf(msg, sizeof msg, "takes %d argument%s, not %d",
             callee->n_params, callee->n_params == 1 ? "" : "s", n);
    return fail_at(c, name, ZR_ESYNTAX, "function '%s' %s", name->v.str,
                   msg);
  }
  if (!note_call(c, callee, n, name))
    return false;
  if (!grow(c, (void **)&c->callees, &c->cap_callees, c->n_callees,
            sizeof *c->callees))
    return false;
  c->callees[c->n_callees] = callee;
  return emit(c, OP_CALL, (int32_t)c->n_callees++, n, 1 - n);
}

/* sum(i, b, n, a) and prod(...): a over i = b, b + 1, ... while i <= n. */
static bool sum_or_prod(compiler *c, bool is_sum) {
  const zr_sdl_token *kw = &c->f->tokens[c->pos - 1];
  if (!want(c, '(', "'('"))
    return false;
  const zr_sdl_token *var = tok(c);
  if (var->kind != T_IDENTIFIER && !word_of(var))
    return expected(c, "an iteration variable");
  c->pos++;
  if (c->n_live == MAX_COUNTERS)
    return fail_at(c, kw, ZR_ELIMIT,
                   "sum and prod nested more than 56 deep");
  int slot = c->n_params + 2 * c->n_live;
  if (!want(c, ',', "','") || !expr(c) ||
      !emit(c, OP_STORE, slot, 0, -1) || !want(c, ',', "','") ||
      !expr(c) || !emit(c, OP_STORE, slot + 1, 0, -1) ||
      !want(c, ',', "','"))
    return false;
  /* The counter is in scope only in the summed expression. */
  c->names[slot] = canonical(var->v.str);
  c->names[slot + 1] = "";
  c->n_live++;
  if (slot + 2 > c->n_slots)
    c->n_slots = slot + 2;
  if (!emit_const(c, is_sum ? 0 : 1))
    return false;
  size_t top = c->n_code;
  if (!emit(c, OP_JGT, slot, 0, 0))
    return false;
  if (!expr(c) || !emit(c, is_sum ? OP_ADD : OP_MUL, 0, 2, -1) ||
      !emit(c, OP_INC, slot, 0, 0) ||
      !emit(c, OP_JUMP, 0, (int32_t)top, 0))
    return false;
  c->code[top].n = (int32_t)c->n_code;
  c->n_live--;
  return want(c, ')', "')'");
}

/* Adds a pigment or spline and its routine to the body's pool; its
   index, or -1. */
static int add_extern(compiler *c,
                      double (*eval)(const void *, int, const double *),
                      const void *what) {
  if (!grow(c, (void **)&c->externs, &c->cap_externs, c->n_externs,
            sizeof *c->externs))
    return -1;
  c->externs[c->n_externs].eval = eval;
  c->externs[c->n_externs].what = what;
  return (int)c->n_externs++;
}

/* Adds a pigment to the body's pool; its index, or -1. */
static int add_pigment(compiler *c, const zr_pigment *pg) {
  return add_extern(c, pigment_extern, pg);
}

/* A call's arguments (want of them) on the stack, then '.' and one of
   items[]: its index, the component's token consumed; -1 after an error.
   kind names the function ("a pigment function") and part what follows
   the '.' ("a colour component") in the messages. */
static int call_component(compiler *c, const zr_sdl_token *name, int want,
                          const char *kind, const char *part,
                          const char *const items[], size_t n_items) {
  int n = arguments(c);
  if (n < 0)
    return -1;
  if (n != want) {
    fail_at(c, name, ZR_ESYNTAX, "function '%s' takes %d argument%s, not %d",
            name->v.str, want, want == 1 ? "" : "s", n);
    return -1;
  }
  if (!accept(c, '.')) {
    char what[96];
    snprintf(what, sizeof what, "'.' and %s after %s", part, kind);
    expected(c, what);
    return -1;
  }
  for (size_t k = 0; k < n_items; k++)
    if (is_word(tok(c), items[k]) ||
        (tok(c)->kind == T_IDENTIFIER && strcmp(tok(c)->v.str,
                                                items[k]) == 0)) {
      c->pos++;
      return (int)k;
    }
  char what[64];
  snprintf(what, sizeof what, "%s after '.'", part);
  expected(c, what);
  return -1;
}

/* F(x, y, z).channel for a pigment function F ("Function Pattern":
   "you have to specify which component of the color vector should be
   used"): the call becomes one OP_TEXTURE on this body's copy of F's
   pigment. */
static bool call_pigment(compiler *c, const zr_fn *callee,
                         const zr_sdl_token *name) {
  static const char *const items[] = {"x", "y", "z", "t", "u", "v",
                                      "red", "green", "blue", "filter",
                                      "transmit", "gray", "grey", "hf"};
  static const int channel[] = {0, 1, 2, 3, 0, 1, 0, 1, 2, 3, 4,
                                TEXTURE_GREY, TEXTURE_GREY, TEXTURE_HF};
  int k = call_component(c, name, 3, "a pigment function",
                         "a colour component", items,
                         sizeof items / sizeof items[0]);
  if (k < 0)
    return false;
  int at = add_pigment(c, callee->externs[0].what);
  return at >= 0 && emit(c, OP_TEXTURE, at, channel[k], -2);
}

/* Adds a spline to the body's pool; its index, or -1. */
static int add_spline(compiler *c, const zr_sdl_spline *s) {
  return add_extern(c, spline_extern, s);
}

/* Adds a transform to the body's pool; its index, or -1. */
static int add_transform(compiler *c, const zr_transform *t) {
  if (!grow(c, (void **)&c->transforms, &c->cap_transforms,
            c->n_transforms, sizeof *c->transforms))
    return -1;
  c->transforms[c->n_transforms] = t;
  return (int)c->n_transforms++;
}

/* F(x, y, z).component for a transform function F (its value is a
   vector, "Function"): one OP_XFORM on this body's copy of F's
   transform. */
static bool call_transform(compiler *c, const zr_fn *callee,
                           const zr_sdl_token *name) {
  static const char *const items[] = {"x", "y", "z", "u", "v",
                                      "red", "green", "blue"};
  static const int channel[] = {0, 1, 2, 0, 1, 0, 1, 2};
  int k = call_component(c, name, 3, "a transform function",
                         "a vector component", items,
                         sizeof items / sizeof items[0]);
  if (k < 0)
    return false;
  int at = add_transform(c, callee->transforms[0]);
  return at >= 0 && emit(c, OP_XFORM, at, channel[k], -2);
}

/* F(t).component for a spline function F ("Spline": a function of a
   spline returns a vector): one OP_SPLINE on this body's copy of F's
   spline. */
static bool call_spline(compiler *c, const zr_fn *callee,
                        const zr_sdl_token *name) {
  static const char *const items[] = {"x", "y", "z", "t", "u", "v",
                                      "red", "green", "blue", "filter",
                                      "transmit"};
  static const int channel[] = {0, 1, 2, 3, 0, 1, 0, 1, 2, 3, 4};
  int k = call_component(c, name, 1, "a spline function",
                         "a vector component", items,
                         sizeof items / sizeof items[0]);
  if (k < 0)
    return false;
  int at = add_spline(c, callee->externs[0].what);
  return at >= 0 && emit(c, OP_SPLINE, at, channel[k], 0);
}

/* A declared identifier in a body. */
static bool declared(compiler *c, const zr_sdl_token *name) {
  const zr_sdl_symbol *s = zr__sdl_lookup(c->p, name->v.str, NULL);
  if (!s)
    return fail_at(c, name, ZR_EUNDEFINED,
                   "undefined identifier '%s' in function", name->v.str);
  const zr_sdl_value *v = &s->value;
  if (v->kind == ZR_SDL_FUNCTION &&
      ((const zr_fn *)v->ptr)->texture_kind == FN_PIGMENT)
    return call_pigment(c, v->ptr, name);
  if (v->kind == ZR_SDL_FUNCTION &&
      ((const zr_fn *)v->ptr)->texture_kind == FN_SPLINE)
    return call_spline(c, v->ptr, name);
  if (v->kind == ZR_SDL_FUNCTION &&
      ((const zr_fn *)v->ptr)->texture_kind == FN_TRANSFORM)
    return call_transform(c, v->ptr, name);
  if (v->kind == ZR_SDL_FUNCTION)
    return call_function(c, v->ptr, name);
  if (v->kind == ZR_SDL_FLOAT)
    return emit_const(c, v->num.v[0]);
  if ((v->kind == ZR_SDL_VECTOR || v->kind == ZR_SDL_COLOUR) &&
      is_char(tok(c), '.')) {
    /* V.x and the like: a float fixed at definition time. */
    static const char *const items[] = {"x", "y", "z", "t", "u", "v",
                                        "red", "green", "blue", "filter",
                                        "transmit"};
    static const int index[] = {0, 1, 2, 3, 0, 1, 0, 1, 2, 3, 4};
    c->pos++;
    for (size_t k = 0; k < sizeof items / sizeof items[0]; k++) {
      if (is_word(tok(c), items[k]) && index[k] < v->num.dim) {
        c->pos++;
        return emit_const(c, v->num.v[index[k]]);
      }
    }
    return expected(c, "a component after '.'");
  }
  return fail_at(c, name, ZR_ESYNTAX,
                 "'%s' is not a float or a function, so it cannot be used "
                 "in a function", name->v.str);
}

static bool constant_word(compiler *c, const char *w) {
  if (strcmp(w, "pi") == 0)
    return emit_const(c, M_PI);
  if (strcmp(w, "true") == 0 || strcmp(w, "yes") == 0 ||
      strcmp(w, "on") == 0)
    return emit_const(c, 1);
  if (strcmp(w, "false") == 0 || strcmp(w, "no") == 0 ||
      strcmp(w, "off") == 0)
    return emit_const(c, 0);
  return false;
}

static bool primary(compiler *c) {
  const zr_sdl_token *t = tok(c);
  if (t->kind == T_NUMBER) {
    c->pos++;
    return emit_const(c, t->v.num);
  }
  if (accept(c, '('))
    return expr(c) && want(c, ')', "')'");
  if (t->kind == T_IDENTIFIER) {
    c->pos++;
    int s = slot_of(c, t->v.str);
    return s >= 0 ? emit(c, OP_LOAD, s, 0, 1) : declared(c, t);
  }
  const char *w = word_of(t);
  if (w && !is_directive(t)) {
    c->pos++;
    int s = slot_of(c, canonical(w));
    if (s >= 0)
      return emit(c, OP_LOAD, s, 0, 1);
    const builtin *b = builtin_find(w);
    if (b)
      return call_builtin(c, b, t);
    if (strcmp(w, "sum") == 0 || strcmp(w, "prod") == 0)
      return sum_or_prod(c, w[0] == 's');
    if (constant_word(c, w))
      return true;
    /* clock, image_width ... are constants while the scene is parsed,
       so a function may use them as POV-Ray's do (trace2.pov). */
    if (t->kind == T_CONSTANT)
      return emit_const(c, zr__sdl_constant(c->p, w));
    if (strcmp(w, "x") == 0 || strcmp(w, "y") == 0 || strcmp(w, "z") == 0 ||
        strcmp(w, "u") == 0 || strcmp(w, "v") == 0)
      return fail_at(c, t, ZR_EUNDEFINED,
                     "'%s' is not a parameter of this function", w);
    if (strcmp(w, "internal") == 0)
      return fail_at(c, t, ZR_ESYNTAX,
                     "'internal' must be the whole body of a function");
    return fail_at(c, t, ZR_ESYNTAX, "'%s' cannot be used in a function", w);
  }
  return expected(c, "a float expression");
}

static bool unary_inner(compiler *c);

static bool unary(compiler *c) {
  if (c->nesting == ZR_FN_MAX_NESTING)
    return fail_at(c, tok(c), ZR_ELIMIT,
                   "the function nests more than %d levels deep",
                   ZR_FN_MAX_NESTING);
  c->nesting++;
  bool ok = unary_inner(c);
  c->nesting--;
  return ok;
}

static bool unary_inner(compiler *c) {
  if (accept(c, '-')) {
    size_t first = c->n_code;
    return unary(c) && emit_op(c, OP_NEG, 1, first);
  }
  if (accept(c, '+'))
    return unary(c);
  if (accept(c, '!')) {
    size_t first = c->n_code;
    return unary(c) && emit_op(c, OP_NOT, 1, first);
  }
  return primary(c);
}

/* Left-associative levels: each lists its operators and what binds
   tighter. */
typedef bool (*level_fn)(compiler *c);

static bool binary_level(compiler *c, level_fn next, const int *chars,
                         const op *ops, int n_ops) {
  size_t first = c->n_code;
  if (!next(c))
    return false;
  for (;;) {
    int k = 0;
    while (k < n_ops && !is_char(tok(c), chars[k]))
      k++;
    if (k == n_ops)
      return true;
    c->pos++;
    size_t right = c->n_code;
    if (!next(c) || !emit_binary(c, ops[k], first, right))
      return false;
  }
}

static bool factor(compiler *c) {
  static const int chars[] = {'*', '/'};
  static const op ops[] = {OP_MUL, OP_DIV};
  return binary_level(c, unary, chars, ops, 2);
}

static bool term(compiler *c) {
  static const int chars[] = {'+', '-'};
  static const op ops[] = {OP_ADD, OP_SUB};
  return binary_level(c, factor, chars, ops, 2);
}

/* REL_TERM: TERM [REL_OPERATOR TERM], not chained (the manual's grammar).
   The scanner makes "<=", ">=" and "!=" single tokens. */
static bool relation(compiler *c) {
  size_t first = c->n_code;
  if (!term(c))
    return false;
  int kind = tok(c)->kind;
  op o;
  switch (kind) {
  case '<': o = OP_LT; break;
  case T_LE: o = OP_LE; break;
  case '=': o = OP_EQ; break;
  case T_NE: o = OP_NE; break;
  case T_GE: o = OP_GE; break;
  case '>': o = OP_GT; break;
  default: return true;
  }
  c->pos++;
  return term(c) && emit_op(c, o, 2, first);
}

static bool conjunction(compiler *c) {
  static const int chars[] = {'&'};
  static const op ops[] = {OP_AND};
  return binary_level(c, relation, chars, ops, 1);
}

static bool expr(compiler *c) {
  static const int chars[] = {'|'};
  static const op ops[] = {OP_OR};
  if (!binary_level(c, conjunction, chars, ops, 1))
    return false;
  const zr_sdl_token *t = tok(c);
  if (is_char(t, '?'))
    return fail_at(c, t, ZR_EUNSUPPORTED,
                   "'?:' cannot be used in a function (POV-Ray 3.7 does not "
                   "allow it either: use select())");
  return true;
}

/* ---- definitions ---- */

/* "(a, b, ...)" after 'function': the parameter names. */
static bool parameter_list(compiler *c) {
  do {
    const zr_sdl_token *t = tok(c);
    const char *name = t->kind == T_IDENTIFIER ? t->v.str : NULL;
    const char *w = word_of(t);
    if (w && (strcmp(w, "x") == 0 || strcmp(w, "y") == 0 ||
              strcmp(w, "z") == 0 || strcmp(w, "u") == 0 ||
              strcmp(w, "v") == 0))
      name = canonical(w);
    if (!name)
      return expected(c, "a parameter name");
    if (slot_of(c, name) >= 0)
      return fail_at(c, t, ZR_ESYNTAX,
                     "parameter '%s' is listed twice", name);
    if (c->n_params == ZR_FN_MAX_PARAMS)
      return fail_at(c, t, ZR_ELIMIT,
                     "a function takes at most 56 parameters");
    c->names[c->n_params++] = name;
    c->pos++;
  } while (accept(c, ','));
  return want(c, ')', "',' or ')'");
}

/* A block the grammar reads for the compiler (a nested parse from
   start_token, ending right after its '}'): the compiler goes on after
   it, in the same file or macro, or fails naming what the block was. */
static bool nested_block(compiler *c, int start_token, const char *what) {
  zr_sdl_parser *p = c->p;
  size_t frames = p->n_frames;
  p->frames[frames - 1].pos = c->pos;
  if (zr__sdl_parse_nested(p, start_token) != ZR_OK) {
    c->failed = true;
    return false;
  }
  c->f = &p->files[c->file];
  if (p->n_frames != frames || p->frames[frames - 1].file != c->file) {
    zr_sdl_loc at = zr__sdl_peek_loc(p, 0);
    zr__sdl_error(p, ZR_ESYNTAX, &at, "a function's %s must end in the "
                  "file or macro where it begins", what);
    c->failed = true;
    return false;
  }
  c->pos = p->frames[frames - 1].pos;
  return true;
}

/* The body of a function of a point: x, y and z loaded, the
   parameters a pattern, pigment or transform takes. */
static bool load_xyz(compiler *c) {
  c->n_params = 3;
  c->n_slots = 3;
  for (int k = 0; k < 3; k++)
    if (!emit(c, OP_LOAD, k, 0, 1))
      return false;
  return true;
}

/*
 * pattern { PATTERN ... } and pigment { ... } bodies: read by the
 * grammar itself (a nested parse from the 'pattern' or 'pigment' token,
 * which ends right after its '}' without looking further), then the
 * body becomes x, y, z and one OP_TEXTURE.  A pigment function called
 * alone (not as F(x,y,z).red) gives its pigment's grey.
 */
static bool texture_body(compiler *c, bool pigment) {
  if (!nested_block(c, T_START_FN_TEXTURE, pigment ? "pigment" : "pattern"))
    return false;
  int at = add_pigment(c, c->p->nested_rvalue.ptr);
  if (at < 0)
    return false;
  c->texture_kind = pigment ? FN_PIGMENT : FN_PATTERN;
  if (!load_xyz(c))
    return false;
  return emit(c, OP_TEXTURE, at, pigment ? TEXTURE_GREY : TEXTURE_PATTERN,
              -2);
}

/* A spline function's body once its spline is known: t, then one
   OP_SPLINE (component 0 when a body calls it alone; other bodies use
   F(t).y and the like, and a call in a scene gives the whole vector). */
static bool spline_code(compiler *c, const zr_sdl_spline *s) {
  int at = add_spline(c, s);
  if (at < 0)
    return false;
  c->names[0] = "t";
  c->n_params = 1;
  c->n_slots = 1;
  c->texture_kind = FN_SPLINE;
  return emit(c, OP_LOAD, 0, 0, 1) && emit(c, OP_SPLINE, at, 0, 0);
}

/* function { spline { ... } }: the grammar reads the spline. */
static bool spline_body(compiler *c) {
  return nested_block(c, T_START_FN_SPLINE, "spline") &&
         spline_code(c, c->p->nested_rvalue.ptr);
}

/* function { S } for a declared spline S, the whole body. */
static const zr_sdl_spline *spline_named(compiler *c) {
  const zr_sdl_token *name = tok(c);
  if (name->kind != T_IDENTIFIER || c->pos + 1 >= c->f->n_tokens ||
      !is_char(&c->f->tokens[c->pos + 1], '}'))
    return NULL;
  const zr_sdl_symbol *s = zr__sdl_lookup(c->p, name->v.str, NULL);
  return s && s->value.kind == ZR_SDL_SPLINE ? s->value.ptr : NULL;
}

/*
 * function { transform { ... } } ("Function": a transform function takes
 * a point and gives it transformed, a vector): the grammar reads the
 * transform (a nested parse from the 'transform' token, ending right
 * after its '}' or identifier), then the body is x, y, z and one
 * OP_XFORM, whose x a body calling it alone gets.
 */
static bool transform_body(compiler *c) {
  if (!nested_block(c, T_START_FN_TRANSFORM, "transform"))
    return false;
  int at = add_transform(c, c->p->nested_rvalue.ptr);
  if (at < 0)
    return false;
  c->texture_kind = FN_TRANSFORM;
  return load_xyz(c) && emit(c, OP_XFORM, at, 0, -2);
}

/* internal(n) as a whole body: the parameters are the routine's. */
static bool internal_body(compiler *c, bool have_params) {
  const zr_sdl_token *at = tok(c);
  c->pos++;
  if (!want(c, '(', "'('"))
    return false;
  const zr_sdl_token *num = tok(c);
  if (num->kind != T_NUMBER)
    return expected(c, "a number");
  c->pos++;
  if (!want(c, ')', "')'"))
    return false;
  /* A number far outside int's range must not reach the conversion
     (undefined behaviour; the fuzzer found internal(6.8e96)). */
  double number = num->v.num;
  const zr_fn_internal *in =
      number >= 0 && number <= 1000 ? zr__fn_internal_find((int)number)
                                    : NULL;
  if (!in || number != in->number) {
    char n[32];
    snprintf(n, sizeof n, "%g", num->v.num);
    return fail_at(c, num, ZR_ESCENE,
                   "there is no internal function %s", n);
  }
  if (have_params && c->n_params != in->params) {
    char n[64];
    snprintf(n, sizeof n, "%d (%s) takes %d", in->number, in->name,
             in->params);
    return fail_at(c, at, ZR_ESYNTAX, "internal function %s parameters", n);
  }
  if (!in->implemented) {
    char reason[64];
    snprintf(reason, sizeof reason, "internal function %d (%s)", in->number,
             in->name);
    c->unsupported = zr__arena_strdup(&c->p->scene->arena, reason);
    if (!c->unsupported)
      return oom(c);
  }
  c->n_params = in->params;
  for (int k = 0; k < in->params; k++)
    if (!emit(c, OP_LOAD, k, 0, 1))
      return false;
  return emit(c, OP_INTERNAL, in->number, in->params, 1 - in->params);
}

static const zr_fn *finish(compiler *c) {
  zr_sdl_parser *p = c->p;
  zr_fn *fn = zr__sdl_alloc(p, sizeof *fn);
  insn *code = zr__sdl_alloc(p, (c->n_code ? c->n_code : 1) * sizeof *code);
  double *consts =
      zr__sdl_alloc(p, (c->n_consts ? c->n_consts : 1) * sizeof *consts);
  const zr_fn **callees = zr__sdl_alloc(
      p, (c->n_callees ? c->n_callees : 1) * sizeof *callees);
  zr_fn_extern *externs = zr__sdl_alloc(
      p, (c->n_externs ? c->n_externs : 1) * sizeof *externs);
  const zr_transform **transforms = zr__sdl_alloc(
      p, (c->n_transforms ? c->n_transforms : 1) * sizeof *transforms);
  if (!fn || !code || !consts || !callees || !externs ||
      !transforms)
    return NULL;
  if (c->n_transforms)
    memcpy(transforms, c->transforms,
           c->n_transforms * sizeof *transforms);
  fn->transforms = (const zr_transform *const *)transforms;
  if (c->n_externs)
    memcpy(externs, c->externs, c->n_externs * sizeof *externs);
  fn->externs = externs;
  fn->texture_kind = c->texture_kind;
  /* An empty pool was never allocated, and memcpy from NULL is
     undefined even for no bytes. */
  if (c->n_code)
    memcpy(code, c->code, c->n_code * sizeof *code);
  if (c->n_consts)
    memcpy(consts, c->consts, c->n_consts * sizeof *consts);
  if (c->n_callees)
    memcpy(callees, c->callees, c->n_callees * sizeof *callees);
  if (c->n_slots < c->n_params)
    c->n_slots = c->n_params;
  fn->n_params = c->n_params;
  fn->n_slots = c->n_slots;
  fn->need = c->n_slots + c->max_height;
  if (c->n_slots + c->need_calls > fn->need)
    fn->need = c->n_slots + c->need_calls;
  fn->depth = c->depth;
  fn->n_code = c->n_code;
  fn->code = code;
  fn->consts = consts;
  fn->callees = (const zr_fn *const *)callees;
  fn->unsupported = c->unsupported;
  return fn;
}

static bool definition(compiler *c, const zr_sdl_loc *at) {
  bool have_params = accept(c, '(');
  if (have_params && !parameter_list(c))
    return false;
  if (!want(c, '{', have_params ? "'{'" : "'(' or '{'"))
    return false;
  if (!have_params) {
    static const char *const xyz[] = {"x", "y", "z"};
    for (int k = 0; k < 3; k++)
      c->names[c->n_params++] = xyz[k];
  }
  c->n_slots = c->n_params;
  const char *w = word_of(tok(c));
  if (w && strcmp(w, "internal") == 0) {
    if (!internal_body(c, have_params))
      return false;
  } else if (w && !have_params &&
             (strcmp(w, "pattern") == 0 || strcmp(w, "pigment") == 0)) {
    if (!texture_body(c, w[1] == 'i'))
      return false;
  } else if (w && !have_params && strcmp(w, "spline") == 0) {
    if (!spline_body(c))
      return false;
  } else if (!have_params && spline_named(c)) {
    const zr_sdl_spline *s = spline_named(c);
    c->pos++;
    if (!spline_code(c, s))
      return false;
  } else if (w && !have_params && strcmp(w, "transform") == 0) {
    if (!transform_body(c))
      return false;
  } else if (!expr(c)) {
    return false;
  }
  if (!want(c, '}', "an operator or '}'") || !emit(c, OP_RETURN, 0, 0, 0))
    return false;
  if (c->n_slots + c->max_height > ZR_FN_MAX_STACK ||
      c->n_slots + c->need_calls > ZR_FN_MAX_STACK) {
    zr__sdl_error(c->p, ZR_ELIMIT, at,
                  "the function needs more than %d values to evaluate",
                  ZR_FN_MAX_STACK);
    return false;
  }
  return true;
}

const zr_fn *zr__sdl_function_parse(zr_sdl_parser *p, const zr_sdl_loc *at) {
  zr_sdl_frame *fr = &p->frames[p->n_frames - 1];
  compiler c;
  memset(&c, 0, sizeof c);
  c.p = p;
  c.file = fr->file;
  c.f = &p->files[fr->file];
  c.pos = fr->pos;
  c.depth = 1;
  const zr_fn *fn = NULL;
  if (definition(&c, at))
    fn = finish(&c);
  free(c.code);
  free(c.consts);
  free(c.callees);
  free(c.externs);
  free(c.transforms);
  /* A pattern or pigment body ran a nested parse, which may have moved
     the frames (a macro called in it): take the frame anew. */
  fr = &p->frames[p->n_frames - 1];
  fr->pos = c.pos;
  /* The engine ends a #declare's value by watching the tokens it hands
     out (directive.c, autoend_due); the body went past it, and ended
     with a '}' at the depth where 'function' stood. */
  if (fn && p->autoend.token)
    p->autoend.operand = true;
  return fn;
}

/* The identifier at loc, from its source line, for messages. */
static void name_at(zr_sdl_parser *p, const zr_sdl_loc *loc, char *buf,
                    size_t size) {
  size_t len = 0;
  const char *line = NULL;
  if (loc->file >= 0 && (size_t)loc->file < p->n_files)
    line = zr__sdl_file_line(&p->files[loc->file], loc->line, &len);
  size_t col = loc->column > 0 ? (size_t)loc->column - 1 : 0;
  size_t n = loc->length > 0 ? (size_t)loc->length : 0;
  if (!line || col + n > len || n + 1 > size)
    n = 0;
  memcpy(buf, line ? line + col : "", n);
  buf[n] = '\0';
}

bool zr__sdl_function_call(zr_sdl_parser *p, const zr_fn *fn,
                           const zr_sdl_list *args,
                           const zr_sdl_loc *name_loc, const zr_sdl_loc *loc,
                           zr_sdl_expr *out) {
  char name[128];
  name_at(p, name_loc, name, sizeof name);
  if (fn->unsupported) {
    zr__sdl_error(p, ZR_EUNSUPPORTED, name_loc,
                  "function '%s' uses %s, which is not supported yet", name,
                  fn->unsupported);
    return false;
  }
  if (args->n != fn->n_params) {
    zr__sdl_error(p, ZR_ESYNTAX, loc, "function '%s' takes %d argument%s, "
                  "not %d", name, fn->n_params,
                  fn->n_params == 1 ? "" : "s", args->n);
    return false;
  }
  if (fn->texture_kind == FN_SPLINE) {
    /* A spline function gives the spline's vector there. */
    *out = zr__sdl_spline_value(fn->externs[0].what, -1, args->v[0]);
    return true;
  }
  if (fn->texture_kind == FN_TRANSFORM) {
    /* A transform function gives the point transformed. */
    zr_vec3 q = zr__xform_point(fn->transforms[0]->m,
                                zr_v3(args->v[0], args->v[1], args->v[2]));
    *out = zr__sdl_vec(q.x, q.y, q.z);
    return true;
  }
  if (fn->texture_kind == FN_PIGMENT) {
    /* A pigment function gives the pigment's colour there. */
    zr_vec3 at = zr_v3(args->v[0], args->v[1], args->v[2]);
    *out = zr__sdl_colour_expr(zr__pigment_eval(fn->externs[0].what, at));
    return true;
  }
  *out = zr__sdl_float(zr__fn_eval(fn, args->v));
  return true;
}
