/*
 * scene.h - the scene model: what a parsed POV-Ray scene is once every
 * directive has run.  Plain data, built once by the parser (lib/sdl) and
 * then only read by the tracer and, later, by radiosity.  Everything is
 * allocated in the scene's arena and freed with it, so objects may share
 * textures, finishes and transforms by pointer.
 *
 * Defaults are POV-Ray 3.7's (reference manual sections "Finish",
 * "Camera", "Light Source", "Global Settings"); zr__*_init() fill them.
 */
#ifndef ZR_SCENE_SCENE_H
#define ZR_SCENE_SCENE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "core/arena.h"
#include "core/transform.h"
#include "core/vec.h"
#include "zrcube.h"

/* Where something was written, for messages after parsing. */
typedef struct zr_source_loc {
  const char *file; /* arena-owned */
  int line;
  int column;
} zr_source_loc;

/* ---- textures ---- */

/*
 * Patterns (reference manual, "Pattern"): a function from a point in
 * pattern space to a value in [0, 1] (lib/scene/pattern.c).  Block
 * patterns (checker, hexagon, brick) give instead the index of a colour
 * of their list: 0, 1 or 2.
 */
typedef enum zr_pattern_kind {
  ZR_PAT_NONE = 0, /* a solid colour */
  ZR_PAT_AGATE,
  ZR_PAT_AVERAGE, /* pigment_map or normal_map entries mixed by weight */
  ZR_PAT_BOXED,
  ZR_PAT_BOZO,
  ZR_PAT_BRICK,
  ZR_PAT_BUMPS,
  ZR_PAT_CELLS,
  ZR_PAT_CHECKER,
  ZR_PAT_CRACKLE,
  ZR_PAT_CYLINDRICAL,
  ZR_PAT_DENTS,
  ZR_PAT_GRADIENT,
  ZR_PAT_GRANITE,
  ZR_PAT_HEXAGON,
  ZR_PAT_LEOPARD,
  ZR_PAT_MARBLE,
  ZR_PAT_ONION,
  ZR_PAT_PIGMENT_PATTERN, /* the grey of a pigment (pattern.pigment) */
  ZR_PAT_PLANAR,
  ZR_PAT_QUILTED,
  ZR_PAT_RADIAL,
  ZR_PAT_RIPPLES,
  ZR_PAT_SPHERICAL,
  ZR_PAT_SPIRAL1,
  ZR_PAT_SPIRAL2,
  ZR_PAT_SPOTTED,
  ZR_PAT_WAVES,
  ZR_PAT_WOOD,
  ZR_PAT_WRINKLES,
  /* lib/scene/pattern_more.c: fractals (magnet 1 or 2 in pattern.fractal)
     and user functions. */
  ZR_PAT_MANDEL,
  ZR_PAT_JULIA,
  ZR_PAT_FUNCTION,
  ZR_PAT_OBJECT, /* a block pattern: 1 inside pattern.object, 0 outside */
  /* density_file df3 (lib/scene/df3.c). */
  ZR_PAT_DENSITY_FILE,
  /* slope { }: from the surface normal, so only where there is one
     (zr__pattern_eval_n; elsewhere the normal counts as zero). */
  ZR_PAT_SLOPE,
  /* tiling N (lib/scene/pattern_tiling.c), N in pattern.tiling. */
  ZR_PAT_TILING,
  /* image_pattern { }: the grey of a picture (pattern.image), or its
     alpha with use_alpha, mapped as an image_map (lib/scene/bitmap.c). */
  ZR_PAT_IMAGE
} zr_pattern_kind;

/* A df3 voxel grid ("Density File Pattern"), mapped onto the unit cube:
   nx * ny * nz values in [0, 1], x varying fastest. */
typedef struct zr_density_file {
  int nx, ny, nz;
  const float *values;
  int interpolate; /* 0 none, 1 trilinear (2, tricubic, acts as 1) */
} zr_density_file;

/* mandel, julia and magnet ("Fractal Pattern"): POV-Ray's defaults are
   exponent 2, interior 0 and exterior 1, both with factor 1. */
typedef struct zr_fractal {
  int iterations;
  int exponent;  /* 2 .. 33 */
  int magnet;    /* 0: none; magnet 1 or 2 */
  double c[2];   /* julia's complex parameter */
  int interior, exterior;
  double interior_factor, exterior_factor;
} zr_fractal;

struct zr_fn; /* a compiled user function (lib/fn/fn.h) */

/* The wave form applied after frequency and phase ("Waveforms"). */
typedef enum zr_wave_kind {
  ZR_WAVE_DEFAULT = 0, /* the pattern's own: triangle for marble, wood */
  ZR_WAVE_RAMP,
  ZR_WAVE_TRIANGLE,
  ZR_WAVE_SINE,
  ZR_WAVE_SCALLOP,
  ZR_WAVE_CUBIC,
  ZR_WAVE_POLY
} zr_wave_kind;

/* A warp { } ("Warps"): each moves the point where the pattern is
   evaluated, in the order written among the pattern's transforms
   (lib/scene/warp.c). */
typedef enum zr_warp_kind {
  ZR_WARP_TURBULENCE,
  ZR_WARP_REPEAT,
  ZR_WARP_BLACK_HOLE,
  ZR_WARP_PLANAR,
  ZR_WARP_CYLINDRICAL,
  ZR_WARP_SPHERICAL,
  ZR_WARP_TOROIDAL,
  ZR_WARP_CUBIC
} zr_warp_kind;

typedef struct zr_warp {
  zr_warp_kind kind;
  /* The owner's transform written before the warp (identity if none):
     the warp acts in that frame. */
  zr_transform frame;
  zr_vec3 turbulence; /* turbulence; black_hole's random centre shift */
  int octaves;
  double omega, lambda;
  int axis;            /* repeat: 0, 1 or 2 */
  double width;        /* repeat: the direction's component */
  zr_vec3 offset;      /* repeat: added per block */
  zr_vec3 flip;        /* repeat: -1 flips an axis in odd blocks, else 1 */
  zr_vec3 centre;      /* black_hole */
  double radius, strength, falloff;
  bool inverse;
  zr_vec3 repeat;      /* black_hole: repeat spacing, zero: none */
  zr_vec3 orientation; /* mapping warps: unit, default <0,0,1> */
  double dist_exp;     /* mapping warps: default 0 */
  double distance;     /* planar */
  double major_radius; /* toroidal: default 1 */
} zr_warp;

/* slope { <Direction> [, Lo, Hi] [altitude <Altitude> [, Lo, Hi]] }
   ("Slope Pattern"): direction and altitude as written (their lengths
   weigh the two parts), the ranges that map to 0 and 1 (defaults 0, 1;
   no altitude: a zero vector). */
typedef struct zr_slope {
  zr_vec3 direction;
  double lo, hi;
  zr_vec3 altitude;
  double alt_lo, alt_hi;
} zr_slope;

