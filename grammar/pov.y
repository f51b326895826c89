/*
 * pov.y - the grammar of the POV-Ray 3.7 scene language (the slice
 * zRcube supports so far), a pure bison parser.
 *
 * The shape follows Bison's C examples (reccalc, bistromathic): a pure
 * parser with locations, LAC and a custom syntax error report that lists
 * exactly the tokens that could come next.  Tokens do not come from flex
 * directly but from the directive engine (lib/sdl/directive.c), which
 * runs #include, #version and #zfor and turns identifiers into typed
 * tokens (float identifier, pigment identifier, ...), the distinction the
 * manual's syntax makes (FLOAT_IDENTIFIER, PIGMENT_IDENTIFIER).  A
 * leading pseudo-token picks the start symbol: a whole scene, or the
 * expression of a directive, parsed by a nested parser.
 * Each directive's rule ends in a token of its own (')' or ';', which
 * the engine supplies after a #version that lacks it) so the nested
 * parser accepts without reading a token past the directive.
 *
 * Syntax and defaults follow the reference manual (r3_4): "Camera",
 * "Light Sources", "Finite/Infinite Solid Primitives", "CSG", "Texture",
 * "Finish", "Float Expressions", "Vector Expressions", "Color
 * Expressions".  Actions are one-liners that call lib/sdl/build.c and
 * lib/sdl/values.c; a failed helper has already reported its error.
 */
%code top {
#include "config.h"
}

%code requires {
#include "sdl/sdl.h"
#include "sdl/build_media.h"
#include "sdl/build_pattern.h"
#include "sdl/spline.h"
}

%code provides {
int zr__pov_lex(ZR__POV_STYPE *lval, zr_sdl_loc *lloc, zr_sdl_parser *p);
int zr__pov_parse(zr_sdl_parser *p);
}

%code {
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/strbuf.h"
#include "scene/pattern.h"
#include "sdl/build_iso.h"
#include "sdl/build_mesh.h"
#include "sdl/build_shape.h"
#include "sdl/build_surface.h"
#include "sdl/build_camlight.h"
#include "sdl/build_media.h"
#include "sdl/function.h"

/* A construct's location is its first token's, underlined to the end
   of its last token when both sit on the same line. */
#define YYLLOC_DEFAULT(Cur, Rhs, N)                                        \
  do {                                                                     \
    if (N) {                                                               \
      (Cur) = YYRHSLOC(Rhs, 1);                                            \
      const zr_sdl_loc *last_ = &YYRHSLOC(Rhs, N);                         \
      if (last_->file == (Cur).file && last_->line == (Cur).line &&        \
          last_->column >= (Cur).column)                                   \
        (Cur).length = last_->column + last_->length - (Cur).column;       \
    } else {                                                               \
      (Cur) = YYRHSLOC(Rhs, 0);                                            \
      (Cur).length = 0;                                                    \
    }                                                                      \
  } while (0)

/* The engine nests parsers (ZR_SDL_MAX_NESTED_PARSE deep at most), each
   a yyparse frame on the C stack: a small initial stack keeps the frame
   small; bison moves deeper stacks to the heap. */
#define YYINITDEPTH 24

/* Helpers report their own errors; the action only stops the parse. */
#define TRY(cond)                                                          \
  do {                                                                     \
    if (!(cond))                                                           \
      YYABORT;                                                             \
  } while (0)

/* With a custom syntax error report, bison calls this only when its
   stack is full (YYMAXDEPTH): the input nests too deeply. */
static void zr__pov_error(const zr_sdl_loc *loc, zr_sdl_parser *p,
                          const char *msg) {
  zr__sdl_error(p, ZR_ELIMIT, loc, "the scene nests too deeply (%s)", msg);
}

static zr_sdl_value numeric_value(const zr_sdl_expr *e) {
  zr_sdl_value v;
  memset(&v, 0, sizeof v);
  v.kind = e->dim == 1 ? ZR_SDL_FLOAT
           : e->dim == 5 ? ZR_SDL_COLOUR : ZR_SDL_VECTOR;
  v.num = *e;
  return v;
}

static zr_sdl_value pointer_value(zr_sdl_kind kind, const void *ptr) {
  zr_sdl_value v;
  memset(&v, 0, sizeof v);
  v.kind = kind;
  v.ptr = ptr;
  return v;
}

/* Gives a list back to the pool once its consumer ran; ok is what the
   consumer returned. */
static bool list_done(zr_sdl_parser *p, zr_sdl_list *l, bool ok) {
  zr__sdl_list_release(p, l);
  return ok;
}

/* The colours of checker, hexagon or brick, in the arena (the grammar's
   value holds a pointer: see zr_sdl_list). */
static zr_sdl_clist *clist_new(zr_sdl_parser *p) {
  zr_sdl_clist *l = zr__sdl_alloc(p, sizeof *l);
  if (l)
    memset(l, 0, sizeof *l);
  return l;
}

static zr_sdl_mod make_mod(zr_sdl_mod_kind kind, const void *ptr) {
  zr_sdl_mod m = {kind, ptr};
  return m;
}

/* An object's pigment, normal or finish block, made from its texture's
   (object_body). */
static bool object_mod_block(zr_sdl_parser *p, zr_object *o,
                             zr_sdl_mod_kind kind, const void *ptr,
                             const zr_sdl_loc *loc) {
  zr_sdl_mod m = make_mod(kind, ptr);
  return zr__sdl_object_mod(p, o, &m, loc);
}

/* no_bump_scale ("Scaling normals") on a normal, or on the normal a
   texture has so far (a copy, so a declared normal keeps its depth
   elsewhere; a texture without a normal has no depth to keep). */
static void no_bump_scale_normal(zr_normal *nm) { nm->no_bump_scale = true; }

static bool no_bump_scale_texture(zr_sdl_parser *p, zr_texture *tx) {
  zr_texture *top = zr__sdl_texture_top(p, tx);
  if (!top)
    return false;
  if (!top->normal)
    return true;
  zr_normal *copy = zr__sdl_alloc(p, sizeof *copy);
  if (!copy)
    return false;
  *copy = *top->normal;
  copy->no_bump_scale = true;
  top->normal = copy;
  return true;
}

/* normal { facets [coords F | size F] } ("Facets"): read, not rendered;
   the surface keeps the rest of the normal (the corpus'
   GSprites_Walls_textures.inc stopped here).  One warning a parse. */
static void facets_warning(zr_sdl_parser *p, const zr_sdl_loc *loc) {
  if (p->facets_warned)
    return;
  p->facets_warned = true;
  zr__sdl_warning(p, loc, "the 'facets' normal pattern is not rendered: "
                          "the surface is shaded without its facets");
}

/* A pattern modifier; e NULL for the keywords without a value. */
static zr_sdl_pmod make_pmod(int token, const zr_sdl_expr *e,
                             const zr_sdl_loc *loc) {
  zr_sdl_pmod m;
  memset(&m, 0, sizeof m);
  m.token = token;
  if (e)
    m.value = *e;
  m.loc = *loc;
  return m;
}

/* The rest of the camera's, light's and settings' items act on the
   scene directly: there is one of each being built at a time. */
#define CAMERA (&p->scene->camera)
#define SETTINGS (&p->scene->settings)
}

%define api.pure full
%define api.prefix {zr__pov_}
%define api.location.type {zr_sdl_loc}
%define parse.error custom
%define parse.lac full
%locations
%param {zr_sdl_parser *p}

%union {
  double num;
  const char *str;
  const double *sphere;
  const double *corners;
  zr_sdl_smooth_run smooth;
  zr_sdl_sphere_tex sphere_tex;
  zr_sdl_decl_name decl;
  zr_sdl_value value;
  zr_sdl_expr expr;
  zr_sdl_list *list;
  zr_sdl_colour_mod cmod;
  zr_sdl_mod mod;
  zr_sdl_lgroup lgroup;
  zr_sdl_reflection refl;
  zr_transform *transform;
  zr_sdl_tblock *tblock;
  zr_sdl_fractal_head fractal;
  zr_sdl_bitmap_file bitmap;
  zr_sdl_bitmap_mod bmod;
  const zr_fn *fn;
  zr_pigment *pigment;
  zr_sdl_pmod pmod;
  zr_sdl_clist *clist;
  zr_colour_map *cmap;
  zr_normal *normal;
  zr_image_map *imap;
  zr_finish *finish;
  zr_texture *texture;
  zr_map *map;
  zr_sdl_material *material;
  zr_interior *interior;
  zr_object *object;
  zr_light *light;
  zr_fog *fog;
  zr_sky_sphere *sky;
  zr_rainbow *rainbow;
  zr_medium *medium;
  zr_sdl_spline *spline;
  zr_slope *slope;
  zr_sdl_photons *photons;
  zr_sdl_photon_args phargs;
  int token;
}

/* Pseudo-tokens: the engine hands one out first to pick the start. */
%token T_START_SCENE "start of scene"
%token T_START_VERSION "start of #version"
%token T_START_PAREN "start of parenthesized expression"
%token T_START_FN_TEXTURE "start of a function's pattern or pigment"
%token T_START_FN_SPLINE "start of a function's spline"
%token T_START_FN_TRANSFORM "start of a function's transform"

%token <num> T_NUMBER "number"
%token <str> T_STRING "string"
%token <str> T_IDENTIFIER "undeclared identifier"
%token <str> T_UNSUPPORTED "unsupported keyword"
%token <str> T_BAD_CHAR "unexpected character"
/* A whole "triangle { <a>, <b>, <c> }" of plain vectors, and a
   sphere's "sphere { <x, y, z>, r" of plain numbers, read from the
   file's bytes as one token each (lib/sdl/tokens.c); the value points
   at the vectors in the file. */
%token <corners> T_TRIANGLE_RUN "triangle with its corners"
%token <sphere> T_SPHERE_RUN "sphere with its centre and radius"
%token <smooth> T_SMOOTH_TRIANGLE_RUN "smooth_triangle with its corners"
/* T_SPHERE_RUN and "texture { T } }" after it (directive.c,
   sphere_textured): a whole object.  Messages call it T_SPHERE_RUN's
   name and never list it (yyreport_syntax_error). */
%token <sphere_tex> T_SPHERE_TEXTURED "textured sphere"
%token <decl> T_DECL_NAME "identifier"
%token <value> T_FLOAT_ID "float identifier"
%token <value> T_VECTOR_ID "vector identifier"
%token <value> T_COLOUR_ID "colour identifier"
%token <value> T_PIGMENT_ID "pigment identifier"
%token <value> T_FINISH_ID "finish identifier"
%token <value> T_TEXTURE_ID "texture identifier"
%token <value> T_INTERIOR_ID "interior identifier"
%token <value> T_OBJECT_ID "object identifier"
/* User-defined functions: lib/sdl/function.c compiles the body. */
%token <value> T_FUNCTION_ID "function identifier"
%token T_FUNCTION "function"
/* Transforms, more patterns (lib/sdl/build_pattern.c). */
%token <value> T_TRANSFORM_ID "transform identifier"
%token T_TRANSFORM "transform"
%token T_MANDEL "mandel"
%token T_JULIA "julia"
%token T_MAGNET "magnet"
%token T_MAX_ITERATION "max_iteration"
%token T_EXPONENT "exponent"
%token T_EXTERIOR "exterior"
%token T_MIN_EXTENT "min_extent"
%token T_PATTERN "pattern"
%token T_TRACE "trace"
%token T_TILES "tiles"
%token T_TILE2 "tile2"
%token T_FORM "form"
%token T_METRIC "metric"
%token T_OFFSET "offset"
%token T_SOLID "solid"
%token T_MAX_EXTENT "max_extent"

/* Textures: patterns, colour maps, normals, image maps. */
%token <value> T_COLOUR_MAP_ID "color_map identifier"
%token <value> T_NORMAL_ID "normal identifier"
%token T_AGATE "agate"
%token T_AGATE_TURB "agate_turb"
%token T_ALL "all"
%token T_BOXED "boxed"
%token T_BOZO "bozo"
%token T_BRICK "brick"
%token T_BRICK_SIZE "brick_size"
%token T_BUMP_MAP "bump_map"
%token T_BUMP_SIZE "bump_size"
%token T_BUMPS "bumps"
%token T_CHECKER "checker"
%token T_COLOUR_MAP "color_map"
%token T_CRACKLE "crackle"
%token T_CUBIC_WAVE "cubic_wave"
%token T_CYLINDRICAL "cylindrical"
%token T_DENTS "dents"
%token T_FREQUENCY "frequency"
%token T_GRADIENT "gradient"
%token T_TILING "tiling"
%token T_GRANITE "granite"
%token T_HEXAGON "hexagon"
%token T_IMAGE_MAP "image_map"
%token T_INTERPOLATE "interpolate"
%token T_JPEG "jpeg"
%token T_LAMBDA "lambda"
%token T_LEOPARD "leopard"
%token T_MAP_TYPE "map_type"
%token T_MATERIAL_MAP "material_map"
%token T_USE_COLOR "use_color"
%token T_USE_INDEX "use_index"
%token T_PROJECTED_THROUGH "projected_through"
%token T_MARBLE "marble"
%token T_MORTAR "mortar"
%token T_NORMAL "normal"
%token T_OCTAVES "octaves"
%token T_OMEGA "omega"
%token T_ONION "onion"
%token T_PHASE "phase"
%token T_PLANAR "planar"
%token T_PNG "png"
%token T_POLY_WAVE "poly_wave"
%token T_PPM "ppm"
%token T_PREMULTIPLIED "premultiplied"
%token T_QUICK_COLOUR "quick_color"
%token T_RADIAL "radial"
%token T_RAMP_WAVE "ramp_wave"
%token T_RIPPLES "ripples"
%token T_SCALLOP_WAVE "scallop_wave"
%token T_SINE_WAVE "sine_wave"
%token T_SPHERICAL "spherical"
%token T_SPOTTED "spotted"
%token T_TRIANGLE_WAVE "triangle_wave"
%token T_TURBULENCE "turbulence"
%token T_WARP "warp"
%token T_BLACK_HOLE "black_hole"
%token T_DIST_EXP "dist_exp"
%token T_FLIP "flip"
%token T_MAJOR_RADIUS "major_radius"
%token T_ORIENTATION "orientation"
%token T_REPEAT "repeat"
%token T_TOROIDAL "toroidal"
%token T_WAVES "waves"
%token T_WOOD "wood"
%token T_WRINKLES "wrinkles"
/* Maps, layered and patterned textures, materials, more patterns
   (lib/sdl/build_texture.c). */
%token <value> T_MATERIAL_ID "material identifier"
%token <value> T_SKY_SPHERE_ID "sky_sphere identifier"
%token <value> T_CAMERA_ID "camera identifier"
%token <value> T_LIGHT_ID "light_source identifier"
%token T_AVERAGE "average"
%token T_CELLS "cells"
%token T_CONTROL0 "control0"
%token T_CONTROL1 "control1"
%token T_MATERIAL "material"
%token T_NOISE_GENERATOR "noise_generator"
%token T_NORMAL_MAP "normal_map"
%token T_NUMBER_OF_WAVES "number_of_waves"
%token T_PIGMENT_MAP "pigment_map"
%token T_PIGMENT_PATTERN "pigment_pattern"
%token T_IMAGE_PATTERN "image_pattern"
%token T_USE_ALPHA "use_alpha"
%token T_QUILTED "quilted"
%token T_SLOPE_MAP "slope_map"
%token T_SPIRAL1 "spiral1"
%token T_SPIRAL2 "spiral2"
%token T_TEXTURE_MAP "texture_map"
%token T_CRAND "crand"

%token T_DECLARE "#declare"
%token T_LOCAL "#local"
%token T_INCLUDE "#include"
%token T_VERSION "#version"
%token T_ZFOR "#zfor"
%token T_ZEND "#zend"
%token T_IF "#if"
%token T_IFDEF "#ifdef"
%token T_IFNDEF "#ifndef"
%token T_ELSE "#else"
%token T_ELSEIF "#elseif"
%token T_END "#end"
%token T_WHILE "#while"
%token T_FOR "#for"
%token T_SWITCH "#switch"
%token T_CASE "#case"
%token T_RANGE "#range"
%token T_BREAK "#break"
%token T_MACRO "#macro"
%token T_UNDEF "#undef"
%token T_DEBUG "#debug"
%token T_WARNING "#warning"
%token T_ERROR "#error"
%token T_FOPEN "#fopen"
%token T_FCLOSE "#fclose"
%token T_READ "#read"
%token T_WRITE "#write"
%token T_DEFAULT "#default"

/* Directive values (lib/sdl/directive.c and builtins.c). */
%token T_START_DECL "start of #declare"
%token T_START_ARG "start of macro argument"
%token T_START_STRING "start of string"
%token T_START_RANGE "start of #range"
%token T_START_FOR "start of #for"
%token T_START_INDEX "start of array index"
%token T_START_DEFAULT "start of #default"
%token T_DECL_END "end of declaration"
%token T_ARG_SEP "end of macro argument"
%token <value> T_STRING_ID "string identifier"
%token <value> T_ARRAY_ID "array identifier"
%token T_CONSTANT "built-in constant"
%token T_LE "<="
%token T_GE ">="
%token T_NE "!="
%token T_DEPRECATED "deprecated"
%token T_INSIDE "inside"
%token T_VTURBULENCE "vturbulence"
%token T_ONCE "once"
%token T_ACOSH "acosh"
%token T_ARRAY "array"
%token T_ASC "asc"
%token T_ASINH "asinh"
%token T_ATANH "atanh"
%token T_BITWISE_AND "bitwise_and"
%token T_BITWISE_OR "bitwise_or"
%token T_BITWISE_XOR "bitwise_xor"
%token T_CHR "chr"
%token T_CONCAT "concat"
%token T_DEFINED "defined"
%token T_DIMENSION_SIZE "dimension_size"
%token T_DIMENSIONS "dimensions"
%token T_FILE_EXISTS "file_exists"
%token T_RAND "rand"
%token T_SEED "seed"
%token T_SELECT "select"
%token T_STR "str"
%token T_STRCMP "strcmp"
%token T_STRLEN "strlen"
%token T_STRLWR "strlwr"
%token T_STRUPR "strupr"
%token T_SUBSTR "substr"
%token T_VAL "val"
%token T_VAXIS_ROTATE "vaxis_rotate"
%token T_VROTATE "vrotate"
%token T_VSTR "vstr"

%token T_ABS "abs"
%token T_ACOS "acos"
%token T_ADC_BAILOUT "adc_bailout"
%token T_AMBIENT "ambient"
%token T_AMBIENT_LIGHT "ambient_light"
%token T_ANGLE "angle"
%token T_ASIN "asin"
%token T_ASSUMED_GAMMA "assumed_gamma"
%token T_ATAN "atan"
%token T_ATAN2 "atan2"
%token T_BACKGROUND "background"
%token T_BLUE "blue"
%token T_BOX "box"
%token T_BRILLIANCE "brilliance"
%token T_CAMERA "camera"
%token T_CEIL "ceil"
%token T_COLOUR "colour"
%token T_CONE "cone"
%token T_CONSERVE_ENERGY "conserve_energy"
%token T_COS "cos"
%token T_COSH "cosh"
%token T_CYLINDER "cylinder"
%token T_DEGREES "degrees"
%token T_DIFFUSE "diffuse"
%token T_DIRECTION "direction"
%token T_DISC "disc"
%token T_DIV "div"
%token T_EMISSION "emission"
%token T_EXP "exp"
%token T_FALLOFF "falloff"
%token T_FALSE "false"
%token T_FILTER "filter"
%token T_GAMMA "gamma"
%token T_FINISH "finish"
%token T_FLOOR "floor"
%token T_FRESNEL "fresnel"
%token T_GLOBAL_SETTINGS "global_settings"
%token T_GRAY "gray"
%token T_GREEN "green"
%token T_INT "int"
%token T_INTERIOR "interior"
%token T_INVERSE "inverse"
%token T_IOR "ior"
%token T_LIGHT_SOURCE "light_source"
%token T_LN "ln"
%token T_LOCATION "location"
%token T_LOG "log"
%token T_LOOK_AT "look_at"
%token T_MATRIX "matrix"
%token T_MAX "max"
%token T_MAX_TRACE_LEVEL "max_trace_level"
%token T_METALLIC "metallic"
%token T_MIN "min"
%token T_MOD "mod"
%token T_NO "no"
%token T_NO_SHADOW "no_shadow"
%token T_NO_BUMP_SCALE "no_bump_scale"
%token T_FACETS "facets"
%token T_COORDS "coords"
%token T_SIZE "size"
%token T_NO_IMAGE "no_image"
%token T_CHARSET "charset"
%token T_ASCII "ascii"
%token T_UTF8 "utf8"
%token T_SYS "sys"
%token T_NO_REFLECTION "no_reflection"
%token T_DOUBLE_ILLUMINATE "double_illuminate"
%token T_IRID "irid"
%token T_IRID_WAVELENGTH "irid_wavelength"
%token T_THICKNESS "thickness"
%token T_SLOPE "slope"
%token T_ALTITUDE "altitude"
%token T_OBJECT "object"
%token T_OFF "off"
%token T_ON "on"
%token T_OPEN "open"
%token T_PERSPECTIVE "perspective"
%token T_PHONG "phong"
%token T_PHONG_SIZE "phong_size"
%token T_PI "pi"
%token T_PIGMENT "pigment"
%token T_PLANE "plane"
%token T_POW "pow"
%token T_RADIANS "radians"
%token T_RED "red"
%token T_REFLECTION "reflection"
%token T_RGB "rgb"
%token T_RGBF "rgbf"
%token T_RGBFT "rgbft"
%token T_RGBT "rgbt"
%token T_SRGB "srgb"
%token T_SRGBF "srgbf"
%token T_SRGBT "srgbt"
%token T_SRGBFT "srgbft"
%token T_RIGHT "right"
%token T_ROTATE "rotate"
%token T_ROUGHNESS "roughness"
%token T_SCALE "scale"
%token T_SHADOWLESS "shadowless"
%token T_SIN "sin"
%token T_SINH "sinh"
%token T_SKY "sky"
%token T_SPECULAR "specular"
%token T_SPHERE "sphere"
%token T_SQRT "sqrt"
%token T_T "t"
%token T_TAN "tan"
%token T_TANH "tanh"
%token T_TEXTURE "texture"
%token T_TRANSLATE "translate"
%token T_TRANSMIT "transmit"
%token T_TRIANGLE "triangle"
%token T_TRUE "true"
%token T_U "u"
%token T_UNION "union"
%token T_UP "up"
%token T_V "v"
%token T_VCROSS "vcross"
%token T_VDOT "vdot"
%token T_VLENGTH "vlength"
%token T_VNORMALIZE "vnormalize"
%token T_X "x"
%token T_Y "y"
%token T_YES "yes"
%token T_Z "z"
/* Meshes and text (lib/sdl/build_mesh.c). */
%token T_FACE_INDICES "face_indices"
%token T_HIERARCHY "hierarchy"
%token T_INSIDE_VECTOR "inside_vector"
%token T_INTERNAL "internal"
%token T_MESH "mesh"
%token T_MESH2 "mesh2"
%token T_NORMAL_INDICES "normal_indices"
%token T_NORMAL_VECTORS "normal_vectors"
%token T_SMOOTH_TRIANGLE "smooth_triangle"
%token T_TEXT "text"
%token T_TEXTURE_LIST "texture_list"
%token T_TTF "ttf"
%token T_UV_INDICES "uv_indices"
%token T_UV_VECTORS "uv_vectors"
%token T_UV_MAPPING "uv_mapping"
%token T_VERTEX_VECTORS "vertex_vectors"
/* CSG, quadrics and object modifiers (lib/sdl/build_object.c). */
%token T_BOUNDED_BY "bounded_by"
%token T_CLIPPED_BY "clipped_by"
%token T_DIFFERENCE "difference"
%token T_HOLLOW "hollow"
%token T_INTERSECTION "intersection"
%token T_MERGE "merge"
%token T_QUADRIC "quadric"
%token T_CUBIC "cubic"
%token T_POLY "poly"
%token T_QUARTIC "quartic"
/* Finite shapes (lib/sdl/build_shape.c). */
%token T_BEZIER_SPLINE "bezier_spline"
%token T_BLOB "blob"
/* isosurface (lib/sdl/build_iso.c). */
%token T_ISOSURFACE "isosurface"
%token T_CONTAINED_BY "contained_by"
%token T_ACCURACY "accuracy"
%token T_MAX_GRADIENT "max_gradient"
%token T_EVALUATE "evaluate"
%token T_MAX_TRACE "max_trace"
%token T_ALL_INTERSECTIONS "all_intersections"
/* height_field (lib/sdl/build_hf.c). */
%token T_HEIGHT_FIELD "height_field"
%token T_SMOOTH "smooth"
%token T_WATER_LEVEL "water_level"
%token T_PGM "pgm"
%token T_GIF "gif"
%token T_POT "pot"
%token T_TGA "tga"
%token T_BMP "bmp"
%token T_TIFF "tiff"
%token T_HDR "hdr"
%token T_EXR "exr"
%token T_LIGHT_GROUP "light_group"
%token T_GLOBAL_LIGHTS "global_lights"
%token T_HF_GRAY_16 "hf_gray_16"
%token T_OVUS "ovus"
%token T_PARAMETRIC "parametric"
%token T_PRECOMPUTE "precompute"
%token T_COMPONENT "component"
%token T_CONIC_SWEEP "conic_sweep"
%token T_CUBIC_SPLINE "cubic_spline"
%token T_LATHE "lathe"
%token T_LINEAR_SPLINE "linear_spline"
%token T_LINEAR_SWEEP "linear_sweep"
%token T_POLYGON "polygon"
%token T_PRISM "prism"
%token T_QUADRATIC_SPLINE "quadratic_spline"
%token T_SOR "sor"
%token T_STRENGTH "strength"
%token T_THRESHOLD "threshold"
%token T_STURM "sturm"
%token T_SUPERELLIPSOID "superellipsoid"
%token T_TORUS "torus"
/* bicubic_patch, sphere_sweep, julia_fractal (lib/sdl/build_surface.c). */
%token T_B_SPLINE "b_spline"
/* spline { ... } values (lib/sdl/spline.c). */
%token T_SPLINE "spline"
%token T_NATURAL_SPLINE "natural_spline"
%token <value> T_SPLINE_ID "spline identifier"
%token T_BICUBIC_PATCH "bicubic_patch"
%token T_CUBE "cube"
%token T_FLATNESS "flatness"
%token T_HYPERCOMPLEX "hypercomplex"
%token T_JULIA_FRACTAL "julia_fractal"
%token T_PRECISION "precision"
%token T_PWR "pwr"
%token T_QUATERNION "quaternion"
%token T_RECIPROCAL "reciprocal"
%token T_SLICE "slice"
%token T_SPHERE_SWEEP "sphere_sweep"
%token T_SQR "sqr"
%token T_TOLERANCE "tolerance"
%token T_TYPE "type"
%token T_U_STEPS "u_steps"
%token T_V_STEPS "v_steps"
/* Cameras, lights and atmosphere (lib/sdl/build_camlight.c). */
%token T_ADAPTIVE "adaptive"
%token T_APERTURE "aperture"
%token T_ARC_ANGLE "arc_angle"
%token T_AREA_ILLUMINATION "area_illumination"
%token T_AREA_LIGHT "area_light"
%token T_BLUR_SAMPLES "blur_samples"
%token T_CIRCULAR "circular"
%token T_CONFIDENCE "confidence"
%token T_DISTANCE "distance"
%token T_FADE_DISTANCE "fade_distance"
%token T_FADE_POWER "fade_power"
%token T_FADE_COLOUR "fade_color"
%token T_DISPERSION "dispersion"
%token T_DISPERSION_SAMPLES "dispersion_samples"
%token T_CAUSTICS "caustics"
%token T_FALLOFF_ANGLE "falloff_angle"
%token T_FISHEYE "fisheye"
%token T_FOCAL_POINT "focal_point"
%token T_FOG "fog"
%token T_FOG_ALT "fog_alt"
%token T_FOG_OFFSET "fog_offset"
%token T_FOG_TYPE "fog_type"
%token T_JITTER "jitter"
%token T_LOOKS_LIKE "looks_like"
%token T_MEDIA_ATTENUATION "media_attenuation"
%token T_MEDIA_INTERACTION "media_interaction"
%token T_OMNIMAX "omnimax"
%token T_MESH_CAMERA "mesh_camera"
%token T_ORIENT "orient"
%token T_ORTHOGRAPHIC "orthographic"
%token T_PANORAMIC "panoramic"
%token T_PARALLEL "parallel"
%token T_POINT_AT "point_at"
%token T_RADIUS "radius"
%token T_RAINBOW "rainbow"
%token T_SKY_SPHERE "sky_sphere"
%token T_SPOTLIGHT "spotlight"
%token T_TIGHTNESS "tightness"
%token T_TURB_DEPTH "turb_depth"
%token T_ULTRA_WIDE_ANGLE "ultra_wide_angle"
%token T_VARIANCE "variance"
%token T_WIDTH "width"
/* Radiosity (lib/sdl/build_radiosity.c): POV-Ray's items of
   global_settings { radiosity { } } and of objects, then zRcube's own. */
