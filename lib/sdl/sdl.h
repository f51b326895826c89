/*
 * sdl.h - the scene description language front end, private to lib/sdl
 * and grammar/.
 *
 * The pieces and how they meet:
 *   tokens.c     lexes one file with the flex scanner (grammar/pov.l) into
 *                an array of tokens, each with its file, line and column;
 *   keywords.c   the reserved words of POV-Ray 3.7 and the token each one
 *                becomes (a keyword outside the supported slice becomes
 *                T_UNSUPPORTED, reported when the parser asks for it);
 *   directive.c  the directive engine: bison's yylex.  It walks the token
 *                arrays, runs #include, #version, #zfor and #zend, turns
 *                identifiers into typed tokens, and formats diagnostics
 *                with the include chain;
 *   values.c     numeric expressions (float, vector, colour) and symbol
 *                tables;
 *   build.c      what the grammar actions call to build the scene model.
 * The grammar itself is grammar/pov.y, a pure bison parser with two entry
 * points chosen by a leading pseudo-token, so the engine can parse the
 * expression of a directive with a nested parser.
 */
#ifndef ZR_SDL_SDL_H
#define ZR_SDL_SDL_H

#include <stdbool.h>
#include <stddef.h>

#include "core/context.h"
#include "core/arena.h"
#include "core/transform.h"
#include "core/vec.h"
#include "scene/scene.h"

/* How deep #include may nest before we call it runaway recursion. */
#define ZR_SDL_MAX_INCLUDE_DEPTH 64
/* The most times one #zfor may repeat: beyond this a typing mistake is
   likelier than a scene, and the count must fit a long anyway. */
#define ZR_SDL_MAX_ZFOR 100000000

/* A place in a scene file: file is an index into the parser's files. */
typedef struct zr_sdl_loc {
  int file;
  int line;
  int column;
  int length; /* columns the token (or the construct) spans on its line */
} zr_sdl_loc;

/*
 * A numeric value: a float (dim 1), a vector (dim 2..4, POV-Ray has 2-D
 * uv and 4-D vectors) or a colour (dim 5: red, green, blue, filter,
 * transmit).  POV-Ray evaluates all three with the same operators and
 * promotes the smaller operand, so one type serves them all.
 */
typedef struct zr_sdl_expr {
  int dim;
  double v[5];
} zr_sdl_expr;

/* A comma-separated list of floats: vector literals and matrix. */
#define ZR_SDL_LIST_MAX 16
typedef struct zr_sdl_list {
  int n;
  double v[ZR_SDL_LIST_MAX];
} zr_sdl_list;

typedef enum zr_sdl_kind {
  ZR_SDL_FLOAT = 0,
  ZR_SDL_VECTOR,
  ZR_SDL_COLOUR,
  ZR_SDL_PIGMENT,
  ZR_SDL_FINISH,
  ZR_SDL_TEXTURE,
  ZR_SDL_INTERIOR,
  ZR_SDL_OBJECT
} zr_sdl_kind;

/* What an identifier stands for.  Pointers are into the scene's arena
   and are never modified after the declaration: users copy them. */
typedef struct zr_sdl_value {
  zr_sdl_kind kind;
  zr_sdl_expr num;
  const void *ptr;
} zr_sdl_value;

/* A name after #declare or #local, with the frame it was written in. */
typedef struct zr_sdl_decl_name {
  const char *name;
  int frame;
} zr_sdl_decl_name;

/* One modifier of a colour: rgb, rgbf, ..., red, green, ..., transmit. */
typedef struct zr_sdl_colour_mod {
  int token;
  zr_sdl_expr value;
  zr_sdl_loc loc;
} zr_sdl_colour_mod;

/* An object modifier as the grammar hands it to build.c. */
typedef enum zr_sdl_mod_kind {
  ZR_SDL_MOD_TRANSFORM = 0,
  ZR_SDL_MOD_PIGMENT,
  ZR_SDL_MOD_FINISH,
  ZR_SDL_MOD_TEXTURE,
  ZR_SDL_MOD_INTERIOR,
  ZR_SDL_MOD_NO_SHADOW,
  ZR_SDL_MOD_INVERSE,
  ZR_SDL_MOD_OPEN
} zr_sdl_mod_kind;

