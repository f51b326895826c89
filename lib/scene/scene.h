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
  ZR_PAT_BOXED,
  ZR_PAT_BOZO,
  ZR_PAT_BRICK,
  ZR_PAT_BUMPS,
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
  ZR_PAT_PLANAR,
  ZR_PAT_RADIAL,
  ZR_PAT_RIPPLES,
  ZR_PAT_SPHERICAL,
  ZR_PAT_SPOTTED,
  ZR_PAT_WAVES,
  ZR_PAT_WOOD,
  ZR_PAT_WRINKLES
} zr_pattern_kind;

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

/* An image_map's picture, decoded once into the scene's arena. */
typedef struct zr_image_map {
  const char *path; /* as written, for messages */
  int width, height;
  const float *pixels; /* width * height * 3 linear floats, top row first */
  int map_type;        /* 0 planar, 1 spherical, 2 cylindrical */
  bool once;
  int interpolate;     /* 0 none, 2 bilinear (others act as 2) */
  double filter_all, transmit_all;
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
} zr_pigment;

/* normal { Pattern [Bump_Size] ... }: the shading normal tilts against
   the slope of the pattern's value, scaled by amount. */
typedef struct zr_normal {
  zr_pattern pattern;
  double amount; /* bump_size */
  const zr_transform *transform; /* as a pigment's */
} zr_normal;

typedef struct zr_finish {
  zr_rgb ambient;    /* default 0.1, times global ambient_light */
  zr_rgb emission;   /* default 0 */
  double diffuse;    /* default 0.6 */
  double brilliance; /* default 1 */
  double phong;      /* default 0 */
  double phong_size; /* default 40 */
  double specular;   /* default 0 */
  double roughness;  /* default 0.05; specular exponent is 1/roughness */
  double metallic;   /* default 0; "metallic" alone means 1 */
  zr_rgb reflection;     /* reflection (the minimum when max is set) */
  zr_rgb reflection_max; /* equal to reflection unless given */
  double reflection_falloff; /* default 1 */
  bool reflection_fresnel;
  /* reflection { metallic Amount }: 0 when absent, 1 when the keyword
     stands alone; povray tints reflections by 1 + Amount * (1 - F) *
     (pigment - 1), so the amount matters (0.5 gives half the tint). */
  double reflection_metallic;
  bool conserve_energy;
} zr_finish;

typedef struct zr_interior {
  double ior; /* default 1 */
} zr_interior;

typedef struct zr_texture {
  const zr_pigment *pigment; /* never NULL in a finished scene */
  const zr_finish *finish;   /* never NULL in a finished scene */
  const zr_normal *normal;   /* NULL: the surface's own normal */
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
  ZR_OBJ_UNION
} zr_object_kind;

typedef struct zr_object zr_object;

struct zr_object {
  zr_object_kind kind;
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
    } cylinder;
    struct {
      zr_vec3 base, cap;
      double base_radius, cap_radius;
      bool open;
    } cone;
    struct {
      zr_vec3 centre, normal; /* normal unit */
      double radius, hole_radius;
    } disc;
    struct {
      zr_object **children;
      size_t n_children;
    } csg;
  } u;
  /* Object to world (NULL: identity).  A union's modifiers are pushed down
     into its children as they are applied, as POV-Ray does, so a union's
     own transform and texture only matter for children added later. */
  const zr_transform *transform;
  const zr_texture *texture;   /* NULL: the default texture */
  const zr_interior *interior; /* NULL: the default interior */
  bool no_shadow;
  bool inverse;
  zr_source_loc where;
};

/* ---- lights, camera, settings ---- */

typedef enum zr_light_kind {
  ZR_LIGHT_POINT = 0
} zr_light_kind;

typedef struct zr_light {
  zr_light_kind kind;
  zr_vec3 location;
  zr_rgb colour;
  bool shadowless;
  zr_source_loc where;
} zr_light;

typedef enum zr_camera_kind {
  ZR_CAMERA_PERSPECTIVE = 0
} zr_camera_kind;

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
  zr_source_loc where;
} zr_camera;

typedef struct zr_settings {
  int max_trace_level;  /* default 5 */
  double adc_bailout;   /* default 1/255 */
  double assumed_gamma; /* default 1.0 */
  bool assumed_gamma_given;
  zr_rgb ambient_light; /* default 1 */
  zr_colour background; /* default black, transmit 0 */
  double version;       /* the last #version; the parser sets 3.7 if none */
} zr_settings;

/* ---- the scene ---- */

struct zr_bvh; /* the tracer's acceleration structure (lib/trace) */

struct zr_scene {
  zr_arena arena;
  zr_object **objects; /* top level, as written */
  size_t n_objects;
  size_t cap_objects;
  zr_light *lights;
  size_t n_lights;
  size_t cap_lights;
  zr_camera camera;
  zr_settings settings;
  const zr_texture *default_texture;
  const zr_interior *default_interior;
  /* Built by zr__scene_finish(): every primitive, unions flattened, each
     with its texture resolved (never NULL). */
  const zr_object **primitives;
  size_t n_primitives;
  struct zr_bvh *bvh;
};

void zr__finish_init(zr_finish *f);
void zr__pigment_init(zr_pigment *p);
void zr__interior_init(zr_interior *i);
void zr__camera_init(zr_camera *c);
void zr__settings_init(zr_settings *s);

/* A new empty scene with POV-Ray's defaults; NULL when out of memory. */
zr_scene *zr__scene_new(void);
zr_status zr__scene_add_object(zr_scene *scene, zr_object *object);
zr_status zr__scene_add_light(zr_scene *scene, const zr_light *light);

/*
 * Ends construction: flattens unions into scene->primitives, resolves
 * default textures, then builds the tracer's BVH.  Called once by the
 * parser after the last statement.
 */
zr_status zr__scene_finish(zr_scene *scene, zr_context *ctx);

/* The object's world-space bounding box; false for unbounded objects
   (planes, and anything inverse). */
bool zr__object_bounds(const zr_object *object, zr_vec3 *lo, zr_vec3 *hi);

#endif /* ZR_SCENE_SCENE_H */
