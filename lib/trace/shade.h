/*
 * shade.h - following one ray through the scene and computing the colour
 * it brings back, with POV-Ray 3.7's lighting model.
 */
#ifndef ZR_TRACE_SHADE_H
#define ZR_TRACE_SHADE_H

#include "scene/scene.h"
#include "trace/intersect.h"

/* How many nested interiors a ray keeps track of for their ior. */
#define ZR_MEDIA_MAX 16

/*
 * How many surfaces one ray path may pass straight through.  povray 3.7
 * does not count a transmitted ray that is not bent (the same ior on
 * both sides) as a trace level: behind two clear boxes without an ior it
 * still sees the scene at max_trace_level 2, while with ior 1.5 it needs
 * level 5.  This separate bound keeps such paths finite.
 */
#define ZR_PASS_MAX 256

/* The objects a ray is inside, innermost last, each with the interior
   of the part it was entered by (a CSG part may have its own: povray
   3.7 keeps the part's interior, wineglass.pov's merge of parts of
   different ior and fade_distance): the ior of the medium it travels
   through is the innermost one's.  Also the number of surfaces the path
   went straight through. */
typedef struct zr_media {
  const zr_object *objects[ZR_MEDIA_MAX];
  const zr_interior *interiors[ZR_MEDIA_MAX];
  int n;
  int passes;
} zr_media;

struct zr_tracer;

/*
 * The one narrow interface through which the tracer asks for indirect
 * light: a model of global illumination (lib/gi: the irradiance cache,
 * the sky) answers for a surface point what the tracer cannot see from
 * the point itself.  The tracer knows no model; a model traces its own
 * rays through the tracer it is handed.
 */
typedef struct zr_indirect_query {
  zr_vec3 p;      /* the point */
  zr_vec3 n;      /* shading normal, on the side the ray came from */
  zr_vec3 n_geo;  /* the normal before any normal { } perturbation */
  double path;    /* distance from the eye along the ray path */
  const zr_object *object;
  /* What the surface reflects of the light answered: diffuse * pigment
     * opacity (a path tracer's Russian roulette weighs by it). */
  zr_rgb reflectance;
} zr_indirect_query;

typedef struct zr_indirect {
  /* The cosine-weighted mean radiance arriving at q (irradiance / pi),
     scaled by the model's brightness; false: the model has nothing
     for this point. */
  bool (*irradiance)(const struct zr_indirect *self,
                     const struct zr_tracer *tracer,
                     const zr_indirect_query *q, zr_rgb *out);
  const void *provider; /* the model, shared by threads, read-only */
  void *scratch;        /* this thread's state for the model, or NULL */
  /* NULL, or whether the model samples object's emission itself at the
     points it answers (a path tracer's next-event estimation): a ray
     the model shot with zr_tracer.skip_sampled_emission then leaves
     that emission out at its first hit, not to count it twice. */
  bool (*samples_emission)(const struct zr_indirect *self,
                           const zr_object *object);
  /* NULL, or the next number in [0, 1) of the model's random stream
     for this sample: an area light then shines from one point of its
     grid picked with it, an unbiased estimate of the grid's mean
     (lib/trace/lights.c), in place of the grid's deterministic
     sampling. */
  double (*next_uniform)(const struct zr_indirect *self);
} zr_indirect;

/*
 * A radiosity solution as the tracer sees it (lib/radiosity implements
 * it): the radiance leaving the surface point p of object towards
 * direction d that the solution carries (false: the object is not in
 * it), and the scene it was solved for.  It is the first member of
 * struct zr_radiosity, so the tracer reads a solution through this
 * alone and includes nothing of lib/radiosity (README, "Layering").
 */
typedef struct zr_radiance_source {
  bool (*radiance)(const struct zr_radiance_source *self,
                   const zr_object *object, zr_vec3 p, zr_vec3 d,
                   zr_rgb *out);
  const zr_scene *scene;
} zr_radiance_source;