typedef struct zr_pattern {
  zr_pattern_kind kind;
  zr_vec3 vector;    /* gradient: unit direction; brick: brick_size */
  double mortar;     /* brick: default 0.5 */
  double agate_turb; /* agate: default 1 */
  /* turbulence <t>: displaces the point by t times a fractal vector
     noise of octaves terms, each omega times weaker and lambda times
     finer than the last (defaults 6, 0.5, 2), before any transform. */
  zr_vec3 turbulence; /* zero: none */
  int octaves;
  double omega, lambda;
  double frequency, phase; /* defaults 1 and 0 */
  zr_wave_kind wave;
  double wave_exponent; /* poly_wave: default 1 */
  int arms;                 /* spiral1, spiral2: number of arms */
  int tiling;               /* tiling: its number, 1 to 27 */
  int waves;                /* ripples, waves: number_of_waves, def. 10 */
  double control0, control1; /* quilted: defaults 1 and 1 */
  /* noise_generator 1, 2 or 3 (default: the global setting, 2).  Kept
     for the record: our noise is one function (lib/scene/pattern.c). */
  int noise_generator;
  const struct zr_pigment *pigment; /* pigment_pattern */
  zr_fractal fractal;               /* mandel, julia */
  const struct zr_fn *fn;           /* function { }: f(x, y, z) */
  const struct zr_object *object;   /* object pattern */
  /* The object pattern's inside test (the tracer's, lib/trace/
     intersect.c), set with object by the parser, so the scene model
     needs no tracer (README, "Layering"). */
  bool (*object_inside)(const struct zr_object *object, zr_vec3 p);
  /* crackle's form (weights of the three nearest distances, default
     <-1,1,0>), metric (default 2), offset and solid ("Crackle"). */
  zr_vec3 crackle_form;
  double crackle_metric, crackle_offset;
  bool crackle_solid;
  const zr_density_file *density_file; /* density_file df3 */
  const struct zr_image_map *image;    /* image_pattern */
  zr_slope slope;                      /* slope { } */
  const zr_warp *warps; /* in the order written, in the arena */
  int n_warps;
} zr_pattern;

/* color_map: values ascending; the colour between two entries is
   interpolated, outside them the nearest entry's. */
typedef struct zr_colour_map_entry {
  double value;
  zr_colour colour;
} zr_colour_map_entry;

typedef struct zr_colour_map {
  size_t n;
  const zr_colour_map_entry *entries;
} zr_colour_map;

/*
 * pigment_map, normal_map, texture_map, slope_map and the lists of block
 * patterns ("checker pigment {..} pigment {..}") share one shape: values
 * ascending (block lists: 0, 1, 2), each with what it selects.  Between
 * two entries a pattern's value blends the two; outside the first and
 * last entry their own holds (reference manual, "Pigment Maps and
 * Pigment Lists", "Normal Maps", "Texture Maps", "Slope Maps").
 */
typedef struct zr_map_entry {
  double value;
  union {
    const struct zr_pigment *pigment;
    const struct zr_normal *normal;
    const struct zr_texture *texture;
    struct {
      double height, slope;
    } slope;
  } u;
} zr_map_entry;

typedef struct zr_map {
  size_t n;
  const zr_map_entry *entries;
  size_t n_unweighted; /* entries that left out their value (weight 1) */
} zr_map;

/* An image_map's picture, decoded once into the scene's arena. */
typedef struct zr_image_map {
  const char *path; /* as written, for messages */
  int width, height;
  /* The picture's samples in the form the file was decoded to
     (lib/image/image.h), top row first, so a grey 8-bit picture costs a
     byte a pixel: float files width * height * 3 linear floats in
     pixels, else stored codes (one or three a pixel, of one byte, or two
     when maxval > 255) or palette indices (indices, with each entry's
     three codes in palette), and in table the colour of each code, in
     the working space for image maps (lib/scene/bitmap.c converts per
     lookup).  layout is a zr_image_layout. */
  const float *pixels;
  int layout;
  const void *codes;
  unsigned maxval;
  const float *table;
  const unsigned short *palette;
  int map_type;        /* 0 planar, 1 spherical, 2 cylindrical, 5 torus */
  bool once;
  int interpolate;     /* 0 none, 2 bilinear (others act as 2) */
  double filter_all, transmit_all;
  /* Palette images only, else NULL and 0: each pixel's palette entry and
     each index's filter and transmit (2 * 256 floats, one pair for each
     byte value, as a file may hold indices past its palette), set by
     "filter all" and "filter INDEX, AMOUNT" in the order written. */
  const unsigned char *indices;
  int palette_size;
  float *palette_ft;
  /* image_map and image_pattern only: NULL, or each pixel's straight
     alpha in [0, 1] from the file (a PNG's alpha channel or tRNS).  An
     image_map adds 1 - alpha to the pixel's transmit ("Using the Alpha
     Channel"; a palette's tRNS is in palette_ft instead), an
     image_pattern with use_alpha takes it as its value. */
  const float *alpha;
  /* bump_map and material_map only: one number a pixel, the bump map's
     height (lib/scene/bitmap.c) or the material map's texture index,
     computed per lookup from code_value (maxval + 1 numbers: each code's
     stored or decoded value) by value_kind, or for a float picture
     (values != NULL) kept one float a pixel. */
  const float *values;
  const double *code_value;
  int value_kind; /* ZR_BITMAP_VALUE_* (bitmap.h) */
  bool use_index; /* bump_map: the heights are the palette indices */
} zr_image_map;

typedef enum zr_pigment_kind {
  ZR_PIGMENT_SOLID = 0,
  ZR_PIGMENT_PATTERN, /* pattern with colour_map or colour list */
  ZR_PIGMENT_IMAGE    /* image_map */
} zr_pigment_kind;

typedef struct zr_pigment {
  zr_pigment_kind kind;
  zr_colour colour;
  /* Pattern to world space in m, world to pattern in inv (NULL:
     identity), like an object's transform; unused by solid colours but
     kept current by the parser, as POV-Ray transforms textures with the
     objects they are on. */
  const zr_transform *transform;
  zr_pattern pattern;
  const zr_colour_map *colour_map; /* NULL: the pattern's default */
  /* Block patterns' colours (checker 2, hexagon 3, brick 2); entries
     not given keep the pattern's defaults. */
  zr_colour list[3];
  const zr_image_map *image; /* ZR_PIGMENT_IMAGE */
  /* pigment_map or a block pattern's list of pigments: the pattern then
     picks or blends these pigments, evaluated in this pigment's pattern
     space, so transforming the outer pigment moves them all. */
  const zr_map *pigment_map;
  /* uv_mapping ("UV Mapping"): the pattern is evaluated at (u, v, 0),
     the hit's surface coordinates, instead of the 3-D point. */
  bool uv_mapping;
  /* quick_color ("Quick Color"): the colour shown instead at +Q5 and
     below (lib/trace/shade.c). */
  bool has_quick;
  zr_colour quick;
} zr_pigment;

