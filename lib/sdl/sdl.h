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
 *                arrays, runs #include, #declare, #version, #zfor and
 *                #zend, turns identifiers into typed tokens (calling
 *                macros, indexing arrays), and formats diagnostics with
 *                the include and macro call chain;
 *   control.c    #if, #while, #for, #switch, #macro, #undef, #debug ...;
 *   fileio.c     #fopen, #fclose, #read, #write;
 *   fastexpr.c   float directive values without a nested parse;
 *   values.c     numeric expressions (float, vector, colour);
 *   builtins.c   comparisons, strings, arrays, rand, vector rotations;
 *   symtab.c     the symbol tables (hash tables);
 *   build.c      what the grammar actions call to build the scene model.
 * The grammar itself is grammar/pov.y, a pure bison parser with two entry
 * points chosen by a leading pseudo-token, so the engine can parse the
 * expression of a directive with a nested parser.
 */
#ifndef ZR_SDL_SDL_H
#define ZR_SDL_SDL_H

#include <setjmp.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

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
/* How deep macro calls may nest: beyond this a macro almost surely
   recurses without end, and each level costs C stack in nested parses. */
#define ZR_SDL_MAX_MACRO_DEPTH 128
/* How deep the engine may nest parsers (a directive's expression inside
   a macro argument inside a declaration ...): each level is a C stack
   frame of yyparse, so this bounds the C stack the parse can use. */
#define ZR_SDL_MAX_NESTED_PARSE 400
/* The most dimensions an array may have ("Array", 3.3.1.10: "up to
   five dimensions"). */
#define ZR_SDL_MAX_DIMS 5

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

/* A comma-separated list of floats: vector literals and matrix.  The
   grammar holds lists by pointer, from a pool (zr__sdl_list_new), so
   its semantic value stays small: bison copies that value at every
   shift and reduction. */
#define ZR_SDL_LIST_MAX 16
typedef struct zr_sdl_list {
  int n;
  double v[ZR_SDL_LIST_MAX];
  struct zr_sdl_list *next_free; /* in the parser's pool */
} zr_sdl_list;

typedef enum zr_sdl_kind {
  ZR_SDL_FLOAT = 0,
  ZR_SDL_VECTOR,
  ZR_SDL_COLOUR,
  ZR_SDL_PIGMENT,
  ZR_SDL_FINISH,
  ZR_SDL_TEXTURE,
  ZR_SDL_INTERIOR,
  ZR_SDL_OBJECT,
  ZR_SDL_STRING, /* ptr: the NUL-terminated text */
  ZR_SDL_ARRAY,  /* ptr: a zr_sdl_array (element assignment changes it) */
  ZR_SDL_MACRO,  /* ptr: a zr_sdl_macro */
  ZR_SDL_ALIAS,  /* ptr: a zr_sdl_alias, a parameter passed by name */
  ZR_SDL_FILE,   /* ptr: a zr_sdl_fhandle made by #fopen */
  ZR_SDL_FUNCTION, /* ptr: a compiled zr_fn (function.h) */
  ZR_SDL_NORMAL,     /* ptr: a zr_normal */
  ZR_SDL_COLOUR_MAP, /* ptr: a zr_colour_map */
  ZR_SDL_MATERIAL,   /* ptr: a zr_sdl_material (build_texture.c) */
  ZR_SDL_SKY_SPHERE, /* ptr: a zr_sky_sphere (build_camlight.c) */
  ZR_SDL_CAMERA,     /* ptr: a finished zr_camera (build_camlight.c) */
  ZR_SDL_MEDIA,      /* ptr: a zr_medium (build_media.c) */
  ZR_SDL_DENSITY,    /* ptr: a zr_pigment, a media density */
  ZR_SDL_TRANSFORM,  /* ptr: a zr_transform (build_pattern.c) */
  ZR_SDL_LIGHT,      /* ptr: a finished zr_light (build_camlight.c) */
  ZR_SDL_SPLINE      /* ptr: a zr_sdl_spline (spline.c) */
} zr_sdl_kind;

/* What an identifier stands for.  Pointers are into the scene's arena
   and are never modified after the declaration: users copy them. */
typedef struct zr_sdl_value {
  zr_sdl_kind kind;
  zr_sdl_expr num;
  const void *ptr;
} zr_sdl_value;

/* A name after #declare or #local, with the frame it was written in,
   whether it is #local, and the indices of an array element target. */
typedef struct zr_sdl_decl_name {
  const char *name;
  int frame;
  bool local;
  /* #declare of a parameter passed by identifier: name and frame are
     the caller's variable, found when the name was read, as a macro may
     end before the value does ("#declare P = object { P }" then #end). */
  bool bound;
  int n_index;
  int index[ZR_SDL_MAX_DIMS];
} zr_sdl_decl_name;

/* An array: dims[0] x dims[1] ... elements in row-major order, kept in
   pages of ZR_SDL_ARRAY_PAGE elements that are made when one of their
   elements is first assigned, so an array costs for what it holds:
   array[100000000] is a table of page pointers until it is filled.
   set[i] of a page tells whether its element i was ever assigned.  A
   page has room for the elements of the array that fall in it, no
   more: array[4]{...} costs four values, not a thousand (a scene that
   copies a small array 100 000 times in a macro kept 6 GB before). */
#define ZR_SDL_ARRAY_PAGE 1024
typedef struct zr_sdl_array_page {
  struct zr_sdl_value *elems; /* in the same block, after the page */
  bool *set;
} zr_sdl_array_page;

typedef struct zr_sdl_array {
  int n_dims;
  int dims[ZR_SDL_MAX_DIMS];
  size_t n;
  zr_sdl_array_page **pages; /* n / ZR_SDL_ARRAY_PAGE rounded up */
} zr_sdl_array;

/* A #macro: its body is tokens [body, end) of a file, end the #end. */
typedef struct zr_sdl_macro {
  const char *name;
  int file;
  size_t body, end;
  int n_params;
  const char **params;
  bool *optional;
} zr_sdl_macro;

/* A parameter passed by identifier: the caller's variable, found by name
   in the table of frame (0: the global table). */
typedef struct zr_sdl_alias {
  size_t frame;
  const char *name;
} zr_sdl_alias;

/* A file opened by #fopen: read files are lexed like scenes and read
   token by token; written ones are stdio streams (fileio.c). */
typedef struct zr_sdl_fhandle {
  int file;   /* read: index into the parser's files; write: -1 */
  size_t pos; /* read: the next token */
  void *out;  /* write: the FILE * */
  bool writing; /* opened for write or append (out NULL: discarded) */
  struct zr_sdl_fhandle *next; /* the parser's open files */
} zr_sdl_fhandle;

/* A rand() stream made by seed() (see builtins.c for the generator). */
typedef struct zr_sdl_rand {
  unsigned long long state;
} zr_sdl_rand;

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
  ZR_SDL_MOD_NO_IMAGE,
  ZR_SDL_MOD_NO_REFLECTION,
  ZR_SDL_MOD_DOUBLE_ILLUMINATE,
  ZR_SDL_MOD_INVERSE,
  ZR_SDL_MOD_OPEN,
  ZR_SDL_MOD_NORMAL,
  /* lib/sdl/build_object.c */
  ZR_SDL_MOD_HOLLOW,        /* ptr: NULL for on, anything else off */
  ZR_SDL_MOD_CLIPPED_BY,    /* ptr: an intersection of the objects */
  ZR_SDL_MOD_BOUNDED_BY,    /* ptr: likewise */
  ZR_SDL_MOD_CLIP_TO_BOUND, /* clipped_by { bounded_by } */
  ZR_SDL_MOD_BOUND_TO_CLIP, /* bounded_by { clipped_by } */
  ZR_SDL_MOD_MATERIAL,      /* ptr: a zr_sdl_material */
  /* lib/sdl/build_media.c */
  ZR_SDL_MOD_INTERIOR_TEXTURE, /* ptr: a zr_texture */
  ZR_SDL_MOD_UV_MAPPING, /* the textures after it use surface (u, v) */
  /* Read and warned about, no effect: radiosity { importance },
     no_radiosity (lib/sdl/build_radiosity.c). */
  ZR_SDL_MOD_PHOTONS,       /* ptr: a zr_sdl_photons */
  ZR_SDL_MOD_IGNORED
} zr_sdl_mod_kind;

