/*
 * function.h - user-defined functions (reference manual 3.3.1.8,
 * "Function"): `function [(params)] { expression }` compiled once into
 * bytecode for a small stack machine over doubles, and evaluated without
 * allocating, from any number of threads at once (patterns and
 * isosurfaces call it per sample).
 */
#ifndef ZR_SDL_FUNCTION_H
#define ZR_SDL_FUNCTION_H

#include <stdbool.h>

#include "sdl/sdl.h"

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

/*
 * Compiles the function whose 'function' keyword (at 'at') the grammar
 * has just shifted: reads the rest, "(params) { ... }", from the token
 * array of the file being read and leaves the engine after its '}'.
 * Returns NULL after reporting an error.
 */
const zr_fn *zr__sdl_function_parse(zr_sdl_parser *p, const zr_sdl_loc *at);

/* F(args) in a float expression: checks the count and evaluates.
   name_loc is the identifier's place (its text names F in messages). */
bool zr__sdl_function_call(zr_sdl_parser *p, const zr_fn *fn,
                           const zr_sdl_list *args,
                           const zr_sdl_loc *name_loc, const zr_sdl_loc *loc,
                           zr_sdl_expr *out);

/* How many arguments fn takes. */
int zr__fn_params(const zr_fn *fn);
/* NULL when fn can be evaluated; otherwise what it needs that zRcube
   does not have yet ("internal function 76 (f_noise3d)", "pattern
   functions"), for the caller's message. */
const char *zr__fn_unsupported(const zr_fn *fn);
/* fn at args[0 .. zr__fn_params(fn)); fn must be supported.  Never
   allocates; safe from any number of threads. */
double zr__fn_eval(const zr_fn *fn, const double *args);

#endif /* ZR_SDL_FUNCTION_H */