/* normal { Pattern [Bump_Size] ... }: the shading normal tilts against
   the slope of the pattern's value, scaled by amount. */
typedef struct zr_normal {
  zr_pattern pattern;
  double amount; /* bump_size */
  const zr_transform *transform; /* as a pigment's */
  /* normal_map or a block pattern's normals: the pattern blends the
     normals these give (their transforms already include this one's). */
  const zr_map *normal_map;
  /* slope_map: the surface's height as a function of the pattern's value,
     a cubic through the entries' heights with their slopes. */
  const zr_map *slope_map;
  /* accuracy: the step of the central differences that measure the
     slope, in pattern units ("Accuracy"; default 0.02). */
  double accuracy;
  bool uv_mapping; /* as a pigment's */
  /* bump_map { }: the normal tilts by the picture's height differences
     (lib/scene/bitmap.c) instead of a pattern's. */
  const zr_image_map *bump_map;
  /* no_bump_scale: the tilt is divided by the transform's scale (the
     cube root of its determinant), so scaling changes the bumps' size
     but not their depth (texture.c). */
  bool no_bump_scale;
} zr_normal;

typedef struct zr_finish {
  zr_rgb ambient;    /* default 0.1, times global ambient_light */
  zr_rgb emission;   /* default 0 */
  double diffuse;    /* default 0.6 */
  /* diffuse A, B: B of the light arriving at the back of the surface
     (thin translucent objects: paper, leaves); default 0 */
  double diffuse_back;
  double brilliance; /* default 1 */
  double phong;      /* default 0 */
  double phong_size; /* default 40 */
  double specular;   /* default 0 */
  double roughness;  /* default 0.05; specular exponent is 1/roughness */
  double metallic;   /* default 0; "metallic" alone means 1 */
  /* crand: random darkening of the diffuse light from light sources by
     up to this fraction (lib/trace/shade.c); default 0. */
  double crand;
  zr_rgb reflection;     /* reflection (the minimum when max is set) */
  zr_rgb reflection_max; /* equal to reflection unless given */
  double reflection_falloff; /* default 1 */
  /* reflection { exponent e }: the reflected colour, each channel c,
     counts as c^(1/e), times the reflection amount (measured:
     bench/provenance/probe.py reflection_exponent); default 1 */
  double reflection_exponent;
  bool reflection_fresnel;
  /* reflection { metallic Amount }: 0 when absent, 1 when the keyword
     stands alone; povray tints reflections by 1 + Amount * (1 - F) *
     (pigment - 1), so the amount matters (0.5 gives half the tint). */
  double reflection_metallic;
  bool conserve_energy;
  /* zRcube's finish { energy P } (issue 4): the power, per channel,
     that each object wearing this finish emits into the radiosity
     solution in all, spread evenly over its emitting sides, so its
     exitance is P / area (lib/radiosity/mesh.c).  Added to emission;
     default 0.  See zrcube(1), "Radiosity settings". */
  zr_rgb energy;
  /* irid { amount thickness t turbulence u } ("Iridescence"): thin-film
     interference tints the light from light sources (lib/trace/shade.c);
     amount 0 (the default) is off, thickness in microns. */
  double irid, irid_thickness, irid_turbulence;
  /* finish { ior N } (POV-Ray 3.0 syntax, which 3.7 renders as the
     interior's ior, with a warning): 0 when absent; the object that
     wears the finish gets it as its interior's ior (lib/sdl/build.c). */
  double legacy_ior;
  /* finish { subsurface { translucency C } } ("Subsurface Light
     Transport"): the mean free path of light inside, per channel, in mm
     (mm_per_unit sets the scene's scale); lit only with a
     global_settings subsurface block (lib/trace/subsurface.c).
     subsurface is false when absent. */
  bool subsurface;
  zr_rgb translucency;
} zr_finish;

typedef struct zr_interior {
  double ior; /* default 1 */
  /* Attenuation of light travelling d inside ("Attenuation"): each
     channel keeps fade_colour + (1 - fade_colour) / (1 + (d /
     fade_distance)^fade_power), exp(-d / fade_distance) for powers
     of 1000 and above; off while either is 0 (lib/trace/shade.c). */
  double fade_distance, fade_power;
  zr_rgb fade_colour; /* default black */
  /* Simulated caustics' power ("Simulated Caustics"; 0: none): light
     through the surface gains by |cos|^(45 power), the cosine of the
     shadow ray and the (perturbed) normal (lib/trace/shade.c). */
  double caustics;
  /* media { } inside (lib/trace/media.c); they add where they overlap. */
  const struct zr_medium *const *media;
  size_t n_media;
  /* dispersion ("Dispersion"; default 1: none): the ratio of the violet
     to the red ior, and the number of steps of the spectrum a refracted
     ray is split into (default 7, at least 2).  As in POV-Ray 3.7 it
     acts only where the interior's ior was given (ior_given; measured:
     interior { dispersion 1.2 } alone bends and tints nothing,
     interior { ior 1 dispersion 1.2 } tints; lib/trace/dispersion.c). */
  double dispersion;
  int dispersion_samples;
  bool ior_given;
} zr_interior;

/*
 * media { } ("Media"): particles that absorb, emit and scatter light,
 * inside an object's interior or, at scene level, in the atmosphere
 * (lib/trace/media.c integrates them).  Colours are per unit length;
 * each is scaled at a point by the product of the densities there.
 */
typedef enum zr_scattering_kind {
  ZR_SCATTER_ISOTROPIC = 1,
  ZR_SCATTER_MIE_HAZY,
  ZR_SCATTER_MIE_MURKY,
  ZR_SCATTER_RAYLEIGH,
  ZR_SCATTER_HENYEY_GREENSTEIN
} zr_scattering_kind;

typedef struct zr_medium {
  int method;                 /* 1, 2 or 3; default 3 */
  int intervals;              /* default 1 */
  int min_samples, max_samples; /* default 1, 1 */
  double confidence;          /* default 0.9 */
  double variance;            /* default 1/128 */
  double ratio;               /* default 0.9 */
  double jitter;              /* default 0 */
  int aa_level;               /* default 3 */
  double aa_threshold;        /* default 0.1 */
  zr_rgb absorption, emission, scattering; /* default black */
  zr_scattering_kind scattering_type;      /* default isotropic */
  double eccentricity;        /* Henyey-Greenstein g; default 0 */
  double extinction;          /* scattering's share of extinction: 1 */
  /* collect off: media photons are neither stored nor gathered in it
     ("Photons and Media"); default on. */
  bool photons_ignored;
  /* density { }: pigments whose colours multiply (none: density 1). */
  const zr_pigment *const *density;
  size_t n_density;
  zr_source_loc where;
} zr_medium;