%token T_RADIOSITY "radiosity"
%token T_NO_RADIOSITY "no_radiosity"
%token T_IMPORTANCE "importance"
%token T_ALWAYS_SAMPLE "always_sample"
%token T_BRIGHTNESS "brightness"
%token T_COUNT "count"
%token T_ERROR_BOUND "error_bound"
%token T_GRAY_THRESHOLD "gray_threshold"
%token T_LOW_ERROR_FACTOR "low_error_factor"
%token T_MAX_SAMPLE "max_sample"
%token T_MAXIMUM_REUSE "maximum_reuse"
%token T_MEDIA "media"
%token T_MINIMUM_REUSE "minimum_reuse"
%token T_NEAREST_COUNT "nearest_count"
%token T_PRETRACE_END "pretrace_end"
%token T_PRETRACE_START "pretrace_start"
%token T_RECURSION_LIMIT "recursion_limit"
%token T_SUBSURFACE "subsurface"
%token T_MM_PER_UNIT "mm_per_unit"
%token T_TRANSLUCENCY "translucency"
%token T_SAVE_FILE "save_file"
%token T_LOAD_FILE "load_file"
%token T_ENERGY "energy"
%token T_BF_BOUND "bf_bound"
%token T_MINIMUM_AREA "minimum_area"
%token T_VISIBILITY_COUNT "visibility_count"
%token T_MAX_ITERATIONS "max_iterations"
%token T_RESIDUAL_BOUND "residual_bound"
/* Media, interior_texture and photons (lib/sdl/build_media.c). */
%token <value> T_MEDIA_ID "media identifier"
%token <value> T_DENSITY_ID "density identifier"
%token T_AA_LEVEL "aa_level"
%token T_AA_THRESHOLD "aa_threshold"
%token T_ABSORPTION "absorption"
%token T_DENSITY "density"
%token T_DENSITY_MAP "density_map"
%token T_DENSITY_FILE "density_file"
%token T_DF3 "df3"
%token T_ECCENTRICITY "eccentricity"
%token T_EXTINCTION "extinction"
%token T_INTERVALS "intervals"
%token T_METHOD "method"
%token T_RATIO "ratio"
%token T_SAMPLES "samples"
%token T_SCATTERING "scattering"
%token T_INTERIOR_TEXTURE "interior_texture"
%token T_PHOTONS "photons"
%token T_AUTOSTOP "autostop"
%token T_COLLECT "collect"
%token T_EXPAND_THRESHOLDS "expand_thresholds"
%token T_GATHER "gather"
%token T_PASS_THROUGH "pass_through"
%token T_REFRACTION "refraction"
%token T_SPACING "spacing"
%token T_TARGET "target"
%type <medium> media media_body scattering_body
%type <pigment> density
%type <map> density_map density_blocks
%type <token> photon_kw
%type <photons> photon_items
%type <phargs> photon_args
%type <fog> fog_body
%type <sky> sky_body
%type <rainbow> rainbow_body

%type <expr> expr primary colour_value colour_spec colour_rgb colour_other
%type <expr> init_colour init_colour_spec init_colour_other
%type <list> list
%type <cmod> colour_item colour_whole
%type <token> func dot_item
%type <value> rvalue other_value init_value
/* Directive values and the expressions only they and parentheses hold
   (comparisons, logic, '? :'), strings and arrays. */
%type <expr> cexpr
%type <list> args dims
%type <str> str_expr str_list hf_file image_map_file
%type <decl> decl_target
%type <token> decl_end arg_end str_func init_begin
%type <object> light_group_head
%type <lgroup> light_group_body
%type <object> object object_body object_head union_head union_body
%type <object> difference_head clip_objects polygon_head
%type <object> poly_head poly_coefs
%type <object> prism_start prism_head lathe_start lathe_head
%type <object> blob_head blob_component sor_head
%type <object> iso_head hf_head par_head
%type <fn> par_fn
%type <expr> blob_strength
%type <token> prism_option
%type <mod> object_mod object_mod_other
%type <token> rad_kw
%type <transform> transform transform_value
%type <tblock> transform_block
%type <fractal> fractal fractal_head
%type <fn> fn_pattern
%type <object> pattern_object
%type <pigment> pigment pigment_start pigment_body
%type <pigment> pigment_start_bare pigment_body_bare
%type <token> pattern_kw block_kw
%type <clist> colour_list colour_list_items
%type <pmod> pattern_mod warp_body warp_item
%type <cmap> colour_map colour_map_head colour_map_body
%type <normal> normal normal_start normal_body bump_map_body
%type <imap> image_map_body material_map_head
%type <imap> image_pattern image_pattern_body
%type <bitmap> bitmap_file
%type <bmod> bitmap_mod
%type <finish> finish finish_head finish_body irid_body
%type <refl> reflection
%type <texture> texture texture_start texture_body layered_texture
%type <map> pigment_map pigment_map_body normal_map normal_map_body
%type <map> texture_map texture_map_body slope_map slope_map_body
%type <slope> slope_block slope_dir
%type <map> pigment_blocks normal_blocks texture_blocks material_textures
%type <material> material material_body
%type <token> spiral_kw
%type <expr> colour_kw_value
%type <interior> interior interior_head interior_body
%type <light> light_body light_done light_object
%type <object> mesh_head mesh2_head mesh2_list texture_list
%type <texture> mesh_texture
%type <token> mesh2_keyword
%type <object> patch_head sweep_head julia_head
%type <token> patch_item sweep_spline julia_function
%type <spline> spline spline_body
%type <token> spline_type

/* OPTIONAL_COMMA ranks below the operators, so "<0,0,0> -1" reads as a
   subtraction, as in POV-Ray, rather than as a missing comma. */
%precedence OPTIONAL_COMMA
/* spline { S (t) ... }: S(t) is a call, not a copy of S then a
   parenthesized parameter, as in POV-Ray. */
%precedence SPLINE_COPY
%precedence '('
/* In an array initialiser, whose elements need no commas between them,
   a token that can continue an element does ("{rgb 1 red 0}" is one
   colour, "{texture {A} texture {B}}" one layered texture, "array[2]
   {...}" an initialised array), as in POV-Ray. */
%precedence '{' T_TEXTURE T_RED T_GREEN T_BLUE T_FILTER T_TRANSMIT
%precedence T_OPEN /* isosurface { ... open }: see iso_head */
%right '?'
%left '|'
%left '&'
%left '<' '>' '=' T_LE T_GE T_NE
%left '+' '-'
%left '*' '/'
%precedence NEG

%%

start:
  T_START_SCENE items
| T_START_PAREN '(' cexpr ')'  { p->nested_value = $3; YYACCEPT; }
| T_START_VERSION expr ';'   { p->nested_value = $2; YYACCEPT; }
| T_START_DECL decl_target '=' rvalue decl_end
    {
      /* POV-Ray 3.7 refuses a float, vector or colour declared without
         its ';' when the language version is 3.5 or later (the default
         without #version) and only warns below ("Possible Parse Error"),
         measured: tests/test_refused.sh. */
      if (!$5 && $4.kind <= ZR_SDL_COLOUR) {
        const char *d = $2.local ? "#local" : "#declare";
        if (p->version >= 3.5 - 1e-9) {
          zr__sdl_error(p, ZR_ESYNTAX, &@4, "'%s' of a float, vector or "
                        "colour needs ';' at its end when the language "
                        "version is 3.5 or later (it is %g here): add the "
                        "';', or set '#version 3.1;'", d, p->version);
          YYABORT;
        }
        zr__sdl_warning(p, &@4, "'%s' of a float, vector or colour "
                                "should end with ';'", d);
      }
      TRY(zr__sdl_define(p, &$2, $2.local, &$4, &@2));
      YYACCEPT;
    }
| T_START_ARG rvalue arg_end
    { p->nested_rvalue = $2; p->nested_end = $3; YYACCEPT; }
| T_START_STRING str_expr
    { p->nested_rvalue = pointer_value(ZR_SDL_STRING, $2); YYACCEPT; }
| T_START_RANGE '(' cexpr ',' cexpr ')'
    {
      p->nested_list.n = 0;
      TRY(zr__sdl_list_add(p, &p->nested_list, &$3, &@3));
      TRY(zr__sdl_list_add(p, &p->nested_list, &$5, &@5));
      YYACCEPT;
    }
| T_START_FOR ',' cexpr ',' cexpr ')'
    {
      p->nested_list.n = 0;
      TRY(zr__sdl_list_add(p, &p->nested_list, &$3, &@3));
      TRY(zr__sdl_list_add(p, &p->nested_list, &$5, &@5));
      YYACCEPT;
    }
| T_START_FOR ',' cexpr ',' cexpr ',' cexpr ')'
    {
      p->nested_list.n = 0;
      TRY(zr__sdl_list_add(p, &p->nested_list, &$3, &@3));
      TRY(zr__sdl_list_add(p, &p->nested_list, &$5, &@5));
      TRY(zr__sdl_list_add(p, &p->nested_list, &$7, &@7));
      YYACCEPT;
    }
| T_START_INDEX '[' cexpr ']'  { p->nested_value = $3; YYACCEPT; }
| T_START_DEFAULT '{' default_items '}'  { YYACCEPT; }
/* function { pigment { ... } } and function { pattern { ... } }
   (lib/sdl/function.c): nothing is read past the closing brace. */
| T_START_FN_TEXTURE pigment
    { p->nested_rvalue = pointer_value(ZR_SDL_PIGMENT, $2); YYACCEPT; }
| T_START_FN_TEXTURE T_PATTERN '{' pigment_body '}'
    { p->nested_rvalue = pointer_value(ZR_SDL_PIGMENT, $4); YYACCEPT; }
/* function { spline { ... } } likewise. */
| T_START_FN_SPLINE spline
    { p->nested_rvalue = pointer_value(ZR_SDL_SPLINE, $2); YYACCEPT; }
/* function { transform { ... } } likewise. */
| T_START_FN_TRANSFORM transform_value
    { p->nested_rvalue = pointer_value(ZR_SDL_TRANSFORM, $2); YYACCEPT; }
;

items:
  %empty
| items item
;

item:
  object               { TRY(zr__sdl_add_object(p, $1, &@1)); }
/* An object identifier alone as a statement: POV-Ray 3.7 renders the
   object, with or without #version, and does not warn (measured:
   tests/legacy/bare_object.pov). */
| T_OBJECT_ID
    {
      zr_object *copy = zr__sdl_object_copy(p, $1.ptr);
      TRY(copy);
      TRY(zr__sdl_add_object(p, copy, &@1));
    }
| camera
| light
/* A light_source identifier alone, likewise: POV-Ray 3.7 adds the light
   (measured: tests/legacy/bare_light.pov). */
| T_LIGHT_ID
    {
      zr_light *copy = zr__sdl_light_copy(p, $1.ptr);
      TRY(copy);
      TRY(zr__sdl_light_add(p, copy, &@1));
    }
| background
| fog_body '}'         { zr__sdl_fog_end(p, $1); }
| sky_body '}'         { TRY(zr__sdl_sky_end(p, $1, &@1)); }
| rainbow_body '}'     { TRY(zr__sdl_rainbow_end(p, $1, &@1)); }
| global_settings
| media                { TRY(zr__sdl_atmosphere_media(p, $1)); }
;

/* ---- #declare and #local (run by the engine through T_START_DECL) ---- */

/* An array element is assigned with "#declare A[i][j] = ...". */
decl_target:
  T_DECL_NAME          { $$ = $1; $$.n_index = 0; }
| decl_target '[' cexpr ']'
    {
      double index;
      $$ = $1;
      TRY(zr__sdl_want_float(p, &$3, &@3, &index));
      if ($$.n_index == ZR_SDL_MAX_DIMS) {
        zr__sdl_error(p, ZR_ESYNTAX, &@3, "an array has at most %d "
                      "dimensions", ZR_SDL_MAX_DIMS);
        YYABORT;
      }
      $$.index[$$.n_index++] = (int)index;
    }
;

/* POV-Ray wants the semicolon after floats, vectors and colours (it
   warns without one) and accepts it after the rest; without it the
   engine ends the declaration with T_DECL_END. */
decl_end:
  ';'                  { $$ = 1; }
| T_DECL_END           { $$ = 0; }
;

/* T_ARG_SEP: the engine ends an argument that is a block (an object, a
   texture ...) when no ',' follows it, as POV-Ray does (shapes.pov:
   "Align_Object(Center_Object(...) -y, <0,0,0>)"). */
arg_end:
  ','                  { $$ = ','; }
| ')'                  { $$ = ')'; }
| T_ARG_SEP            { $$ = ','; }
;

rvalue:
  colour_value  { $$ = numeric_value(&$1); }
| other_value
;

/* Every value but a float, vector or colour. */
other_value:
  T_PIGMENT_ID  { $$ = $1; }
| T_FINISH_ID   { $$ = $1; }
| T_TEXTURE_ID  { $$ = $1; }
| T_INTERIOR_ID { $$ = $1; }
| T_MEDIA_ID    { $$ = $1; }
| media         { $$ = pointer_value(ZR_SDL_MEDIA, $1); }
| T_DENSITY_ID  { $$ = $1; }
| density       { $$ = pointer_value(ZR_SDL_DENSITY, $1); }
| T_OBJECT_ID   { $$ = $1; }
| T_NORMAL_ID   { $$ = $1; }
| T_COLOUR_MAP_ID { $$ = $1; }
| T_MATERIAL_ID { $$ = $1; }
| T_SKY_SPHERE_ID { $$ = $1; }
| sky_body '}'  { $$ = pointer_value(ZR_SDL_SKY_SPHERE, $1); }
| T_CAMERA_ID   { $$ = $1; }
| T_LIGHT_ID    { $$ = $1; }
| light_done    { $$ = pointer_value(ZR_SDL_LIGHT, $1); }
| camera
    {
      const zr_camera *c;
      TRY(c = zr__sdl_camera_value(p));
      $$ = pointer_value(ZR_SDL_CAMERA, c);
    }
| material      { $$ = pointer_value(ZR_SDL_MATERIAL, $1); }
| normal        { $$ = pointer_value(ZR_SDL_NORMAL, $1); }
| colour_map    { $$ = pointer_value(ZR_SDL_COLOUR_MAP, $1); }
| T_FUNCTION_ID %prec SPLINE_COPY { $$ = $1; }
| T_TRANSFORM_ID { $$ = $1; }
| transform_value { $$ = pointer_value(ZR_SDL_TRANSFORM, $1); }
| T_SPLINE_ID %prec SPLINE_COPY { $$ = $1; }
| spline        { $$ = pointer_value(ZR_SDL_SPLINE, $1); }
| T_FUNCTION
    {
      /* The state after 'function' only reduces, so bison has read
         nothing past it and the compiler can take the body straight
         from the token array; the check keeps that promise honest. */
      if (yychar != ZR__POV_EMPTY) {
        zr__sdl_error(p, ZR_ESYNTAX, &@1, "internal error: the parser "
                      "looked past 'function'");
        YYABORT;
      }
      const zr_fn *fn = zr__sdl_function_parse(p, &@1);
      TRY(fn);
      $$ = pointer_value(ZR_SDL_FUNCTION, fn);
    }
| pigment       { $$ = pointer_value(ZR_SDL_PIGMENT, $1); }
| finish        { $$ = pointer_value(ZR_SDL_FINISH, $1); }
| layered_texture %prec OPTIONAL_COMMA
    { $$ = pointer_value(ZR_SDL_TEXTURE, $1); }
| interior      { $$ = pointer_value(ZR_SDL_INTERIOR, $1); }
| object        { $$ = pointer_value(ZR_SDL_OBJECT, $1); }
| str_expr      { $$ = pointer_value(ZR_SDL_STRING, $1); }
| T_ARRAY_ID
    {
      zr_sdl_array *a;
      TRY(a = zr__sdl_array_copy(p, $1.ptr));
      $$ = pointer_value(ZR_SDL_ARRAY, a);
    }
| T_ARRAY dims %prec OPTIONAL_COMMA
    {
      zr_sdl_array *a;
      TRY(list_done(p, $2, (a = zr__sdl_array_new(p, $2, &@2)) != NULL));
      $$ = pointer_value(ZR_SDL_ARRAY, a);
    }
| T_ARRAY dims init_begin init_items opt_comma '}'
    {
      zr_sdl_array *a;
      TRY(list_done(p, $2, (a = zr__sdl_array_new(p, $2, &@2)) != NULL));
      TRY(zr__sdl_array_init(p, a, (size_t)$3, &@$));
      $$ = pointer_value(ZR_SDL_ARRAY, a);
    }
;

/* trace()'s fourth argument names the variable that gets the normal,
   declared or not: the state after its ',' only reduces this, so the
   engine has not read the name yet when it is told to hand it over as
   a name. */
trace_normal:
  %empty               { p->want_decl_name = true; p->decl_local = false; }
;

/* ---- #default ---- */

default_items:
  %empty
| default_items default_item
;

default_item:
  texture              { TRY(zr__sdl_set_default(p, $1, NULL, NULL)); }
| pigment              { TRY(zr__sdl_set_default(p, NULL, $1, NULL)); }
| finish               { TRY(zr__sdl_set_default(p, NULL, NULL, $1)); }
| normal
    {
      zr_texture *t;
      TRY(t = zr__sdl_texture_new(p, p->scene->default_texture));
      t->normal = $1;
      TRY(zr__sdl_set_default(p, t, NULL, NULL));
    }
;

/* ---- arrays ---- */

dims:
  '[' cexpr ']'
    { TRY($$ = zr__sdl_list_new(p)); TRY(zr__sdl_list_add(p, $$, &$2, &@2)); }
| dims '[' cexpr ']'   { $$ = $1; TRY(zr__sdl_list_add(p, $$, &$3, &@3)); }
;

/* The elements of every level go to p->init in row-major order; the
   value is where this initialiser's elements start. */
init_begin:
  '{'                  { $$ = (int)p->n_init; }
;

/* POV-Ray reads the elements without commas between them too
   (lemon.inc: "<0.1, 9.4> <0.1, 9.4>"), and a comparison, '&', '|' or
   '?:' outside parentheses is none of an element's business there (as
   in any of its float expressions): "{1 <3,4>}" is two elements and
   "{1 -2}" one, -1, since an operator continues the element. */
init_items:
  init_item
| init_items comma init_item
;

init_item:
  init_value           { TRY(zr__sdl_init_add(p, &$1, &@1)); }
| '{' init_items opt_comma '}'
;

init_value:
  init_colour          { $$ = numeric_value(&$1); }
| other_value
;

/* colour_value with expr where it has cexpr. */
init_colour:
  T_COLOUR init_colour_spec
    {
      $$ = $2;
      if ($$.dim != 5) {
        zr_sdl_colour_mod none = {0, $$, @2};
        TRY(zr__sdl_colour_apply(p, &$$, &none));
      }
    }
| init_colour_spec
;

init_colour_spec:
  colour_rgb %prec OPTIONAL_COMMA
| init_colour_other %prec OPTIONAL_COMMA
;

init_colour_other:
  expr %prec OPTIONAL_COMMA
| colour_item
    {
      $$ = zr__sdl_colour_expr(zr_colour5(0, 0, 0, 0, 0));
      TRY(zr__sdl_colour_apply(p, &$$, &$1));
    }
| init_colour_other colour_item
    { $$ = $1; TRY(zr__sdl_colour_apply(p, &$$, &$2)); }
;

/* POV-Ray accepts a comma after an initialiser's last element. */
opt_comma:
  %empty
| ','
;

/* ---- strings ---- */

str_expr:
  T_STRING
| T_STRING_ID          { $$ = $1.ptr; }
| T_CONCAT '(' str_list ')' { $$ = $3; }
| T_STR '(' cexpr ',' cexpr ',' cexpr ')'
    {
      double v, w, prec;
      TRY(zr__sdl_want_any_float(p, &$3, &@3, &v));
      TRY(zr__sdl_want_float(p, &$5, &@5, &w));
      TRY(zr__sdl_want_float(p, &$7, &@7, &prec));
      TRY($$ = zr__sdl_str(p, v, w, prec, &@$));
    }
| T_VSTR '(' cexpr ',' cexpr ',' str_expr ',' cexpr ',' cexpr ')'
    {
      double n, w, prec;
      TRY(zr__sdl_want_float(p, &$3, &@3, &n));
      TRY(zr__sdl_want_float(p, &$9, &@9, &w));
      TRY(zr__sdl_want_float(p, &$11, &@11, &prec));
      TRY($$ = zr__sdl_vstr(p, n, &$5, $7, w, prec, &@$));
    }
| T_CHR '(' cexpr ')'
    {
      double code;
      TRY(zr__sdl_want_float(p, &$3, &@3, &code));
      TRY($$ = zr__sdl_chr(p, code, &@3));
    }
