/*
 * function.h - compiling user-defined functions (reference manual
 * 3.3.1.8, "Function"): `function [(params)] { expression }` compiled
 * once into bytecode that lib/fn runs (lib/fn/fn.h evaluates it).
 */
#ifndef ZR_SDL_FUNCTION_H
#define ZR_SDL_FUNCTION_H

#include <stdbool.h>

#include "fn/fn.h"
#include "sdl/sdl.h"

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

#endif /* ZR_SDL_FUNCTION_H */