/*
 * A texture.  A layered one ("Layered Textures") is a chain from the
 * bottom layer, the one an object points to, upward through over; each
 * layer lets the ones below show through its pigment's filter and
 * transmit.  A patterned one ("Patterned Textures": texture_map, block
 * patterns of textures, material_map) has a map: its pattern picks or
 * blends the map's textures, whose transforms already include this
 * texture's; its pigment, finish and normal are then the first entry's,
 * for code that wants one plain colour (radiosity, shadows).
 */
typedef struct zr_texture {
  const zr_pigment *pigment; /* never NULL in a finished scene */
  const zr_finish *finish;   /* never NULL in a finished scene */
  const zr_normal *normal;   /* NULL: the surface's own normal */
  const struct zr_texture *over; /* the layer on top of this one */
  const zr_map *map;             /* patterned texture: NULL if plain */
  zr_pattern pattern;            /* the map's pattern */
  const zr_transform *transform; /* the map pattern's, as a pigment's */
  /* texture { uv_mapping ... }: every pattern of this texture (pigment,
     normal, map and the map's textures) uses the surface's (u, v, 0). */
  bool uv_mapping;
  /* material_map { }: the picture's index at the point picks the map's
     entry (modulo their number) instead of the pattern. */
  const zr_image_map *material;
} zr_texture;

/* ---- objects ---- */

typedef enum zr_object_kind {
  ZR_OBJ_SPHERE = 0,
  ZR_OBJ_BOX,
  ZR_OBJ_PLANE,
  ZR_OBJ_TRIANGLE,
  ZR_OBJ_CYLINDER,
  ZR_OBJ_CONE,
  ZR_OBJ_DISC,
  ZR_OBJ_UNION,
  ZR_OBJ_MESH, /* mesh, mesh2 and smooth_triangle (lib/trace/obj_mesh.c) */
  ZR_OBJ_TEXT, /* text { ttf ... } (lib/trace/obj_text.c) */
  /* CSG kept as one primitive (lib/trace/csg.c).  A difference is built
     as an intersection whose later children are inverted, as POV-Ray's
     manual defines it ("Difference"). */
  ZR_OBJ_INTERSECTION,
  ZR_OBJ_MERGE,
  ZR_OBJ_QUADRIC, /* lib/trace/obj_quadric.c */
  ZR_OBJ_TORUS,   /* lib/trace/obj_torus.c */
  ZR_OBJ_POLYGON, /* lib/trace/obj_polygon.c */
  ZR_OBJ_SUPERELLIPSOID, /* lib/trace/obj_superellipsoid.c */
  ZR_OBJ_PRISM,          /* lib/trace/obj_prism.c */
  ZR_OBJ_LATHE,          /* lib/trace/obj_lathe.c */
  ZR_OBJ_BLOB,           /* lib/trace/obj_blob.c */
  ZR_OBJ_POLY,           /* poly, cubic, quartic: lib/trace/obj_poly.c */
  ZR_OBJ_SOR,            /* lib/trace/obj_sor.c */
  ZR_OBJ_SPHERE_SWEEP,   /* lib/trace/obj_sweep.c */
  ZR_OBJ_JULIA,          /* julia_fractal: lib/trace/obj_julia.c */
  ZR_OBJ_ISOSURFACE,     /* lib/trace/obj_isosurface.c */
  ZR_OBJ_HEIGHT_FIELD,   /* lib/trace/obj_height_field.c */
  ZR_OBJ_OVUS,           /* lib/trace/obj_ovus.c */
  ZR_OBJ_PARAMETRIC      /* lib/trace/obj_parametric.c */
} zr_object_kind;

/* Whether the object is a CSG node with children in u.csg. */
static inline bool zr__is_csg(zr_object_kind kind) {
  return kind == ZR_OBJ_UNION || kind == ZR_OBJ_INTERSECTION ||
         kind == ZR_OBJ_MERGE;
}

struct zr_mesh; /* triangles and their BVH, shared by every copy
                  (lib/scene/shapes.h) */
struct zr_hf_grid; /* a height field's samples (lib/scene/shapes.h) */
struct zr_fn;   /* a compiled user function (lib/fn/fn.h) */

/* One component of a blob ("Blob"): its field is
   strength (1 - d^2 / radius^2)^2 within radius of its centre (sphere)
   or of its axis from a to b with hemispherical ends (cylinder). */
typedef struct zr_blob_component {
  bool cylinder;
  zr_vec3 a, b; /* a: the sphere's centre */
  double radius, strength;
  const zr_transform *transform; /* component to blob; NULL: identity */
  /* The component's own texture (pigment, finish, normal or texture
     given inside it), in blob space; NULL: the blob's.  Where fields
     overlap, the lit colours of the textures blend by each component's
     field at the point (measured on POV-Ray 3.7's renders). */
  const struct zr_texture *texture;
} zr_blob_component;
struct zr_text; /* extruded glyph outlines, shared likewise (shapes.h) */

typedef struct zr_object zr_object;

/* An object's photons { } block ("Shooting Photons at an Object"). */
typedef struct zr_photon_object {
  bool target;       /* light sources shoot photons at it */
  double spacing;    /* target's spacing multiplier; default 1 */
  bool refraction, reflection; /* it bends / mirrors photons; off */
  bool refraction_set, reflection_set; /* the block gave them */
  bool collect;      /* photons are stored and gathered on it; on */
  bool pass_through; /* photons cross it unchanged; default no_shadow */
} zr_photon_object;