| T_SUBSTR '(' str_expr ',' cexpr ',' cexpr ')'
    {
      double start, len;
      TRY(zr__sdl_want_float(p, &$5, &@5, &start));
      TRY(zr__sdl_want_float(p, &$7, &@7, &len));
      TRY($$ = zr__sdl_substr(p, $3, start, len, &@$));
    }
| T_STRUPR '(' str_expr ')' { TRY($$ = zr__sdl_strcase(p, $3, true)); }
| T_STRLWR '(' str_expr ')' { TRY($$ = zr__sdl_strcase(p, $3, false)); }
;

str_list:
  str_expr
| str_list ',' str_expr { TRY($$ = zr__sdl_concat(p, $1, $3)); }
;

str_func:
  T_ASC { $$ = T_ASC; }     | T_STRLEN { $$ = T_STRLEN; }
| T_VAL { $$ = T_VAL; }     | T_FILE_EXISTS { $$ = T_FILE_EXISTS; }
;

/* POV-Ray lets the comma between the items of an object or light be
   left out ("sphere { <0,0,0> 1 }"); the vectors' commas stay. */
comma:
  %empty %prec OPTIONAL_COMMA
| ','
;

/* ---- expressions ---- */

/* Conditions: '?:' below '|' below '&' below the comparisons, as in the
   reference manual's "Float Operators" (by precedence, which keeps
   the chain of unit reductions per operand short).  They are written inside
   parentheses, function arguments and directive values, where a '<'
   after an operand cannot start a vector. */
cexpr:
  expr
| cexpr '?' cexpr ':' cexpr %prec '?'
    {
      bool c;
      TRY(zr__sdl_truth(p, &$1, &@1, &c));
      $$ = c ? $3 : $5;
    }
| cexpr '|' cexpr      { TRY(zr__sdl_compare(p, '|', &$1, &$3, &@2, &$$)); }
| cexpr '&' cexpr      { TRY(zr__sdl_compare(p, '&', &$1, &$3, &@2, &$$)); }
| cexpr '<' cexpr      { TRY(zr__sdl_compare(p, '<', &$1, &$3, &@2, &$$)); }
| cexpr '>' cexpr      { TRY(zr__sdl_compare(p, '>', &$1, &$3, &@2, &$$)); }
| cexpr '=' cexpr      { TRY(zr__sdl_compare(p, '=', &$1, &$3, &@2, &$$)); }
| cexpr T_LE cexpr     { TRY(zr__sdl_compare(p, T_LE, &$1, &$3, &@2, &$$)); }
| cexpr T_GE cexpr     { TRY(zr__sdl_compare(p, T_GE, &$1, &$3, &@2, &$$)); }
| cexpr T_NE cexpr     { TRY(zr__sdl_compare(p, T_NE, &$1, &$3, &@2, &$$)); }
/* Strings compare as strcmp orders them (meshcam_macros.inc: "#if
   (c_file != "")"). */
| str_expr '=' str_expr
    { $$ = zr__sdl_float(strcmp($1, $3) == 0); }
| str_expr T_NE str_expr
    { $$ = zr__sdl_float(strcmp($1, $3) != 0); }
| str_expr '<' str_expr
    { $$ = zr__sdl_float(strcmp($1, $3) < 0); }
| str_expr '>' str_expr
    { $$ = zr__sdl_float(strcmp($1, $3) > 0); }
| str_expr T_LE str_expr
    { $$ = zr__sdl_float(strcmp($1, $3) <= 0); }
| str_expr T_GE str_expr
    { $$ = zr__sdl_float(strcmp($1, $3) >= 0); }
;

args:
  cexpr
    { TRY($$ = zr__sdl_list_new(p)); TRY(zr__sdl_list_add(p, $$, &$1, &@1)); }
| args ',' cexpr       { $$ = $1; TRY(zr__sdl_list_add(p, $$, &$3, &@3)); }
;

expr:
  expr '+' expr        { TRY(zr__sdl_binop(p, '+', &$1, &$3, &@2, &$$)); }
| expr '-' expr        { TRY(zr__sdl_binop(p, '-', &$1, &$3, &@2, &$$)); }
| expr '*' expr        { TRY(zr__sdl_binop(p, '*', &$1, &$3, &@2, &$$)); }
| expr '/' expr        { TRY(zr__sdl_binop(p, '/', &$1, &$3, &@2, &$$)); }
| '-' expr %prec NEG   { $$ = $2; zr__sdl_negate(&$$); }
| '+' expr %prec NEG   { $$ = $2; }
| '!' expr %prec NEG
    {
      /* POV-Ray calls values within 1e-10 of zero false ("Numeric
         Expressions"). */
      double v;
      TRY(zr__sdl_want_float(p, &$2, &@2, &v));
      $$ = zr__sdl_float(fabs(v) < 1e-10 ? 1 : 0);
    }
| primary
;

primary:
  T_NUMBER             { $$ = zr__sdl_float($1); }
| T_FLOAT_ID           { $$ = $1.num; }
| T_VECTOR_ID          { $$ = $1.num; }
| T_COLOUR_ID          { $$ = $1.num; }
| '(' cexpr ')'        { $$ = $2; }
| '<' list '>'
    { TRY(list_done(p, $2, zr__sdl_from_list(p, $2, &@$, &$$))); }
/* POV-Ray reads a comma before the '>' ("rgb<0.2,0.1,0.5,>"). */
| '<' list ',' '>'
    { TRY(list_done(p, $2, zr__sdl_from_list(p, $2, &@$, &$$))); }
| T_X                  { $$ = zr__sdl_vec(1, 0, 0); }
| T_Y                  { $$ = zr__sdl_vec(0, 1, 0); }
| T_Z                  { $$ = zr__sdl_vec(0, 0, 1); }
| T_T
    {
      $$ = zr__sdl_vec(0, 0, 0);
      $$.dim = 4;
      $$.v[3] = 1;
    }
| T_U                  { $$ = zr__sdl_vec(1, 0, 0); $$.dim = 2; }
| T_V                  { $$ = zr__sdl_vec(0, 1, 0); $$.dim = 2; }
| T_PI                 { $$ = zr__sdl_float(3.14159265358979323846); }
| T_TRUE               { $$ = zr__sdl_float(1); }
| T_YES                { $$ = zr__sdl_float(1); }
| T_ON                 { $$ = zr__sdl_float(1); }
| T_FALSE              { $$ = zr__sdl_float(0); }
| T_NO                 { $$ = zr__sdl_float(0); }
| T_OFF                { $$ = zr__sdl_float(0); }
| func '(' args ')'
    { TRY(list_done(p, $3, zr__sdl_call(p, $1, $3, &@$, &$$))); }
| str_func '(' str_expr ')'
    { TRY(zr__sdl_string_float(p, $1, $3, &@$, &$$)); }
| T_STRCMP '(' str_expr ',' str_expr ')'
    {
      int c = strcmp($3, $5);
      $$ = zr__sdl_float(c < 0 ? -1 : c > 0);
    }
| T_DIMENSIONS '(' T_ARRAY_ID ')'
    { $$ = zr__sdl_float(((const zr_sdl_array *)$3.ptr)->n_dims); }
| T_DIMENSION_SIZE '(' T_ARRAY_ID ',' cexpr ')'
    {
      double d;
      TRY(zr__sdl_want_float(p, &$5, &@5, &d));
      TRY(zr__sdl_dimension_size(p, $3.ptr, d, &@5, &$$));
    }
  /* seed(n) is a number in POV-Ray 3.7, the new stream's place among
     all made so far (0, 1, ...): it needs a #declare's ';', and can be
     computed with ("(Rotate_Y + clock) * City_Seed", mjhorvath's
     GSprites_Scenery_prototypes.inc); rand(n) takes stream n (measured:
     tests/refused/seed_number.pov). */
| T_SEED '(' cexpr ')'
    {
      double n;
      TRY(zr__sdl_want_float(p, &$3, &@3, &n));
      TRY(zr__sdl_seed(p, n));
      $$ = zr__sdl_float((double)(p->n_seeds - 1));
    }
| T_RAND '(' cexpr ')'
    {
      double n;
      const zr_sdl_rand *r;
      TRY(zr__sdl_want_float(p, &$3, &@3, &n));
      TRY(r = zr__sdl_seed_numbered(p, n, &@3));
      $$ = zr__sdl_float(zr__sdl_rand(r));
    }
| T_TRACE '(' T_OBJECT_ID ',' expr ',' expr ')'
    { TRY(zr__sdl_trace(p, $3.ptr, &$5, &$7, NULL, &@$, &$$)); }
| T_TRACE '(' T_OBJECT_ID ',' expr ',' expr ',' trace_normal T_DECL_NAME ')'
    { TRY(zr__sdl_trace(p, $3.ptr, &$5, &$7, &$10, &@$, &$$)); }
| T_MIN_EXTENT '(' T_OBJECT_ID ')'  { $$ = zr__sdl_extent(p, $3.ptr, false); }
| T_MAX_EXTENT '(' T_OBJECT_ID ')'  { $$ = zr__sdl_extent(p, $3.ptr, true); }
| T_INSIDE '(' T_OBJECT_ID ',' expr ')'
    { TRY(zr__sdl_inside(p, $3.ptr, &$5, &@5, &$$)); }
| T_VTURBULENCE '(' expr ',' expr ',' expr ',' expr ')'
    { TRY(zr__sdl_vturbulence(p, &$3, &$5, &$7, &$9, &@$, &$$)); }
| T_VAXIS_ROTATE '(' expr ',' expr ',' expr ')'
    { TRY(zr__sdl_vaxis_rotate(p, &$3, &$5, &$7, &@$, &$$)); }
| T_VROTATE '(' expr ',' expr ')'
    { TRY(zr__sdl_vrotate(p, &$3, &$5, &@$, &$$)); }
| T_FUNCTION_ID '(' list ')'
    {
      TRY(list_done(p, $3, zr__sdl_function_call(p, $1.ptr, $3, &@1, &@$,
                                                  &$$)));
    }
| T_SPLINE_ID '(' cexpr ')'
    {
      double t;
      TRY(zr__sdl_want_float(p, &$3, &@3, &t));
      $$ = zr__sdl_spline_value($1.ptr, -1, t);
    }
| T_SPLINE_ID '(' cexpr ',' spline_type ')'
    {
      double t;
      TRY(zr__sdl_want_float(p, &$3, &@3, &t));
      $$ = zr__sdl_spline_value($1.ptr, $5, t);
    }
| T_VLENGTH '(' expr ')'
    { TRY(zr__sdl_vcall(p, T_VLENGTH, &$3, NULL, &@$, &$$)); }
| T_VNORMALIZE '(' expr ')'
    { TRY(zr__sdl_vcall(p, T_VNORMALIZE, &$3, NULL, &@$, &$$)); }
| T_VDOT '(' expr ',' expr ')'
    { TRY(zr__sdl_vcall(p, T_VDOT, &$3, &$5, &@$, &$$)); }
| T_VCROSS '(' expr ',' expr ')'
    { TRY(zr__sdl_vcall(p, T_VCROSS, &$3, &$5, &@$, &$$)); }
| primary '.' dot_item { TRY(zr__sdl_dot(p, &$1, $3, &@3, &$$)); }
;

/* The commas between a vector's components may be left out, as
   POV-Ray's own woods.inc does ("translate < -1 0 0 >"); an operator
   after a component still continues it ("<1 -2>" is <-1>), since
   OPTIONAL_COMMA ranks below the operators. */
list:
  expr %prec OPTIONAL_COMMA
    { TRY($$ = zr__sdl_list_new(p)); TRY(zr__sdl_list_add(p, $$, &$1, &@1)); }
| list comma expr %prec OPTIONAL_COMMA
    { $$ = $1; TRY(zr__sdl_list_add(p, $$, &$3, &@3)); }
;

func:
  T_SIN { $$ = T_SIN; }     | T_COS { $$ = T_COS; }
| T_TAN { $$ = T_TAN; }     | T_ASIN { $$ = T_ASIN; }
| T_ACOS { $$ = T_ACOS; }   | T_ATAN { $$ = T_ATAN; }
| T_ATAN2 { $$ = T_ATAN2; } | T_SINH { $$ = T_SINH; }
| T_COSH { $$ = T_COSH; }   | T_TANH { $$ = T_TANH; }
| T_SQRT { $$ = T_SQRT; }   | T_POW { $$ = T_POW; }
| T_ABS { $$ = T_ABS; }     | T_MIN { $$ = T_MIN; }
| T_MAX { $$ = T_MAX; }     | T_EXP { $$ = T_EXP; }
| T_LOG { $$ = T_LOG; }     | T_LN { $$ = T_LN; }
| T_FLOOR { $$ = T_FLOOR; } | T_CEIL { $$ = T_CEIL; }
| T_INT { $$ = T_INT; }     | T_MOD { $$ = T_MOD; }
| T_DIV { $$ = T_DIV; }     | T_DEGREES { $$ = T_DEGREES; }
| T_RADIANS { $$ = T_RADIANS; }
| T_ACOSH { $$ = T_ACOSH; } | T_ASINH { $$ = T_ASINH; }
| T_ATANH { $$ = T_ATANH; } | T_SELECT { $$ = T_SELECT; }
| T_BITWISE_AND { $$ = T_BITWISE_AND; }
| T_BITWISE_OR { $$ = T_BITWISE_OR; }
| T_BITWISE_XOR { $$ = T_BITWISE_XOR; }
;

dot_item:
  T_X { $$ = T_X; }               | T_Y { $$ = T_Y; }
| T_Z { $$ = T_Z; }               | T_T { $$ = T_T; }
| T_U { $$ = T_U; }               | T_V { $$ = T_V; }
| T_RED { $$ = T_RED; }           | T_GREEN { $$ = T_GREEN; }
| T_BLUE { $$ = T_BLUE; }         | T_FILTER { $$ = T_FILTER; }
| T_TRANSMIT { $$ = T_TRANSMIT; } | T_GRAY { $$ = T_GRAY; }
;

/* ---- colours ---- */

/* "colour" in front makes any value a colour; without it an expression
   with no colour items keeps its own type (#declare A = 1; is a float). */
colour_value:
  colour_kw_value
| colour_spec
;

colour_kw_value:
  T_COLOUR colour_spec
    {
      $$ = $2;
      if ($$.dim != 5) {
        zr_sdl_colour_mod none = {0, $$, @2};
        TRY(zr__sdl_colour_apply(p, &$$, &none));
      }
    }
;

/* A colour is an expression, or rgb/rgbf/rgbt/rgbft and then any
   component items ("rgb <0,1,0> red 1"), or component items alone.  A
   second rgb starts another colour, as in POV-Ray, where "color rgb 1
   rgb 0" is an error and "checker rgb 1 rgb <1,0,0>" two colours. */
colour_spec:
  colour_rgb
| colour_other
;

colour_rgb:
  colour_whole
    {
      $$ = zr__sdl_colour_expr(zr_colour5(0, 0, 0, 0, 0));
      TRY(zr__sdl_colour_apply(p, &$$, &$1));
    }
| colour_rgb colour_item
    { $$ = $1; TRY(zr__sdl_colour_apply(p, &$$, &$2)); }
;

colour_other:
  cexpr
| colour_item
    {
      $$ = zr__sdl_colour_expr(zr_colour5(0, 0, 0, 0, 0));
      TRY(zr__sdl_colour_apply(p, &$$, &$1));
    }
| colour_other colour_item
    { $$ = $1; TRY(zr__sdl_colour_apply(p, &$$, &$2)); }
;

colour_whole:
  T_RGB expr %prec OPTIONAL_COMMA
    { $$.token = T_RGB; $$.value = $2; $$.loc = @2; }
| T_RGBF expr %prec OPTIONAL_COMMA
    { $$.token = T_RGBF; $$.value = $2; $$.loc = @2; }
| T_RGBT expr %prec OPTIONAL_COMMA
    { $$.token = T_RGBT; $$.value = $2; $$.loc = @2; }
| T_RGBFT expr %prec OPTIONAL_COMMA
    { $$.token = T_RGBFT; $$.value = $2; $$.loc = @2; }
| T_SRGB expr %prec OPTIONAL_COMMA
    { $$.token = T_SRGB; $$.value = $2; $$.loc = @2; }
| T_SRGBF expr %prec OPTIONAL_COMMA
    { $$.token = T_SRGBF; $$.value = $2; $$.loc = @2; }
| T_SRGBT expr %prec OPTIONAL_COMMA
    { $$.token = T_SRGBT; $$.value = $2; $$.loc = @2; }
| T_SRGBFT expr %prec OPTIONAL_COMMA
    { $$.token = T_SRGBFT; $$.value = $2; $$.loc = @2; }
;

colour_item:
  T_RED expr %prec OPTIONAL_COMMA
    { $$.token = T_RED; $$.value = $2; $$.loc = @2; }
| T_GREEN expr %prec OPTIONAL_COMMA
    { $$.token = T_GREEN; $$.value = $2; $$.loc = @2; }
| T_BLUE expr %prec OPTIONAL_COMMA
    { $$.token = T_BLUE; $$.value = $2; $$.loc = @2; }
| T_FILTER expr %prec OPTIONAL_COMMA
    { $$.token = T_FILTER; $$.value = $2; $$.loc = @2; }
| T_TRANSMIT expr %prec OPTIONAL_COMMA
    { $$.token = T_TRANSMIT; $$.value = $2; $$.loc = @2; }
;

/* ---- objects ---- */

object:
  object_body '}'
| T_TRIANGLE_RUN
    {
      TRY($$ = zr__sdl_object_new(p, ZR_OBJ_TRIANGLE, &@1));
      zr__sdl_triangle_run($1, $$->u.triangle.p);
      zr__sdl_degenerate_triangle(p, $$->u.triangle.p, &@1);
    }
| T_SMOOTH_TRIANGLE_RUN
    { TRY($$ = zr__sdl_smooth_triangle_run(p, &$1, &@1)); }
| T_SPHERE_TEXTURED
    {
      TRY($$ = zr__sdl_sphere_textured(p, &$1, &@1));
      /* The place object_body '}' has: to the sphere's '}'. */
      @$.length = $1.length;
    }
| union_body '}'
| light_group_body '}'
    { TRY(zr__sdl_light_group_done(p, $1.object, $1.global, &@1)); $$ = $1.object; }
;

/* light_group { objects and light sources, then [global_lights B]
   and transformations } (reference manual, "Light Group"): a union
   whose lights light only its own objects. */
light_group_head:
  T_LIGHT_GROUP '{'
    { TRY($$ = zr__sdl_object_new(p, ZR_OBJ_UNION, &@1)); }
| light_group_head object
    { TRY(zr__sdl_union_add(p, $1, $2)); $$ = $1; }
/* "light_group { L1 }": an object identifier alone, as the manual's
   nested group has it. */
| light_group_head T_OBJECT_ID
    {
      zr_object *copy = zr__sdl_object_copy(p, $2.ptr);
      TRY(copy);
      TRY(zr__sdl_union_add(p, $1, copy));
      $$ = $1;
    }
| light_group_head light_done
    { TRY(zr__sdl_csg_add_light(p, $1, $2)); $$ = $1; }
;

light_group_body:
  light_group_head     { $$.object = $1; $$.global = false; }
| light_group_body T_GLOBAL_LIGHTS expr
    {
      double on;
      TRY(zr__sdl_want_float(p, &$3, &@3, &on));
      $$ = $1;
      $$.global = on != 0.0;
    }
| light_group_body T_GLOBAL_LIGHTS  { $$ = $1; $$.global = true; }
| light_group_body transform
    {
      zr_sdl_mod m = make_mod(ZR_SDL_MOD_TRANSFORM, $2);
      TRY(zr__sdl_object_mod(p, $1.object, &m, &@2));
      $$ = $1;
    }
;

object_body:
  object_head
| object_body object_mod_other
    { TRY(zr__sdl_object_mod(p, $1, &$2, &@2)); $$ = $1; }
/* An object's pigment { }, normal { } and finish { } modify those of
   the texture it has (its top layer's), as inside a texture block:
   POV-Ray 3.7's renders (tests/test_object_mods.sh: sphere { texture {
   ... finish { diffuse 0 } } finish { ambient 0.4 } } keeps diffuse 0,
   pigment { scale 5 } keeps the texture's checker). */
| object_body { zr__sdl_texture_base(p, $1->texture, 'p'); } pigment
    { TRY(object_mod_block(p, $1, ZR_SDL_MOD_PIGMENT, $3, &@3)); $$ = $1; }
| object_body { zr__sdl_texture_base(p, $1->texture, 'f'); } finish
    { TRY(object_mod_block(p, $1, ZR_SDL_MOD_FINISH, $3, &@3)); $$ = $1; }
| object_body { zr__sdl_texture_base(p, $1->texture, 'n'); } normal
    { TRY(object_mod_block(p, $1, ZR_SDL_MOD_NORMAL, $3, &@3)); $$ = $1; }
| object_body T_STURM  { TRY(zr__sdl_sturm(p, $1, &@2)); $$ = $1; }
;

object_head:
  T_SPHERE '{' expr comma expr
    {
      TRY($$ = zr__sdl_object_new(p, ZR_OBJ_SPHERE, &@1));
      TRY(zr__sdl_want_vector(p, &$3, &@3, &$$->u.sphere.centre));
      TRY(zr__sdl_want_float(p, &$5, &@5, &$$->u.sphere.radius));
      zr__sdl_sphere_radius(p, $$, &@5);
    }
| T_SPHERE_RUN
    {
      TRY($$ = zr__sdl_object_new(p, ZR_OBJ_SPHERE, &@1));
      zr__sdl_sphere_run($1, $$);
      zr__sdl_sphere_radius(p, $$, &@1);
    }
| T_BOX '{' expr comma expr
    {
      TRY($$ = zr__sdl_object_new(p, ZR_OBJ_BOX, &@1));
      TRY(zr__sdl_want_extent(p, &$3, &@3, &$$->u.box.corner1));
      TRY(zr__sdl_want_extent(p, &$5, &@5, &$$->u.box.corner2));
    }
| T_PLANE '{' expr comma expr
    {
      TRY($$ = zr__sdl_object_new(p, ZR_OBJ_PLANE, &@1));
      TRY(zr__sdl_want_vector(p, &$3, &@3, &$$->u.plane.normal));
      TRY(zr__sdl_want_float(p, &$5, &@5, &$$->u.plane.distance));
      if (zr_v3_len($$->u.plane.normal) == 0) {
        zr__sdl_error(p, ZR_ESCENE, &@3, "the plane's normal is zero");
        YYABORT;
      }
      /* A x + B y + C z = D |<A,B,C>| (reference manual, "Plane"). */
      $$->u.plane.normal = zr_v3_norm($$->u.plane.normal);
    }
| T_TRIANGLE '{' expr comma expr comma expr
    {
      TRY($$ = zr__sdl_object_new(p, ZR_OBJ_TRIANGLE, &@1));
      TRY(zr__sdl_want_vector(p, &$3, &@3, &$$->u.triangle.p[0]));
      TRY(zr__sdl_want_vector(p, &$5, &@5, &$$->u.triangle.p[1]));
      TRY(zr__sdl_want_vector(p, &$7, &@7, &$$->u.triangle.p[2]));
      zr__sdl_degenerate_triangle(p, $$->u.triangle.p, &@1);
    }
| T_CYLINDER '{' expr comma expr comma expr
    {
      TRY($$ = zr__sdl_object_new(p, ZR_OBJ_CYLINDER, &@1));
      TRY(zr__sdl_want_vector(p, &$3, &@3, &$$->u.cylinder.base));
      TRY(zr__sdl_want_vector(p, &$5, &@5, &$$->u.cylinder.cap));
      TRY(zr__sdl_want_float(p, &$7, &@7, &$$->u.cylinder.radius));
      TRY(zr__sdl_axis_given(p, $$->u.cylinder.base, $$->u.cylinder.cap,
                             "cylinder", &@5));
      $$->u.cylinder.height = zr__axis_measure(
          $$->u.cylinder.base, $$->u.cylinder.cap, &$$->u.cylinder.axis);
    }
| T_CONE '{' expr comma expr comma expr comma expr
    {
      TRY($$ = zr__sdl_object_new(p, ZR_OBJ_CONE, &@1));
      TRY(zr__sdl_want_vector(p, &$3, &@3, &$$->u.cone.base));
      TRY(zr__sdl_want_float(p, &$5, &@5, &$$->u.cone.base_radius));
      TRY(zr__sdl_want_vector(p, &$7, &@7, &$$->u.cone.cap));
      TRY(zr__sdl_want_float(p, &$9, &@9, &$$->u.cone.cap_radius));
      TRY(zr__sdl_axis_given(p, $$->u.cone.base, $$->u.cone.cap, "cone",
                             &@7));
      $$->u.cone.height = zr__axis_measure($$->u.cone.base, $$->u.cone.cap,
                                           &$$->u.cone.axis);
    }