typedef struct zr_sdl_mod {
  zr_sdl_mod_kind kind;
  const void *ptr; /* zr_transform, zr_pigment, ... in the arena */
} zr_sdl_mod;

/* The contents of a reflection { ... } block. */
typedef struct zr_sdl_reflection {
  zr_rgb min, max;
  double falloff;
  double metallic; /* "metallic" alone means 1 */
  bool falloff_given, fresnel, fresnel_given, metallic_given;
  bool max_given;
} zr_sdl_reflection;

/* The semantic value of a token as the engine hands it to bison. */
typedef union zr_sdl_lexval {
  double num;
  const char *str;
  zr_sdl_decl_name decl;
  zr_sdl_value value;
} zr_sdl_lexval;

/* ---- token arrays ---- */

typedef struct zr_sdl_token {
  int kind; /* a bison token kind, or a character */
  int line;
  int column;
  int length;
  union {
    double num;
    const char *str; /* interned in the file's arena */
  } v;
} zr_sdl_token;

/* One scene or include file, lexed once and kept while parsing. */
typedef struct zr_sdl_file {
  char *path;             /* as opened, malloc'ed */
  const char *scene_path; /* the same, in the scene's arena */
  char *bytes;
  size_t size;
  size_t *line_starts; /* byte offset of each line, index line - 1 */
  size_t n_lines;
  zr_sdl_token *tokens;
  size_t n_tokens;
  zr_arena strings; /* identifier and string texts */
} zr_sdl_file;

/*
 * Lexes bytes into f (which takes ownership of path and bytes).  On a
 * lexical error fills *err_loc and err (a message of at most err_size
 * bytes) and returns ZR_ESYNTAX; ZR_ENOMEM when out of memory.
 */
zr_status zr__sdl_file_lex(zr_sdl_file *f, int file_index, char *path,
                           char *bytes, size_t size, zr_sdl_loc *err_loc,
                           char *err, size_t err_size);
void zr__sdl_file_free(zr_sdl_file *f);

/* What the flex scanner keeps between tokens (its "extra" data). */
typedef struct zr_sdl_lexer {
  zr_sdl_file *file;
  int line, column;       /* where the next character is */
  int comment_depth;      /* nesting of block comments */
  zr_sdl_loc comment_at;  /* where the outermost open comment began */
  bool failed;
  bool out_of_memory;
  zr_sdl_loc error_at;
  char error[160];
} zr_sdl_lexer;