struct zr_object {
  zr_object_kind kind;
  /* Object to world (NULL: identity).  A union's modifiers are pushed down
     into its children as they are applied, as POV-Ray does, so a union's
     own transform and texture only matter for children added later. */
  const zr_transform *transform;
  const zr_texture *texture;   /* NULL: the default texture */
  const zr_interior *interior; /* NULL: the default interior */
  /* interior_texture { }: the texture of the inside (back) of the
     surface; NULL: the same as outside. */
  const zr_texture *interior_texture;
  bool no_shadow;
  /* no_image: unseen by camera rays (and what they pass straight
     through); no_reflection: unseen in reflections.  Both still cast
     shadows ("No_Image", "No_Reflection"). */
  bool no_image, no_reflection;
  /* double_illuminate: a light on either side of the surface lights it
     ("Double_Illuminate"), the back as if the normal were turned. */
  bool double_illuminate;
  /* The innermost light_group the object is in (an index into the
     scene's light_groups), 0 for none ("Light Group"). */
  uint32_t light_group;
  bool inverse;
  bool hollow; /* stored for media; it changes nothing else */
  /* uv_mapping as an object modifier: the textures given after it use
     the surface's (u, v) and no longer move with the object. */
  bool uv_mapping;
  /* While parsing: transform was composed for this object alone (no copy
     of the object shares it), so the next transformation may change it
     in place (lib/sdl/build.c, transform_object).  Unused after. */
  bool own_transform;
  /* bound is the box of the object's own bounded_by, and rays that miss
     it skip the object (lib/trace/prepare.c bound_by_box, intersect.c);
     false: bound is a union's, or a poly's own, or unused. */
  bool bound_cuts;
  /* clipped_by: only the surface inside this object remains (an
     intersection of the clipping objects); NULL when not clipped. */
  const zr_object *clip;
  /* bounded_by: for clipped_by { bounded_by }, and as the box of a
     primitive the tracer cannot box itself (a quartic, a poly), its own
     or its union's (lib/trace/prepare.c, bounds.c).  An object's own
     bound whose box is smaller than the object's is replaced by that box
     when the scene is finished (bound_cuts); a correct bound never
     changes the picture. */
  const zr_object *bound;
  /* photons { } ("Photons"): NULL for the defaults (collects photons,
     neither a target nor reflecting or refracting them, passes them
     through when no_shadow).  A union's block is pushed down into its
     children like its other modifiers. */
  const struct zr_photon_object *photons;
  /* In a finished scene, the CSG primitive this object is a part of
     (NULL for a primitive itself): rays enter and leave its interior,
     not the part's. */
  const zr_object *solid;
  zr_source_loc where;
  /* The shape's own data, last: an object of a small kind (sphere,
     plane, triangle, box) is allocated with only its own part of the
     union (zr__object_size), so copies must copy that many bytes. */
  union {
    struct {
      zr_vec3 centre;
      double radius;
    } sphere;
    struct {
      zr_vec3 corner1, corner2; /* as written; min/max taken when tracing */
    } box;
    struct {
      zr_vec3 normal; /* unit */
      double distance; /* points p with dot(p, normal) == distance */
    } plane;
    struct {
      zr_vec3 p[3];
    } triangle;
    struct {
      zr_vec3 base, cap;
      double radius;
      bool open;
      /* The unit axis base -> cap and its length, measured by the
         parser (zr__axis_measure); a height of 0 (an object made by
         hand) has the tracer measure them for each ray. */
      zr_vec3 axis;
      double height;
    } cylinder;
    struct {
      zr_vec3 base, cap;
      double base_radius, cap_radius;
      bool open;
      zr_vec3 axis; /* as the cylinder's */
      double height;
    } cone;
    struct {
      zr_vec3 centre, normal; /* normal unit */
      double radius, hole_radius;
    } disc;
    struct {
      zr_object **children;
      size_t n_children;
      /* Light sources written inside the CSG: they follow its
         transforms and join the scene's lights when the object does
         (lib/sdl/build_object.c), as in POV-Ray. */
      struct zr_light **lights;
      size_t n_lights;
      /* The world box of each child, set on the parts of a CSG
         primitive when the scene is prepared (lib/trace/prepare.c) and
         NULL elsewhere: the tracer skips a child whose box the ray
         misses, or that does not hold the point it tests. */
      struct zr_csg_box {
        zr_vec3 lo, hi;
        bool bounded;
        /* The box holds the child's surface, and the child holds every
           point outside it: the box of an inverted child (a part cut
           out by a difference) is the box of its un-inverted shape
           (lib/trace/bounds.c, zr__complement_bounds). */
        bool holds_outside;
      } *boxes;
      /* This part's own world box before its clip (what bounds.c
         would compute from the children), set with boxes and NULL
         elsewhere: an intersection's box is narrowed from its
         children's shapes (lib/trace/bounds_csg.c), which cost 20% of
         a render whose area lights ask the box of every part for each
         shadow shaft (lib/trace/shaft.c). */
      const struct zr_csg_box *whole;
      /* For a part with many children, a tree of their boxes made
         with them (lib/trace/csg.c), NULL otherwise: the tracer finds
         the children a ray or point meets without testing every box. */
      const struct zr_csg_tree *tree;
    } csg;
    struct {
      const struct zr_mesh *data;
      /* For a mesh with a texture list: one copy of this object per
         listed texture, made when the scene is finished (NULL before),
         so a hit on a textured triangle reports the copy that carries
         its texture. */
      const zr_object *textured;
      /* The texture list moved with this object (NULL: the mesh's as
         written): object { M scale 2 } carries M's listed textures
         along, as any texture moves with its object. */
      const struct zr_texture *const *textures;
    } mesh;
    struct {
      const struct zr_text *data;
    } text;
    struct {
      /* A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J,
         negative inside ("Quadric"). */
      double coef[10];
    } quadric;
    struct {
      int order;
      /* The (order+1)(order+2)(order+3)/6 coefficients in POV-Ray's
         order ("Poly, Cubic and Quartic"): x's power falling, then y's,
         then z's; n_coef counts those given while parsing. */
      double *coef;
      int n_coef;
    } poly;
    struct {
      /* About the y axis in the x-z plane ("Torus"); sturm is kept for
         the record, as the root finder is always the careful one. */
      double major, minor;
      bool sturm;
    } torus;
    struct {
      /* Flat, in the plane dot(p, normal) == distance; the points as
         (u, v) = (dot(p, u_axis), dot(p, v_axis)).  Edges are given as
         x0 y0 x1 y1 quadruples; a point is inside when a line from it
         crosses an odd number of them ("Polygon").  points is the list
         as written, kept while the parser reads it. */
      zr_vec3 normal, u_axis, v_axis;
      double distance;
      const double *edges;
      size_t n_edges;
      zr_vec3 lo, hi; /* the box of the points */
      zr_vec3 *points;
      size_t n_points, n_expected;
    } polygon;
    struct {
      /* (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) < 1 inside
         ("Superquadric Ellipsoid"). */
      double e, n;
    } superellipsoid;
    struct {
      /* Closed curves in the x-z plane swept along y from y0 to y1
         ("Prism"); a conic sweep scales the curve by y, from the apex
         at the origin.  Each curve segment is a cubic in s in [0, 1]:
         x = seg[0] + seg[1] s + seg[2] s^2 + seg[3] s^3, z likewise
         with seg[4..7].  lo and hi box the curve (x, z in .x, .z);
         box[4 i ..] = xlo, xhi, zlo, zhi box piece i (NULL: not made,
         the tracer then works them out per call).  side[i] tells
         which way piece i's wall faces (lib/trace/obj_prism.c
         zr__prism_wall_sides; NULL or 0: not known, found per hit). */
      int spline; /* 0 linear, 1 quadratic, 2 cubic, 3 bezier */
      bool conic, open, sturm;
      double y0, y1; /* y0 <= y1 */
      const double *seg;
      const double *box;
      const signed char *side;
      size_t n_seg;
      zr_vec3 lo, hi;
      zr_vec3 *points; /* as written, kept while the parser reads it */
      size_t n_points, n_expected;
    } prism;
    struct {
      /* A curve in the (r, y) plane turned about the y axis ("Lathe"),
         stored as a prism's: seg[0..3] give r(s), seg[4..7] y(s).  lo
         and hi box the curve (r in .x, y in .y); box[4 i ..] = rlo,
         rhi, ylo, yhi box piece i, as a prism's. */
      int spline; /* 0 linear, 1 quadratic, 2 cubic, 3 bezier */
      bool sturm;
      const double *seg;
      const double *box;
      size_t n_seg;
      zr_vec3 lo, hi;
      zr_vec3 *points;
      size_t n_points, n_expected;
    } lathe;
    struct {
      /* The surface where the components' fields add up to threshold,
         inside where they exceed it. */
      double threshold; /* default 1 */
      bool sturm;
      zr_blob_component *components;
      size_t n_components, cap_components;
      bool textured; /* some component has a texture of its own */
    } blob;
    struct {
      /* A surface of revolution ("Surface of Revolution"): per segment
         seg[6 i ..] = h0, h1, c0, c1, c2, c3 with
         x^2 + z^2 = c0 + c1 u + c2 u^2 + c3 u^3, u = (y - h0) / (h1 - h0)
         for h0 <= y <= h1; caps at the ends unless open. */
      bool open, sturm;
      const double *seg;
      size_t n_seg;
      double rmax;
      zr_vec3 *points; /* as written, kept while the parser reads it */
      size_t n_points, n_expected;
    } sor;
    struct {
      /* sphere_sweep ("Sphere Sweep"): its spline pieces, shared by
         every copy (lib/scene/shapes.h). */
      const struct zr_sphere_sweep *data;
    } sweep;
    struct {
      /* julia_fractal ("Julia Fractal"): lib/scene/shapes.h. */
      const struct zr_julia *data;
    } julia;
    struct {
      /* isosurface ("Isosurface"): where fn(x, y, z) equals threshold
         within the container, a box [lo, hi] or a sphere; inside where
         fn is below threshold.  The search trusts |grad fn| to stay
         below max_gradient and stops at intervals of accuracy; it
         reports the first max_trace crossings along a ray (0: all). */
      const struct zr_fn *fn;
      bool sphere, open;
      zr_vec3 lo, hi;
      zr_vec3 centre;
      double radius;
      double threshold, accuracy, max_gradient;
      int max_trace;
    } isosurface;
    struct {
      /* height_field ("Height Field"): a w x h grid of heights in
         [0, 1] over the unit square of the x-z plane, each square cut
         into two triangles, found through the grid's block hierarchy
         (lib/scene/shapes.h); water_level hides what lies below it. */
      const struct zr_hf_grid *grid;
      int w, h;
      double water_level;
      bool smooth;
    } height_field;
    struct {
      /* ovus ("Ovus"): a sphere of radius bottom at the origin below
         y0, one of radius top about <0, bottom, 0> above y1, and
         between them a lemon: the circle of radius lemon_r about
         (r, y) = (-lemon_c, lemon_h) turned about the y axis, tangent to
         both (lib/sdl/build_iso.c computes it).  lemon_r is 0 when the
         top sphere holds the bottom one: the ovus is the top sphere. */
      double bottom, top;
      double lemon_r, lemon_c, lemon_h;
      double y0, y1;
    } ovus;
    struct {
      /* parametric ("Parametric"): the points <fn[0], fn[1], fn[2]>(u,
         v) for u in [u0, u1], v in [v0, v1] that lie in the container
         (a box [lo, hi] or a sphere); a shell, with no inside.  Every
         partial derivative of the three is taken to stay below
         max_gradient; accuracy ends the subdivision. */
      const struct zr_fn *fn[3];
      double u0, v0, u1, v1;
      bool sphere;
      zr_vec3 lo, hi, centre;
      double radius;
      double max_gradient, accuracy;
    } parametric;
  } u;
};