| T_DISC '{' expr comma expr comma expr
    {
      TRY($$ = zr__sdl_object_new(p, ZR_OBJ_DISC, &@1));
      TRY(zr__sdl_want_vector(p, &$3, &@3, &$$->u.disc.centre));
      TRY(zr__sdl_want_vector(p, &$5, &@5, &$$->u.disc.normal));
      TRY(zr__sdl_want_float(p, &$7, &@7, &$$->u.disc.radius));
      $$->u.disc.normal = zr_v3_norm($$->u.disc.normal);
    }
| T_DISC '{' expr comma expr comma expr comma expr
    {
      TRY($$ = zr__sdl_object_new(p, ZR_OBJ_DISC, &@1));
      TRY(zr__sdl_want_vector(p, &$3, &@3, &$$->u.disc.centre));
      TRY(zr__sdl_want_vector(p, &$5, &@5, &$$->u.disc.normal));
      TRY(zr__sdl_want_float(p, &$7, &@7, &$$->u.disc.radius));
      TRY(zr__sdl_want_float(p, &$9, &@9, &$$->u.disc.hole_radius));
      $$->u.disc.normal = zr_v3_norm($$->u.disc.normal);
    }
| T_OBJECT '{' T_OBJECT_ID
    { TRY($$ = zr__sdl_object_copy(p, $3.ptr)); }
| T_OBJECT '{' object  { $$ = $3; } /* "object { union { ... } ... }" */
| poly_coefs '>'       { TRY(zr__sdl_poly_done(p, $1, &@2)); $$ = $1; }
| T_QUADRIC '{' expr comma expr comma expr comma expr
    {
      zr_sdl_expr e[4] = {$3, $5, $7, $9};
      zr_sdl_loc at[4] = {@3, @5, @7, @9};
      TRY($$ = zr__sdl_quadric(p, e, &@1, at));
    }
| T_TORUS '{' expr comma expr
    { TRY($$ = zr__sdl_torus(p, &@1, &$3, &@3, &$5, &@5)); }
| T_SUPERELLIPSOID '{' expr
    { TRY($$ = zr__sdl_superellipsoid(p, &@1, &$3, &@3)); }
| polygon_head         { TRY(zr__sdl_polygon_done(p, $1, &@1)); $$ = $1; }
| prism_head           { TRY(zr__sdl_prism_done(p, $1, &@1)); $$ = $1; }
| lathe_head           { TRY(zr__sdl_lathe_done(p, $1, &@1)); $$ = $1; }
| blob_head
| iso_head %prec OPTIONAL_COMMA
| hf_head              { TRY(zr__sdl_height_field_done(p, $1, &@1)); $$ = $1; }
| par_head           { TRY(zr__sdl_parametric_done(p, $1, &@1)); $$ = $1; }
| T_OVUS '{' expr comma expr
    { TRY($$ = zr__sdl_ovus(p, &@1, &$3, &@3, &$5, &@5)); }
| sor_head             { TRY(zr__sdl_sor_done(p, $1, &@1)); $$ = $1; }
| patch_head           { TRY(zr__sdl_patch_done(p, $1, &@1)); $$ = $1; }
| sweep_head           { TRY(zr__sdl_sweep_done(p, $1, &@1)); $$ = $1; }
| julia_head           { TRY(zr__sdl_julia_done(p, $1, &@1)); $$ = $1; }
| mesh_head            { TRY(zr__sdl_mesh_done(p, $1, &@1)); $$ = $1; }
/* mesh { M ... } and mesh2 { M ... }: a copy of the declared mesh, as
   object { M ... } (POV-Ray accepts both; the mesh camera's manual
   section writes it so). */
| T_MESH '{' T_OBJECT_ID
    { TRY($$ = zr__sdl_mesh_copy(p, $3.ptr, &@3)); }
| T_MESH2 '{' T_OBJECT_ID
    { TRY($$ = zr__sdl_mesh_copy(p, $3.ptr, &@3)); }
| mesh2_head           { TRY(zr__sdl_mesh_done(p, $1, &@1)); $$ = $1; }
| T_SMOOTH_TRIANGLE '{' expr comma expr comma expr comma expr comma expr
  comma expr
    {
      zr_sdl_expr e[6] = {$3, $5, $7, $9, $11, $13};
      zr_sdl_loc l[6] = {@3, @5, @7, @9, @11, @13};
      TRY($$ = zr__sdl_smooth_triangle(p, &@1, e, l));
    }
/* The commas between font, string and thickness are optional. */
| T_TEXT '{' T_TTF str_expr comma str_expr comma expr comma expr
    {
      TRY($$ = zr__sdl_text(p, &@1, $4, 0, &@4, $6, &$8, &@8, &$10,
                            &@10));
    }
| T_TEXT '{' T_INTERNAL expr comma str_expr comma expr comma expr
    {
      double font;
      TRY(zr__sdl_want_float(p, &$4, &@4, &font));
      TRY($$ = zr__sdl_text(p, &@1, NULL, font, &@4, $6, &$8, &@8, &$10,
                            &@10));
    }
;

/* polygon { Number_Of_Points, <Point_1> <Point_2> ... }: the commas
   between points may be left out, as between an object's items. */
polygon_head:
  T_POLYGON '{' expr %prec OPTIONAL_COMMA
    { TRY($$ = zr__sdl_polygon_new(p, &@1, &$3, &@3)); }
| polygon_head ',' expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_polygon_point(p, $1, &$3, &@3)); $$ = $1; }
| polygon_head expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_polygon_point(p, $1, &$2, &@2)); $$ = $1; }
;

/* prism { [spline and sweep keywords] Height_1, Height_2, N, <Point>... }
   (reference manual, "Prism"). */
prism_start:
  T_PRISM '{'          { TRY($$ = zr__sdl_prism_new(p, &@1)); }
| prism_start prism_option
    { zr__sdl_prism_option($1, $2); $$ = $1; }
;

prism_option:
  T_LINEAR_SPLINE      { $$ = 0; }
| T_QUADRATIC_SPLINE   { $$ = 1; }
| T_CUBIC_SPLINE       { $$ = 2; }
| T_BEZIER_SPLINE      { $$ = 3; }
| T_LINEAR_SWEEP       { $$ = 4; }
| T_CONIC_SWEEP        { $$ = 5; }
;

prism_head:
  prism_start expr comma expr comma expr %prec OPTIONAL_COMMA
    {
      zr_sdl_expr e[3] = {$2, $4, $6};
      zr_sdl_loc at[3] = {@2, @4, @6};
      TRY(zr__sdl_prism_size(p, $1, e, at));
      $$ = $1;
    }
| prism_head ',' expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_prism_point(p, $1, &$3, &@3)); $$ = $1; }
| prism_head expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_prism_point(p, $1, &$2, &@2)); $$ = $1; }
;

/* lathe { [spline keyword] N, <Point>... } (reference manual, "Lathe"). */
lathe_start:
  T_LATHE '{'          { TRY($$ = zr__sdl_lathe_new(p, &@1)); }
| lathe_start prism_option
    { TRY(zr__sdl_lathe_option(p, $1, $2, &@2)); $$ = $1; }
;

lathe_head:
  lathe_start expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_lathe_count(p, $1, &$2, &@2)); $$ = $1; }
| lathe_head ',' expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_lathe_point(p, $1, &$3, &@3)); $$ = $1; }
| lathe_head expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_lathe_point(p, $1, &$2, &@2)); $$ = $1; }
;

/* blob { threshold T  sphere { ... }  cylinder { ... }  component ... }
   (reference manual, "Blob").  A component's rule carries the blob; its
   modifiers go to the blob's last component. */
blob_head:
  T_BLOB '{'           { TRY($$ = zr__sdl_blob_new(p, &@1)); }
| blob_head T_THRESHOLD expr
    { TRY(zr__sdl_blob_threshold(p, $1, &$3, &@3)); $$ = $1; }
| blob_component '}'   { $$ = $1; }
| blob_head T_COMPONENT expr comma expr comma expr
    {
      zr_sdl_expr e[3] = {$3, $5, $7};
      zr_sdl_loc at[3] = {@3, @5, @7};
      TRY(zr__sdl_blob_component(p, $1, false, true, e, at));
      $$ = $1;
    }
/* hierarchy only switches POV-Ray's inner bounding: no picture change. */
| blob_head T_HIERARCHY expr  { $$ = $1; }
| blob_head T_HIERARCHY       { $$ = $1; }
;

blob_component:
  blob_head T_SPHERE '{' expr comma expr comma blob_strength
    {
      zr_sdl_expr e[3] = {$4, $6, $8};
      zr_sdl_loc at[3] = {@4, @6, @8};
      TRY(zr__sdl_blob_component(p, $1, false, false, e, at));
      $$ = $1;
    }
| blob_head T_CYLINDER '{' expr comma expr comma expr comma blob_strength
    {
      zr_sdl_expr e[4] = {$4, $6, $8, $10};
      zr_sdl_loc at[4] = {@4, @6, @8, @10};
      TRY(zr__sdl_blob_component(p, $1, true, false, e, at));
      $$ = $1;
    }
| blob_component object_mod
    {
      zr_blob_component *c =
          &$1->u.blob.components[$1->u.blob.n_components - 1];
      TRY(zr__sdl_blob_component_mod(p, $1, c, &$2, &@2));
      $$ = $1;
    }
;

blob_strength:
  expr
| T_STRENGTH expr      { $$ = $2; }
;

/* isosurface { function { ... } [contained_by { sphere | box }]
   [threshold T] [accuracy A] [max_gradient G] [evaluate P0, P1, P2]
   [open] [max_trace N | all_intersections] } (reference manual,
   "Isosurface").  As for a declared function, the state after
   'function' only reduces, so the compiler reads the body from the
   token array.  open among these items is the isosurface's (T_OPEN
   outranks the reduction to object_head), after them the object
   modifier's, which means the same. */
iso_head:
  T_ISOSURFACE '{' T_FUNCTION
    {
      if (yychar != ZR__POV_EMPTY) {
        zr__sdl_error(p, ZR_ESYNTAX, &@3, "internal error: the parser "
                      "looked past 'function'");
        YYABORT;
      }
      const zr_fn *fn = zr__sdl_function_parse(p, &@3);
      TRY(fn);
      TRY($$ = zr__sdl_isosurface_new(p, &@1, fn, &@3));
    }
| iso_head T_CONTAINED_BY '{' object '}'
    { TRY(zr__sdl_isosurface_container(p, $1, $4, &@2)); $$ = $1; }
| iso_head T_THRESHOLD expr
    { TRY(zr__sdl_isosurface_item(p, $1, T_THRESHOLD, &$3, &@3)); $$ = $1; }
| iso_head T_ACCURACY expr
    { TRY(zr__sdl_isosurface_item(p, $1, T_ACCURACY, &$3, &@3)); $$ = $1; }
| iso_head T_MAX_GRADIENT expr
    {
      TRY(zr__sdl_isosurface_item(p, $1, T_MAX_GRADIENT, &$3, &@3));
      $$ = $1;
    }
| iso_head T_MAX_TRACE expr
    { TRY(zr__sdl_isosurface_item(p, $1, T_MAX_TRACE, &$3, &@3)); $$ = $1; }
| iso_head T_ALL_INTERSECTIONS
    {
      TRY(zr__sdl_isosurface_item(p, $1, T_ALL_INTERSECTIONS, NULL, &@2));
      $$ = $1;
    }
| iso_head T_EVALUATE expr comma expr comma expr
    {
      zr_sdl_expr e[3] = {$3, $5, $7};
      zr_sdl_loc at[3] = {@3, @5, @7};
      TRY(zr__sdl_isosurface_item(p, $1, T_EVALUATE, e, at));
      $$ = $1;
    }
| iso_head T_OPEN
    {
      $1->u.isosurface.open = true;
      $$ = $1;
    }
;

/* height_field { [png | gif | pot | tga | pgm | ppm | jpeg] "file" | function W, H { ... }
   [smooth] [water_level L] [hierarchy [B]] } (reference manual, "Height
   Field"); the file's own bytes say what it is.  The function's '{' is
   shifted, then its body read from the token array. */
hf_head:
  T_HEIGHT_FIELD '{' hf_file
    { TRY($$ = zr__sdl_height_field_image(p, &@1, $3, &@3, false)); }
| T_HEIGHT_FIELD '{' T_POT str_expr
    { TRY($$ = zr__sdl_height_field_image(p, &@1, $4, &@4, true)); }
| T_HEIGHT_FIELD '{' T_FUNCTION expr comma expr '{'
    {
      const zr_fn *fn = zr__sdl_height_field_fn_body(p, &@7);
      TRY(fn);
      zr_sdl_expr e[2] = {$4, $6};
      zr_sdl_loc at[2] = {@4, @6};
      TRY($$ = zr__sdl_height_field_function(p, &@1, e, at, fn, &@3));
    }
| hf_head T_SMOOTH
    { TRY(zr__sdl_height_field_item(p, $1, T_SMOOTH, NULL, &@2)); $$ = $1; }
| hf_head T_WATER_LEVEL expr
    {
      TRY(zr__sdl_height_field_item(p, $1, T_WATER_LEVEL, &$3, &@3));
      $$ = $1;
    }
/* hierarchy only switches POV-Ray's inner bounding: no picture change. */
| hf_head T_HIERARCHY expr  { $$ = $1; }
| hf_head T_HIERARCHY       { $$ = $1; }
;

/* parametric { function { x(u, v) } function { y(u, v) }
   function { z(u, v) } <u1, v1>, <u2, v2> [contained_by { sphere | box }]
   [max_gradient G] [accuracy A] [precompute DEPTH, x, y, z] } (reference
   manual, "Parametric").  precompute only speeds POV-Ray up: it is read
   and checked. */
par_head:
  T_PARAMETRIC '{' par_fn comma par_fn comma par_fn comma expr comma expr
    {
      const zr_fn *fn[3] = {$3, $5, $7};
      zr_sdl_loc fl[3] = {@3, @5, @7};
      zr_sdl_expr e[2] = {$9, $11};
      zr_sdl_loc at[2] = {@9, @11};
      TRY($$ = zr__sdl_parametric_new(p, &@1, fn, fl, e, at));
    }
| par_head T_CONTAINED_BY '{' object '}'
    { TRY(zr__sdl_parametric_container(p, $1, $4, &@2)); $$ = $1; }
| par_head T_MAX_GRADIENT expr
    {
      TRY(zr__sdl_parametric_item(p, $1, T_MAX_GRADIENT, &$3, &@3));
      $$ = $1;
    }
| par_head T_ACCURACY expr
    { TRY(zr__sdl_parametric_item(p, $1, T_ACCURACY, &$3, &@3)); $$ = $1; }
| par_head T_PRECOMPUTE expr par_vars
    {
      TRY(zr__sdl_parametric_item(p, $1, T_PRECOMPUTE, &$3, &@3));
      $$ = $1;
    }
;

par_fn:
  T_FUNCTION
    {
      if (yychar != ZR__POV_EMPTY) {
        zr__sdl_error(p, ZR_ESYNTAX, &@1, "internal error: the parser "
                      "looked past 'function'");
        YYABORT;
      }
      TRY($$ = zr__sdl_function_parse(p, &@1));
    }
;

par_vars:
  par_var
| par_vars comma par_var
;

par_var:
  T_X
| T_Y
| T_Z
;

hf_file:
  str_expr
| T_PNG str_expr       { $$ = $2; }
| T_PGM str_expr       { $$ = $2; }
| T_PPM str_expr       { $$ = $2; }
| T_JPEG str_expr      { $$ = $2; }
| T_GIF str_expr       { $$ = $2; }
| T_TGA str_expr       { $$ = $2; }
| T_BMP str_expr       { $$ = $2; }
| T_TIFF str_expr      { $$ = $2; }
| T_HDR str_expr       { $$ = $2; }
| T_EXR str_expr       { $$ = $2; }
;

/* sor { N, <Point>... } (reference manual, "Surface of Revolution"). */
sor_head:
  T_SOR '{' expr %prec OPTIONAL_COMMA
    { TRY($$ = zr__sdl_sor_new(p, &@1, &$3, &@3)); }
| sor_head ',' expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_sor_point(p, $1, &$3, &@3)); $$ = $1; }
| sor_head expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_sor_point(p, $1, &$2, &@2)); $$ = $1; }
;

/* bicubic_patch { type T flatness F u_steps U v_steps V <P1> ... <P16>
   [uv_vectors <C1> <C2> <C3> <C4>] } (reference manual, "Bicubic
   Patch"); the commas between points may be left out. */
patch_head:
  T_BICUBIC_PATCH '{'  { TRY($$ = zr__sdl_patch_new(p, &@1)); }
| patch_head patch_item expr %prec OPTIONAL_COMMA
    {
      TRY(zr__sdl_patch_item(p, $1, (zr_sdl_patch_item)$2, &$3, &@3));
      $$ = $1;
    }
| patch_head expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_patch_point(p, $1, &$2, &@2)); $$ = $1; }
| patch_head ',' expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_patch_point(p, $1, &$3, &@3)); $$ = $1; }
| patch_head T_UV_VECTORS expr comma expr comma expr comma expr
  %prec OPTIONAL_COMMA
    {
      zr_sdl_expr e[4] = {$3, $5, $7, $9};
      zr_sdl_loc at[4] = {@3, @5, @7, @9};
      TRY(zr__sdl_patch_uv(p, $1, e, at));
      $$ = $1;
    }
;

patch_item:
  T_TYPE               { $$ = ZR_SDL_PATCH_TYPE; }
| T_FLATNESS           { $$ = ZR_SDL_PATCH_FLATNESS; }
| T_U_STEPS            { $$ = ZR_SDL_PATCH_U_STEPS; }
| T_V_STEPS            { $$ = ZR_SDL_PATCH_V_STEPS; }
;

/* spline { [SPLINE_ID] [SPLINE_TYPE] T1, <V1> [,] T2, <V2> [,] ... }
   (reference manual, "Spline"); the parts may come in any order, as
   POV-Ray reads them, and a spline identifier copies its points. */
spline:
  spline_body '}'      { $$ = $1; TRY(zr__sdl_spline_finish(p, $$, &@$)); }
;

spline_body:
  T_SPLINE '{'         { TRY($$ = zr__sdl_spline_new(p, NULL)); }
| spline_body T_SPLINE_ID %prec SPLINE_COPY
    { TRY($$ = zr__sdl_spline_new(p, $2.ptr)); }
| spline_body spline_type { $$ = $1; $$->type = $2; }
| spline_body expr comma expr comma
    { $$ = $1; TRY(zr__sdl_spline_add(p, $$, &$2, &@2, &$4)); }
;

spline_type:
  T_LINEAR_SPLINE      { $$ = ZR_SPLINE_LINEAR; }
| T_QUADRATIC_SPLINE   { $$ = ZR_SPLINE_QUADRATIC; }
| T_CUBIC_SPLINE       { $$ = ZR_SPLINE_CUBIC; }
| T_NATURAL_SPLINE     { $$ = ZR_SPLINE_NATURAL; }
;

/* sphere_sweep { SPLINE N, <Centre>, Radius ... [tolerance T] }
   (reference manual, "Sphere Sweep"). */
sweep_head:
  T_SPHERE_SWEEP '{' sweep_spline expr %prec OPTIONAL_COMMA
    { TRY($$ = zr__sdl_sweep_new(p, &@1, $3, &$4, &@4)); }
| sweep_head ',' expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_sweep_item(p, $1, &$3, &@3)); $$ = $1; }
| sweep_head expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_sweep_item(p, $1, &$2, &@2)); $$ = $1; }
| sweep_head T_TOLERANCE expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_sweep_tolerance(p, $1, &$3, &@3)); $$ = $1; }
;

sweep_spline:
  T_LINEAR_SPLINE      { $$ = 0; }
| T_B_SPLINE           { $$ = 1; }
| T_CUBIC_SPLINE       { $$ = 2; }
;

/* julia_fractal { <P> [quaternion | hypercomplex] [FUNCTION]
   [max_iteration N] [precision P] [slice <N>, D] } (reference manual,
   "Julia Fractal"). */
julia_head:
  T_JULIA_FRACTAL '{' expr
    { TRY($$ = zr__sdl_julia_new(p, &@1, &$3, &@3)); }
| julia_head T_QUATERNION  { zr__sdl_julia_algebra($1, 0); $$ = $1; }
| julia_head T_HYPERCOMPLEX  { zr__sdl_julia_algebra($1, 1); $$ = $1; }
| julia_head julia_function
    { TRY(zr__sdl_julia_function(p, $1, $2, &@2)); $$ = $1; }
| julia_head T_PWR '(' expr ',' expr ')'
    { TRY(zr__sdl_julia_pwr(p, $1, &$4, &@4, &$6, &@6)); $$ = $1; }
| julia_head T_MAX_ITERATION expr
    { TRY(zr__sdl_julia_iterations(p, $1, &$3, &@3)); $$ = $1; }
| julia_head T_PRECISION expr
    { TRY(zr__sdl_julia_precision(p, $1, &$3, &@3)); $$ = $1; }
| julia_head T_SLICE expr comma expr
    { TRY(zr__sdl_julia_slice(p, $1, &$3, &@3, &$5, &@5)); $$ = $1; }
;

julia_function:
  T_SQR { $$ = T_SQR; }     | T_CUBE { $$ = T_CUBE; }
| T_RECIPROCAL { $$ = T_RECIPROCAL; }
| T_EXP { $$ = T_EXP; }     | T_LN { $$ = T_LN; }
| T_SIN { $$ = T_SIN; }     | T_ASIN { $$ = T_ASIN; }
| T_SINH { $$ = T_SINH; }   | T_ASINH { $$ = T_ASINH; }
| T_COS { $$ = T_COS; }     | T_ACOS { $$ = T_ACOS; }
| T_COSH { $$ = T_COSH; }   | T_ACOSH { $$ = T_ACOSH; }
| T_TAN { $$ = T_TAN; }     | T_ATAN { $$ = T_ATAN; }
| T_TANH { $$ = T_TANH; }   | T_ATANH { $$ = T_ATANH; }
;

/* ---- meshes (reference manual, "Mesh" and "Mesh2") ---- */

/* mesh { triangle { ... } smooth_triangle { ... } ... inside_vector }:
   the triangles, then the mesh's own modifiers, then the object's. */
mesh_head:
  T_MESH '{'           { TRY($$ = zr__sdl_mesh_new(p, false, &@1)); }
| mesh_head T_TRIANGLE_RUN
    { TRY(zr__sdl_mesh_triangle_run(p, $1, $2, &@2)); $$ = $1; }
| mesh_head T_SMOOTH_TRIANGLE_RUN
    { TRY(zr__sdl_mesh_smooth_triangle_run(p, $1, &$2, &@2)); $$ = $1; }
| mesh_head T_TRIANGLE '{' expr comma expr comma expr mesh_texture '}'
    {
      zr_sdl_expr v[3] = {$4, $6, $8};
      zr_sdl_loc l[3] = {@4, @6, @8};
      TRY(zr__sdl_mesh_triangle(p, $1, v, l, NULL, NULL, NULL, NULL, $9));
      $$ = $1;
    }
| mesh_head T_TRIANGLE '{' expr comma expr comma expr
  T_UV_VECTORS expr comma expr comma expr mesh_texture '}'
    {
      zr_sdl_expr v[3] = {$4, $6, $8}, uv[3] = {$10, $12, $14};
      zr_sdl_loc l[3] = {@4, @6, @8}, ul[3] = {@10, @12, @14};
      TRY(zr__sdl_mesh_triangle(p, $1, v, l, NULL, NULL, uv, ul, $15));
      $$ = $1;
    }
| mesh_head T_SMOOTH_TRIANGLE '{' expr comma expr comma expr comma expr
  comma expr comma expr mesh_texture '}'
    {
      zr_sdl_expr v[3] = {$4, $8, $12}, n[3] = {$6, $10, $14};
      zr_sdl_loc vl[3] = {@4, @8, @12}, nl[3] = {@6, @10, @14};
      TRY(zr__sdl_mesh_triangle(p, $1, v, vl, n, nl, NULL, NULL, $15));
      $$ = $1;
    }
| mesh_head T_SMOOTH_TRIANGLE '{' expr comma expr comma expr comma expr
  comma expr comma expr T_UV_VECTORS expr comma expr comma expr
  mesh_texture '}'
    {
      zr_sdl_expr v[3] = {$4, $8, $12}, n[3] = {$6, $10, $14};
      zr_sdl_expr uv[3] = {$16, $18, $20};
      zr_sdl_loc vl[3] = {@4, @8, @12}, nl[3] = {@6, @10, @14};
      zr_sdl_loc ul[3] = {@16, @18, @20};
      TRY(zr__sdl_mesh_triangle(p, $1, v, vl, n, nl, uv, ul, $21));
      $$ = $1;
    }
| mesh_head T_INSIDE_VECTOR expr
    { TRY(zr__sdl_mesh_inside_vector(p, $1, &$3, &@3)); $$ = $1; }
/* hierarchy only switches POV-Ray's inner bounding on or off: the
   picture is the same either way, and zRcube always builds it. */