typedef struct zr_sdl_mod {
  zr_sdl_mod_kind kind;
  const void *ptr; /* zr_transform, zr_pigment, ... in the arena */
} zr_sdl_mod;

/* The contents of a reflection { ... } block. */
/* A light_group being read: its union and its global_lights. */
typedef struct zr_sdl_lgroup {
  zr_object *object;
  bool global;
} zr_sdl_lgroup;

typedef struct zr_sdl_reflection {
  zr_rgb min, max;
  double falloff;
  double metallic; /* "metallic" alone means 1 */
  double exponent;
  bool falloff_given, fresnel, fresnel_given, metallic_given;
  bool exponent_given;
  bool max_given;
} zr_sdl_reflection;

/* A pattern modifier (turbulence, octaves, frequency, ramp_wave,
   warp { turbulence ... } ...) as the grammar hands it to build.c. */
typedef struct zr_sdl_turb {
  zr_vec3 turbulence;
  int octaves;
  double omega, lambda;
} zr_sdl_turb;

/* Kept small: it is a member of the grammar's semantic value, and every
   nested parser holds a stack of those on the C stack. */
typedef struct zr_sdl_pmod {
  int token; /* the keyword's token; T_WARP for a warp { } */
  zr_sdl_expr value; /* its argument (dim 0: none) */
  zr_sdl_loc loc;
  struct zr_warp *warp; /* T_WARP: the warp, in the arena */
} zr_sdl_pmod;

/* The colours after checker, hexagon or brick. */
typedef struct zr_sdl_clist {
  int n;
  zr_colour c[3];
  zr_sdl_loc loc; /* of the last colour, for "too many colours" */
} zr_sdl_clist;

/*
 * T_SPHERE_TEXTURED: a T_SPHERE_RUN that the tokens "texture { T } }"
 * follow on the sphere's line, T a texture identifier, handed to the
 * grammar as one token (directive.c, sphere_textured).  The columns
 * are those of the slow path's locations: the texture block's, from
 * 'texture' to its '}', and the whole object's, to the sphere's '}'.
 */
typedef struct zr_sdl_sphere_tex {
  const double *sphere;      /* T_SPHERE_RUN's centre and radius */
  const zr_texture *texture; /* T's value */
  int texture_column, texture_length;
  int length; /* of "sphere { ... }" from the keyword */
} zr_sdl_sphere_tex;

/* T_SMOOTH_TRIANGLE_RUN's value: its three corners and its three
   normals, nine values each, in the file's run arrays (tokens.c). */
typedef struct zr_sdl_smooth_run {
  const double *corners, *normals;
} zr_sdl_smooth_run;

/* The semantic value of a token as the engine hands it to bison. */
typedef union zr_sdl_lexval {
  double num;
  const char *str;
  const double *sphere; /* T_SPHERE_RUN's centre and radius */
  const double *corners; /* T_TRIANGLE_RUN's three corners */
  zr_sdl_smooth_run smooth; /* T_SMOOTH_TRIANGLE_RUN */
  zr_sdl_sphere_tex sphere_tex; /* T_SPHERE_TEXTURED */
  zr_sdl_decl_name decl;
  zr_sdl_value value;
} zr_sdl_lexval;

/* ---- token arrays ---- */

/*
 * The kind of the one token that stands for a run of plain mesh2 items
 * (numlist.c): no bison token has it, only mesh2's fast reader
 * (build_mesh.c) reads it.
 */
#define ZR_SDL_NUMBER_LIST 0x100000

/* Where such a run is in its file's bytes. */
typedef struct zr_sdl_numlist {
  size_t begin, end;
  int line, column; /* of begin */
  bool uv;          /* uv_vectors: 2-D items too */
  size_t n_items;
} zr_sdl_numlist;

typedef struct zr_sdl_token {
  int kind; /* a bison token kind, or a character */
  int line;
  int column;
  int length;
  union {
    double num;
    const char *str; /* interned in the file's arena */
    const zr_sdl_numlist *list; /* ZR_SDL_NUMBER_LIST */
    const double *sphere; /* T_SPHERE_RUN: x, y, z and r (tokens.c) */
    /* T_TRIANGLE_RUN: its corners, nine values in the file's corner
       array (tokens.c; their index there while the file is lexed) */
    const double *corners;
    size_t corner;
    /* T_SMOOTH_TRIANGLE_RUN: the index of its corners in the file's
       corner array and of its normals in its normal array */
    struct {
      uint32_t corner, normal;
    } smooth;
  } v;
} zr_sdl_token;

/* Reads a run of plain mesh2 items from bytes [pos, end), counting
   lines and columns from (line, column). */
typedef struct zr_sdl_numreader {
  const char *bytes;
  size_t pos, end;
  int line, column;
  bool uv;       /* 2-D vectors are items too */
  bool comma_ok; /* a comma may come before the next item */
} zr_sdl_numreader;

/* The next item of the run: its values (v[2] = 0 for a 2-D one), dim
   and the place of its '<'.  False, with the reader left where it was,
   when what follows is not a plain item. */
bool zr__sdl_numlist_item(zr_sdl_numreader *r, double v[3], int *dim,
                          int *line, int *column);
/* ' ', '\t', '\n', '\v', '\f' and '\r', the scanner's blanks
   (grammar/pov.l): one test of a bit mask. */
static inline bool zr__sdl_is_blank(char c) {
  unsigned char u = (unsigned char)c;
  return u <= ' ' && ((UINT64_C(1) << u) & UINT64_C(0x100003E00)) != 0;
}

/* The first byte from pos on, before end, that is not a blank, with
   *line and *column moved past the blanks as the scanner counts them
   (one column a byte, a newline starts the next line).  The lexer's
   quick tokens (tokens.c) and the number reader (numlist.c) both skip
   blanks so; the place lives in locals, which stay in registers. */
static inline size_t zr__sdl_skip_blanks(const char *b, size_t pos,
                                         size_t end, int *line,
                                         int *column) {
  int l = *line, c = *column;
  while (pos < end && zr__sdl_is_blank(b[pos])) {
    if (b[pos] == '\n') {
      l++;
      c = 1;
    } else {
      c++;
    }
    pos++;
  }
  *line = l;
  *column = c;
  return pos;
}

/* A sphere's "<x, y, z>, r" (T_SPHERE_RUN, tokens.c): the centre in
   v[0..2] and the radius in v[3].  False, with the reader left where it
   was, when what follows is not that. */
bool zr__sdl_numlist_sphere(zr_sdl_numreader *r, double v[4]);