/* ---- lights, camera, settings ---- */

typedef enum zr_light_kind {
  ZR_LIGHT_POINT = 0,
  ZR_LIGHT_SPOT,    /* spotlight: a cone about location -> point_at */
  ZR_LIGHT_CYLINDER /* cylinder: a tube about that line */
} zr_light_kind;

/*
 * A light source ("Light Source"; lib/trace/lights.c shines it).  Every
 * kind may also be parallel, an area light, faded and shadowless.
 * Spot and cylinder lights keep radius and falloff in degrees and
 * units respectively, as written; tightness is the exponent of the
 * cosine (spot) or of the fraction of the radius (cylinder).
 */
typedef struct zr_light {
  zr_light_kind kind;
  zr_vec3 location;
  zr_rgb colour;
  bool shadowless;
  bool parallel;     /* rays along location -> point_at everywhere */
  zr_vec3 point_at;  /* default <0,0,0> */
  double radius;     /* spot 30 (degrees), cylinder 0.75 (units) */
  double falloff;    /* spot 45, cylinder 1 */
  double tightness;  /* default 0 */
  double fade_distance; /* 0: no fading */
  double fade_power;    /* default 0: no fading */
  /* area_light Axis1, Axis2, Size1, Size2: a grid of size1 x size2
     point lights spanning axis1 x axis2 about location. */
  bool area;
  zr_vec3 axis1, axis2;
  int size1, size2;
  int adaptive;   /* -1: not adaptive (every point is sampled) */
  bool jitter;    /* deterministic: from a hash of pixel and point */
  bool circular, orient, area_illumination;
  bool media_interaction, media_attenuation; /* parsed; no media yet */
  /* looks_like { }: the object, moved to the light and given no_shadow,
     is also one of the scene's objects; NULL: none. */
  zr_object *looks_like;
  /* projected_through { }: light reaches a point only along rays that
     cross this object, which is not one of the scene's objects and
     casts no shadow (lib/trace/lights.c); NULL: none. */
  zr_object *projected_through;
  /* photons { } in the light: whether its photons may be refracted and
     reflected (both on unless switched off: povray 3.7 renders the
     caustic of a target lens under a light without a photons block as
     under one with "refraction on"), and whether the area light's
     extent is used (area_light; not simulated: photons leave from
     location). */
  bool photon_refraction, photon_reflection, photon_area;
  /* The light_group the light is in, 0 for none: it then lights only
     the objects of that group and of the groups inside it. */
  uint32_t light_group;
  zr_source_loc where;
  /* Derived by zr__scene_add_light() from the fields above, so that
     shading asks no cos() or sqrt() per point: the unit axis from
     point_at toward location (<0,1,0> when they coincide), and the
     cosines of a spotlight's falloff and radius angles. */
  zr_vec3 axis;
  double cos_falloff, cos_radius;
} zr_light;