/* Called by the scanner's actions (grammar/pov.l). */
const char *zr__sdl_lex_intern(zr_sdl_lexer *lx, const char *s, size_t n);
const char *zr__sdl_lex_string(zr_sdl_lexer *lx, const char *s, size_t n);
void zr__sdl_lex_fail(zr_sdl_lexer *lx, const zr_sdl_loc *at,
                      const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* The text of a line (without its newline) and its length. */
const char *zr__sdl_file_line(const zr_sdl_file *f, int line, size_t *len);

/* ---- keywords ---- */

typedef struct zr_sdl_keyword {
  const char *name;
  int token; /* T_UNSUPPORTED for reserved words outside the slice */
} zr_sdl_keyword;

/* The keyword spelled s[0..n), or NULL. */
const zr_sdl_keyword *zr__sdl_keyword_find(const char *s, size_t n);
/* The directive spelled s[0..n) without its '#', or NULL. */
const zr_sdl_keyword *zr__sdl_directive_find(const char *s, size_t n);
/* Every reserved word, for tests. */
const zr_sdl_keyword *zr__sdl_keywords(size_t *count);

/* ---- symbol tables ---- */

typedef struct zr_sdl_symbol {
  char *name;
  zr_sdl_value value;
} zr_sdl_symbol;

typedef struct zr_sdl_symtab {
  zr_sdl_symbol *items;
  size_t n, cap;
} zr_sdl_symtab;

void zr__sdl_symtab_free(zr_sdl_symtab *t);
zr_sdl_symbol *zr__sdl_symtab_find(zr_sdl_symtab *t, const char *name);
zr_status zr__sdl_symtab_set(zr_sdl_symtab *t, const char *name,
                             const zr_sdl_value *value);
void zr__sdl_symtab_remove(zr_sdl_symtab *t, const char *name);

/* ---- the parser state ---- */

/* A #zfor loop being replayed from its file's token array. */
typedef struct zr_sdl_loop {
  size_t start; /* index of the first token of the body */
  size_t end;   /* index of the matching #zend */
  long count, done;
  bool had_outer; /* a zr existed in this scope before the loop */
  zr_sdl_value outer;
} zr_sdl_loop;

/* A file being read: the top-level scene or an included file. */
typedef struct zr_sdl_frame {
  int file;
  size_t pos;
  zr_sdl_symtab locals; /* #local names (unused in frame 0: global) */
  zr_sdl_loc included_at;
  zr_sdl_loop *loops;
  size_t n_loops, cap_loops;
} zr_sdl_frame;

typedef struct zr_sdl_parser {
  zr_context *ctx;
  zr_scene *scene;
  zr_status status; /* the first error's status */
  zr_sdl_file *files;
  size_t n_files, cap_files;
  zr_sdl_frame *frames;
  size_t n_frames, cap_frames;
  zr_sdl_symtab globals;
  double version;
  int start_token; /* pseudo-token for the next yylex, 0 for none */
  /* While the expression of #version is read: its bracket depth and
     whether the last token ended an operand (see directive.c). */
  bool in_version;
  int version_depth;
  bool version_operand;
  bool want_decl_name;
  /* The token last handed to bison, for messages. */
  zr_sdl_loc last_loc;
  const char *last_text;
  /* Where a nested expression parse leaves its result. */
  zr_sdl_expr nested_value;
  /* What a camera block defers to its end (see build.c). */
  struct {
    bool look_at_given, angle_given;
    zr_vec3 look_at;
    double angle;
    zr_transform transform;
  } camera;
} zr_sdl_parser;

/* Reports an error at loc (NULL: no place) with the include chain;
   records and returns status.  Later errors keep the first status. */
zr_status zr__sdl_error(zr_sdl_parser *p, zr_status status,
                        const zr_sdl_loc *loc, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
void zr__sdl_warning(zr_sdl_parser *p, const zr_sdl_loc *loc,
                     const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* Arena memory, reporting ZR_ENOMEM when there is none. */
void *zr__sdl_alloc(zr_sdl_parser *p, size_t size);
/* Parses one float expression for a directive (nested parse). */
zr_status zr__sdl_parse_expr(zr_sdl_parser *p, int start_token,
                             zr_sdl_expr *out);
/* bison's yylex: the next token after directives ran (directive.c). */
int zr__sdl_next(zr_sdl_lexval *val, zr_sdl_loc *loc, zr_sdl_parser *p);
/* A bison symbol name as messages show it: reserved words and directives
   quoted ("'sphere'"), classes bare ("number"). */
const char *zr__sdl_token_name(const char *name, char *buf, size_t size);
/* Defines name in the global table (is_local false) or in frame's. */
bool zr__sdl_define(zr_sdl_parser *p, const zr_sdl_decl_name *name,
                    bool is_local, const zr_sdl_value *value,
                    const zr_sdl_loc *loc);

/* ---- expressions (values.c) ---- */

zr_sdl_expr zr__sdl_float(double f);
zr_sdl_expr zr__sdl_vec(double x, double y, double z);
bool zr__sdl_binop(zr_sdl_parser *p, int op, const zr_sdl_expr *a,
                   const zr_sdl_expr *b, const zr_sdl_loc *loc,
                   zr_sdl_expr *out);
void zr__sdl_negate(zr_sdl_expr *e);
bool zr__sdl_from_list(zr_sdl_parser *p, const zr_sdl_list *l,
                       const zr_sdl_loc *loc, zr_sdl_expr *out);
bool zr__sdl_list_add(zr_sdl_parser *p, zr_sdl_list *l, const zr_sdl_expr *e,
                      const zr_sdl_loc *loc);
bool zr__sdl_dot(zr_sdl_parser *p, const zr_sdl_expr *e, int item,
                 const zr_sdl_loc *loc, zr_sdl_expr *out);
bool zr__sdl_vcall(zr_sdl_parser *p, int func, const zr_sdl_expr *a,
                   const zr_sdl_expr *b, const zr_sdl_loc *loc,
                   zr_sdl_expr *out);
bool zr__sdl_call(zr_sdl_parser *p, int func, const zr_sdl_list *args,
                  const zr_sdl_loc *loc, zr_sdl_expr *out);
bool zr__sdl_want_float(zr_sdl_parser *p, const zr_sdl_expr *e,
                        const zr_sdl_loc *loc, double *out);
bool zr__sdl_want_vector(zr_sdl_parser *p, const zr_sdl_expr *e,
                         const zr_sdl_loc *loc, zr_vec3 *out);
bool zr__sdl_want_colour(zr_sdl_parser *p, const zr_sdl_expr *e,
                         const zr_sdl_loc *loc, zr_colour *out);
bool zr__sdl_want_rgb(zr_sdl_parser *p, const zr_sdl_expr *e,
                      const zr_sdl_loc *loc, zr_rgb *out);
/* Applies rgb/rgbf/.../red/green/... to a colour expression (dim 5). */
bool zr__sdl_colour_apply(zr_sdl_parser *p, zr_sdl_expr *colour,
                          const zr_sdl_colour_mod *mod);
zr_sdl_expr zr__sdl_colour_expr(zr_colour c);

/* ---- building the scene (build.c) ---- */

zr_object *zr__sdl_object_new(zr_sdl_parser *p, zr_object_kind kind,
                              const zr_sdl_loc *loc);
zr_object *zr__sdl_object_copy(zr_sdl_parser *p, const zr_object *o);
bool zr__sdl_sphere(zr_sdl_parser *p, zr_object *o, const zr_sdl_expr *c,
                    const zr_sdl_loc *cl, const zr_sdl_expr *r,
                    const zr_sdl_loc *rl);
bool zr__sdl_union_add(zr_sdl_parser *p, zr_object *u, zr_object *child);
bool zr__sdl_object_mod(zr_sdl_parser *p, zr_object *o,
                        const zr_sdl_mod *mod, const zr_sdl_loc *loc);
zr_transform *zr__sdl_transform(zr_sdl_parser *p, int token,
                                const zr_sdl_expr *e, const zr_sdl_loc *loc);
zr_transform *zr__sdl_matrix(zr_sdl_parser *p, const zr_sdl_list *l,
                             const zr_sdl_loc *loc);
zr_pigment *zr__sdl_pigment_new(zr_sdl_parser *p, const zr_pigment *from);
bool zr__sdl_pigment_transform(zr_sdl_parser *p, zr_pigment *pg,
                               const zr_transform *t);
zr_finish *zr__sdl_finish_new(zr_sdl_parser *p, const zr_finish *from);
void zr__sdl_finish_reflection(zr_finish *f, const zr_sdl_reflection *r);
zr_texture *zr__sdl_texture_new(zr_sdl_parser *p, const zr_texture *from);
bool zr__sdl_texture_transform(zr_sdl_parser *p, zr_texture *tx,
                               const zr_transform *t);
bool zr__sdl_texture_done(zr_sdl_parser *p, zr_texture *tx);
zr_interior *zr__sdl_interior_new(zr_sdl_parser *p, const zr_interior *from);
/* A point light with its place set; the grammar fills the rest. */
bool zr__sdl_light(zr_sdl_parser *p, zr_light *l, const zr_sdl_loc *loc);
void zr__sdl_camera_begin(zr_sdl_parser *p, const zr_sdl_loc *loc);
bool zr__sdl_camera_angle(zr_sdl_parser *p, double degrees,
                          const zr_sdl_loc *loc);
void zr__sdl_camera_look_at(zr_sdl_parser *p, zr_vec3 target);
void zr__sdl_camera_transform(zr_sdl_parser *p, const zr_transform *t);
/* Applies what the block deferred: angle, look_at, then transforms. */
void zr__sdl_camera_end(zr_sdl_parser *p);

#endif /* ZR_SDL_SDL_H */