/* One scene or include file, lexed once and kept while parsing. */
typedef struct zr_sdl_file {
  char *path;             /* as opened, malloc'ed */
  const char *scene_path; /* the same, in the scene's arena */
  char *bytes;
  size_t size;
  size_t *line_starts; /* byte offset of each line, index line - 1,
                          made when a message needs it (NULL before) */
  size_t n_lines;
  zr_sdl_token *tokens;
  size_t n_tokens;
  /* For each block directive, the index of the next directive of its
     block: #if -> #elseif/#else/#end, #switch -> #case..., #while,
     #for and #macro -> #end; zr__sdl_link() finds it.  Only the
     directives that have one are listed, by ascending index: a word per
     token cost as much as the tokens of a file of spheres. */
  struct zr_sdl_link {
    size_t from, to;
  } *links;
  size_t n_links;
  zr_arena strings; /* identifier and string texts */
  /* The token array and the file's bytes are charged to this budget
     (NULL: none) while the file is held. */
  struct zr_budget *budget;
  size_t charged;
  size_t tokens_charged; /* token slots the budget has been charged for */
  size_t block_tokens; /* directives that open or continue a block */
  /* The corners of the file's T_TRIANGLE_RUN tokens, nine values each in
     the order of the tokens, in corner_arena: the scene's arena when
     the parser lexes (zr__sdl_file_lex_scene), so that a mesh made of
     runs keeps them as its vertices (build_mesh.c); else strings. */
  double *corners;
  size_t n_corners, cap_corners; /* values */
  /* The normals of its T_SMOOTH_TRIANGLE_RUN tokens (whose corners are
     in corners too), nine values each, in corner_arena as well. */
  double *normals;
  size_t n_normals, cap_normals;
  zr_arena *corner_arena;
} zr_sdl_file;

/*
 * Lexes bytes into f (which takes ownership of path and bytes).  On a
 * lexical error fills *err_loc and err (a message of at most err_size
 * bytes) and returns ZR_ESYNTAX; ZR_ENOMEM when out of memory.
 */
zr_status zr__sdl_file_lex(zr_sdl_file *f, int file_index, char *path,
                           char *bytes, size_t size, zr_sdl_loc *err_loc,
                           char *err, size_t err_size);
/* The same, charging the file to budget; ZR_ELIMIT (err says so) when
   it does not fit. */
zr_status zr__sdl_file_lex_budget(zr_sdl_file *f, int file_index,
                                  char *path, char *bytes, size_t size,
                                  struct zr_budget *budget,
                                  zr_sdl_loc *err_loc, char *err,
                                  size_t err_size);
/* The same with the corners of triangle runs in corner_arena, which
   outlives the file (the scene's): a mesh may keep them. */
zr_status zr__sdl_file_lex_scene(zr_sdl_file *f, int file_index, char *path,
                                 char *bytes, size_t size,
                                 struct zr_budget *budget,
                                 zr_arena *corner_arena, zr_sdl_loc *err_loc,
                                 char *err, size_t err_size);
/* The same with every token from the flex scanner, none from the
   lexer's own reader of plain words and braces (tokens.c): the tokens
   must be the same either way (tests/test_lexer.c). */
zr_status zr__sdl_file_lex_scanner_only(zr_sdl_file *f, int file_index,
                                        char *path, char *bytes,
                                        size_t size, zr_sdl_loc *err_loc,
                                        char *err, size_t err_size);
void zr__sdl_file_free(zr_sdl_file *f);
/* The next directive of the block of the directive at token i (see
   links above), (size_t)-1 when there is none. */
size_t zr__sdl_link(const zr_sdl_file *f, size_t i);

/* What the flex scanner keeps between tokens (its "extra" data). */
typedef struct zr_sdl_lexer {
  zr_sdl_file *file;
  int line, column;       /* where the next character is */
  size_t offset;          /* the same place as a byte of the file */
  size_t read_pos;        /* the next byte the scanner's input reads */
  size_t read_size;       /* how much its next read copies (at most) */
  int comment_depth;      /* nesting of block comments */
  zr_sdl_loc comment_at;  /* where the outermost open comment began */
  /* The scanner holds no bytes read ahead: it was just started (or
     started again after a run), so the lexer may take plain words and
     braces itself before it (tokens.c, quick_token). */
  bool fresh;
  bool restart; /* the scanner is to be restarted before it reads */
  bool scanner_only; /* never take them (tests compare the two) */
  /* The keyword sphere_run found after a sphere's radius, its offset
     and length: quick_token takes it there without a second search. */
  const struct zr_sdl_keyword *known_keyword;
  size_t known_at, known_length;
  const char *last_name; /* the identifier interned last, and its */
  size_t last_name_length; /* length (zr__sdl_lex_intern) */
  bool failed;
  bool out_of_memory;
  zr_sdl_loc error_at;
  char error[160];
  /* Where a fatal error of the scanner itself returns to (its own
     allocations failing): flex would print and exit(), and a library
     never does (zr__sdl_lex_fatal). */
  jmp_buf fatal;
} zr_sdl_lexer;

/* The scanner's YY_FATAL_ERROR (grammar/pov.l): marks the lexer failed
   with msg and returns to its jmp_buf, never to the scanner. */
_Noreturn void zr__sdl_lex_fatal(void *scanner, const char *msg);

