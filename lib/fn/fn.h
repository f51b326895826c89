/*
 * fn.h - user-defined functions at run time (reference manual 3.3.1.8,
 * "Function"): a body compiled once (by lib/sdl/function.c, the
 * compiler, which stays with the parser) into bytecode for a small stack
 * machine over doubles (lib/fn/vm.c), evaluated without allocating, from
 * any number of threads at once (patterns and isosurfaces call it per
 * sample).
 *
 * lib/fn sits below the scene model and the tracer, which both call it,
 * and calls nothing above lib/core: what a body reaches outside the
 * machine (a pigment, a spline) it reaches through the callbacks the
 * compiler stored in it (lib/fn/code.h).
 */
#ifndef ZR_FN_FN_H
#define ZR_FN_FN_H

#include <stdbool.h>

/* POV-Ray's documented limits ("Declaring User-Defined Float
   Functions"): at most 56 parameters, calls nested at most 1024 deep. */
#define ZR_FN_MAX_PARAMS 56
#define ZR_FN_MAX_DEPTH 1024
/* The doubles one evaluation may use (parameters, sum/prod counters and
   the operand stacks of every active call): 32 KiB on the caller's C
   stack, so evaluating never allocates.  A chain of 1024 calls needs
   about 1030. */
#define ZR_FN_MAX_STACK 4096
/* How deeply a body may nest parentheses, signs and calls: the compiler
   recurses on them, so this bounds the C stack it uses. */
#define ZR_FN_MAX_NESTING 256

/* A compiled function: immutable, in the scene's arena. */
typedef struct zr_fn zr_fn;

/* How many arguments fn takes. */
int zr__fn_params(const zr_fn *fn);
/* NULL when fn can be evaluated; otherwise what it needs that zRcube
   does not have yet ("internal function 76 (f_noise3d)", "pattern
   functions"), for the caller's message. */
const char *zr__fn_unsupported(const zr_fn *fn);
/* fn at args[0 .. zr__fn_params(fn)); fn must be supported.  Never
   allocates; safe from any number of threads. */
double zr__fn_eval(const zr_fn *fn, const double *args);

#endif /* ZR_FN_FN_H */