| mesh_head T_HIERARCHY expr  { $$ = $1; }
| mesh_head T_HIERARCHY       { $$ = $1; }
;

mesh_texture:
  %empty               { $$ = NULL; }
| texture
;

mesh2_head:
  T_MESH2 '{'          { TRY($$ = zr__sdl_mesh_new(p, true, &@1)); }
| mesh2_list '}'       { TRY(zr__sdl_mesh2_close(p, $1, &@2)); $$ = $1; }
| texture_list '}'     { TRY(zr__sdl_mesh2_close(p, $1, &@2)); $$ = $1; }
| mesh2_head T_INSIDE_VECTOR expr
    { TRY(zr__sdl_mesh_inside_vector(p, $1, &$3, &@3)); $$ = $1; }
| mesh2_head T_HIERARCHY expr  { $$ = $1; }
| mesh2_head T_HIERARCHY       { $$ = $1; }
;

/* A list of numbers or vectors.  The state after its '{' only reduces,
   so bison has read nothing past it and the plain items can be read
   straight from the token array; the check keeps that promise honest
   (a look-ahead already read just sends every item through here). */
mesh2_list:
  mesh2_head mesh2_keyword '{'
    {
      TRY(zr__sdl_mesh2_open(p, $1, (zr_sdl_mesh2_list)$2, &@2,
                             yychar == ZR__POV_EMPTY));
      $$ = $1;
    }
| mesh2_list expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_mesh2_item(p, $1, &$2, &@2)); $$ = $1; }
| mesh2_list ','       { $$ = $1; }
;

mesh2_keyword:
  T_VERTEX_VECTORS     { $$ = ZR_SDL_M2_VERTICES; }
| T_NORMAL_VECTORS     { $$ = ZR_SDL_M2_NORMALS; }
| T_UV_VECTORS         { $$ = ZR_SDL_M2_UVS; }
| T_FACE_INDICES       { $$ = ZR_SDL_M2_FACES; }
| T_NORMAL_INDICES     { $$ = ZR_SDL_M2_NORMAL_INDICES; }
| T_UV_INDICES         { $$ = ZR_SDL_M2_UV_INDICES; }
;

texture_list:
  mesh2_head T_TEXTURE_LIST '{' expr
    {
      TRY(zr__sdl_mesh2_open(p, $1, ZR_SDL_M2_TEXTURES, &@2, false));
      TRY(zr__sdl_mesh2_item(p, $1, &$4, &@4));
      $$ = $1;
    }
| texture_list ','     { $$ = $1; }
| texture_list texture
    { TRY(zr__sdl_mesh2_texture(p, $1, $2, &@2)); $$ = $1; }
;

/* POV-Ray's CSG syntax puts the children first, then the modifiers,
   which therefore reach every child. */
union_head:
  T_UNION '{'          { TRY($$ = zr__sdl_object_new(p, ZR_OBJ_UNION, &@1)); }
| T_INTERSECTION '{'
    { TRY($$ = zr__sdl_object_new(p, ZR_OBJ_INTERSECTION, &@1)); }
| T_MERGE '{'          { TRY($$ = zr__sdl_object_new(p, ZR_OBJ_MERGE, &@1)); }
| union_head object    { TRY(zr__sdl_union_add(p, $1, $2)); $$ = $1; }
| union_head light_done
    { TRY(zr__sdl_csg_add_light(p, $1, $2)); $$ = $1; }
;

/* poly { Order, <A1, ..., An> }, cubic { <...> }, quartic { <...> }:
   as many coefficients as the order asks, which may exceed a list's. */
poly_head:
  T_POLY '{' expr comma '<'
    { TRY($$ = zr__sdl_poly_new(p, &$3, &@3, &@1)); }
| T_CUBIC '{' '<'
    {
      zr_sdl_expr three = zr__sdl_float(3);
      TRY($$ = zr__sdl_poly_new(p, &three, &@1, &@1));
    }
| T_QUARTIC '{' '<'
    {
      zr_sdl_expr four = zr__sdl_float(4);
      TRY($$ = zr__sdl_poly_new(p, &four, &@1, &@1));
    }
;

/* Commas between coefficients may be left out, as in a vector
   (hyptorus.pov ends a line without one). */
poly_coefs:
  poly_head expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_poly_coef(p, $1, &$2, &@2)); $$ = $1; }
| poly_coefs comma expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_poly_coef(p, $1, &$3, &@3)); $$ = $1; }
;

/* A difference is an intersection with every child after the first
   inverted. */
difference_head:
  T_DIFFERENCE '{'
    { TRY($$ = zr__sdl_object_new(p, ZR_OBJ_INTERSECTION, &@1)); }
| difference_head object
    { TRY(zr__sdl_difference_add(p, $1, $2)); $$ = $1; }
| difference_head light_done
    { TRY(zr__sdl_csg_add_light(p, $1, $2)); $$ = $1; }
;

/* A declared object's name alone as the last child of a CSG (Voro++'s
   irregular.pov: union { particles translate <-4,0,0> }): POV-Ray 3.7
   reads it as object { particles }, the modifiers after it go to the
   whole CSG as usual, and another object after it is refused (measured:
   tests/legacy/bare_object_csg.pov). */
union_body:
  union_head
| difference_head
| union_head T_OBJECT_ID
    {
      zr_object *copy = zr__sdl_object_copy(p, $2.ptr);
      TRY(copy);
      TRY(zr__sdl_union_add(p, $1, copy));
      $$ = $1;
    }
| difference_head T_OBJECT_ID
    {
      zr_object *copy = zr__sdl_object_copy(p, $2.ptr);
      TRY(copy);
      TRY(zr__sdl_difference_add(p, $1, copy));
      $$ = $1;
    }
| union_body object_mod_other
    { TRY(zr__sdl_object_mod(p, $1, &$2, &@2)); $$ = $1; }
/* The same for a CSG: its own texture's, else the default texture's
   (a child's texture is not the CSG's). */
| union_body { zr__sdl_texture_base(p, $1->texture, 'p'); } pigment
    { TRY(object_mod_block(p, $1, ZR_SDL_MOD_PIGMENT, $3, &@3)); $$ = $1; }
| union_body { zr__sdl_texture_base(p, $1->texture, 'f'); } finish
    { TRY(object_mod_block(p, $1, ZR_SDL_MOD_FINISH, $3, &@3)); $$ = $1; }
| union_body { zr__sdl_texture_base(p, $1->texture, 'n'); } normal
    { TRY(object_mod_block(p, $1, ZR_SDL_MOD_NORMAL, $3, &@3)); $$ = $1; }
;

/* A blob component's modifiers; an object's pigment, normal and finish
   start from its texture's (object_body above). */
object_mod:
  object_mod_other
| pigment              { $$ = make_mod(ZR_SDL_MOD_PIGMENT, $1); }
| finish               { $$ = make_mod(ZR_SDL_MOD_FINISH, $1); }
| normal               { $$ = make_mod(ZR_SDL_MOD_NORMAL, $1); }
;

object_mod_other:
  transform            { $$ = make_mod(ZR_SDL_MOD_TRANSFORM, $1); }
| texture              { $$ = make_mod(ZR_SDL_MOD_TEXTURE, $1); }
| interior             { $$ = make_mod(ZR_SDL_MOD_INTERIOR, $1); }
| material             { $$ = make_mod(ZR_SDL_MOD_MATERIAL, $1); }
| T_NO_SHADOW          { $$ = make_mod(ZR_SDL_MOD_NO_SHADOW, NULL); }
| T_NO_IMAGE           { $$ = make_mod(ZR_SDL_MOD_NO_IMAGE, NULL); }
| T_NO_REFLECTION      { $$ = make_mod(ZR_SDL_MOD_NO_REFLECTION, NULL); }
| T_DOUBLE_ILLUMINATE
    { $$ = make_mod(ZR_SDL_MOD_DOUBLE_ILLUMINATE, NULL); }
| T_NO_RADIOSITY
    {
      zr__sdl_radiosity_object(p, T_NO_RADIOSITY, &@1);
      $$ = make_mod(ZR_SDL_MOD_IGNORED, NULL);
    }
| T_RADIOSITY '{' object_radiosity '}'
    {
      zr__sdl_radiosity_object(p, T_RADIOSITY, &@1);
      $$ = make_mod(ZR_SDL_MOD_IGNORED, NULL);
    }
| T_INVERSE            { $$ = make_mod(ZR_SDL_MOD_INVERSE, NULL); }
| T_UV_MAPPING         { $$ = make_mod(ZR_SDL_MOD_UV_MAPPING, NULL); }
| T_INTERIOR_TEXTURE '{' texture_body '}'
    {
      TRY(zr__sdl_texture_done(p, $3));
      $$ = make_mod(ZR_SDL_MOD_INTERIOR_TEXTURE, $3);
    }
/* photons { } (lib/sdl/build_media.c): POV-Ray ignores an object's
   block when global_settings has none. */
| T_PHOTONS '{' photon_items '}'  { $$ = make_mod(ZR_SDL_MOD_PHOTONS, $3); }
| T_OPEN               { $$ = make_mod(ZR_SDL_MOD_OPEN, NULL); }
| T_HOLLOW             { $$ = make_mod(ZR_SDL_MOD_HOLLOW, NULL); }
| T_HOLLOW expr
    {
      double on;
      TRY(zr__sdl_want_float(p, &$2, &@2, &on));
      /* Any non-NULL pointer says "off". */
      $$ = make_mod(ZR_SDL_MOD_HOLLOW, on != 0.0 ? NULL : (const void *)p);
    }
| T_CLIPPED_BY '{' clip_objects '}'
    { $$ = make_mod(ZR_SDL_MOD_CLIPPED_BY, $3); }
| T_CLIPPED_BY '{' T_BOUNDED_BY '}'
    { $$ = make_mod(ZR_SDL_MOD_CLIP_TO_BOUND, NULL); }
| T_BOUNDED_BY '{' clip_objects '}'
    { $$ = make_mod(ZR_SDL_MOD_BOUNDED_BY, $3); }
| T_BOUNDED_BY '{' T_CLIPPED_BY '}'
    { $$ = make_mod(ZR_SDL_MOD_BOUND_TO_CLIP, NULL); }
;

/* An object's radiosity { importance I }: read, checked, unused. */
object_radiosity:
  %empty
| object_radiosity T_IMPORTANCE expr
    {
      double v;
      TRY(zr__sdl_want_float(p, &$3, &@3, &v));
      if (!(v > 0.0 && v <= 1.0)) {
        zr__sdl_error(p, ZR_ESCENE, &@3,
                      "importance must be greater than 0 and at most 1");
        YYABORT;
      }
    }
;

/* The objects of clipped_by and bounded_by, kept as their
   intersection. */
clip_objects:
  object
    {
      TRY($$ = zr__sdl_object_new(p, ZR_OBJ_INTERSECTION, &@1));
      TRY(zr__sdl_union_add(p, $$, $1));
    }
| clip_objects object  { TRY(zr__sdl_union_add(p, $1, $2)); $$ = $1; }
/* "clipped_by { Id }": an object identifier alone, which POV-Ray 3.7
   reads without a warning (tests/legacy/clip_id.pov). */
| T_OBJECT_ID
    {
      zr_object *copy = zr__sdl_object_copy(p, $1.ptr);
      TRY(copy);
      TRY($$ = zr__sdl_object_new(p, ZR_OBJ_INTERSECTION, &@1));
      TRY(zr__sdl_union_add(p, $$, copy));
    }
| clip_objects T_OBJECT_ID
    {
      zr_object *copy = zr__sdl_object_copy(p, $2.ptr);
      TRY(copy);
      TRY(zr__sdl_union_add(p, $1, copy));
      $$ = $1;
    }
;

transform:
  T_SCALE expr %prec OPTIONAL_COMMA
    { TRY($$ = zr__sdl_transform(p, T_SCALE, &$2, &@2)); }
| T_ROTATE expr %prec OPTIONAL_COMMA
    { TRY($$ = zr__sdl_transform(p, T_ROTATE, &$2, &@2)); }
| T_TRANSLATE expr %prec OPTIONAL_COMMA
    { TRY($$ = zr__sdl_transform(p, T_TRANSLATE, &$2, &@2)); }
| T_MATRIX '<' list '>'
    { TRY(list_done(p, $3, ($$ = zr__sdl_matrix(p, $3, &@3)) != NULL)); }
| transform_value
;

/* transform Name and transform { ... } ("Transformations"): inverse
   anywhere in a block inverts the whole block, as in POV-Ray. */
transform_value:
  T_TRANSFORM T_TRANSFORM_ID
    { TRY($$ = zr__sdl_transform_copy(p, $2.ptr)); }
| T_TRANSFORM '{' transform_block '}'
    { TRY($$ = zr__sdl_transform_block_end(p, $3)); }
;

transform_block:
  %empty               { TRY($$ = zr__sdl_transform_block_new(p)); }
| transform_block transform
    { zr__sdl_transform_block_add($1, $2); $$ = $1; }
| transform_block T_TRANSFORM_ID
    { zr__sdl_transform_block_add($1, $2.ptr); $$ = $1; }
| transform_block T_INVERSE  { $1->inverse = true; $$ = $1; }
;

/* ---- textures ---- */

pigment:
  T_PIGMENT '{' { zr__sdl_block_base(p, 'p'); } pigment_body '}'
    { $$ = $4; }
;

/* A pigment's body also stands alone in pigment_pattern { } and in the
   entries of a pigment_map. */
pigment_start:
  pigment_start_bare
/* A colour first makes the pigment that colour, yet what it modifies
   (an object's pigment, a texture identifier's) keeps its transform,
   colour_map and warps for a pattern named later: POV-Ray 3.7 draws
   object { object { B pigment { rgb C } } pigment { gradient x } }
   with B's gradient scale and colour_map (tests/test_pigment_keep.sh;
   corpus church-window.pov). */
| colour_value
    {
      TRY($$ = zr__sdl_pigment_new(p, zr__sdl_take_pigment_base(p)));
      $$->kind = ZR_PIGMENT_SOLID;
      TRY(zr__sdl_want_colour(p, &$1, &@1, &$$->colour));
    }
;

pigment_start_bare:
  %empty
    { TRY($$ = zr__sdl_pigment_new(p, zr__sdl_take_pigment_base(p))); }
| T_PIGMENT_ID
    {
      zr__sdl_take_pigment_base(p);
      TRY($$ = zr__sdl_pigment_new(p, $1.ptr));
    }
/* density { DENSITY_IDENTIFIER ... } (build_media.c). */
| T_DENSITY_ID
    {
      zr__sdl_take_pigment_base(p);
      TRY($$ = zr__sdl_pigment_new(p, $1.ptr));
    }
| T_IMAGE_MAP '{' image_map_body '}'
    {
      zr__sdl_take_pigment_base(p);
      TRY($$ = zr__sdl_pigment_new(p, NULL));
      $$->kind = ZR_PIGMENT_IMAGE;
      $$->image = $3;
    }
;

pigment_body:
  pigment_start
| pigment_body pigment_item
;

/* An average's pigment_map entry may leave out its weight when its
   pigment does not start with a colour ("Average" pattern: "[gradient y
   color_map { ... }]"); POV-Ray then reads no colour first either. */
pigment_body_bare:
  pigment_start_bare
| pigment_body_bare pigment_item
;

/* The items after a pigment's start.  Each works on the pigment before
   it on the stack, $<pigment>0: a pigment_item only ever follows a
   pigment_body or a pigment_body_bare, which are the same pigment. */
pigment_item:
  transform
    { TRY(zr__sdl_pigment_transform(p, $<pigment>0, $1)); }
| pattern_kw
    { TRY(zr__sdl_pigment_pattern(p, $<pigment>0, $1, NULL)); }
| block_kw colour_list
    { TRY(zr__sdl_pigment_pattern(p, $<pigment>0, $1, $2)); }
| block_kw pigment_blocks
    {
      TRY(zr__sdl_pigment_pattern(p, $<pigment>0, $1, NULL));
      TRY(zr__sdl_pigment_map_set(p, $<pigment>0, $2, &@2));
    }
| spiral_kw expr
    {
      TRY(zr__sdl_pigment_pattern(p, $<pigment>0, $1, NULL));
      TRY(zr__sdl_spiral_arms(p, &$<pigment>0->pattern, &$2, &@2));
    }
| fractal
    {
      TRY(zr__sdl_pigment_pattern(p, $<pigment>0, $1.kind, NULL));
      zr__sdl_fractal_set(&$<pigment>0->pattern, &$1);
    }
/* object { OBJECT Outside, Inside } ("Object Pattern"). */
| T_OBJECT '{' pattern_object colour_list '}'
    {
      TRY(zr__sdl_pigment_pattern(p, $<pigment>0, ZR_PAT_OBJECT, $4));
      zr__sdl_pattern_object(&$<pigment>0->pattern, $3);
    }
| T_OBJECT '{' pattern_object pigment_blocks '}'
    {
      TRY(zr__sdl_pigment_pattern(p, $<pigment>0, ZR_PAT_OBJECT, NULL));
      zr__sdl_pattern_object(&$<pigment>0->pattern, $3);
      TRY(zr__sdl_pigment_map_set(p, $<pigment>0, $4, &@4));
    }
| fn_pattern
    {
      TRY(zr__sdl_pigment_pattern(p, $<pigment>0, ZR_PAT_FUNCTION, NULL));
      TRY(zr__sdl_pattern_function(p, &$<pigment>0->pattern, $1, &@1));
    }
| T_PIGMENT_PATTERN '{' pigment_body '}'
    {
      zr_pigment *pg = $<pigment>0;
      TRY(zr__sdl_pigment_pattern(p, pg, ZR_PAT_PIGMENT_PATTERN, NULL));
      zr__sdl_pigment_pattern_of(&pg->pattern, $3);
    }
| image_pattern
    {
      TRY(zr__sdl_pigment_pattern(p, $<pigment>0, ZR_PAT_IMAGE, NULL));
      $<pigment>0->pattern.image = $1;
    }
| pigment_map
    { TRY(zr__sdl_pigment_map_set(p, $<pigment>0, $1, &@1)); }
/* A density's own items (build_media.c): its body is a pigment's. */
| density_map
    { TRY(zr__sdl_pigment_map_set(p, $<pigment>0, $1, &@1)); }
| T_DENSITY_FILE T_DF3 str_expr
    { TRY(zr__sdl_density_file(p, $<pigment>0, $3, &@3)); }
| T_INTERPOLATE expr
    {
      zr_pigment *pg = $<pigment>0;
      TRY(zr__sdl_density_interpolate(p, &pg->pattern, &$2, &@2));
    }
| block_kw density_blocks
    {
      TRY(zr__sdl_pigment_pattern(p, $<pigment>0, $1, NULL));
      TRY(zr__sdl_pigment_map_set(p, $<pigment>0, $2, &@2));
    }
| slope_block
    {
      TRY(zr__sdl_pigment_pattern(p, $<pigment>0, ZR_PAT_SLOPE, NULL));
      $<pigment>0->pattern.slope = *$1;
    }
/* tiling N ("Tiling Pattern"). */
| T_TILING expr
    {
      TRY(zr__sdl_pigment_pattern(p, $<pigment>0, ZR_PAT_TILING, NULL));
      TRY(zr__sdl_tiling(p, &$<pigment>0->pattern, &$2, &@2));
    }
| T_GRADIENT expr
    {
      TRY(zr__sdl_pigment_pattern(p, $<pigment>0, ZR_PAT_GRADIENT, NULL));
      TRY(zr__sdl_gradient(p, &$<pigment>0->pattern, &$2, &@2));
    }
| pattern_mod
    {
      zr_pigment *pg = $<pigment>0;
      TRY(zr__sdl_pattern_mod_in(p, &pg->pattern, pg->transform, &$1));
    }
| colour_map  { $<pigment>0->colour_map = $1; }
/* uv_mapping ("UV Mapping"): the pattern takes the surface's (u, v, 0). */
| T_UV_MAPPING  { $<pigment>0->uv_mapping = true; }
/* quick_color: the colour of POV-Ray's previews at +Q5 and below. */
| T_QUICK_COLOUR colour_value
    {
      zr_pigment *pg = $<pigment>0;
      TRY(zr__sdl_want_colour(p, &$2, &@2, &pg->quick));
      pg->has_quick = true;
    }
;

/* ---- patterns (reference manual, "Pattern") ---- */

pattern_kw:
  T_AGATE { $$ = ZR_PAT_AGATE; }         | T_BOXED { $$ = ZR_PAT_BOXED; }
| T_BOZO { $$ = ZR_PAT_BOZO; }           | T_BUMPS { $$ = ZR_PAT_BUMPS; }
| T_CRACKLE { $$ = ZR_PAT_CRACKLE; }     | T_DENTS { $$ = ZR_PAT_DENTS; }
| T_CYLINDRICAL { $$ = ZR_PAT_CYLINDRICAL; }
| T_GRANITE { $$ = ZR_PAT_GRANITE; }     | T_LEOPARD { $$ = ZR_PAT_LEOPARD; }
| T_MARBLE { $$ = ZR_PAT_MARBLE; }       | T_ONION { $$ = ZR_PAT_ONION; }
| T_PLANAR { $$ = ZR_PAT_PLANAR; }       | T_RADIAL { $$ = ZR_PAT_RADIAL; }
| T_RIPPLES { $$ = ZR_PAT_RIPPLES; }     | T_SPOTTED { $$ = ZR_PAT_SPOTTED; }
| T_SPHERICAL { $$ = ZR_PAT_SPHERICAL; } | T_WAVES { $$ = ZR_PAT_WAVES; }
| T_WOOD { $$ = ZR_PAT_WOOD; }           | T_WRINKLES { $$ = ZR_PAT_WRINKLES; }
| T_AVERAGE { $$ = ZR_PAT_AVERAGE; }     | T_CELLS { $$ = ZR_PAT_CELLS; }
| T_QUILTED { $$ = ZR_PAT_QUILTED; }
;

/* mandel Iterations, julia <C>, Iterations, magnet 1|2 mandel ...
   ("Fractal Pattern"); exponent, interior and exterior are pattern
   modifiers. */
fractal:
  fractal_head
| T_MAGNET expr fractal_head
    { $$ = $3; TRY(zr__sdl_fractal_magnet(p, &$$, &$2, &@2)); }
;

fractal_head:
  T_MANDEL expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_fractal_head(p, &$$, ZR_PAT_MANDEL, NULL, NULL, &$2, &@2)); }
| T_JULIA expr comma expr %prec OPTIONAL_COMMA
    {
      TRY(zr__sdl_fractal_head(p, &$$, ZR_PAT_JULIA, &$2, &@2, &$4, &@4));
    }
;

/* The object of an object pattern or looks_like: an identifier alone is
   a copy. */
pattern_object:
  T_OBJECT_ID          { TRY($$ = zr__sdl_object_copy(p, $1.ptr)); }
| object
;

/* function { ... } as a pattern: compiled like a declared function's
   body (the state after 'function' only reduces, see rvalue). */
fn_pattern:
  T_FUNCTION
    {
      if (yychar != ZR__POV_EMPTY) {
        zr__sdl_error(p, ZR_ESYNTAX, &@1, "internal error: the parser "
                      "looked past 'function'");
        YYABORT;
      }
      TRY($$ = zr__sdl_function_parse(p, &@1));
    }
;

/* spiral1 and spiral2 take their number of arms. */
spiral_kw:
  T_SPIRAL1 { $$ = ZR_PAT_SPIRAL1; }     | T_SPIRAL2 { $$ = ZR_PAT_SPIRAL2; }
;

/* "checker pigment {A}, pigment {B}": a block pattern's items. */
pigment_blocks:
  pigment
    {
      zr_map_entry e = {.u.pigment = $1};
      TRY($$ = zr__sdl_map_new(p));
      TRY(zr__sdl_map_add_block(p, $$, &e, &@1));
    }
| pigment_blocks pigment
    {
      zr_map_entry e = {.u.pigment = $2};
      TRY(zr__sdl_map_add_block(p, $1, &e, &@2));
      $$ = $1;
    }
| pigment_blocks ','   { $$ = $1; }
;

normal_blocks:
  normal
    {
      zr_map_entry e = {.u.normal = $1};
      TRY($$ = zr__sdl_map_new(p));
      TRY(zr__sdl_map_add_block(p, $$, &e, &@1));
    }
| normal_blocks normal
    {
      zr_map_entry e = {.u.normal = $2};
      TRY(zr__sdl_map_add_block(p, $1, &e, &@2));
      $$ = $1;
    }
| normal_blocks ','    { $$ = $1; }
;

texture_blocks:
  texture
    {
      zr_map_entry e = {.u.texture = $1};
      TRY($$ = zr__sdl_map_new(p));
      TRY(zr__sdl_map_add_block(p, $$, &e, &@1));
    }
| texture_blocks texture
    {
      zr_map_entry e = {.u.texture = $2};
      TRY(zr__sdl_map_add_block(p, $1, &e, &@2));
      $$ = $1;
    }