typedef enum zr_camera_kind {
  ZR_CAMERA_PERSPECTIVE = 0,
  ZR_CAMERA_ORTHOGRAPHIC,
  ZR_CAMERA_FISHEYE,
  ZR_CAMERA_ULTRA_WIDE_ANGLE,
  ZR_CAMERA_OMNIMAX,
  ZR_CAMERA_PANORAMIC,
  ZR_CAMERA_CYLINDER, /* cylinder_type 1-4 */
  ZR_CAMERA_SPHERICAL,
  ZR_CAMERA_MESH /* mesh_camera { }: rays from mesh faces */
} zr_camera_kind;

/* One mesh of a mesh_camera, as written in its block. */
typedef struct zr_camera_mesh {
  const struct zr_mesh *data;
  const zr_transform *transform; /* mesh to world; NULL: identity */
} zr_camera_mesh;

/*
 * mesh_camera { rays distribution [max_distance] mesh { } ... [smooth] }
 * ("Mesh projection"; lib/trace/camera_mesh.c shoots its rays).  For
 * distribution 3 the faces of the first mesh are also sorted into a
 * grid x grid table over uv space, so a pixel's face is found fast:
 * cell c holds faces cell_faces[cell_start[c] .. cell_start[c + 1]), in
 * the order they were written.
 */
typedef struct zr_mesh_camera {
  int rays_per_pixel;
  int distribution; /* 0-3 */
  double max_distance; /* 0: no limit */
  bool smooth;
  const zr_camera_mesh *meshes;
  size_t n_meshes;
  size_t n_faces; /* of all the meshes */
  int grid;
  double grid_lo[2], cell_size[2]; /* the uv of cell (0, 0), a cell's size */
  const uint32_t *cell_start, *cell_faces;
} zr_mesh_camera;

/*
 * The camera after all its modifiers ran, in POV-Ray's terms: a ray
 * through the image point (u, v) in [-0.5, 0.5]^2 (u right, v up) has the
 * direction  direction + u * right + v * up  from location.
 */
typedef struct zr_camera {
  zr_camera_kind kind;
  zr_vec3 location;  /* default <0,0,0> */
  zr_vec3 direction; /* default <0,0,1> */
  zr_vec3 up;        /* default <0,1,0> */
  zr_vec3 right;     /* default <1.33,0,0> */
  zr_vec3 sky;       /* default <0,1,0> */
  bool given;        /* false when the scene has no camera block */
  /* Other projections (lib/trace/render.c says how each maps (u, v)):
     the horizontal and vertical angles in degrees (fisheye, ultra wide,
     cylinder: 90 unless given; spherical 360 and half the horizontal). */
  int cylinder_type; /* 1-4 */
  double h_angle, v_angle;
  /* Focal blur: aperture 0 is off.  blur_samples is the most samples a
     pixel takes, blur_min the fewest before confidence and variance
     may stop it. */
  double aperture;
  int blur_samples, blur_min;
  zr_vec3 focal_point;
  double confidence; /* default 0.9 */
  double variance;   /* default 1/128 */
  const zr_normal *normal; /* perturbs every camera ray; NULL: none */
  const zr_mesh_camera *mesh; /* ZR_CAMERA_MESH only */
  zr_source_loc where;
} zr_camera;

/*
 * fog { } ("Fog"): type 1 constant, 2 ground fog (denser below offset
 * along up, thinning as 1 / (1 + (h - offset) / alt)^2 above).  The
 * colour's filter and transmit let some of what is behind through.
 */
typedef struct zr_fog zr_fog;
struct zr_fog {
  int type;
  double distance;
  zr_colour colour;
  zr_vec3 turbulence; /* zero: none */
  int octaves;
  double omega, lambda, turb_depth;
  double offset, alt;
  zr_vec3 up;                    /* unit */
  const zr_transform *transform; /* for turbulence; NULL: identity */
  const zr_fog *next;
};

/* sky_sphere { pigment... } ("Sky Sphere"): pigments evaluated at the
   ray's direction, the last on top; emission scales the result. */
typedef struct zr_sky_sphere {
  const zr_pigment *const *pigments;
  size_t n_pigments;
  const zr_transform *transform; /* NULL: identity */
  zr_rgb emission;               /* default 1 */
} zr_sky_sphere;

/* rainbow { } ("Rainbow"): a fog-like arc at angle +- width / 2 from
   direction, coloured by colour_map from the inside out. */
typedef struct zr_rainbow zr_rainbow;
struct zr_rainbow {
  zr_vec3 direction; /* unit */
  double angle, width, distance, jitter;
  double arc_angle, falloff_angle; /* degrees, default 180 */
  zr_vec3 up;                      /* unit */
  const zr_colour_map *colour_map;
  const zr_rainbow *next;
};

/*
 * global_settings { radiosity { ... } } (lib/sdl/build_radiosity.c).
 * POV-Ray's own items drive the irradiance cache (lib/gi/cache.c); an
 * item not written is 0 (or -1 for max_sample and the switches), so
 * zr_gi_params_init() puts POV-Ray's default in its place.  zRcube's
 * items (bf_bound, minimum_area, visibility_count, max_iterations,
 * residual_bound) set the hierarchical solver and are 0 when not
 * given, so the library's defaults and the command line decide.
 */
typedef struct zr_radiosity_settings {
  bool on;            /* a radiosity block was read */
  double brightness;  /* scales the diffuse interreflection; default 1 */
  double bf_eps;      /* zr_radiosity_params.bf_eps when > 0 */
  double area_eps;    /* .area_eps when > 0 */
  double residual;    /* .residual when > 0 */
  int visibility_rays; /* .visibility_rays when > 0 */
  int max_iterations;  /* .max_iterations when > 0 */
  /* POV-Ray's items (zr_gi_params), 0 when not written. */
  int count, count_pool;
  int nearest_count, nearest_count_max;
  int recursion_limit;
  double error_bound, low_error_factor, gray_threshold;
  double minimum_reuse, maximum_reuse;
  double pretrace_start, pretrace_end;
  double adc_bailout;
  bool gray_given, adc_given, max_sample_given;
  double max_sample;
  /* normal, media, always_sample: -1 not written, else 0 or 1. */
  int normal, media, always_sample;
  /* save_file and load_file (in the scene's arena), NULL if none. */
  const char *save_file, *load_file;
} zr_radiosity_settings;

/* global_settings { photons { } } ("Photon Global Settings"). */
typedef struct zr_photon_settings {
  bool on;           /* a block was given: photons are shot */
  double spacing;    /* > 0: photons this far apart at the targets */
  double count;      /* > 0: about this many photons in all */
  int gather_min, gather_max; /* photons gathered per point; 20, 100 */
  double jitter;     /* of the shooting directions, in cells; 0.4 */
  int max_trace_level;        /* -1: the scene's */
  double adc_bailout;         /* < 0: the scene's */
  double radius, radius_multiplier; /* gather radius (0: found), 1 */
  double autostop;   /* read; every target is covered whole */
  double expand_increase;     /* 0.2 */
  int expand_min;             /* 40 */
  /* media MAX_STEPS, FACTOR ("Photons and Media"): photons stored in
     scattering media, at most media_steps along each stretch of a
     photon's path through media, media_factor times the surface
     spacing apart; 0 steps: none.  radius's third and fourth values:
     the media photons' gather radius (0: found) and its multiplier. */
  int media_steps;            /* 0 */
  double media_factor;        /* 1 */
  double media_radius, media_radius_multiplier; /* 0, 1 */
} zr_photon_settings;

