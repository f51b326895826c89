/*
 * code.h - the bytecode of a compiled user function, shared by the
 * compiler (lib/sdl/function.c) and the machine that runs it
 * (lib/fn/vm.c), and the internal functions of functions.inc
 * (lib/fn/internal.c).  Nothing else looks inside a zr_fn.
 */
#ifndef ZR_FN_CODE_H
#define ZR_FN_CODE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "core/transform.h"
#include "fn/fn.h"

/*
 * Something a body reaches outside the machine, a pigment or a spline
 * (lib/scene, lib/sdl): the compiler, which knows both, stores the thing
 * and the routine that evaluates it, so the machine needs neither.
 * eval(what, which, at) gives value `which` (a colour channel, a
 * spline component, -1 a pattern's value) at the point at[0..2] (a
 * pigment) or at the parameter at[0] (a spline).
 */
typedef struct zr_fn_extern {
  double (*eval)(const void *what, int which, const double *at);
  const void *what;
} zr_fn_extern;

/*
 * The instructions.  CONST pushes consts[arg], LOAD pushes slot[arg],
 * STORE pops into slot[arg], INC adds 1 to slot[arg], JGT jumps to n
 * when slot[arg] > slot[arg + 1], JUMP jumps to n.  The arithmetic takes
 * its operands from the stack; the _S and _K forms take the right one
 * from slot[arg] or consts[arg] instead (most right operands are one,
 * and one dispatch instead of two is most of the speed).  CALL runs
 * callees[arg] and INTERNAL internal function arg on the top n values;
 * TEXTURE evaluates externs[arg] (a pigment) at the top three values,
 * giving its pattern's value (n -1) or colour channel n (5: its grey);
 * SPLINE evaluates externs[arg] (a spline) at the top value, giving
 * component n; XFORM moves the top three values by transforms[arg]
 * and gives component n;
 * RETURN ends every program with the top value.
 */
#define OPS(X)                                                             \
  X(OP_CONST) X(OP_LOAD) X(OP_STORE) X(OP_INC) X(OP_JGT) X(OP_JUMP)        \
  X(OP_ADD) X(OP_SUB) X(OP_MUL) X(OP_DIV)                                  \
  X(OP_ADD_S) X(OP_SUB_S) X(OP_MUL_S) X(OP_DIV_S)                          \
  X(OP_ADD_K) X(OP_SUB_K) X(OP_MUL_K) X(OP_DIV_K)                          \
  X(OP_LT) X(OP_LE) X(OP_EQ) X(OP_NE) X(OP_GE) X(OP_GT) X(OP_AND) X(OP_OR) \
  X(OP_NEG) X(OP_NOT)                                                      \
  X(OP_SIN) X(OP_COS) X(OP_TAN) X(OP_ASIN) X(OP_ACOS) X(OP_ATAN)           \
  X(OP_SINH) X(OP_COSH) X(OP_TANH) X(OP_ASINH) X(OP_ACOSH) X(OP_ATANH)     \
  X(OP_EXP) X(OP_LN) X(OP_LOG) X(OP_SQRT) X(OP_ABS) X(OP_FLOOR)            \
  X(OP_CEIL) X(OP_INT) X(OP_DEGREES) X(OP_RADIANS)                         \
  X(OP_ATAN2) X(OP_POW) X(OP_MOD) X(OP_MIN) X(OP_MAX)                      \
  X(OP_SELECT3) X(OP_SELECT4) X(OP_CALL) X(OP_INTERNAL) X(OP_TEXTURE)    \
  X(OP_SPLINE) X(OP_XFORM) X(OP_RETURN)

#define AS_ENUM(o) o,
typedef enum op { OPS(AS_ENUM) } op;
#undef AS_ENUM

typedef struct insn {
  uint8_t op;
  int32_t arg;
  int32_t n;
} insn;

struct zr_fn {
  int n_params;
  int n_slots;  /* parameters, then sum/prod counters and limits */
  int need;     /* doubles an evaluation uses, callees included */
  int depth;    /* 1 + the deepest chain of calls below */
  size_t n_code;
  const insn *code;
  const double *consts;
  const zr_fn *const *callees;
  const char *unsupported; /* NULL, or what is missing (see header) */
  /* pattern { }, pigment { } and spline { } bodies, and calls of
     pigment and spline functions: what OP_TEXTURE and OP_SPLINE
     evaluate. */
  const zr_fn_extern *externs;
  int texture_kind; /* 0 plain or FN_PATTERN ... FN_TRANSFORM */
  /* transform { } bodies and calls of transform functions: what
     OP_XFORM applies. */
  const zr_transform *const *transforms;
};

#define FN_PATTERN 1
#define FN_PIGMENT 2
#define FN_SPLINE 3
#define FN_TRANSFORM 4
/* The channel OP_TEXTURE gives for a pattern's value, and the grey. */
#define TEXTURE_PATTERN (-1)
#define TEXTURE_GREY 5
#define TEXTURE_HF 6

/* Runs f with its parameters (and room for the rest of f->need) at
   base: the compiler folds constants with it (lib/fn/vm.c). */
double zr__fn_run(const zr_fn *f, double *base);

/* An internal function of functions.inc: its number, name and
   parameter count (x, y, z and the extra ones functions.inc lists). */
typedef struct zr_fn_internal {
  int number;
  const char *name;
  int params;
  bool implemented;
} zr_fn_internal;

/* The internal function of that number, or NULL (lib/fn/internal.c). */
const zr_fn_internal *zr__fn_internal_find(int number);
/* Internal function `number` (implemented) at a[0 .. params). */
double zr__fn_internal_eval(int number, const double *a);

#endif /* ZR_FN_CODE_H */