/* The radiance source of a public radiosity solution (NULL: none). */
static inline const zr_radiance_source *
zr__radiance_source(const zr_radiosity *rad) {
  return (const zr_radiance_source *)(const void *)rad;
}

/* What one thread needs to trace rays in a scene. */
/*
 * The last object that blocked each light's shadow rays, for one thread
 * (ZR_SHADOW_CACHE_SLOTS lights, by their address): the next shadow ray
 * to that light tries it first, and when it blocks the ray again the
 * walk of the hierarchy is skipped.  The answer is the walk's (an
 * opaque blocker makes any walk black), so the image bytes do not
 * depend on what the cache held.
 */
enum { ZR_SHADOW_CACHE_SLOTS = 16, ZR_SHAFT_SLOTS = 4,
       ZR_SHAFT_LIST_MAX = 16 };
/* What an area light's shadow rays from a point can meet
   (lib/trace/shaft.h): n = -1 unknown, 0 nothing, else only objects[0
   .. n), each stopping any ray that crosses it. */
typedef struct zr_shaft_plan {
  int n;
  const zr_object *objects[ZR_SHAFT_LIST_MAX];
} zr_shaft_plan;
typedef struct zr_shadow_cache {
  const zr_light *light[ZR_SHADOW_CACHE_SLOTS];
  const zr_object *blocker[ZR_SHADOW_CACHE_SLOTS];
  /* The blocker is a shape of one closed form that stops any ray it
     crosses (shade.c, stops_light): one crossing in the ray's interval
     answers, without shading the crossing as the walk does. */
  bool stops[ZR_SHADOW_CACHE_SLOTS];
  /* The last shafts tested (lib/trace/shaft.c): hull + 1 (0: an empty
     slot), the point the shadow rays leave from, and the plan, which
     the next light of the same group from the same point reuses. */
  struct zr_shaft_memo {
    uint32_t hull;
    zr_vec3 apex;
    zr_shaft_plan plan;
  } shaft[ZR_SHAFT_SLOTS];
  unsigned shaft_next;
} zr_shadow_cache;

typedef struct zr_tracer {
  const zr_scene *scene;
  zr_render_stats *stats; /* never NULL */
  /* A radiosity solution of scene (NULL: none): it replaces ambient and
     emission with the diffuse light it carries (lib/radiosity). */
  const zr_radiance_source *radiosity;
  int radiosity_only; /* 1: a ray sees the solution at its first hit */
  /* Which objects this ray and the rays it spawns do not see: the
     camera's rays hide no_image objects, reflected rays no_reflection
     ones (ZR_HIDE_*; 0 for rays of other origins). */
  unsigned hide;
  /* Indirect light (NULL: none): see zr_indirect above.  gi_depth is 0
     for rays from the camera and d for rays a model shot to gather at
     bounce d; path is the length of the path before this ray's origin
     (for a model's sample rays), no_media makes rays ignore media. */
  const zr_indirect *indirect;
  int gi_depth;
  double path;
  bool no_media;
  /* Rays that pass through fog and rainbows unchanged: the irradiance
     cache's sample rays (povray 3.7 lights a floor through a fog of
     distance 1 with the full light of a wall 3 units away;
     tests/test_gi_fog.sh). */
  bool no_fog;
  /* A pretrace: camera-visible points (gi_depth 0) skip direct light. */
  bool skip_direct;
  /* What a low quality leaves out (zr_render_params.quality, set by
     zr__tracer_quality; all false at the default 9): shadows (below 4),
     area lights as such (below 5, one shadow ray to the centre),
     transmitted rays (below 6), reflected rays (below 8). */
  bool no_shadows, point_area_lights, no_transmitted, no_reflected;
  /* +Q5 and below: pigments with a quick_color show it; +Q1 and below
     (flat): no lighting at all, a surface shows its pigment's colour
     (the bottom layer's), filter, transmit and finish ignored. */
  bool quick_colours, flat;
  /* The surface this ray meets first leaves out the emission that
     indirect->samples_emission says the model sampled; the rays it
     spawns do not (lib/gi/path.c). */
  bool skip_sampled_emission;
  /* > 0: the adc_bailout this ray and the rays it spawns compare their
     weight with (a radiosity block's, for its sample rays); 0: the
     scene's global_settings one. */
  double bailout;
  /* +UA (zr_render_params.alpha): NULL, or where a camera ray adds the
     share of its pixel left clear: clear_weight (1 for the camera ray,
     times filter * grey + transmit of each surface it went through)
     times what the background leaves clear (zr__sky_clear), and that
     ray sees the background as zr__sky_clear colours it.  Reflected
     rays and the indirect model's rays carry none. */
  double *clear;
  double clear_weight;
  /* This thread's last shadow blockers (NULL: none kept); the tracer is
     otherwise read-only, this is a hint that changes no result. */
  zr_shadow_cache *shadow_cache;
  /* The path of interiors (zr__media_cross) of the ray whose surface
     is being lit, where its shadow rays start (NULL: none, as for
     every ray but those of direct_light in shade.c). */
  const zr_media *shadow_path;
  /* The interiors of the ray whose media are being sampled, where the
     shadow rays of its samples start (NULL: where their crossings say;
     lib/trace/media.c zr__media_shadow). */
  const zr_media *media_start;
  /* A ray that a dispersing interior split (lib/trace/dispersion.c)
     carries one colour of the spectrum, at dispersion_u in -0.5 (red)
     .. 0.5 (violet): it and the rays it spawns refract with that
     colour's ior in every dispersing interior and are split no more. */
  bool dispersed;
  double dispersion_u;
} zr_tracer;