typedef struct zr_settings {
  int max_trace_level;  /* default 5 */
  double adc_bailout;   /* default 1/255 */
  double assumed_gamma; /* default 1.0 */
  int number_of_waves;  /* waves and ripples made after it; default 10 */
  int noise_generator;  /* patterns made after it; default 0 (= 2) */
  bool assumed_gamma_given;
  /* A legacy scene without assumed_gamma: POV-Ray turns gamma
     correction off and writes the colours as they are (directive.c). */
  bool gamma_correction_off;
  zr_rgb ambient_light; /* default 1 */
  /* irid_wavelength: iridescence's red, green and blue wavelengths in
     microns ("Irid_Wavelength"); default <0.70, 0.52, 0.48>. */
  zr_rgb irid_wavelength;
  zr_colour background; /* default black, transmit 1 (clear) */
  double version;       /* the last #version; the parser sets 3.7 if none */
  /* A #version directive was read: POV-Ray 3.7 drops ambient under
     radiosity only for scenes that declare 3.7 (measured: a sphere of
     ambient 0.3 diffuse 0.6 under a white sky renders 0.9 without
     #version and 0.6 with "#version 3.7;"). */
  bool version_given;
  zr_radiosity_settings radiosity;
  zr_photon_settings photons;
  /* Subsurface light transport ("Subsurface Light Transport"):
     mm_per_unit (default 10) is the scene's scale; a subsurface { }
     block (subsurface_on) turns the finishes' translucency on, with
     samples (default 50, 50: diffuse and single-scattering samples per
     point) and radiosity (default off). */
  double mm_per_unit;
  bool subsurface_on, subsurface_radiosity;
  int subsurface_samples[2];
  /* Atmospheric effects (lib/trace/atmosphere.c): lists in the order
     written, NULL when absent. */
  const zr_fog *fogs;
  const zr_sky_sphere *sky_sphere;
  const zr_rainbow *rainbows;
  /* Atmospheric media ("Atmospheric Media"), in the order written. */
  const zr_medium *const *media;
  size_t n_media;
} zr_settings;

/* ---- the scene ---- */

struct zr_bvh; /* the tracer's acceleration structure (lib/trace) */
struct zr_photon_map; /* photons stored by lib/trace/photons.c */
struct zr_embree;     /* lib/trace/embree.c's meshes, when built with it */
struct zr_light_shafts; /* lib/trace/shaft.c's area light shafts */

struct zr_scene {
  zr_arena arena;
  zr_object **objects; /* top level, as written */
  size_t n_objects;
  size_t cap_objects;
  zr_light *lights;
  size_t n_lights;
  size_t cap_lights;
  /* light_group { }s, indexed from 1 (entry 0 is unused): the group each
     is inside (0: none) and whether the scene's own lights light its
     objects too (global_lights). */
  struct zr_light_group {
    uint32_t parent;
    bool global_lights;
  } *light_groups;
  size_t n_light_groups; /* entries, 0 or 1 + the number of groups */
  zr_camera camera;
  zr_settings settings;
  const zr_texture *default_texture;
  const zr_interior *default_interior;
  /* Built by zr__scene_finish() (lib/trace/prepare.c): every primitive,
     unions flattened, each with its texture resolved (never NULL), how
     many of them are bounded, and the tracer's BVH with the routine
     that frees it (set with it, so the model needs no tracer). */
  const zr_object **primitives;
  size_t n_primitives, n_finite_primitives;
  struct zr_bvh *bvh;
  /* Also by zr__scene_finish(): the first primitives (in their order)
     whose inside holds the camera's location, found once rather than
     on every render call (lib/trace/render.c, zr__camera_media). */
  const zr_object *camera_inside[16];
  int n_camera_inside;
  void (*bvh_free)(struct zr_bvh *bvh);
  /* The caustic photons (NULL: no photons block, or none stored), and
     the routine that frees them (lib/trace/photons.c, set with them). */
  struct zr_photon_map *photons;
  void (*photons_free)(struct zr_photon_map *photons);
  /* What the photon pass did (zr_scene_info): photons shot from the
     lights and photons stored (lib/trace/photons.c). */
  unsigned long long photons_shot, photons_stored;
  unsigned long long media_photons_stored;
  double media_photons_radius;
  /* The meshes' Embree scenes when the tracer uses that backend (NULL:
     none), and the routine that frees them (lib/trace/embree.c). */
  struct zr_embree *embree;
  void (*embree_free)(struct zr_embree *embree);
  /* The area lights' shadow shafts (NULL: no light has one), and the
     routine that frees them (lib/trace/shaft.c, set with them). */
  struct zr_light_shafts *shafts;
  void (*shafts_free)(struct zr_light_shafts *shafts);
  unsigned long long parse_steps; /* the work budget the parse used */
};

/* The bytes an object of this kind is allocated with: the common fields
   and its part of the union (a sphere's 32 bytes rather than the union's
   160; issue 13's memory per sphere). */
size_t zr__object_size(zr_object_kind kind);

/* The unit axis from base to cap and its length (0, and axis
   unchanged, when the two are the same point): a cylinder's or a
   cone's frame, measured once by the parser and, by the same
   operations, by the tracer for an object made without it. */
static inline double zr__axis_measure(zr_vec3 base, zr_vec3 cap,
                                      zr_vec3 *axis) {
  zr_vec3 a = zr_v3_sub(cap, base);
  double h = zr_v3_len(a);
  if (h > 0.0)
    *axis = zr_v3_scale(a, 1.0 / h);
  return h;
}

void zr__finish_init(zr_finish *f);
void zr__pigment_init(zr_pigment *p);
void zr__interior_init(zr_interior *i);
void zr__camera_init(zr_camera *c);
void zr__settings_init(zr_settings *s);

/* A new empty scene with POV-Ray's defaults; NULL when out of memory. */
zr_scene *zr__scene_new(void);
zr_status zr__scene_add_object(zr_scene *scene, zr_object *object);
/* Adds a copy of light, its derived fields (axis, cos_falloff,
   cos_radius) filled in by zr__light_derive(). */
zr_status zr__scene_add_light(zr_scene *scene, const zr_light *light);
void zr__light_derive(zr_light *light);

#endif /* ZR_SCENE_SCENE_H */