| texture_blocks ','   { $$ = $1; }
;

/* pigment_map { [Value PIGMENT_BODY] ... } and the other maps
   (reference manual, "Pigment Maps and Pigment Lists", "Normal Maps",
   "Texture Maps", "Slope Maps"). */
pigment_map:
  T_PIGMENT_MAP '{' pigment_map_body '}'
    { TRY(zr__sdl_map_done(p, $3, "pigment_map", &@1)); $$ = $3; }
;

pigment_map_body:
  %empty               { TRY($$ = zr__sdl_map_new(p)); }
| pigment_map_body '[' expr comma pigment_body ']'
    {
      zr_map_entry e = {.u.pigment = $5};
      TRY(zr__sdl_map_add(p, $1, &$3, &@3, &e));
      $$ = $1;
    }
/* An average's entry may leave out its weight, 1, when its pigment
   does not start with a colour ("[function { ... } color_map { ... }]",
   "[gradient y color_map { ... }]"). */
| pigment_map_body '[' pigment_body_bare ']'
    {
      zr_map_entry e = {.u.pigment = $3};
      TRY(zr__sdl_map_add_weight1(p, $1, &e));
      $$ = $1;
    }
;

normal_map:
  T_NORMAL_MAP '{' normal_map_body '}'
    { TRY(zr__sdl_map_done(p, $3, "normal_map", &@1)); $$ = $3; }
;

normal_map_body:
  %empty               { TRY($$ = zr__sdl_map_new(p)); }
| normal_map_body '[' expr comma normal_body ']'
    {
      zr_map_entry e = {.u.normal = $5};
      TRY(zr__sdl_map_add(p, $1, &$3, &@3, &e));
      $$ = $1;
    }
/* An average's entries may leave out their weight, 1. */
| normal_map_body '[' normal_body ']'
    {
      zr_map_entry e = {.u.normal = $3};
      TRY(zr__sdl_map_add_weight1(p, $1, &e));
      $$ = $1;
    }
;

texture_map:
  T_TEXTURE_MAP '{' texture_map_body '}'
    { TRY(zr__sdl_map_done(p, $3, "texture_map", &@1)); $$ = $3; }
;

texture_map_body:
  %empty               { TRY($$ = zr__sdl_map_new(p)); }
| texture_map_body '[' expr comma texture_body ']'
    {
      TRY(zr__sdl_texture_done(p, $5));
      zr_map_entry e = {.u.texture = $5};
      TRY(zr__sdl_map_add(p, $1, &$3, &@3, &e));
      $$ = $1;
    }
| texture_map_body '[' texture_body ']'
    {
      TRY(zr__sdl_texture_done(p, $3));
      zr_map_entry e = {.u.texture = $3};
      TRY(zr__sdl_map_add_weight1(p, $1, &e));
      $$ = $1;
    }
;

slope_map:
  T_SLOPE_MAP '{' slope_map_body '}'
    { TRY(zr__sdl_map_done(p, $3, "slope_map", &@1)); $$ = $3; }
;

slope_map_body:
  %empty               { TRY($$ = zr__sdl_map_new(p)); }
| slope_map_body '[' expr comma expr ']'
    { TRY(zr__sdl_slope_add(p, $1, &$3, &@3, &$5, &@5)); $$ = $1; }
;

block_kw:
  T_CHECKER { $$ = ZR_PAT_CHECKER; }     | T_HEXAGON { $$ = ZR_PAT_HEXAGON; }
| T_BRICK { $$ = ZR_PAT_BRICK; }
;

/* "checker Red, Blue" or "checker color Red color Blue": a comma or the
   colour keyword separates the colours ("Color List Pigments"). */
colour_list:
  %empty               { TRY($$ = clist_new(p)); }
| colour_list_items
;

colour_list_items:
  colour_value
    { TRY($$ = clist_new(p)); TRY(zr__sdl_clist_add(p, $$, &$1, &@1)); }
| colour_list_items ',' colour_value
    { $$ = $1; TRY(zr__sdl_clist_add(p, $$, &$3, &@3)); }
| colour_list_items T_COLOUR colour_spec
    { $$ = $1; TRY(zr__sdl_clist_add(p, $$, &$3, &@3)); }
| colour_list_items colour_rgb
    { $$ = $1; TRY(zr__sdl_clist_add(p, $$, &$2, &@2)); }
/* "checker Black White": a colour identifier after another colour
   without a comma (POV-Ray 3.7 renders it without a warning). */
| colour_list_items T_COLOUR_ID
    { $$ = $1; TRY(zr__sdl_clist_add(p, $$, &$2.num, &@2)); }
;

pattern_mod:
  T_TURBULENCE expr    { $$ = make_pmod(T_TURBULENCE, &$2, &@2); }
| T_OCTAVES expr       { $$ = make_pmod(T_OCTAVES, &$2, &@2); }
| T_OMEGA expr         { $$ = make_pmod(T_OMEGA, &$2, &@2); }
| T_LAMBDA expr        { $$ = make_pmod(T_LAMBDA, &$2, &@2); }
| T_FREQUENCY expr     { $$ = make_pmod(T_FREQUENCY, &$2, &@2); }
| T_PHASE expr         { $$ = make_pmod(T_PHASE, &$2, &@2); }
| T_AGATE_TURB expr    { $$ = make_pmod(T_AGATE_TURB, &$2, &@2); }
| T_MORTAR expr        { $$ = make_pmod(T_MORTAR, &$2, &@2); }
| T_BRICK_SIZE expr    { $$ = make_pmod(T_BRICK_SIZE, &$2, &@2); }
| T_RAMP_WAVE          { $$ = make_pmod(T_RAMP_WAVE, NULL, &@1); }
| T_TRIANGLE_WAVE      { $$ = make_pmod(T_TRIANGLE_WAVE, NULL, &@1); }
| T_SINE_WAVE          { $$ = make_pmod(T_SINE_WAVE, NULL, &@1); }
| T_SCALLOP_WAVE       { $$ = make_pmod(T_SCALLOP_WAVE, NULL, &@1); }
| T_CUBIC_WAVE         { $$ = make_pmod(T_CUBIC_WAVE, NULL, &@1); }
| T_POLY_WAVE          { $$ = make_pmod(T_POLY_WAVE, NULL, &@1); }
| T_POLY_WAVE expr     { $$ = make_pmod(T_POLY_WAVE, &$2, &@2); }
| T_CONTROL0 expr      { $$ = make_pmod(T_CONTROL0, &$2, &@2); }
| T_CONTROL1 expr      { $$ = make_pmod(T_CONTROL1, &$2, &@2); }
| T_NOISE_GENERATOR expr { $$ = make_pmod(T_NOISE_GENERATOR, &$2, &@2); }
| T_NUMBER_OF_WAVES expr { $$ = make_pmod(T_NUMBER_OF_WAVES, &$2, &@2); }
| T_EXPONENT expr      { $$ = make_pmod(T_EXPONENT, &$2, &@2); }
| T_FORM expr          { $$ = make_pmod(T_FORM, &$2, &@2); }
| T_METRIC expr        { $$ = make_pmod(T_METRIC, &$2, &@2); }
| T_OFFSET expr        { $$ = make_pmod(T_OFFSET, &$2, &@2); }
| T_SOLID              { $$ = make_pmod(T_SOLID, NULL, &@1); }
| T_INTERIOR expr ',' expr
    { TRY(zr__sdl_fractal_colouring(p, T_INTERIOR, &$2, &$4, &@2, &$$)); }
| T_EXTERIOR expr ',' expr
    { TRY(zr__sdl_fractal_colouring(p, T_EXTERIOR, &$2, &$4, &@2, &$$)); }
| warp_body '}'
;

/* warp { kind ... } ("Warps"): the kind's keyword first, then items
   that build_warp.c checks against the kind. */
warp_body:
  T_WARP '{' T_TURBULENCE expr
    { TRY(zr__sdl_warp_new(p, ZR_WARP_TURBULENCE, &$4, NULL, &@4, &$$)); }
| T_WARP '{' T_REPEAT expr
    { TRY(zr__sdl_warp_new(p, ZR_WARP_REPEAT, &$4, NULL, &@4, &$$)); }
| T_WARP '{' T_BLACK_HOLE expr ',' expr
    { TRY(zr__sdl_warp_new(p, ZR_WARP_BLACK_HOLE, &$4, &$6, &@4, &$$)); }
| T_WARP '{' T_PLANAR
    { TRY(zr__sdl_warp_new(p, ZR_WARP_PLANAR, NULL, NULL, &@3, &$$)); }
| T_WARP '{' T_PLANAR expr ',' expr
    { TRY(zr__sdl_warp_new(p, ZR_WARP_PLANAR, &$4, &$6, &@4, &$$)); }
| T_WARP '{' T_CYLINDRICAL
    { TRY(zr__sdl_warp_new(p, ZR_WARP_CYLINDRICAL, NULL, NULL, &@3, &$$)); }
| T_WARP '{' T_SPHERICAL
    { TRY(zr__sdl_warp_new(p, ZR_WARP_SPHERICAL, NULL, NULL, &@3, &$$)); }
| T_WARP '{' T_TOROIDAL
    { TRY(zr__sdl_warp_new(p, ZR_WARP_TOROIDAL, NULL, NULL, &@3, &$$)); }
| T_WARP '{' T_CUBIC
    { TRY(zr__sdl_warp_new(p, ZR_WARP_CUBIC, NULL, NULL, &@3, &$$)); }
| warp_body warp_item
    { $$ = $1; TRY(zr__sdl_warp_item(p, &$$, &$2)); }
;

warp_item:
  T_OCTAVES expr       { $$ = make_pmod(T_OCTAVES, &$2, &@1); }
| T_OMEGA expr         { $$ = make_pmod(T_OMEGA, &$2, &@1); }
| T_LAMBDA expr        { $$ = make_pmod(T_LAMBDA, &$2, &@1); }
| T_TURBULENCE expr    { $$ = make_pmod(T_TURBULENCE, &$2, &@1); }
| T_OFFSET expr        { $$ = make_pmod(T_OFFSET, &$2, &@1); }
| T_FLIP expr          { $$ = make_pmod(T_FLIP, &$2, &@1); }
| T_STRENGTH expr      { $$ = make_pmod(T_STRENGTH, &$2, &@1); }
| T_FALLOFF expr       { $$ = make_pmod(T_FALLOFF, &$2, &@1); }
| T_INVERSE            { $$ = make_pmod(T_INVERSE, NULL, &@1); }
| T_REPEAT expr        { $$ = make_pmod(T_REPEAT, &$2, &@1); }
| T_ORIENTATION expr   { $$ = make_pmod(T_ORIENTATION, &$2, &@1); }
| T_DIST_EXP expr      { $$ = make_pmod(T_DIST_EXP, &$2, &@1); }
| T_MAJOR_RADIUS expr  { $$ = make_pmod(T_MAJOR_RADIUS, &$2, &@1); }
;

/* color_map { [Value Colour] ... } (reference manual, "Color Maps"). */
colour_map:
  colour_map_body '}'
    { TRY(zr__sdl_colour_map_done(p, $1, &@1)); $$ = $1; }
;

colour_map_head:
  T_COLOUR_MAP '{'     { TRY($$ = zr__sdl_colour_map_new(p, NULL)); }
| T_COLOUR_MAP '{' T_COLOUR_MAP_ID
    { TRY($$ = zr__sdl_colour_map_new(p, $3.ptr)); }
;

colour_map_body:
  colour_map_head
| colour_map_body '[' expr comma colour_value ']'
    { TRY(zr__sdl_colour_map_add(p, $1, &$3, &@3, &$5, &@5)); $$ = $1; }
/* The form before POV-Ray 3: [From, To color C1 color C2]. */
| colour_map_body '[' expr comma expr colour_kw_value colour_kw_value ']'
    {
      TRY(zr__sdl_colour_map_add(p, $1, &$3, &@3, &$6, &@6));
      TRY(zr__sdl_colour_map_add(p, $1, &$5, &@5, &$7, &@7));
      $$ = $1;
    }
;

/* ---- normals (reference manual, "Normal") ---- */

normal:
  T_NORMAL '{' { zr__sdl_block_base(p, 'n'); } normal_body '}'
    { $$ = $4; }
;

normal_start:
  %empty
    { TRY($$ = zr__sdl_normal_new(p, zr__sdl_take_normal_base(p))); }
| T_NORMAL_ID
    {
      zr__sdl_take_normal_base(p);
      TRY($$ = zr__sdl_normal_new(p, $1.ptr));
    }
;

normal_body:
  normal_start
| normal_body T_NO_BUMP_SCALE
    { no_bump_scale_normal($1); $$ = $1; }
| normal_body T_FACETS
    { facets_warning(p, &@2); $$ = $1; }
| normal_body T_COORDS expr
    { $$ = $1; }
| normal_body T_SIZE expr
    { $$ = $1; }
| normal_body T_DENSITY_FILE T_DF3 str_expr
    { TRY(zr__sdl_normal_density_file(p, $1, $4, NULL, &@4)); $$ = $1; }
| normal_body T_DENSITY_FILE T_DF3 str_expr ',' expr
    { TRY(zr__sdl_normal_density_file(p, $1, $4, &$6, &@6)); $$ = $1; }
| normal_body T_INTERPOLATE expr
    { TRY(zr__sdl_density_interpolate(p, &$1->pattern, &$3, &@3)); $$ = $1; }
| normal_body pattern_kw
    { TRY(zr__sdl_normal_pattern(p, $1, $2, NULL, &@2)); $$ = $1; }
| normal_body pattern_kw expr
    { TRY(zr__sdl_normal_pattern(p, $1, $2, &$3, &@3)); $$ = $1; }
| normal_body block_kw
    { TRY(zr__sdl_normal_pattern(p, $1, $2, NULL, &@2)); $$ = $1; }
| normal_body block_kw expr
    { TRY(zr__sdl_normal_pattern(p, $1, $2, &$3, &@3)); $$ = $1; }
| normal_body block_kw normal_blocks
    {
      TRY(zr__sdl_normal_pattern(p, $1, $2, NULL, &@2));
      TRY(zr__sdl_normal_map_set(p, $1, $3, &@3));
      $$ = $1;
    }
| normal_body spiral_kw expr
    {
      TRY(zr__sdl_normal_pattern(p, $1, $2, NULL, &@2));
      TRY(zr__sdl_spiral_arms(p, &$1->pattern, &$3, &@3));
      $$ = $1;
    }
| normal_body spiral_kw expr ',' expr
    {
      TRY(zr__sdl_normal_pattern(p, $1, $2, &$5, &@5));
      TRY(zr__sdl_spiral_arms(p, &$1->pattern, &$3, &@3));
      $$ = $1;
    }
| normal_body fractal
    {
      TRY(zr__sdl_normal_pattern(p, $1, $2.kind, NULL, &@2));
      zr__sdl_fractal_set(&$1->pattern, &$2);
      $$ = $1;
    }
| normal_body fractal comma expr
    {
      TRY(zr__sdl_normal_pattern(p, $1, $2.kind, &$4, &@4));
      zr__sdl_fractal_set(&$1->pattern, &$2);
      $$ = $1;
    }
| normal_body fn_pattern
    {
      TRY(zr__sdl_normal_pattern(p, $1, ZR_PAT_FUNCTION, NULL, &@2));
      TRY(zr__sdl_pattern_function(p, &$1->pattern, $2, &@2));
      $$ = $1;
    }
| normal_body fn_pattern expr
    {
      TRY(zr__sdl_normal_pattern(p, $1, ZR_PAT_FUNCTION, &$3, &@3));
      TRY(zr__sdl_pattern_function(p, &$1->pattern, $2, &@2));
      $$ = $1;
    }
| normal_body T_PIGMENT_PATTERN '{' pigment_body '}'
    {
      TRY(zr__sdl_normal_pattern(p, $1, ZR_PAT_PIGMENT_PATTERN, NULL, &@2));
      zr__sdl_pigment_pattern_of(&$1->pattern, $4);
      $$ = $1;
    }
| normal_body T_PIGMENT_PATTERN '{' pigment_body '}' comma expr
    {
      TRY(zr__sdl_normal_pattern(p, $1, ZR_PAT_PIGMENT_PATTERN, &$7, &@7));
      zr__sdl_pigment_pattern_of(&$1->pattern, $4);
      $$ = $1;
    }
| normal_body image_pattern
    {
      TRY(zr__sdl_normal_pattern(p, $1, ZR_PAT_IMAGE, NULL, &@2));
      $1->pattern.image = $2;
      $$ = $1;
    }
| normal_body image_pattern comma expr
    {
      TRY(zr__sdl_normal_pattern(p, $1, ZR_PAT_IMAGE, &$4, &@4));
      $1->pattern.image = $2;
      $$ = $1;
    }
| normal_body normal_map
    { TRY(zr__sdl_normal_map_set(p, $1, $2, &@2)); $$ = $1; }
| normal_body slope_map  { $1->slope_map = $2; $$ = $1; }
| normal_body slope_block
    {
      zr__sdl_error(p, ZR_EUNSUPPORTED, &@2, "the slope pattern in a "
                    "normal is not supported (pigments and textures are)");
      YYABORT;
    }
| normal_body T_GRADIENT expr
    {
      TRY(zr__sdl_normal_pattern(p, $1, ZR_PAT_GRADIENT, NULL, &@2));
      TRY(zr__sdl_gradient(p, &$1->pattern, &$3, &@3));
      $$ = $1;
    }
| normal_body T_GRADIENT expr ',' expr
    {
      TRY(zr__sdl_normal_pattern(p, $1, ZR_PAT_GRADIENT, &$5, &@5));
      TRY(zr__sdl_gradient(p, &$1->pattern, &$3, &@3));
      $$ = $1;
    }
/* "gradient x 0.6" without the comma (gliese1337's Flame1.pov): POV-Ray
   3.7 takes the bump size after the vector (tests/legacy/
   gradient_amount.pov).  Only a plain number can follow without a comma:
   a '-' or '(' would continue the vector's expression. */
| normal_body T_GRADIENT expr T_NUMBER
    {
      zr_sdl_expr amount = zr__sdl_float($4);
      TRY(zr__sdl_normal_pattern(p, $1, ZR_PAT_GRADIENT, &amount, &@4));
      TRY(zr__sdl_gradient(p, &$1->pattern, &$3, &@3));
      $$ = $1;
    }
| normal_body T_BUMP_SIZE expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->amount)); $$ = $1; }
| normal_body T_BUMP_MAP '{' bump_map_body '}'
    { TRY(zr__sdl_bump_map_end(p, $1, $4, &@2)); $$ = $1; }
| normal_body T_ACCURACY expr
    { TRY(zr__sdl_normal_accuracy(p, $1, &$3, &@3)); $$ = $1; }
| normal_body transform
    { TRY(zr__sdl_normal_transform(p, $1, $2)); $$ = $1; }
| normal_body T_UV_MAPPING  { $1->uv_mapping = true; $$ = $1; }
| normal_body pattern_mod
    {
      TRY(zr__sdl_pattern_mod_in(p, &$1->pattern, $1->transform, &$2));
      $$ = $1;
    }
;

/* ---- image maps (reference manual, "Image Map") ---- */

/* FILE, then "gamma G" or "gamma srgb" and "premultiplied B" if any, in
   either order ("The Gamma Option", "Using the Alpha Channel": they
   must follow the file name): the head of image_map, bump_map and
   image_pattern. */
bitmap_file:
  image_map_file
    { $$ = (zr_sdl_bitmap_file){.name = $1, .loc = @1}; }
| bitmap_file T_GAMMA expr
    {
      $$ = $1;
      $$.gamma = $3;
      $$.has_gamma = true;
      $$.srgb = false;
      $$.gamma_loc = @3;
    }
| bitmap_file T_GAMMA T_SRGB
    {
      $$ = $1;
      $$.has_gamma = false;
      $$.srgb = true;
      $$.gamma_loc = @3;
    }
| bitmap_file T_PREMULTIPLIED expr
    {
      $$ = $1;
      $$.premultiplied = $3;
      $$.has_premultiplied = true;
      $$.premultiplied_loc = @3;
    }
;

/* The items every bitmap takes ("Specifying an Image Map"): map_type N,
   once, interpolate N. */
bitmap_mod:
  T_MAP_TYPE expr
    {
      $$ = (zr_sdl_bitmap_mod){.token = T_MAP_TYPE, .value = $2,
                               .has_value = true, .loc = @2};
    }
| T_ONCE { $$ = (zr_sdl_bitmap_mod){.token = T_ONCE, .loc = @1}; }
| T_INTERPOLATE expr
    {
      $$ = (zr_sdl_bitmap_mod){.token = T_INTERPOLATE, .value = $2,
                               .has_value = true, .loc = @2};
    }
;

image_map_file:
  str_expr
| T_PNG str_expr       { $$ = $2; @$ = @2; }
| T_JPEG str_expr      { $$ = $2; @$ = @2; }
| T_PPM str_expr       { $$ = $2; @$ = @2; }
| T_PGM str_expr       { $$ = $2; @$ = @2; }
| T_GIF str_expr       { $$ = $2; @$ = @2; }
| T_TGA str_expr       { $$ = $2; @$ = @2; }
| T_BMP str_expr       { $$ = $2; @$ = @2; }
| T_TIFF str_expr      { $$ = $2; @$ = @2; }
| T_HDR str_expr       { $$ = $2; @$ = @2; }
| T_EXR str_expr       { $$ = $2; @$ = @2; }
;

image_map_body:
  bitmap_file { TRY($$ = zr__sdl_bitmap_new(p, "image_map", &$1)); }
| image_map_body bitmap_mod
    {
      const zr_sdl_expr *v = $2.has_value ? &$2.value : NULL;
      TRY(zr__sdl_image_map_mod(p, $1, $2.token, v, &$2.loc));
      $$ = $1;
    }
| image_map_body T_FILTER T_ALL expr
    { TRY(zr__sdl_image_map_mod(p, $1, T_FILTER, &$4, &@4)); $$ = $1; }
| image_map_body T_TRANSMIT T_ALL expr
    { TRY(zr__sdl_image_map_mod(p, $1, T_TRANSMIT, &$4, &@4)); $$ = $1; }
| image_map_body T_FILTER expr ',' expr
    {
      TRY(zr__sdl_image_map_index(p, $1, T_FILTER, &$3, &@3, &$5, &@5));
      $$ = $1;
    }
| image_map_body T_TRANSMIT expr ',' expr
    {
      TRY(zr__sdl_image_map_index(p, $1, T_TRANSMIT, &$3, &@3, &$5, &@5));
      $$ = $1;
    }
;

/* image_pattern { FILE [gamma G] ITEMS } ("Image Pattern"): the
   picture's grey, read as a bump_map reads it, is the pattern's value,
   or with use_alpha its transparency. */
image_pattern:
  T_IMAGE_PATTERN '{' image_pattern_body '}' { $$ = $3; }
;

image_pattern_body:
  bitmap_file { TRY($$ = zr__sdl_bitmap_new(p, "image_pattern", &$1)); }
| image_pattern_body bitmap_mod
    {
      const zr_sdl_expr *v = $2.has_value ? &$2.value : NULL;
      TRY(zr__sdl_image_map_mod(p, $1, $2.token, v, &$2.loc));
      $$ = $1;
    }
/* use_alpha: the value is 1 - alpha, 0 where the file has no alpha
   (measured: tests/test_image_pattern.sh). */
| image_pattern_body T_USE_ALPHA
    { TRY(zr__sdl_image_map_mod(p, $1, T_USE_ALPHA, NULL, &@2)); $$ = $1; }
;

/* bump_map { FILE [gamma G] ITEMS } ("Bump Map"), build_texture.c. */
bump_map_body:
  bitmap_file
    {
      TRY($$ = zr__sdl_bump_map_new(p,
                                    zr__sdl_bitmap_new(p, "bump_map", &$1)));
    }
| bump_map_body bitmap_mod
    {
      const zr_sdl_expr *v = $2.has_value ? &$2.value : NULL;
      TRY(zr__sdl_bump_map_mod(p, $1, $2.token, v, &$2.loc));
      $$ = $1;
    }
| bump_map_body T_USE_INDEX
    { TRY(zr__sdl_bump_map_mod(p, $1, T_USE_INDEX, NULL, &@2)); $$ = $1; }
| bump_map_body T_USE_COLOR
    { TRY(zr__sdl_bump_map_mod(p, $1, T_USE_COLOR, NULL, &@2)); $$ = $1; }
| bump_map_body T_BUMP_SIZE expr
    { TRY(zr__sdl_bump_map_mod(p, $1, T_BUMP_SIZE, &$3, &@3)); $$ = $1; }
;

/* material_map { FILE ITEMS TEXTURES TRANSFORMS } ("Material Maps"). */
material_map_head:
  image_map_file
    {
      zr_sdl_bitmap_file f = {.name = $1, .loc = @1};
      TRY($$ = zr__sdl_bitmap_new(p, "material_map", &f));
    }