/* Sets the tracer's quality flags and no_media for POV-Ray's +Q: 0 to 11
   (reference 3.2.8.3; measured with povray 3.7.0, tests/test_quality.sh:
   no shadows at 3, hard shadows at 4, area lights from 5, refraction
   from 6 and reflection from 8; media from 9 as the reference says). */
void zr__tracer_quality(zr_tracer *tracer, int quality);

enum { ZR_HIDE_IMAGE = 1u << 0, ZR_HIDE_REFLECTION = 1u << 1 };

/*
 * The colour seen along ray (whose direction need not be unit length).
 * level is 1 for a camera ray and grows by one with each reflection or
 * refraction; weight is the ray's contribution to the pixel, compared
 * against adc_bailout before secondary rays are spawned.  media may be
 * NULL for a ray in empty space.
 */
zr_rgb zr__trace_ray(const zr_tracer *tracer, const zr_ray *ray, int level,
                     double weight, const zr_media *media);
/* zr__trace_ray(), and the ray parameter of the first surface it met
   in *t_hit (INFINITY when it escaped). */
zr_rgb zr__trace_ray_hit(const zr_tracer *tracer, const zr_ray *ray,
                         int level, double weight, const zr_media *media,
                         double *t_hit);
/* The indirect light provider of an irradiance cache made for scene
   (lib/gi/cache.c), or NULL when the cache is for another scene. */
const zr_indirect *zr__gi_indirect_for(const zr_gi_cache *cache,
                                       const zr_scene *scene);
/* The mean of params->path_samples path-traced samples over pixel
   (x, y), pixel = y * width + x (lib/gi/path.c); base is the caller's
   camera tracer, camera_media the objects around the camera. */
zr_rgb zr__path_pixel(const zr_path *path, const zr_tracer *base,
                      const zr_media *camera_media,
                      const zr_render_params *params, uint32_t pixel,
                      int x, int y);
/* Whether path is a path tracer made for scene. */
bool zr__path_for(const zr_path *path, const zr_scene *scene);
/* A camera ray that sees surfaces only within distance (world units)
   of its origin (mesh_camera's max_distance). */