/* Called by the scanner's actions (grammar/pov.l). */
int zr__sdl_lex_input(zr_sdl_lexer *lx, char *buf, int max);
const char *zr__sdl_lex_intern(zr_sdl_lexer *lx, const char *s, size_t n);
const char *zr__sdl_lex_string(zr_sdl_lexer *lx, const char *s, size_t n);
void zr__sdl_lex_fail(zr_sdl_lexer *lx, const zr_sdl_loc *at,
                      const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* The text of a line (without its newline) and its length ("" and 0
   for a line the file does not have, or when out of memory: the lines'
   offsets are found at the first call). */
const char *zr__sdl_file_line(zr_sdl_file *f, int line, size_t *len);
/* The offset of a line's first byte in the file; false as above. */
bool zr__sdl_file_line_start(zr_sdl_file *f, int line, size_t *start);

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

/* Symbol tables are open-addressing hash tables (symtab.c). */
typedef struct zr_sdl_symbol {
  char *name; /* NULL: an empty slot */
  unsigned hash;
  bool removed; /* a tombstone left by #undef */
  /* "#declare deprecated [once] ["message"] Name": warn when used. */
  bool deprecated, deprecated_once, warned;
  const char *deprecated_message;
  zr_sdl_value value;
} zr_sdl_symbol;

typedef struct zr_sdl_symtab {
  zr_sdl_symbol *slots;
  size_t n, used, cap; /* live names, live + tombstones, slots */
} zr_sdl_symtab;

void zr__sdl_symtab_init(zr_sdl_symtab *t);
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

/* An #if, #while, #for or #switch being run in a frame. */
typedef enum zr_sdl_ctl_kind {
  ZR_SDL_CTL_IF = 0,
  ZR_SDL_CTL_WHILE,
  ZR_SDL_CTL_FOR,
  ZR_SDL_CTL_SWITCH
} zr_sdl_ctl_kind;

typedef struct zr_sdl_ctl {
  zr_sdl_ctl_kind kind;
  size_t open;        /* index of the opening directive */
  size_t body;        /* #for: index of the first token of the body */
  const char *var;    /* #for: the counter */
  double to, step;    /* #for */
  double value;       /* #switch */
} zr_sdl_ctl;

/* A file being read (the top-level scene or an included file) or a
   macro being run. */
typedef struct zr_sdl_frame {
  int file;
  size_t pos;
  zr_sdl_symtab locals; /* #local names (unused in frame 0: global) */
  zr_sdl_loc included_at; /* or, for a macro, where it was called */
  const zr_sdl_macro *macro; /* NULL for a file */
  zr_sdl_loop *loops;
  size_t n_loops, cap_loops;
  zr_sdl_ctl *ctl;
  size_t n_ctl, cap_ctl;
} zr_sdl_frame;

/* What ends a directive's expression that has no token of its own: the
   engine hands the grammar an end token when the expression is complete
   and the next token cannot continue it (see directive.c). */
typedef struct zr_sdl_autoend {
  int token;   /* 0: none; ';' for #version, T_DECL_END for #declare */
  int depth;   /* brackets open */
  unsigned long long angles; /* bit i: bracket i is a vector's '<' */
  bool operand; /* the last token may end an expression */
  int last;     /* the last token's kind */
} zr_sdl_autoend;

/* How often the parse reports progress and looks for a cancel: every
   this many tokens (a power of two). */
#define ZR_SDL_PROGRESS_TOKENS 4096

/* A texture whose every part a transformation changes (pigment,
   normal, their transforms, map entries, layers and the map's
   transform) was copied by the transformation before for 'owner' alone:
   the next ones may change those parts in place (build.c).  'seen' is
   the texture as that copy left it, compared byte for byte: any other
   change makes the next transformation copy again. */
typedef struct zr_sdl_own {
  const void *owner;    /* the object, NULL for a texture block */
  const zr_texture *tx; /* NULL: none */
  /* Copied by an object's transform, which leaves parts with
     uv_mapping shared (moving_object): only transforms of objects may
     then change it in place, which leave the same parts alone. */
  bool moving;
  zr_texture seen;
} zr_sdl_own;

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
  bool version_given; /* a #version was read */
  /* The pixels of every image_map read, taken to the working gamma
     space once assumed_gamma is known (the end of the parse). */
  float **image_pixels;
  size_t *image_sizes;
  /* For each, NULL or the values its file's codes give as they are
     (code / maxval), which replace the pixels if the scene turns out to
     have gamma correction off (a legacy scene without assumed_gamma). */
  float **image_codes;
  size_t n_images, cap_images;
  int start_token; /* pseudo-token for the next yylex, 0 for none */
  zr_sdl_autoend autoend;
  bool want_decl_name;
  bool decl_local; /* the name wanted follows #local */
  /* An object's transform is being applied to its textures: patterns
     with uv_mapping stay where they are on the surface. */
  bool moving_object;
  /* What the next pigment { }, normal { } or finish { } without an
     identifier starts from: its texture's own (set just before the
     block inside a texture), else the default texture's once #default
     changed it ("Pigment", "Normal", "Finish": the items modify the
     current values).  Taken and cleared as the block starts. */
  const zr_pigment *pigment_base;
  const zr_normal *normal_base;
  /* The normal block just begun, until its first pattern keyword:
     that keyword keeps the bump size the block starts from (build.c,
     zr__sdl_normal_pattern). */
  const zr_normal *normal_fresh;
  const zr_finish *finish_base;
  int base_set;         /* bits 1, 2, 4: pigment, normal, finish base set */
  /* The copy texture { T ... } started from, and T: a texture that
     changed nothing of T is T itself, not a copy (a million spheres
     with texture { T } share one; build_texture.c). */
  zr_texture *texture_copy;
  const zr_texture *texture_copied;
  /* The textures a transformation may change in place instead of
     copying (build.c, zr__sdl_texture_move): the one of the texture
     block being read and the one of the object being built. */
  zr_sdl_own own_body, own_object;
  bool default_changed; /* a #default was read */
  int nested_depth; /* parsers running, for ZR_SDL_MAX_NESTED_PARSE */
  int macro_depth;
  int include_depth;
  /* Steps taken against the context's work budget: directives run,
     macro calls, loop passes (zr__sdl_spend). */
  unsigned long long work;
  /* Tokens delivered so far, for progress (zr__sdl_next). */
  unsigned long long tokens_read;
  /* POV-Ray radiosity items of the current block that mean nothing
     here, one bit each (lib/sdl/build_radiosity.c); object radiosity
     keywords already warned about, so a scene gets one warning. */
  unsigned radiosity_ignored;
  unsigned radiosity_object_warned;
  bool facets_warned; /* normal { facets }: grammar/pov.y */
  /* Render settings the language can read (image_width, clock...). */
  int image_width, image_height;
  double clock;
  zr_parse_options anim; /* the clock identifiers (zr_parse_options) */
  /* Where nested parses leave a value, a list or an argument's end. */
  zr_sdl_value nested_rvalue;
  zr_sdl_list nested_list;
  int nested_end;
  zr_sdl_fhandle *handles; /* files #fopen opened, closed at the end */
  /* The main scene file's folder, resolved (NULL for a string): a scene
     may read below it (lib/core/iopolicy.c). */
  char *scene_dir;
  zr_sdl_list *free_lists; /* the grammar's lists, for reuse */
  /* Every stream seed() made, in order: POV-Ray numbers them 0, 1, ...
     (seed()'s value printed as a float), and rand(n) with a float n takes
     stream n (rand.inc's VRand(1) in poliana-girl's glasstestreal.pov). */
  zr_sdl_rand **seeds;
  size_t n_seeds, cap_seeds;
  /* The warp list a pattern last grew, its length then and its room:
     the pattern that still has that length appends in place (the
     HabitablePlanet scene writes 1536 warps in one pigment: copying the
     list at each one cost 1.5 s of parse).  A copy of the pattern made
     earlier has the same pointer but, once one of them appended, no
     longer the same length, so it copies. */
  zr_warp *warp_tail;
  int warp_tail_n, warp_tail_cap;
  /* The elements of an array initialiser being parsed, in order. */
  zr_sdl_value *init;
  size_t n_init, cap_init;
  /* The token last handed to bison, for messages. */
  zr_sdl_loc last_loc;
  const char *last_text;
  /* Where a nested expression parse leaves its result. */
  zr_sdl_expr nested_value;
  /* What a camera block defers to its end (see build.c). */
  struct {
    /* The scene's camera before this block: a camera block that is a
       #declare's value gives it back (zr__sdl_camera_value). */
    zr_camera saved;
    bool from_id; /* camera { CAMERA_IDENTIFIER ... } */
    bool look_at_given, angle_given;
    bool right_given, up_given, v_angle_given, type_given;
    zr_vec3 look_at;
    double angle, v_angle;
    zr_transform transform;
    /* mesh_camera { }: the camera's mesh block while it is read, its
       meshes in an array of cap_meshes. */
    zr_mesh_camera *mesh;
    zr_sdl_loc mesh_at;
    zr_sdl_loc look_at_at; /* where look_at was written */
    size_t cap_meshes;
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
/* One step of the parse's work budget, spent by the directive or macro
   call at at (what names it for the message: "'#while'", "macro 'M'");
   false after a located error once the budget is used up. */
bool zr__sdl_spend(zr_sdl_parser *p, const zr_sdl_loc *at,
                   const char *what);
/* The grammar's name of a token kind ("#declare", "sphere"). */
const char *zr__sdl_kind_name(int kind);
/* Arena memory, reporting ZR_ENOMEM when there is none. */
void *zr__sdl_alloc(zr_sdl_parser *p, size_t size);
/* The same, not zeroed: for what is about to be written whole. */
void *zr__sdl_alloc_raw(zr_sdl_parser *p, size_t size);
/* Reports that an allocation of size bytes from the scene's arena failed
   (over the memory budget, or out of memory), as zr__sdl_alloc does;
   a->over_budget tells which. */
void zr__sdl_alloc_failed(zr_sdl_parser *p, size_t size);
/* A built-in float constant's value (clock, image_width, version ...;
   "Built-in Float Identifiers"), name one of the T_CONSTANT words. */
double zr__sdl_constant(const zr_sdl_parser *p, const char *name);
/* Parses one float expression for a directive (nested parse). */
zr_status zr__sdl_parse_expr(zr_sdl_parser *p, int start_token,
                             zr_sdl_expr *out);
/* bison's yylex: the next token after directives ran (directive.c). */
int zr__sdl_next(zr_sdl_lexval *val, zr_sdl_loc *loc, zr_sdl_parser *p);
/* A bison symbol name as messages show it: reserved words and directives
   quoted ("'sphere'"), classes bare ("number"). */
const char *zr__sdl_token_name(const char *name, char *buf, size_t size);
/* Runs #declare (is_local false: the innermost existing name, else a new
   global) or #local (frame's table), also for an array element. */
bool zr__sdl_define(zr_sdl_parser *p, const zr_sdl_decl_name *name,
                    bool is_local, const zr_sdl_value *value,
                    const zr_sdl_loc *loc);
/* Parses a nested directive value starting with start_token: the result
   is left in p->nested_value / nested_rvalue / nested_list. */
zr_status zr__sdl_parse_nested(zr_sdl_parser *p, int start_token);

/* ---- the engine's internals (directive.c, control.c) ---- */

zr_sdl_frame *zr__sdl_top(zr_sdl_parser *p);
zr_sdl_loc zr__sdl_token_loc(int file, const zr_sdl_token *t);
/* The token k places ahead in the newest frame (the end of file token
   when there are fewer). */
const zr_sdl_token *zr__sdl_peek(zr_sdl_parser *p, size_t k);
/* Where the token k places ahead is. */
zr_sdl_loc zr__sdl_peek_loc(zr_sdl_parser *p, size_t k);
/* The next token if it is kind (true), else "expected <what>" (false). */
bool zr__sdl_expect(zr_sdl_parser *p, int kind, const char *what);
/* The next token's name if it is an identifier, else "expected an
   identifier after '<after>'" and NULL. */
const char *zr__sdl_read_name(zr_sdl_parser *p, const char *after);
bool zr__sdl_push_frame(zr_sdl_parser *p, int file, const zr_sdl_loc *at);
void zr__sdl_pop_frame(zr_sdl_parser *p);
/* The table #local writes to in frame (frame 0's is the global one). */
zr_sdl_symtab *zr__sdl_scope(zr_sdl_parser *p, size_t frame);
/* The innermost symbol called name, a parameter passed by identifier
   resolved to the caller's variable; *frame (if not NULL) gets the
   frame whose table holds it.  NULL when undefined. */
zr_sdl_symbol *zr__sdl_lookup(zr_sdl_parser *p, const char *name,
                              size_t *frame);
/* Runs a block or message directive (#if ... #end, #while, #for,
   #switch, #macro, #undef, #debug ...) whose token was just read. */
bool zr__sdl_run_directive(zr_sdl_parser *p, const zr_sdl_token *t,
                           const zr_sdl_loc *at);
/* Reads "(Name)" or "(Name[i]...)" after #ifdef or defined. */
bool zr__sdl_read_defined(zr_sdl_parser *p, const zr_sdl_loc *at,
                          bool *out);
/* Invokes a macro whose name was just read at 'at'. */
bool zr__sdl_call_macro(zr_sdl_parser *p, const zr_sdl_macro *m,
                        const zr_sdl_loc *at);
/* The fast path for float values (fastexpr.c): "( expr )" at the current
   place, and "Name = expr ;" after #declare or #local.  False when the
   value needs the grammar: nothing was consumed or reported then. */
bool zr__sdl_fast_paren(zr_sdl_parser *p, double *out);
bool zr__sdl_fast_declare(zr_sdl_parser *p, bool is_local);
/* A macro argument that is a float expression or a vector literal,
   followed by ',' or ')' (left in *end). */
bool zr__sdl_fast_argument(zr_sdl_parser *p, zr_sdl_value *value,
                           int *end);
/* #fopen, #fclose, #read and #write (fileio.c), and the data file
   search they use (directive.c): like #include's, -1 after reporting. */
bool zr__sdl_run_file_directive(zr_sdl_parser *p, int kind,
                                const zr_sdl_loc *at);
void zr__sdl_close_files(zr_sdl_parser *p);
int zr__sdl_open_data(zr_sdl_parser *p, const char *name,
                      const zr_sdl_loc *at);
/* Reads one place a search tries (directive.c), under the I/O
   restrictions: ZR_ENOTFOUND silently when no file is there; any other
   failure, a refusal among them, reported at 'at' as "cannot read
   <what>: <why>" (the file's contents never quoted).  relative: the
   scene's name for the file does not start with '/' (path is it joined
   to the folder searched), which the default restrictions read
   wherever it leads. */
zr_status zr__sdl_read_file(zr_sdl_parser *p, const char *path,
                            bool relative, const zr_sdl_loc *at,
                            const char *what, char **bytes, size_t *size);
/* #default: the texture, pigment or finish of objects made from now on
   (control.c). */
/* The bases of the next pigment, normal or finish block of texture tx
   (its top layer's own), see pigment_base; kind is 'p', 'n' or 'f'. */
void zr__sdl_texture_base(zr_sdl_parser *p, const zr_texture *tx, int kind);
/* Raises every image_map's pixels to 1/gamma, or with gamma_off takes
   the codes of files decoded through a stated transfer as they are
   (build.c). */
void zr__sdl_images_to_working_gamma(zr_sdl_parser *p, double gamma,
                                     bool gamma_off);
/* The same for a block outside a texture (or in a texture that set
   none): the default texture's once #default changed it. */
void zr__sdl_block_base(zr_sdl_parser *p, int kind);
/* The base a block starts from (and clears it): NULL for the built-in
   defaults. */
const zr_pigment *zr__sdl_take_pigment_base(zr_sdl_parser *p);
const zr_normal *zr__sdl_take_normal_base(zr_sdl_parser *p);
const zr_finish *zr__sdl_take_finish_base(zr_sdl_parser *p);
bool zr__sdl_set_default(zr_sdl_parser *p, const zr_texture *texture,
                         const zr_pigment *pigment,
                         const zr_finish *finish);
/* Checks, at the end of a file, that its blocks were all closed. */
bool zr__sdl_check_blocks(zr_sdl_parser *p);

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
/* An empty list from the parser's pool (in the scene's arena), NULL
   after reporting that memory ran out; release gives it back. */
zr_sdl_list *zr__sdl_list_new(zr_sdl_parser *p);
void zr__sdl_list_release(zr_sdl_parser *p, zr_sdl_list *l);
bool zr__sdl_dot(zr_sdl_parser *p, const zr_sdl_expr *e, int item,
                 const zr_sdl_loc *loc, zr_sdl_expr *out);
bool zr__sdl_vcall(zr_sdl_parser *p, int func, const zr_sdl_expr *a,
                   const zr_sdl_expr *b, const zr_sdl_loc *loc,
                   zr_sdl_expr *out);
bool zr__sdl_call(zr_sdl_parser *p, int func, const zr_sdl_list *args,
                  const zr_sdl_loc *loc, zr_sdl_expr *out);
bool zr__sdl_want_float(zr_sdl_parser *p, const zr_sdl_expr *e,
                        const zr_sdl_loc *loc, double *out);
/* A float that may be infinite or not a number: what str() prints
   (POV-Ray writes "inf", "-inf", "-nan" after a division by zero). */
bool zr__sdl_want_any_float(zr_sdl_parser *p, const zr_sdl_expr *e,
                            const zr_sdl_loc *loc, double *out);
/* A box corner: a vector whose components may be +-inf (a division by
   zero upstream: POV-Ray renders the box as reaching infinity), never
   a NaN. */
bool zr__sdl_want_extent(zr_sdl_parser *p, const zr_sdl_expr *e,
                         const zr_sdl_loc *loc, zr_vec3 *out);
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

/* ---- built-in functions, strings and arrays (builtins.c) ---- */

/* Truth of a condition: POV-Ray calls |v| < 1e-10 false. */
bool zr__sdl_truth(zr_sdl_parser *p, const zr_sdl_expr *e,
                   const zr_sdl_loc *loc, bool *out);
/* Comparisons and logic: op is '<', '>', '=', T_LE, T_GE, T_NE, '&',
   '|'. */
bool zr__sdl_compare(zr_sdl_parser *p, int op, const zr_sdl_expr *a,
                     const zr_sdl_expr *b, const zr_sdl_loc *loc,
                     zr_sdl_expr *out);
bool zr__sdl_vaxis_rotate(zr_sdl_parser *p, const zr_sdl_expr *v,
                          const zr_sdl_expr *axis, const zr_sdl_expr *deg,
                          const zr_sdl_loc *loc, zr_sdl_expr *out);
/* inside(Object, Point): 1 when the point is inside the object. */
bool zr__sdl_inside(zr_sdl_parser *p, const zr_object *o,
                    const zr_sdl_expr *point, const zr_sdl_loc *loc,
                    zr_sdl_expr *out);
/* vturbulence(Lambda, Omega, Octaves, Point): the pattern code's
   turbulence displacement (lib/scene/pattern.c) at the point. */
bool zr__sdl_vturbulence(zr_sdl_parser *p, const zr_sdl_expr *lambda,
                         const zr_sdl_expr *omega,
                         const zr_sdl_expr *octaves,
                         const zr_sdl_expr *point, const zr_sdl_loc *loc,
                         zr_sdl_expr *out);
bool zr__sdl_vrotate(zr_sdl_parser *p, const zr_sdl_expr *v,
                     const zr_sdl_expr *r, const zr_sdl_loc *loc,
                     zr_sdl_expr *out);
/* String functions: results are in the scene's arena, NULL after an
   error was reported. */
const char *zr__sdl_strdup(zr_sdl_parser *p, const char *s, size_t n);
const char *zr__sdl_concat(zr_sdl_parser *p, const char *a, const char *b);
const char *zr__sdl_str(zr_sdl_parser *p, double v, double width,
                        double prec, const zr_sdl_loc *loc);
const char *zr__sdl_vstr(zr_sdl_parser *p, double n, const zr_sdl_expr *v,
                         const char *sep, double width, double prec,
                         const zr_sdl_loc *loc);
const char *zr__sdl_substr(zr_sdl_parser *p, const char *s, double start,
                           double len, const zr_sdl_loc *loc);
const char *zr__sdl_chr(zr_sdl_parser *p, double code,
                        const zr_sdl_loc *loc);
const char *zr__sdl_strcase(zr_sdl_parser *p, const char *s, bool upper);
/* Float functions of strings: T_ASC, T_STRLEN, T_VAL, T_FILE_EXISTS. */
bool zr__sdl_string_float(zr_sdl_parser *p, int func, const char *s,
                          const zr_sdl_loc *loc, zr_sdl_expr *out);
bool zr__sdl_file_exists(zr_sdl_parser *p, const char *name);
/* seed(n) and rand(stream). */
const zr_sdl_rand *zr__sdl_seed(zr_sdl_parser *p, double n);
double zr__sdl_rand(const zr_sdl_rand *stream);
/* The stream seed() made as its number n (from 0), or NULL after a
   located error: POV-Ray's "Illegal random number generator." */
const zr_sdl_rand *zr__sdl_seed_numbered(zr_sdl_parser *p, double n,
                                         const zr_sdl_loc *loc);
/* POV-Ray's generator: the state seed(n) starts from, and one step that
   returns the next value in [0, 1]. */
unsigned long long zr__sdl_seed_state(double n);
double zr__sdl_rand_step(unsigned long long *state);
/* Arrays: a new array of the given dimensions, its initialiser (the
   p->init values), a copy, and dimension_size(). */
zr_sdl_array *zr__sdl_array_new(zr_sdl_parser *p, const zr_sdl_list *dims,
                                const zr_sdl_loc *loc);
bool zr__sdl_array_init(zr_sdl_parser *p, zr_sdl_array *a, size_t start,
                        const zr_sdl_loc *loc);
bool zr__sdl_init_add(zr_sdl_parser *p, const zr_sdl_value *v,
                      const zr_sdl_loc *loc);
zr_sdl_array *zr__sdl_array_copy(zr_sdl_parser *p, const zr_sdl_array *a);
bool zr__sdl_dimension_size(zr_sdl_parser *p, const zr_sdl_array *a,
                            double dim, const zr_sdl_loc *loc,
                            zr_sdl_expr *out);
/* The element of a at the indices, checked, to be assigned (marked as
   set, its page made if needed); NULL after an error. */
zr_sdl_value *zr__sdl_array_at(zr_sdl_parser *p, const char *name,
                               zr_sdl_array *a, const int *index, int n,
                               const zr_sdl_loc *loc);
/* The element at the indices, checked, to be read: NULL after an error;
   otherwise *set tells whether it was ever assigned (when it was not,
   the value returned must not be used). */
const zr_sdl_value *zr__sdl_array_get(zr_sdl_parser *p, const char *name,
                                      const zr_sdl_array *a,
                                      const int *index, int n,
                                      const zr_sdl_loc *loc, bool *set);

/* ---- building the scene (build.c) ---- */

/* Warns, as POV-Ray 3.7 does ("Degenerate triangle. Please remove.",
   measured), about a triangle whose corners are on one line. */
void zr__sdl_degenerate_triangle(zr_sdl_parser *p, const zr_vec3 *corners,
                                 const zr_sdl_loc *at);
/* Warns about a negative radius (at: where the radius is). */
void zr__sdl_sphere_radius(zr_sdl_parser *p, const zr_object *sphere,
                           const zr_sdl_loc *at);
/* The centre and radius of a T_SPHERE_RUN token, the four numbers the
   lexer read (run, in its file's arena), into sphere. */
void zr__sdl_sphere_run(const double *run, zr_object *sphere);
/* The object of a T_SPHERE_TEXTURED token (at: its place, the sphere
   keyword's): the calls the grammar's actions make, in their order, for
   the tokens it stands for; NULL after an error. */
zr_object *zr__sdl_sphere_textured(zr_sdl_parser *p,
                                   const zr_sdl_sphere_tex *s,
                                   const zr_sdl_loc *at);
/* A cylinder's or cone's axis must have a length: POV-Ray 3.7 stops on
   base point = apex point (measured); false after the error at at. */
bool zr__sdl_axis_given(zr_sdl_parser *p, zr_vec3 base, zr_vec3 cap,
                        const char *shape, const zr_sdl_loc *at);
zr_object *zr__sdl_object_new(zr_sdl_parser *p, zr_object_kind kind,
                              const zr_sdl_loc *loc);
zr_object *zr__sdl_object_copy(zr_sdl_parser *p, const zr_object *o);
bool zr__sdl_sphere(zr_sdl_parser *p, zr_object *o, const zr_sdl_expr *c,
                    const zr_sdl_loc *cl, const zr_sdl_expr *r,
                    const zr_sdl_loc *rl);
bool zr__sdl_union_add(zr_sdl_parser *p, zr_object *u, zr_object *child);
/* CSG and the rarer object modifiers (lib/sdl/build_object.c). */
void zr__sdl_object_invert(zr_object *o);
bool zr__sdl_difference_add(zr_sdl_parser *p, zr_object *d,
                            zr_object *child);
bool zr__sdl_object_mod_more(zr_sdl_parser *p, zr_object *o,
                             const zr_sdl_mod *mod);
/* A light source written inside a union (or other CSG): it follows the
   object's transforms and joins the scene with it. */
bool zr__sdl_csg_add_light(zr_sdl_parser *p, zr_object *csg, zr_light *l);
/* A copy of a light (and of its looks_like object) for the parser to
   change. */
zr_light *zr__sdl_light_copy(zr_sdl_parser *p, const zr_light *l);
/* After a CSG object's shallow copy: its own copies of its lights. */
bool zr__sdl_csg_copy_lights(zr_sdl_parser *p, zr_object *copy);
/* The closing brace of light_group { } (build_object.c): its lights and
   objects become a new group's, a group inside it that group's child.
   global: global_lights on. */
bool zr__sdl_light_group_done(zr_sdl_parser *p, zr_object *group,
                              bool global, const zr_sdl_loc *loc);
/* Adds a finished top-level object to the scene, and the lights that
   its CSG carries to the scene's lights. */
bool zr__sdl_add_object(zr_sdl_parser *p, zr_object *o,
                        const zr_sdl_loc *loc);
zr_object *zr__sdl_quadric(zr_sdl_parser *p, const zr_sdl_expr e[4],
                           const zr_sdl_loc *loc, const zr_sdl_loc at[4]);
zr_object *zr__sdl_poly_new(zr_sdl_parser *p, const zr_sdl_expr *order,
                            const zr_sdl_loc *order_loc,
                            const zr_sdl_loc *loc);
bool zr__sdl_poly_coef(zr_sdl_parser *p, zr_object *o, const zr_sdl_expr *e,
                       const zr_sdl_loc *loc);
bool zr__sdl_poly_done(zr_sdl_parser *p, zr_object *o,
                       const zr_sdl_loc *loc);
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
/* irid { } items: kw T_IRID (the amount), T_THICKNESS or T_TURBULENCE;
   each a float >= 0. */
bool zr__sdl_finish_irid(zr_sdl_parser *p, zr_finish *f, int kw,
                         const zr_sdl_expr *e, const zr_sdl_loc *loc);
/* slope { D [, lo, hi] }: D a non-zero vector; lo and hi floats (both or
   neither; lo_loc for both).  altitude A [, lo, hi] the same. */
zr_slope *zr__sdl_slope_new(zr_sdl_parser *p, const zr_sdl_expr *d,
                            const zr_sdl_loc *d_loc, const zr_sdl_expr *lo,
                            const zr_sdl_expr *hi,
                            const zr_sdl_loc *lo_loc);
bool zr__sdl_slope_altitude(zr_sdl_parser *p, zr_slope *sl,
                            const zr_sdl_expr *a, const zr_sdl_loc *a_loc,
                            const zr_sdl_expr *lo, const zr_sdl_expr *hi,
                            const zr_sdl_loc *lo_loc);
/* global_settings { irid_wavelength C }: every channel > 0. */
bool zr__sdl_irid_wavelength(zr_sdl_parser *p, const zr_sdl_expr *e,
                             const zr_sdl_loc *loc);
/* reflection { exponent e }: e must be positive. */
bool zr__sdl_reflection_exponent(zr_sdl_parser *p, double e,
                                 const zr_sdl_loc *loc);
zr_texture *zr__sdl_texture_new(zr_sdl_parser *p, const zr_texture *from);
bool zr__sdl_texture_transform(zr_sdl_parser *p, zr_texture *tx,
                               const zr_transform *t);
/* zr__sdl_texture_transform, in place when own holds tx for owner (see
   zr_sdl_own); own then holds tx.  tx itself must be private. */
bool zr__sdl_texture_move(zr_sdl_parser *p, zr_sdl_own *own,
                          const void *owner, zr_texture *tx,
                          const zr_transform *t);
/* tx goes to o as its first texture: the texture block that made it
   passes it to the object (p->own_body to p->own_object). */
void zr__sdl_texture_given(zr_sdl_parser *p, const zr_object *o,
                           const zr_texture *tx);
bool zr__sdl_texture_done(zr_sdl_parser *p, zr_texture *tx);
zr_interior *zr__sdl_interior_new(zr_sdl_parser *p, const zr_interior *from);
/* Patterns, colour maps, normals and image maps (build.c). */
bool zr__sdl_pigment_pattern(zr_sdl_parser *p, zr_pigment *pg, int kind,
                             const zr_sdl_clist *list);
bool zr__sdl_gradient(zr_sdl_parser *p, zr_pattern *pt,
                      const zr_sdl_expr *e, const zr_sdl_loc *loc);
/* octaves' value, checked against the manual's range 1 .. 10. */
bool zr__sdl_octaves(zr_sdl_parser *p, const zr_sdl_expr *e,
                     const zr_sdl_loc *loc, int *octaves);
bool zr__sdl_pattern_mod(zr_sdl_parser *p, zr_pattern *pt,
                         const zr_sdl_pmod *m);
/* warp { } (build_warp.c): a new warp of kind ZR_WARP_* from its first
   item's values (a, b: NULL when absent), a later item, and a pattern
   modifier whose warps act in the owner's transform so far (frame, NULL:
   identity). */
bool zr__sdl_warp_new(zr_sdl_parser *p, int kind, const zr_sdl_expr *a,
                      const zr_sdl_expr *b, const zr_sdl_loc *loc,
                      zr_sdl_pmod *out);
bool zr__sdl_warp_item(zr_sdl_parser *p, zr_sdl_pmod *wm,
                       const zr_sdl_pmod *m);
bool zr__sdl_pattern_warp(zr_sdl_parser *p, zr_pattern *pt,
                          const zr_transform *frame, const zr_sdl_pmod *m);
bool zr__sdl_pattern_mod_in(zr_sdl_parser *p, zr_pattern *pt,
                            const zr_transform *frame,
                            const zr_sdl_pmod *m);
bool zr__sdl_clist_add(zr_sdl_parser *p, zr_sdl_clist *l,
                       const zr_sdl_expr *e, const zr_sdl_loc *loc);
zr_colour_map *zr__sdl_colour_map_new(zr_sdl_parser *p,
                                      const zr_colour_map *from);
bool zr__sdl_colour_map_add(zr_sdl_parser *p, zr_colour_map *m,
                            const zr_sdl_expr *v, const zr_sdl_loc *vl,
                            const zr_sdl_expr *c, const zr_sdl_loc *cl);
bool zr__sdl_colour_map_done(zr_sdl_parser *p, const zr_colour_map *m,
                             const zr_sdl_loc *loc);
zr_normal *zr__sdl_normal_new(zr_sdl_parser *p, const zr_normal *from);
bool zr__sdl_normal_pattern(zr_sdl_parser *p, zr_normal *nm, int kind,
                            const zr_sdl_expr *amount,
                            const zr_sdl_loc *loc);
bool zr__sdl_normal_transform(zr_sdl_parser *p, zr_normal *nm,
                              const zr_transform *t);

/* Maps, layered and patterned textures, materials (build_texture.c). */
typedef struct zr_sdl_material {
  const zr_texture *texture;   /* NULL: none given */
  const zr_interior *interior; /* NULL: none given */
} zr_sdl_material;

zr_map *zr__sdl_map_new(zr_sdl_parser *p);
/* Appends an entry whose value is v (ascending), item in e->u. */
bool zr__sdl_map_add(zr_sdl_parser *p, zr_map *m, const zr_sdl_expr *v,
                     const zr_sdl_loc *vl, zr_map_entry *e);
/* Appends an entry written without a value, which only average allows
   ("Average": the weight is then 1). */
bool zr__sdl_map_add_weight1(zr_sdl_parser *p, zr_map *m, zr_map_entry *e);
/* Appends a block pattern's next item: its value is its index. */
bool zr__sdl_map_add_block(zr_sdl_parser *p, zr_map *m, zr_map_entry *e,
                           const zr_sdl_loc *loc);
bool zr__sdl_slope_add(zr_sdl_parser *p, zr_map *m, const zr_sdl_expr *v,
                       const zr_sdl_loc *vl, const zr_sdl_expr *hs,
                       const zr_sdl_loc *hsl);
bool zr__sdl_map_done(zr_sdl_parser *p, const zr_map *m, const char *what,
                      const zr_sdl_loc *loc);
bool zr__sdl_pigment_map_set(zr_sdl_parser *p, zr_pigment *pg,
                             const zr_map *m, const zr_sdl_loc *loc);
bool zr__sdl_normal_map_set(zr_sdl_parser *p, zr_normal *nm,
                            const zr_map *m, const zr_sdl_loc *loc);
bool zr__sdl_texture_map_set(zr_sdl_parser *p, zr_texture *tx,
                             const zr_map *m, const zr_sdl_loc *loc);
/* spiral1/spiral2 Number_of_Arms on a pattern already of that kind. */
/* tiling N: N from 1 to 27 (its whole part) and known to lib/scene. */
bool zr__sdl_tiling(zr_sdl_parser *p, zr_pattern *pt, const zr_sdl_expr *n,
                    const zr_sdl_loc *loc);
bool zr__sdl_spiral_arms(zr_sdl_parser *p, zr_pattern *pt,
                         const zr_sdl_expr *arms, const zr_sdl_loc *loc);
/* pigment_pattern { ... } makes pt that pattern of pg. */
void zr__sdl_pigment_pattern_of(zr_pattern *pt, const zr_pigment *pg);
/* A texture's own pattern (for its texture_map or block list). */
void zr__sdl_texture_pattern(zr_texture *tx, int kind);
/* above layered on top of below (NULL: above alone); below's chain is
   copied, above's shared. */
zr_texture *zr__sdl_texture_layer(zr_sdl_parser *p, const zr_texture *below,
                                  const zr_texture *above);
/* tx, or the texture identifier's texture it was copied from when it is
   still the same bytes: textures are never changed once made (changes
   copy them), so objects can share one. */
zr_texture *zr__sdl_texture_shared(zr_sdl_parser *p, zr_texture *tx);
/* The top layer of tx, a private copy: the chain above tx is copied
   (tx itself must be one already); NULL when out of memory. */
zr_texture *zr__sdl_texture_top(zr_sdl_parser *p, zr_texture *tx);
/* The parts of a texture transform zr__sdl_texture_transform leaves to
   this file: the map's pattern and textures, and the layers above. */
bool zr__sdl_texture_transform_more(zr_sdl_parser *p, zr_texture *tx,
                                    const zr_transform *t);
zr_sdl_material *zr__sdl_material_new(zr_sdl_parser *p,
                                      const zr_sdl_material *from);
bool zr__sdl_material_texture(zr_sdl_parser *p, zr_sdl_material *m,
                              const zr_texture *tx);
bool zr__sdl_material_transform(zr_sdl_parser *p, zr_sdl_material *m,
                                const zr_transform *t);
/*
 * Reads an image or data file named in the scene (image_map,
 * height_field, density_file), searched like #include, under the I/O
 * restrictions: ZR_OK with *path (where it was found) and *bytes
 * malloc'ed; ZR_ENOTFOUND, reporting nothing, when it is nowhere;
 * another status after reporting at 'at' (a refused file is not read).
 */
zr_status zr__sdl_read_image(zr_sdl_parser *p, const char *name,
                             const zr_sdl_loc *at, const char *what,
                             char **path, char **bytes, size_t *size);
/* A bitmap's file as written (grammar/pov.y bitmap_file): its name, and
   "gamma G" (has_gamma, gamma) or "gamma srgb" (srgb) after it, gamma_loc
   the value's or the keyword srgb's place; "premultiplied B"
   (has_premultiplied, premultiplied at premultiplied_loc). */
typedef struct zr_sdl_bitmap_file {
  const char *name;
  zr_sdl_loc loc;
  zr_sdl_expr gamma;
  bool has_gamma, srgb;
  zr_sdl_loc gamma_loc;
  zr_sdl_expr premultiplied;
  bool has_premultiplied;
  zr_sdl_loc premultiplied_loc;
} zr_sdl_bitmap_file;
/* An item every bitmap takes: token T_MAP_TYPE or T_INTERPOLATE with its
   value, or T_ONCE (has_value false); loc the value's or once's place. */
typedef struct zr_sdl_bitmap_mod {
  int token;
  zr_sdl_expr value;
  bool has_value;
  zr_sdl_loc loc;
} zr_sdl_bitmap_mod;
/* Reads the picture of what ("image_map", "bump_map", "image_pattern" or
   "material_map", which messages name), searched like #include; all but
   an image_map also get the picture's values. */
zr_image_map *zr__sdl_bitmap_new(zr_sdl_parser *p, const char *what,
                                 const zr_sdl_bitmap_file *file);
bool zr__sdl_image_map_mod(zr_sdl_parser *p, zr_image_map *im, int token,
                           const zr_sdl_expr *e, const zr_sdl_loc *loc);
/* bump_map { } (build_texture.c): a fresh normal holding the picture,
   its items (T_MAP_TYPE, T_ONCE, T_INTERPOLATE, T_USE_INDEX,
   T_USE_COLOR, T_BUMP_SIZE), then the normal it goes in. */
zr_normal *zr__sdl_bump_map_new(zr_sdl_parser *p, zr_image_map *im);
bool zr__sdl_bump_map_mod(zr_sdl_parser *p, zr_normal *bump, int token,
                          const zr_sdl_expr *e, const zr_sdl_loc *loc);
bool zr__sdl_bump_map_end(zr_sdl_parser *p, zr_normal *nm,
                          const zr_normal *bump, const zr_sdl_loc *loc);
/* material_map { FILE MODS TEXTURES TRANSFORMS } on texture tx; its
   textures are appended with their index as their value. */
bool zr__sdl_material_add(zr_sdl_parser *p, zr_map *m, zr_map_entry *e);
bool zr__sdl_material_map(zr_sdl_parser *p, zr_texture *tx,
                          const zr_image_map *im, const zr_map *textures,
                          const zr_transform *t, const zr_sdl_loc *loc);
/* "filter INDEX, AMOUNT" or "transmit INDEX, AMOUNT" (token T_FILTER or
   T_TRANSMIT) for one palette entry. */
bool zr__sdl_image_map_index(zr_sdl_parser *p, zr_image_map *im, int token,
                             const zr_sdl_expr *index,
                             const zr_sdl_loc *index_loc,
                             const zr_sdl_expr *amount,
                             const zr_sdl_loc *amount_loc);
/* Cameras, lights and atmospheric effects: lib/sdl/build_camlight.h. */

/* ---- radiosity settings (build_radiosity.c) ---- */

/* global_settings { radiosity {: radiosity on, a new block's items. */
void zr__sdl_radiosity_begin(zr_sdl_parser *p);
/* One item: keyword token kw with its value a and second value b (NULL
   when not written); loc is the last thing written. */
bool zr__sdl_radiosity_item(zr_sdl_parser *p, int kw, const zr_sdl_expr *a,
                            const zr_sdl_expr *b, const zr_sdl_loc *loc);
/* save_file or load_file (POV-Ray 3.6), read and warned about. */
bool zr__sdl_radiosity_file(zr_sdl_parser *p, int kw, const char *name,
                            const zr_sdl_loc *loc);
/* The block's closing brace: one warning naming the ignored items. */
void zr__sdl_radiosity_end(zr_sdl_parser *p, const zr_sdl_loc *loc);
/* An object's no_radiosity or radiosity { importance }: a warning. */
void zr__sdl_radiosity_object(zr_sdl_parser *p, int kw,
                              const zr_sdl_loc *loc);
/* finish { energy P }: P a float or colour, every channel >= 0. */
bool zr__sdl_finish_energy(zr_sdl_parser *p, zr_finish *f,
                           const zr_sdl_expr *e, const zr_sdl_loc *loc);

#endif /* ZR_SDL_SDL_H */