| material_map_head bitmap_mod
    {
      const zr_sdl_expr *v = $2.has_value ? &$2.value : NULL;
      TRY(zr__sdl_image_map_mod(p, $1, $2.token, v, &$2.loc));
      $$ = $1;
    }
;

/* Any number of textures, indexed from 0. */
material_textures:
  texture
    {
      zr_map_entry e = {.u.texture = $1};
      TRY($$ = zr__sdl_map_new(p));
      TRY(zr__sdl_material_add(p, $$, &e));
    }
| material_textures texture
    {
      zr_map_entry e = {.u.texture = $2};
      TRY(zr__sdl_material_add(p, $1, &e));
      $$ = $1;
    }
| material_textures ','  { $$ = $1; }
;

finish:
  finish_body '}'
;

/* slope { <D> [, Lo, Hi] [altitude <A> [, Lo, Hi]] } ("Slope Pattern"). */
slope_block:
  slope_dir '}'
/* POV-Ray 3.7 also reads the direction alone, without braces
   (terrain.inc: "slope -z"). */
| T_SLOPE expr %prec OPTIONAL_COMMA
    { TRY($$ = zr__sdl_slope_new(p, &$2, &@2, NULL, NULL, NULL)); }
| slope_dir T_ALTITUDE expr '}'
    {
      TRY(zr__sdl_slope_altitude(p, $1, &$3, &@3, NULL, NULL, NULL));
      $$ = $1;
    }
| slope_dir T_ALTITUDE expr ',' expr ',' expr '}'
    {
      TRY(zr__sdl_slope_altitude(p, $1, &$3, &@3, &$5, &$7, &@5));
      $$ = $1;
    }
;

slope_dir:
  T_SLOPE '{' expr
    { TRY($$ = zr__sdl_slope_new(p, &$3, &@3, NULL, NULL, NULL)); }
| T_SLOPE '{' expr ',' expr ',' expr
    { TRY($$ = zr__sdl_slope_new(p, &$3, &@3, &$5, &$7, &@5)); }
| T_SLOPE '{' T_POINT_AT
    {
      zr__sdl_error(p, ZR_EUNSUPPORTED, &@3,
                    "slope { point_at } is not supported; give a direction");
      YYABORT;
    }
;

/* irid { Amount [thickness T] [turbulence U] } ("Iridescence"). */
irid_body:
  finish_body T_IRID '{' expr
    { TRY(zr__sdl_finish_irid(p, $1, T_IRID, &$4, &@4)); $$ = $1; }
| irid_body T_THICKNESS expr
    { TRY(zr__sdl_finish_irid(p, $1, T_THICKNESS, &$3, &@3)); $$ = $1; }
| irid_body T_TURBULENCE expr
    { TRY(zr__sdl_finish_irid(p, $1, T_TURBULENCE, &$3, &@3)); $$ = $1; }
;

finish_head:
  finish_open
    { TRY($$ = zr__sdl_finish_new(p, zr__sdl_take_finish_base(p))); }
| finish_open T_FINISH_ID
    {
      zr__sdl_take_finish_base(p);
      TRY($$ = zr__sdl_finish_new(p, $2.ptr));
    }
;

finish_open:
  T_FINISH '{'         { zr__sdl_block_base(p, 'f'); }
;

finish_body:
  finish_head
/* POV-Ray 3.0's refraction and ior in a finish: POV-Ray 3.7 moves the
   ior to the interior and reads refraction 1 as no change, each with a
   warning (measured: tests/legacy/finish_ior.pov). */
| finish_body T_IOR expr
    {
      TRY(zr__sdl_want_float(p, &$3, &@3, &$1->legacy_ior));
      zr__sdl_warning(p, &@2, "Index of refraction value should be "
                      "specified in 'interior{...}' statement.");
      $$ = $1;
    }
| finish_body T_REFRACTION expr
    {
      double r;
      TRY(zr__sdl_want_float(p, &$3, &@3, &r));
      zr__sdl_warning(p, &@2, "Refraction value unnecessary to turn on "
                      "refraction. To attenuate, the fade_power and "
                      "fade_distance keywords should be specified in "
                      "'interior{...}' statement.");
      if (r != 1.0 && r != 0.0)
        zr__sdl_warning(p, &@2, "zRcube renders 'refraction %g' as "
                        "'refraction 1': POV-Ray dims the light through "
                        "the object", r);
      $$ = $1;
    }
| finish_body T_AMBIENT colour_value
    { TRY(zr__sdl_want_rgb(p, &$3, &@3, &$1->ambient)); $$ = $1; }
| finish_body T_EMISSION colour_value
    { TRY(zr__sdl_want_rgb(p, &$3, &@3, &$1->emission)); $$ = $1; }
| finish_body T_ENERGY colour_value
    { TRY(zr__sdl_finish_energy(p, $1, &$3, &@3)); $$ = $1; }
| finish_body T_DIFFUSE expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->diffuse)); $$ = $1; }
| finish_body T_DIFFUSE expr ',' expr
    {
      TRY(zr__sdl_want_float(p, &$3, &@3, &$1->diffuse));
      TRY(zr__sdl_want_float(p, &$5, &@5, &$1->diffuse_back));
      $$ = $1;
    }
| finish_body T_BRILLIANCE expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->brilliance)); $$ = $1; }
| finish_body T_PHONG expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->phong)); $$ = $1; }
| irid_body '}'
| finish_body T_PHONG_SIZE expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->phong_size)); $$ = $1; }
| finish_body T_SPECULAR expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->specular)); $$ = $1; }
| finish_body T_ROUGHNESS expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->roughness)); $$ = $1; }
| finish_body T_METALLIC
    { $1->metallic = 1; $$ = $1; }
| finish_body T_METALLIC expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->metallic)); $$ = $1; }
| finish_body T_CRAND expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->crand)); $$ = $1; }
| finish_body T_CONSERVE_ENERGY
    { $1->conserve_energy = true; $$ = $1; }
/* subsurface { translucency C } ("Subsurface Light Transport"; a float
   C means that value in every channel). */
| finish_body T_SUBSURFACE '{' T_TRANSLUCENCY colour_value '}'
    {
      TRY(zr__sdl_want_rgb(p, &$5, &@5, &$1->translucency));
      $1->subsurface = true;
      $$ = $1;
    }
| finish_body T_REFLECTION colour_value
    {
      TRY(zr__sdl_want_rgb(p, &$3, &@3, &$1->reflection));
      $1->reflection_max = $1->reflection;
      $$ = $1;
    }
| finish_body T_REFLECTION '{' reflection '}'
    { zr__sdl_finish_reflection($1, &$4); $$ = $1; }
;

/* reflection { [min,] max [fresnel [on]] [falloff F] [metallic [M]] } */
reflection:
  colour_value
    {
      memset(&$$, 0, sizeof $$);
      TRY(zr__sdl_want_rgb(p, &$1, &@1, &$$.max));
      $$.min = $$.max;
    }
| colour_value ',' colour_value
    {
      memset(&$$, 0, sizeof $$);
      TRY(zr__sdl_want_rgb(p, &$1, &@1, &$$.min));
      TRY(zr__sdl_want_rgb(p, &$3, &@3, &$$.max));
      $$.max_given = true;
    }
/* "reflection { 0.0 1.0 fresnel on }" (gamma_showcase.pov): POV-Ray
   takes the maximum without its comma when it is a plain number. */
| colour_value T_NUMBER
    {
      memset(&$$, 0, sizeof $$);
      TRY(zr__sdl_want_rgb(p, &$1, &@1, &$$.min));
      $$.max = zr_rgb3($2, $2, $2);
      $$.max_given = true;
    }
| reflection T_EXPONENT expr
    {
      $$ = $1;
      TRY(zr__sdl_want_float(p, &$3, &@3, &$$.exponent));
      TRY(zr__sdl_reflection_exponent(p, $$.exponent, &@3));
      $$.exponent_given = true;
    }
| reflection T_FALLOFF expr
    {
      $$ = $1;
      TRY(zr__sdl_want_float(p, &$3, &@3, &$$.falloff));
      $$.falloff_given = true;
    }
| reflection T_FRESNEL
    { $$ = $1; $$.fresnel = true; $$.fresnel_given = true; }
| reflection T_FRESNEL expr
    {
      double on;
      $$ = $1;
      TRY(zr__sdl_want_float(p, &$3, &@3, &on));
      $$.fresnel = on != 0;
      $$.fresnel_given = true;
    }
| reflection T_METALLIC
    { $$ = $1; $$.metallic = 1; $$.metallic_given = true; }
| reflection T_METALLIC expr
    {
      $$ = $1;
      TRY(zr__sdl_want_float(p, &$3, &@3, &$$.metallic));
      $$.metallic_given = true;
    }
;

texture:
  T_TEXTURE '{' texture_body '}'
    {
      TRY(zr__sdl_texture_done(p, $3));
      $$ = zr__sdl_texture_shared(p, $3);
    }
;

/* "texture {T1} texture {T2}": T2 layered on T1 ("Layered Textures"). */
layered_texture:
  texture
| layered_texture texture
    { TRY($$ = zr__sdl_texture_layer(p, $1, $2)); }
;

texture_start:
  %empty               { TRY($$ = zr__sdl_texture_new(p, NULL)); }
| T_TEXTURE_ID
    {
      TRY($$ = zr__sdl_texture_new(p, $1.ptr));
      p->texture_copy = $$;
      p->texture_copied = $1.ptr;
    }
/* A pigment, finish or normal identifier first in a texture (older
   syntax that POV-Ray 3.7 renders without a warning; later in the
   texture it refuses them; measured: tests/legacy/texture_ids.pov). */
| T_PIGMENT_ID
    {
      TRY($$ = zr__sdl_texture_new(p, NULL));
      TRY($$->pigment = zr__sdl_pigment_new(p, $1.ptr));
    }
| T_FINISH_ID
    {
      TRY($$ = zr__sdl_texture_new(p, NULL));
      TRY($$->finish = zr__sdl_finish_new(p, $1.ptr));
    }
| T_NORMAL_ID
    {
      TRY($$ = zr__sdl_texture_new(p, NULL));
      TRY($$->normal = zr__sdl_normal_new(p, $1.ptr));
    }
;

/* A pattern with a texture_map or a block pattern's textures makes a
   patterned texture ("Patterned Textures"). */
texture_body:
  texture_start
| texture_body pattern_kw
    { zr__sdl_texture_pattern($1, $2); $$ = $1; }
| texture_body slope_block
    {
      zr__sdl_texture_pattern($1, ZR_PAT_SLOPE);
      $1->pattern.slope = *$2;
      $$ = $1;
    }
| texture_body T_GRADIENT expr
    {
      zr__sdl_texture_pattern($1, ZR_PAT_GRADIENT);
      TRY(zr__sdl_gradient(p, &$1->pattern, &$3, &@3));
      $$ = $1;
    }
| texture_body spiral_kw expr
    {
      zr__sdl_texture_pattern($1, $2);
      TRY(zr__sdl_spiral_arms(p, &$1->pattern, &$3, &@3));
      $$ = $1;
    }
| texture_body block_kw texture_blocks
    {
      zr__sdl_texture_pattern($1, $2);
      TRY(zr__sdl_texture_map_set(p, $1, $3, &@3));
      $$ = $1;
    }
| texture_body fractal
    {
      zr__sdl_texture_pattern($1, $2.kind);
      zr__sdl_fractal_set(&$1->pattern, &$2);
      $$ = $1;
    }
| texture_body T_OBJECT '{' pattern_object texture_blocks '}'
    {
      zr__sdl_texture_pattern($1, ZR_PAT_OBJECT);
      zr__sdl_pattern_object(&$1->pattern, $4);
      TRY(zr__sdl_texture_map_set(p, $1, $5, &@5));
      $$ = $1;
    }
/* tiles { TEXTURE tile2 TEXTURE }: the checker of two textures, as
   POV-Ray before 3 wrote it ("Patterned Textures"). */
| texture_body T_TILES '{' layered_texture T_TILE2 layered_texture '}'
    {
      zr__sdl_texture_pattern($1, ZR_PAT_CHECKER);
      TRY(zr__sdl_tiles(p, $1, $4, $6, &@2));
      $$ = $1;
    }
| texture_body fn_pattern
    {
      zr__sdl_texture_pattern($1, ZR_PAT_FUNCTION);
      TRY(zr__sdl_pattern_function(p, &$1->pattern, $2, &@2));
      $$ = $1;
    }
| texture_body T_PIGMENT_PATTERN '{' pigment_body '}'
    {
      zr__sdl_texture_pattern($1, ZR_PAT_PIGMENT_PATTERN);
      zr__sdl_pigment_pattern_of(&$1->pattern, $4);
      $$ = $1;
    }
| texture_body image_pattern
    {
      zr__sdl_texture_pattern($1, ZR_PAT_IMAGE);
      $1->pattern.image = $2;
      $$ = $1;
    }
| texture_body pattern_mod
    {
      TRY(zr__sdl_pattern_mod_in(p, &$1->pattern, $1->transform, &$2));
      $$ = $1;
    }
| texture_body texture_map
    { TRY(zr__sdl_texture_map_set(p, $1, $2, &@2)); $$ = $1; }
| texture_body T_MATERIAL_MAP '{' material_map_head material_textures
    transform_block '}'
    {
      zr_transform *t;
      TRY(t = zr__sdl_transform_block_end(p, $6));
      TRY(zr__sdl_material_map(p, $1, $4, $5, t, &@2));
      $$ = $1;
    }
/* In a layered texture these change the top layer (build_texture.c). */
| texture_body T_UV_MAPPING
    {
      zr_texture *top;
      TRY(top = zr__sdl_texture_top(p, $1));
      top->uv_mapping = true;
      $$ = $1;
    }
| texture_body { zr__sdl_texture_base(p, $1, 'p'); } pigment
    {
      zr_texture *top;
      TRY(top = zr__sdl_texture_top(p, $1));
      top->pigment = $3;
      $$ = $1;
    }
| texture_body { zr__sdl_texture_base(p, $1, 'f'); } finish
    {
      zr_texture *top;
      TRY(top = zr__sdl_texture_top(p, $1));
      top->finish = $3;
      $$ = $1;
    }
| texture_body { zr__sdl_texture_base(p, $1, 'n'); } normal
    {
      zr_texture *top;
      TRY(top = zr__sdl_texture_top(p, $1));
      top->normal = $3;
      $$ = $1;
    }
| texture_body transform
    { TRY(zr__sdl_texture_move(p, &p->own_body, NULL, $1, $2)); $$ = $1; }
| texture_body T_NO_BUMP_SCALE
    { TRY(no_bump_scale_texture(p, $1)); $$ = $1; }
;

interior:
  interior_body '}'
;

/* material { [MATERIAL_IDENTIFIER] texture {...} interior {...} } */
material:
  T_MATERIAL '{' material_body '}'  { $$ = $3; }
;

material_body:
  %empty               { TRY($$ = zr__sdl_material_new(p, NULL)); }
| T_MATERIAL_ID        { TRY($$ = zr__sdl_material_new(p, $1.ptr)); }
| material_body texture
    { TRY(zr__sdl_material_texture(p, $1, $2)); $$ = $1; }
| material_body interior  { $1->interior = $2; $$ = $1; }
| material_body transform
    { TRY(zr__sdl_material_transform(p, $1, $2)); $$ = $1; }
;

interior_head:
  T_INTERIOR '{'       { TRY($$ = zr__sdl_interior_new(p, NULL)); }
| T_INTERIOR '{' T_INTERIOR_ID
    { TRY($$ = zr__sdl_interior_new(p, $3.ptr)); }
;

interior_body:
  interior_head
| interior_body T_IOR expr
    {
      TRY(zr__sdl_want_float(p, &$3, &@3, &$1->ior));
      $1->ior_given = true;
      $$ = $1;
    }
| interior_body T_FADE_DISTANCE expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->fade_distance)); $$ = $1; }
/* Dispersion splits refracted light into a spectrum
   (lib/trace/dispersion.c).  POV-Ray 3.7 truncates dispersion_samples
   to a whole number (2.7 renders as 2) and refuses 0 and 1 (measured
   with bench/conform/dispersion_probe.pov); the manual's minimum is 2. */
| interior_body T_DISPERSION expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->dispersion)); $$ = $1; }
| interior_body T_DISPERSION_SAMPLES expr
    {
      double n;
      TRY(zr__sdl_want_float(p, &$3, &@3, &n));
      /* The upper bound only keeps a typo from tracing for days: every
         refracted ray becomes this many. */
      if (!(n >= 2.0) || n > 1e6) {
        zr__sdl_error(p, ZR_ESCENE, &@3,
                      "dispersion_samples must be between 2 and 1000000");
        YYABORT;
      }
      $1->dispersion_samples = (int)n;
      $$ = $1;
    }
| interior_body T_CAUSTICS expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->caustics)); $$ = $1; }
| interior_body T_FADE_POWER expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->fade_power)); $$ = $1; }
| interior_body T_FADE_COLOUR colour_value
    { TRY(zr__sdl_want_rgb(p, &$3, &@3, &$1->fade_colour)); $$ = $1; }
| interior_body media
    { TRY(zr__sdl_interior_media(p, $1, $2)); $$ = $1; }
;

/* ---- media (reference manual, "Media"; lib/sdl/build_media.c) ---- */

media:
  media_body '}'       { $$ = $1; }
;

media_body:
  T_MEDIA '{'          { TRY($$ = zr__sdl_media_new(p, NULL, &@1)); }
| T_MEDIA '{' T_MEDIA_ID
    { TRY($$ = zr__sdl_media_new(p, $3.ptr, &@1)); }
| media_body T_METHOD expr
    { TRY(zr__sdl_media_item(p, $1, T_METHOD, &$3, &@3)); $$ = $1; }
| media_body T_INTERVALS expr
    { TRY(zr__sdl_media_item(p, $1, T_INTERVALS, &$3, &@3)); $$ = $1; }
| media_body T_SAMPLES expr
    { TRY(zr__sdl_media_item(p, $1, T_SAMPLES, &$3, &@3)); $$ = $1; }
| media_body T_SAMPLES expr ',' expr
    { TRY(zr__sdl_media_samples(p, $1, &$3, &@3, &$5, &@5)); $$ = $1; }
| media_body T_CONFIDENCE expr
    { TRY(zr__sdl_media_item(p, $1, T_CONFIDENCE, &$3, &@3)); $$ = $1; }
| media_body T_VARIANCE expr
    { TRY(zr__sdl_media_item(p, $1, T_VARIANCE, &$3, &@3)); $$ = $1; }
| media_body T_RATIO expr
    { TRY(zr__sdl_media_item(p, $1, T_RATIO, &$3, &@3)); $$ = $1; }
| media_body T_JITTER expr
    { TRY(zr__sdl_media_item(p, $1, T_JITTER, &$3, &@3)); $$ = $1; }
| media_body T_AA_LEVEL expr
    { TRY(zr__sdl_media_item(p, $1, T_AA_LEVEL, &$3, &@3)); $$ = $1; }
| media_body T_AA_THRESHOLD expr
    { TRY(zr__sdl_media_item(p, $1, T_AA_THRESHOLD, &$3, &@3)); $$ = $1; }
| media_body T_ABSORPTION colour_value
    { TRY(zr__sdl_media_item(p, $1, T_ABSORPTION, &$3, &@3)); $$ = $1; }
| media_body T_EMISSION colour_value
    { TRY(zr__sdl_media_item(p, $1, T_EMISSION, &$3, &@3)); $$ = $1; }
/* collect: whether media photons are stored and gathered in it
   ("Photons and Media"; lib/trace/photons.c). */
| media_body T_COLLECT          { $1->photons_ignored = false; $$ = $1; }
| media_body T_COLLECT expr
    {
      bool on;
      TRY(zr__sdl_light_bool(p, &$3, &@3, &on));
      $1->photons_ignored = !on;
      $$ = $1;
    }
| scattering_body '}'
| media_body density
    { TRY(zr__sdl_media_density(p, $1, $2)); $$ = $1; }
| media_body transform
    { TRY(zr__sdl_media_transform(p, $1, $2)); $$ = $1; }
;

/* scattering { Type, COLOR [eccentricity Value] [extinction Value] } */
scattering_body:
  media_body T_SCATTERING '{' expr comma colour_value
    {
      TRY(zr__sdl_media_scattering(p, $1, &$4, &@4, &$6, &@6));
      $$ = $1;
    }
| scattering_body T_ECCENTRICITY expr
    { TRY(zr__sdl_media_eccentricity(p, $1, &$3, &@3)); $$ = $1; }
| scattering_body T_EXTINCTION expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->extinction)); $$ = $1; }
;

/* density { [PATTERN_TYPE] [DENSITY_MODIFIER...] }: a pigment's body,
   whose colour multiplies the media's ("Density"). */
density:
  T_DENSITY '{' pigment_body '}'  { $$ = $3; }
;

/* density_map { [Value DENSITY_BODY] ... } ("Density Maps and Density
   Lists"), read as a pigment_map. */
density_map:
  T_DENSITY_MAP '{' pigment_map_body '}'
    { TRY(zr__sdl_map_done(p, $3, "density_map", &@1)); $$ = $3; }
;

/* "checker density {A}, density {B}" */
density_blocks:
  density
    {
      zr_map_entry e = {.u.pigment = $1};
      TRY($$ = zr__sdl_map_new(p));
      TRY(zr__sdl_map_add_block(p, $$, &e, &@1));
    }
| density_blocks density
    {
      zr_map_entry e = {.u.pigment = $2};
      TRY(zr__sdl_map_add_block(p, $1, &e, &@2));
      $$ = $1;
    }
| density_blocks ','   { $$ = $1; }
;

/* ---- photons blocks (lib/sdl/build_media.c, lib/trace/photons.c) ---- */

/* An object's or a light's photons { }, and global_settings' one. */
photon_items:
  %empty               { TRY($$ = zr__sdl_photons_new(p)); }
| photon_items photon_kw
    { TRY(zr__sdl_photons_item(p, $1, $2, NULL, &@2)); $$ = $1; }
| photon_items photon_kw photon_args
    { TRY(zr__sdl_photons_item(p, $1, $2, &$3, &@2)); $$ = $1; }
| photon_items photon_kw ',' photon_args
    {
      $4.skip_first = true;
      TRY(zr__sdl_photons_item(p, $1, $2, &$4, &@2));
      $$ = $1;
    }
| photon_items T_LOAD_FILE str_expr
    { TRY(zr__sdl_photons_file(p, $1, false, &@2)); $$ = $1; }
| photon_items T_SAVE_FILE str_expr
    { TRY(zr__sdl_photons_file(p, $1, true, &@2)); $$ = $1; }
;

photon_args:
  expr
    {
      $$.n = 1;
      $$.skip_first = false;
      TRY(zr__sdl_want_float(p, &$1, &@1, &$$.v[0]));
    }
| photon_args ',' expr
    {
      $$ = $1;
      if ($$.n < 4)
        TRY(zr__sdl_want_float(p, &$3, &@3, &$$.v[$$.n++]));
    }
;

photon_kw:
  T_TARGET { $$ = T_TARGET; }            | T_REFRACTION { $$ = T_REFRACTION; }
| T_REFLECTION { $$ = T_REFLECTION; }    | T_COLLECT { $$ = T_COLLECT; }
| T_PASS_THROUGH { $$ = T_PASS_THROUGH; } | T_AREA_LIGHT { $$ = T_AREA_LIGHT; }
| T_SPACING { $$ = T_SPACING; }          | T_COUNT { $$ = T_COUNT; }
| T_GATHER { $$ = T_GATHER; }            | T_MEDIA { $$ = T_MEDIA; }
| T_JITTER { $$ = T_JITTER; }            | T_RADIUS { $$ = T_RADIUS; }
| T_MAX_TRACE_LEVEL { $$ = T_MAX_TRACE_LEVEL; }
| T_ADC_BAILOUT { $$ = T_ADC_BAILOUT; }  | T_AUTOSTOP { $$ = T_AUTOSTOP; }
| T_EXPAND_THRESHOLDS { $$ = T_EXPAND_THRESHOLDS; }
;

/* ---- camera, lights, background, global settings ---- */

camera:
  camera_body '}'      { TRY(zr__sdl_camera_end(p)); }
;

camera_body:
  T_CAMERA '{'         { zr__sdl_camera_begin(p, &@1); }
| T_CAMERA '{' T_CAMERA_ID
    {
      zr__sdl_camera_begin(p, &@1);
      zr__sdl_camera_from(p, $3.ptr);
    }
| camera_body T_PERSPECTIVE
    { TRY(zr__sdl_camera_type(p, ZR_CAMERA_PERSPECTIVE, NULL, &@2)); }
| camera_body T_ORTHOGRAPHIC
    { TRY(zr__sdl_camera_type(p, ZR_CAMERA_ORTHOGRAPHIC, NULL, &@2)); }
| camera_body T_FISHEYE
    { TRY(zr__sdl_camera_type(p, ZR_CAMERA_FISHEYE, NULL, &@2)); }