zr_rgb zr__trace_camera_ray_within(const zr_tracer *tracer,
                                   const zr_ray *ray, double distance,
                                   const zr_media *media);

/* The pigment's colour at a world point (solid colours for now). */
zr_colour zr__pigment_at(const zr_pigment *pigment, zr_vec3 p);

/*
 * The light that reaches point `to` from a light at `from` (both world
 * points) through the scene: 1 when nothing is in the way, 0 behind an
 * opaque object, and filter * colour + transmit for each transparent
 * surface crossed.  Objects with no_shadow cast none.  light (NULL
 * for none) is the light shining from `from`: with photons, objects
 * that refract its photons stop it (lib/trace/photons.h).
 */
zr_rgb zr__shadow_transmission(const zr_tracer *tracer,
                               const zr_light *light, zr_vec3 from,
                               zr_vec3 to);

/* The reflection amount of finish f at a point of colour colour, for
   a ray of unit direction d meeting unit normal n (facing the ray)
   from a medium of index n1 towards n2 ("Specular Reflection"). */
zr_rgb zr__reflection_amount(const zr_finish *f, zr_colour colour,
                             zr_vec3 d, zr_vec3 n, double n1, double n2);
/* c after travelling distance d inside media's innermost object
   (its interior's fade_distance, fade_power, fade_colour). */
zr_rgb zr__interior_fade(const zr_media *media, double d, zr_rgb c);
/* c after the last stretch, of length d, of a ray that meets part at a
   surface: faded by the interior the ray leaves there, if any
   (shade.c explains). */
zr_rgb zr__exit_fade(const zr_scene *scene, const zr_media *media,
                     const zr_object *part, double d, zr_rgb c);
/* next: media after a crossing of part, which goes out of the interior
   of part when media holds it, else into it (shade.c explains); true
   when it went in. */
bool zr__media_cross(const zr_scene *scene, const zr_media *media,
                     const zr_object *part, zr_media *next);
double zr__media_ior(const zr_media *media);

/* The mirror direction of unit d about unit n. */
static inline zr_vec3 zr__reflect(zr_vec3 d, zr_vec3 n) {
  return zr_v3_madd(d, n, -2.0 * zr_v3_dot(d, n));
}

/*
 * Refracts unit d at a surface with unit normal n facing against d
 * (dot(d, n) < 0), with eta = n1 / n2 the ratio of the indices on the
 * incoming and outgoing sides.  Returns false on total
 * internal reflection.
 */
bool zr__refract(zr_vec3 d, zr_vec3 n, double eta, zr_vec3 *out);

/* Unpolarised Fresnel reflectance for a ray meeting a surface at cos_i
   (> 0) from a medium of index n1 into n2; 1 on total internal
   reflection. */
double zr__fresnel(double cos_i, double n1, double n2);

/* Subsurface light transport (lib/trace/subsurface.c): whether finish f
   takes it here (a translucency, a global subsurface block, quality 9 or
   above), and the light it brings to p (normal n facing the viewer, d
   the incoming ray) for a total diffuse reflectance per channel; it
   replaces the light sources' diffuse term there. */
bool zr__subsurface_on(const zr_tracer *tr, const zr_finish *f);
zr_rgb zr__subsurface_light(const zr_tracer *tr, const zr_object *object,
                            const zr_finish *f, zr_vec3 p, zr_vec3 n,
                            zr_vec3 d, zr_rgb reflectance);

/* The share of the light's own colour in a metallic highlight or
   reflection at an angle with cosine cos_angle (0 facing, 1 grazing). */
double zr__metallic_white(double cos_angle);
/* finish { irid { } }: the factor, per channel, by which thin-film
   interference scales a light's colour at p, given the cosines of the
   angles to the light and to the viewer (lib/trace/shade.c). */
zr_rgb zr__irid_tint(const zr_finish *f, const zr_settings *gs, zr_vec3 p,
                     double cos_light, double cos_eye);

#endif /* ZR_TRACE_SHADE_H */