| camera_body T_ULTRA_WIDE_ANGLE
    { TRY(zr__sdl_camera_type(p, ZR_CAMERA_ULTRA_WIDE_ANGLE, NULL, &@2)); }
| camera_body T_OMNIMAX
    { TRY(zr__sdl_camera_type(p, ZR_CAMERA_OMNIMAX, NULL, &@2)); }
| camera_body T_PANORAMIC
    { TRY(zr__sdl_camera_type(p, ZR_CAMERA_PANORAMIC, NULL, &@2)); }
| camera_body T_SPHERICAL
    { TRY(zr__sdl_camera_type(p, ZR_CAMERA_SPHERICAL, NULL, &@2)); }
| camera_body T_CYLINDER expr
    { TRY(zr__sdl_camera_type(p, ZR_CAMERA_CYLINDER, &$3, &@3)); }
| camera_body T_APERTURE expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &CAMERA->aperture)); }
| camera_body T_BLUR_SAMPLES expr
    { TRY(zr__sdl_camera_blur_samples(p, NULL, &$3, &@3)); }
| camera_body T_BLUR_SAMPLES expr ',' expr
    { TRY(zr__sdl_camera_blur_samples(p, &$3, &$5, &@5)); }
| camera_body T_FOCAL_POINT expr
    { TRY(zr__sdl_want_vector(p, &$3, &@3, &CAMERA->focal_point)); }
| camera_body T_CONFIDENCE expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &CAMERA->confidence)); }
| camera_body T_VARIANCE expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &CAMERA->variance)); }
| camera_body normal   { CAMERA->normal = $2; }
| camera_body T_LOCATION expr
    { TRY(zr__sdl_want_vector(p, &$3, &@3, &CAMERA->location)); }
| camera_body T_DIRECTION expr
    { TRY(zr__sdl_want_vector(p, &$3, &@3, &CAMERA->direction)); }
| camera_body T_UP expr
    {
      TRY(zr__sdl_want_vector(p, &$3, &@3, &CAMERA->up));
      p->camera.up_given = true;
    }
| camera_body T_RIGHT expr
    {
      TRY(zr__sdl_want_vector(p, &$3, &@3, &CAMERA->right));
      p->camera.right_given = true;
    }
| camera_body T_SKY expr
    { TRY(zr__sdl_want_vector(p, &$3, &@3, &CAMERA->sky)); }
| camera_body T_ANGLE expr
    {
      double degrees;
      TRY(zr__sdl_want_float(p, &$3, &@3, &degrees));
      TRY(zr__sdl_camera_angle(p, degrees, NULL, &@3));
    }
| camera_body T_ANGLE expr ',' expr
    {
      double h, v;
      TRY(zr__sdl_want_float(p, &$3, &@3, &h));
      TRY(zr__sdl_want_float(p, &$5, &@5, &v));
      TRY(zr__sdl_camera_angle(p, h, &v, &@3));
    }
| camera_body T_LOOK_AT expr
    {
      zr_vec3 target;
      TRY(zr__sdl_want_vector(p, &$3, &@3, &target));
      zr__sdl_camera_look_at(p, target, &@3);
    }
| camera_body transform
    { zr__sdl_camera_transform(p, $2); }
| camera_body mesh_camera '}'
    { TRY(zr__sdl_mesh_camera_end(p, &@2)); }
;

/* mesh_camera { rays distribution [max_distance] mesh { } ... [smooth] }
   ("Mesh projection"; lib/sdl/build_meshcam.c). */
mesh_camera:
  T_MESH_CAMERA '{' expr comma expr
    { TRY(zr__sdl_mesh_camera(p, &@1, &$3, &@3, &$5, &@5, NULL, NULL)); }
| T_MESH_CAMERA '{' expr comma expr comma expr
    { TRY(zr__sdl_mesh_camera(p, &@1, &$3, &@3, &$5, &@5, &$7, &@7)); }
| mesh_camera object   { TRY(zr__sdl_mesh_camera_add(p, $2, &@2)); }
| mesh_camera T_SMOOTH { TRY(zr__sdl_mesh_camera_smooth(p, &@2)); }
;

light:
  light_done           { TRY(zr__sdl_light_add(p, $1, &@1)); }
;

/* A finished light: a scene item, a #declare's value or a part of a
   union, which it then follows.  object { LIGHT_IDENTIFIER ... } and
   object { light_source { ... } ... } are lights too, as in POV-Ray. */
light_done:
  light_body '}'       { TRY(zr__sdl_light_end(p, $1, &@1)); $$ = $1; }
| light_object '}'     { $$ = $1; }
;

light_object:
  T_OBJECT '{' T_LIGHT_ID { TRY($$ = zr__sdl_light_copy(p, $3.ptr)); }
  /* "object { light_source { ... } }" (gnu0000's POV1/OLD/TSTS-A.POV):
     POV-Ray 3.7 lights the scene with it (tests/refused/object_light). */
| T_OBJECT '{' light_done { $$ = $3; }
| light_object transform
    { zr__sdl_light_transform(p, $1, $2); $$ = $1; }
;

light_body:
  T_LIGHT_SOURCE '{' T_LIGHT_ID
    { TRY($$ = zr__sdl_light_copy(p, $3.ptr)); }
| T_LIGHT_SOURCE '{' expr comma colour_value
    {
      TRY($$ = zr__sdl_alloc(p, sizeof *$$));
      TRY(zr__sdl_light(p, $$, &@1));
      TRY(zr__sdl_want_rgb(p, &$5, &@5, &$$->colour));
      TRY(zr__sdl_want_vector(p, &$3, &@3, &$$->location));
    }
| light_body T_SHADOWLESS  { $1->shadowless = true; $$ = $1; }
| light_body transform
    { zr__sdl_light_transform(p, $1, $2); $$ = $1; }
| light_body T_SPOTLIGHT
    { zr__sdl_light_kind(p, $1, ZR_LIGHT_SPOT); $$ = $1; }
| light_body T_CYLINDER
    { zr__sdl_light_kind(p, $1, ZR_LIGHT_CYLINDER); $$ = $1; }
| light_body T_PARALLEL     { $1->parallel = true; $$ = $1; }
| light_body T_POINT_AT expr
    { TRY(zr__sdl_want_vector(p, &$3, &@3, &$1->point_at)); $$ = $1; }
| light_body T_RADIUS expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->radius)); $$ = $1; }
| light_body T_FALLOFF expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->falloff)); $$ = $1; }
| light_body T_TIGHTNESS expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->tightness)); $$ = $1; }
| light_body T_FADE_DISTANCE expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->fade_distance)); $$ = $1; }
| light_body T_FADE_POWER expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->fade_power)); $$ = $1; }
| light_body T_AREA_LIGHT expr comma expr comma expr comma expr
    {
      zr_sdl_expr e[4] = {$3, $5, $7, $9};
      zr_sdl_loc at[4] = {@3, @5, @7, @9};
      TRY(zr__sdl_area_light(p, $1, e, at));
      $$ = $1;
    }
| light_body T_ADAPTIVE expr
    { TRY(zr__sdl_light_int(p, &$3, &@3, 0, &$1->adaptive)); $$ = $1; }
| light_body T_JITTER       { $1->jitter = true; $$ = $1; }
| light_body T_CIRCULAR     { $1->circular = true; $$ = $1; }
| light_body T_ORIENT       { $1->orient = true; $$ = $1; }
| light_body T_AREA_ILLUMINATION
    { $1->area_illumination = true; $$ = $1; }
| light_body T_AREA_ILLUMINATION expr
    { TRY(zr__sdl_light_bool(p, &$3, &@3, &$1->area_illumination)); $$ = $1; }
| light_body T_MEDIA_INTERACTION
    { $1->media_interaction = true; $$ = $1; }
| light_body T_MEDIA_INTERACTION expr
    { TRY(zr__sdl_light_bool(p, &$3, &@3, &$1->media_interaction)); $$ = $1; }
| light_body T_MEDIA_ATTENUATION
    { $1->media_attenuation = true; $$ = $1; }
| light_body T_MEDIA_ATTENUATION expr
    { TRY(zr__sdl_light_bool(p, &$3, &@3, &$1->media_attenuation)); $$ = $1; }
| light_body T_PHOTONS '{' photon_items '}'
    { TRY(zr__sdl_photons_light(p, $1, $4, &@2)); $$ = $1; }
/* The object may be an identifier alone ("looks_like { LightShape }",
   qtvrpanorama.pov), as in an object pattern. */
| light_body T_LOOKS_LIKE '{' pattern_object '}'
    { TRY(zr__sdl_looks_like(p, $1, $4, &@4)); $$ = $1; }
/* projected_through { OBJECT } ("Projected_Through"): only the object's
   shape matters (lib/trace/lights.c); it is not one of the scene's. */
| light_body T_PROJECTED_THROUGH '{' object '}'
    { $1->projected_through = $4; $$ = $1; }
| light_body T_PROJECTED_THROUGH '{' T_OBJECT_ID '}'
    {
      TRY($1->projected_through = zr__sdl_object_copy(p, $4.ptr));
      $$ = $1;
    }

;

background:
  T_BACKGROUND '{' colour_value '}'
    { TRY(zr__sdl_want_colour(p, &$3, &@3, &SETTINGS->background)); }
;

/* fog { } ("Fog"): items in any order; the colour is any colour. */
fog_body:
  T_FOG '{'            { TRY($$ = zr__sdl_fog_new(p, &@1)); }
| fog_body T_FOG_TYPE expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_fog_type(p, $1, &$3, &@3)); $$ = $1; }
| fog_body T_DISTANCE expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->distance)); $$ = $1; }
/* The colour, item by item: "color" alone only marks it, so "color
   Gray rgbt 0.5" and "rgb 1 transmit 0.2" read without ambiguity, and
   a bare colour expression is one too ("fog { distance 200 Wheat*.5 }").
   An expression after an item's value continues that value ("distance
   200 - 50"): the items rank below the operators (OPTIONAL_COMMA). */
| fog_body T_COLOUR    { $$ = $1; }
| fog_body expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_want_colour(p, &$2, &@2, &$1->colour)); $$ = $1; }
| fog_body colour_item
    { TRY(zr__sdl_colour_item_to(p, &$2, &$1->colour)); $$ = $1; }
| fog_body colour_whole
    { TRY(zr__sdl_colour_item_to(p, &$2, &$1->colour)); $$ = $1; }
| fog_body T_TURBULENCE expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_want_vector(p, &$3, &@3, &$1->turbulence)); $$ = $1; }
| fog_body T_OCTAVES expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_light_int(p, &$3, &@3, 1, &$1->octaves)); $$ = $1; }
| fog_body T_OMEGA expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->omega)); $$ = $1; }
| fog_body T_LAMBDA expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->lambda)); $$ = $1; }
| fog_body T_TURB_DEPTH expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->turb_depth)); $$ = $1; }
| fog_body T_FOG_OFFSET expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->offset)); $$ = $1; }
| fog_body T_FOG_ALT expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->alt)); $$ = $1; }
| fog_body T_UP expr %prec OPTIONAL_COMMA
    { TRY(zr__sdl_want_vector(p, &$3, &@3, &$1->up)); $$ = $1; }
| fog_body transform
    { TRY(zr__sdl_fog_transform(p, $1, $2)); $$ = $1; }
;

/* sky_sphere { pigment... [emission C] [transforms] } */
sky_body:
  T_SKY_SPHERE '{'     { TRY($$ = zr__sdl_sky_new(p, NULL)); }
| T_SKY_SPHERE '{' T_SKY_SPHERE_ID
    { TRY($$ = zr__sdl_sky_new(p, $3.ptr)); }
| sky_body pigment     { TRY(zr__sdl_sky_pigment(p, $1, $2)); $$ = $1; }
| sky_body T_EMISSION colour_value
    { TRY(zr__sdl_want_rgb(p, &$3, &@3, &$1->emission)); $$ = $1; }
| sky_body transform
    { TRY(zr__sdl_sky_transform(p, $1, $2)); $$ = $1; }
;

/* rainbow { direction angle width distance color_map ... } */
rainbow_body:
  T_RAINBOW '{'        { TRY($$ = zr__sdl_rainbow_new(p)); }
| rainbow_body T_DIRECTION expr
    { TRY(zr__sdl_want_vector(p, &$3, &@3, &$1->direction)); $$ = $1; }
| rainbow_body T_ANGLE expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->angle)); $$ = $1; }
| rainbow_body T_WIDTH expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->width)); $$ = $1; }
| rainbow_body T_DISTANCE expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->distance)); $$ = $1; }
| rainbow_body T_JITTER expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->jitter)); $$ = $1; }
| rainbow_body T_UP expr
    { TRY(zr__sdl_want_vector(p, &$3, &@3, &$1->up)); $$ = $1; }
| rainbow_body T_ARC_ANGLE expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->arc_angle)); $$ = $1; }
| rainbow_body T_FALLOFF_ANGLE expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &$1->falloff_angle)); $$ = $1; }
| rainbow_body colour_map  { $1->colour_map = $2; $$ = $1; }
;

global_settings:
  global_body '}'
;

global_body:
  T_GLOBAL_SETTINGS '{'
| global_body T_MAX_TRACE_LEVEL expr
    {
      double level;
      TRY(zr__sdl_want_float(p, &$3, &@3, &level));
      if (level < 1 || level > 256) {
        zr__sdl_error(p, ZR_ESCENE, &@3,
                      "max_trace_level must be between 1 and 256");
        YYABORT;
      }
      SETTINGS->max_trace_level = (int)level;
    }
| global_body T_ADC_BAILOUT expr
    { TRY(zr__sdl_want_float(p, &$3, &@3, &SETTINGS->adc_bailout)); }
/* charset: zRcube reads strings as UTF-8, POV-Ray 3.7's default, of
   which ASCII is a part; the system's code page has no meaning here. */
| global_body T_CHARSET T_UTF8
| global_body T_CHARSET T_ASCII
| global_body T_CHARSET T_SYS
    {
      zr__sdl_error(p, ZR_EUNSUPPORTED, &@3,
                    "'charset sys' is not supported (utf8 or ascii)");
      YYABORT;
    }
| global_body T_HF_GRAY_16
    { zr__sdl_warning(p, &@2, "'hf_gray_16' is ignored since POV-Ray 3.7 "
                      "(an output option: +FNg or Grayscale_Output)"); }
| global_body T_HF_GRAY_16 expr
    { zr__sdl_warning(p, &@2, "'hf_gray_16' is ignored since POV-Ray 3.7 "
                      "(an output option: +FNg or Grayscale_Output)"); }
| global_body T_ASSUMED_GAMMA expr
    {
      TRY(zr__sdl_want_float(p, &$3, &@3, &SETTINGS->assumed_gamma));
      SETTINGS->assumed_gamma_given = true;
    }
| global_body T_NUMBER_OF_WAVES expr
    {
      double n;
      TRY(zr__sdl_want_float(p, &$3, &@3, &n));
      if (n < 1) {
        zr__sdl_error(p, ZR_ESCENE, &@3,
                      "number_of_waves must be at least 1");
        YYABORT;
      }
      SETTINGS->number_of_waves = (int)n;
    }
/* The default noise_generator of patterns made after it
   (lib/scene/pattern.c). */
| global_body T_NOISE_GENERATOR expr
    {
      double g;
      TRY(zr__sdl_want_float(p, &$3, &@3, &g));
      if (g != 1 && g != 2 && g != 3) {
        zr__sdl_error(p, ZR_ESCENE, &@3,
                      "noise_generator must be 1, 2 or 3");
        YYABORT;
      }
      SETTINGS->noise_generator = (int)g;
    }
| global_body T_AMBIENT_LIGHT colour_value
    { TRY(zr__sdl_want_rgb(p, &$3, &@3, &SETTINGS->ambient_light)); }
| global_body T_IRID_WAVELENGTH colour_value
    { TRY(zr__sdl_irid_wavelength(p, &$3, &@3)); }
| global_body radiosity_body '}'
    { zr__sdl_radiosity_end(p, &@3); }
| global_body T_PHOTONS '{' photon_items '}'
    { TRY(zr__sdl_photons_global(p, $4, &@2)); }
/* mm_per_unit and subsurface { samples D, S radiosity B } ("Subsurface
   Light Transport"; lib/trace/subsurface.c). */
| global_body T_MM_PER_UNIT expr
    {
      double mm;
      TRY(zr__sdl_want_float(p, &$3, &@3, &mm));
      if (!(mm > 0.0) || !isfinite(mm)) {
        zr__sdl_error(p, ZR_ESCENE, &@3, "mm_per_unit must be positive");
        YYABORT;
      }
      SETTINGS->mm_per_unit = mm;
    }
| global_body subsurface_body '}'
;

subsurface_body:
  T_SUBSURFACE '{'
    { SETTINGS->subsurface_on = true; }
| subsurface_body T_SAMPLES expr ',' expr
    {
      double d, s;
      TRY(zr__sdl_want_float(p, &$3, &@3, &d));
      TRY(zr__sdl_want_float(p, &$5, &@5, &s));
      if (!(d >= 1.0 && d <= 1e6) || !(s >= 1.0 && s <= 1e6)) {
        zr__sdl_error(p, ZR_ESCENE, &@3,
                      "subsurface samples must be between 1 and 1000000");
        YYABORT;
      }
      SETTINGS->subsurface_samples[0] = (int)d;
      SETTINGS->subsurface_samples[1] = (int)s;
    }
| subsurface_body T_RADIOSITY expr
    {
      double on;
      TRY(zr__sdl_want_float(p, &$3, &@3, &on));
      SETTINGS->subsurface_radiosity = on != 0.0;
      if (on != 0.0)
        zr__sdl_warning(p, &@2, "subsurface { radiosity on } is not "
                        "simulated: subsurface light comes from light "
                        "sources only");
    }
| subsurface_body T_RADIOSITY
    {
      SETTINGS->subsurface_radiosity = true;
      zr__sdl_warning(p, &@2, "subsurface { radiosity on } is not "
                      "simulated: subsurface light comes from light "
                      "sources only");
    }
;

/* global_settings { radiosity { ... } }; the items' meaning here is in
   lib/sdl/build_radiosity.c and zrcube(1). */
radiosity_body:
  T_RADIOSITY '{'
    { zr__sdl_radiosity_begin(p); }
| radiosity_body rad_kw
    { TRY(zr__sdl_radiosity_item(p, $2, NULL, NULL, &@2)); }
| radiosity_body rad_kw expr
    { TRY(zr__sdl_radiosity_item(p, $2, &$3, NULL, &@3)); }
| radiosity_body rad_kw expr ',' expr
    { TRY(zr__sdl_radiosity_item(p, $2, &$3, &$5, &@5)); }
| radiosity_body T_SAVE_FILE str_expr
    { TRY(zr__sdl_radiosity_file(p, T_SAVE_FILE, $3, &@3)); }
| radiosity_body T_LOAD_FILE str_expr
    { TRY(zr__sdl_radiosity_file(p, T_LOAD_FILE, $3, &@3)); }
;

rad_kw:
  T_ADC_BAILOUT         { $$ = T_ADC_BAILOUT; }
| T_ALWAYS_SAMPLE       { $$ = T_ALWAYS_SAMPLE; }
| T_BRIGHTNESS          { $$ = T_BRIGHTNESS; }
| T_COUNT               { $$ = T_COUNT; }
| T_ERROR_BOUND         { $$ = T_ERROR_BOUND; }
| T_GRAY_THRESHOLD      { $$ = T_GRAY_THRESHOLD; }
| T_LOW_ERROR_FACTOR    { $$ = T_LOW_ERROR_FACTOR; }
| T_MAX_SAMPLE          { $$ = T_MAX_SAMPLE; }
| T_MAXIMUM_REUSE       { $$ = T_MAXIMUM_REUSE; }
| T_MEDIA               { $$ = T_MEDIA; }
| T_MINIMUM_REUSE       { $$ = T_MINIMUM_REUSE; }
| T_NEAREST_COUNT       { $$ = T_NEAREST_COUNT; }
| T_NORMAL              { $$ = T_NORMAL; }
| T_PRETRACE_END        { $$ = T_PRETRACE_END; }
| T_PRETRACE_START      { $$ = T_PRETRACE_START; }
| T_RECURSION_LIMIT     { $$ = T_RECURSION_LIMIT; }
| T_SUBSURFACE          { $$ = T_SUBSURFACE; }
| T_BF_BOUND            { $$ = T_BF_BOUND; }
| T_MINIMUM_AREA        { $$ = T_MINIMUM_AREA; }
| T_VISIBILITY_COUNT    { $$ = T_VISIBILITY_COUNT; }
| T_MAX_ITERATIONS      { $$ = T_MAX_ITERATIONS; }
| T_RESIDUAL_BOUND      { $$ = T_RESIDUAL_BOUND; }
;

%%

const char *zr__sdl_kind_name(int kind) {
  return yysymbol_name(YYTRANSLATE(kind));
}

/* How many expected tokens a message lists before it gives up. */
#define MAX_EXPECTED 32

static int yyreport_syntax_error(const yypcontext_t *yyctx,
                                 zr_sdl_parser *p) {
  /* T_SPHERE_TEXTURED stands for tokens that are expected or not as
     T_SPHERE_RUN is: it is called by that name and never listed, so
     that messages are the same with or without it. */
  yysymbol_kind_t expected[MAX_EXPECTED + 2];
  int n = yypcontext_expected_tokens(yyctx, expected, MAX_EXPECTED + 2);
  for (int i = 0; i < n; i++)
    if (expected[i] == YYSYMBOL_T_SPHERE_TEXTURED) {
      memmove(&expected[i], &expected[i + 1],
              (size_t)(n - i - 1) * sizeof *expected);
      n--;
      break;
    }
  yysymbol_kind_t got = yypcontext_token(yyctx);
  if (got == YYSYMBOL_T_SPHERE_TEXTURED)
    got = YYSYMBOL_T_SPHERE_RUN;
  zr_strbuf sb;
  zr__strbuf_init(&sb);
  char buf[128];
  if (got != YYSYMBOL_YYEMPTY) {
    const char *name = zr__sdl_token_name(yysymbol_name(got), buf,
                                          sizeof buf);
    zr__strbuf_printf(&sb, "unexpected %s", name);
    if (p->last_text && got != YYSYMBOL_T_STRING &&
        (got == YYSYMBOL_T_DECL_NAME || (got >= YYSYMBOL_T_FLOAT_ID &&
                                         got <= YYSYMBOL_T_OBJECT_ID)))
      zr__strbuf_printf(&sb, " '%s'", p->last_text);
  }
  if (n > 0 && n <= MAX_EXPECTED) {
    zr__strbuf_puts(&sb, got != YYSYMBOL_YYEMPTY ? ", expected " :
                                                   "expected ");
    for (int i = 0; i < n; i++) {
      if (i > 0)
        zr__strbuf_puts(&sb, i == n - 1 ? " or " : ", ");
      zr__strbuf_puts(&sb, zr__sdl_token_name(yysymbol_name(expected[i]),
                                              buf, sizeof buf));
    }
  }
  zr__sdl_error(p, sb.failed ? ZR_ENOMEM : ZR_ESYNTAX,
                yypcontext_location(yyctx), "%s", zr__strbuf_cstr(&sb));
  zr__strbuf_free(&sb);
  return 0;
}

int zr__pov_lex(ZR__POV_STYPE *lval, zr_sdl_loc *lloc, zr_sdl_parser *p) {
  zr_sdl_lexval v;
  int kind = zr__sdl_next(&v, lloc, p);
  switch (kind) {
  case T_NUMBER:
    lval->num = v.num;
    break;
  case T_STRING:
  case T_IDENTIFIER:
  case T_UNSUPPORTED:
    lval->str = v.str;
    break;
  case T_TRIANGLE_RUN:
    lval->corners = v.corners;
    break;
  case T_SMOOTH_TRIANGLE_RUN:
    lval->smooth = v.smooth;
    break;
  case T_SPHERE_RUN:
    lval->sphere = v.sphere;
    break;
  case T_SPHERE_TEXTURED:
    lval->sphere_tex = v.sphere_tex;
    break;
  case T_DECL_NAME:
    lval->decl = v.decl;
    break;
  case T_FLOAT_ID:
  case T_VECTOR_ID:
  case T_COLOUR_ID:
  case T_PIGMENT_ID:
  case T_FINISH_ID:
  case T_TEXTURE_ID:
  case T_INTERIOR_ID:
  case T_OBJECT_ID:
  case T_FUNCTION_ID:
  case T_TRANSFORM_ID:
  case T_NORMAL_ID:
  case T_COLOUR_MAP_ID:
  case T_MATERIAL_ID:
  case T_SKY_SPHERE_ID:
  case T_MEDIA_ID:
  case T_DENSITY_ID:
  case T_CAMERA_ID:
  case T_LIGHT_ID:
  case T_STRING_ID:
  case T_ARRAY_ID:
  case T_SPLINE_ID:
    lval->value = v.value;
    break;
  default:
    break;
  }
  return kind;
}
