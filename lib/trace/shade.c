/*
 * shade.c - POV-Ray 3.7's classic lighting model (reference manual,
 * "Finish", "Light Source", "Interior", "Pigment" and the global
 * settings max_trace_level, adc_bailout and ambient_light).
 *
 * The colour a ray brings back from a surface point with pigment colour
 * C = (r, g, b, filter f, transmit t) is the sum of
 *   - the surface's own light, scaled by its opacity k = 1 - f - t:
 *       k * C * (ambient * ambient_light + emission)
 *       k * C * diffuse * (N.L)^brilliance * light      for each light
 *   - highlights, not scaled by k (a clear glass still shows them):
 *       phong * (R.L)^phong_size * light * M
 *       specular * (N.H)^(1/roughness) * light * M
 *     where R is the mirrored view direction, H the half vector and M the
 *     metallic tint, between white and C;
 *   - mirror reflection, reflection * (the reflected ray's colour), where
 *     the amount may vary between reflection and reflection_max with the
 *     angle (falloff) or by Fresnel's law;
 *   - transmission, (f * C + t) * (the refracted ray's colour), refracted
 *     by Snell's law with the interiors' ior (the media a ray is in are
 *     tracked as it enters and leaves objects);
 *   - on total internal reflection of a transparent surface, povray
 *     replaces both of the last two by the mirrored ray's colour at full
 *     strength, and so does this.
 * These rules were checked against renders of small scenes by povray
 * 3.7 (the tests in tests/test_shade.c state the measured values).
 *
 * A light only shines on the side of the surface that faces the viewer,
 * so nothing lights an opaque surface through itself (unless the object
 * has double_illuminate, which lights the back as the front); irid
 * tints each light's colour by thin-film interference (zr__irid_tint);
 * shadow rays pass
 * through transparent surfaces, each crossing scaling the light by its
 * f * C + t.  Light is not attenuated with distance unless the light
 * fades; spotlights, cylinder, parallel and area lights are shaped in
 * lib/trace/lights.c, and fog, rainbows and the sky_sphere act at the
 * ray's end (lib/trace/atmosphere.c).  Participating media (interior
 * media of hollow containers, atmospheric media) act on each ray
 * segment and dim shadow rays through their containers
 * (lib/trace/media.c); interior_texture replaces the texture where a
 * ray meets the inside of a surface.  Rays are followed to
 * max_trace_level (deeper ones return black, as in POV-Ray; a ray that
 * passes a surface unbent does not count), and a
 * secondary ray is spawned only if its weight, the product of the
 * reflection and transmission amounts along its path, exceeds
 * adc_bailout.
 *
 * With a radiosity solution (lib/radiosity, issue 4) the surface's own
 * light k * C * (ambient * ambient_light + emission) is replaced by
 * k * L, the solution's outgoing diffuse radiance at the hit, which
 * already holds emission * C and every diffuse bounce of the emitters'
 * light (Hanrahan, Salzman and Aupperle 1991): ambient is POV-Ray's
 * stand-in for exactly that light, so adding it too would count it
 * twice.  Direct light from light sources, highlights, reflection and
 * refraction stay as above, and reflected or refracted rays see the
 * radiosity-lit scene because they are shaded by the same rule.  An
 * object the solution has no surface for (an infinite plane) keeps the
 * classic rule.  In radiosity-only mode a ray returns L at its first
 * hit and nothing else, to show the solution alone.
 */
#include "trace/shade.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "scene/pattern.h"
#include "scene/shapes.h"
#include "scene/texture.h"
#include "trace/atmosphere.h"
#include "trace/bvh.h"
#include "trace/dispersion.h"
#include "trace/photons.h"
#include "trace/lights.h"
#include "trace/media.h"
#include "trace/obj_shapes.h"

zr_colour zr__pigment_at(const zr_pigment *pigment, zr_vec3 p) {
  return zr__pigment_eval(pigment, p); /* lib/scene/texture.c */
}

/* fmax as glibc computes it (the first operand when it is greater or
   the second is a NaN, else the second), in comparisons that -O2 keeps
   inline where fmax stays a call: rgb_max runs a few times a ray (the
   calls were 1% of bench/peers.sh's sphereflake), same values bit for
   bit. */
static inline double max_of(double a, double b) {
  return a > b || b != b ? a : b;
}

static double rgb_max(zr_rgb c) { return max_of(c.r, max_of(c.g, c.b)); }
static double rgb_absmax(zr_rgb c) {
  return fmax(fabs(c.r), fmax(fabs(c.g), fabs(c.b)));
}

/* f * C + t: the light a surface of colour c lets through. */
static zr_rgb see_through(zr_colour c) {
  return zr_rgb3(c.f * c.r + c.t, c.f * c.g + c.t, c.f * c.b + c.t);
}

/* A surface a shadow ray crossed: where, and the part of the object. */
typedef struct shadow_crossing {
  double t;
  const zr_object *part;
} shadow_crossing;

/* How many crossings a shadow ray's fading follows; a ray through more
   fades by the first ones the walk met (BVH order, not distance). */
#define SHADOW_SURFACES_MAX 64

typedef struct shadow_walk {
  const zr_ray *ray;
  const zr_scene *scene;
  const zr_light *source; /* NULL: not a light's shadow ray */
  zr_rgb light;
  /* Crossings of hollow containers with media (lib/trace/media.c). */
  zr_media_crossing crossings[ZR_MEDIA_LIST_MAX];
  size_t n_crossings;
  /* Every surface the ray crossed (unordered), for the fading of
     interiors (shadow_fade); fades: whether one of them fades light. */
  shadow_crossing surfaces[SHADOW_SURFACES_MAX];
  size_t n_surfaces;
  bool fades;
  const zr_object *blocker; /* the surface that stopped the light */
} shadow_walk;

/* Whether in fades the light of a shadow ray: povray 3.7 lets it
   through a clear block of fade_power 0, or -1, unfaded, where the
   camera's rays through the block are halved (fade_distance 1, power
   0: bench/conform/fade_power_probe.sh); powers above 0 fade both
   alike (0.25 and 0.5 measured too). */
static bool shadow_fades(const zr_interior *in) {
  return in && in->fade_distance != 0.0 && in->fade_power > 0.0;
}

/*
 * What is left of each channel of light after distance d inside an
 * interior that fades it ("Attenuation" in the reference's Interior
 * section, 3.4.8.1.6: 1 / (1 + (d / fade_distance)^fade_power), and an
 * exponential for fade_power 1000 or above).  Below 1000 fade_color
 * mixes in as fade_colour + (1 - fade_colour) * a per channel; at 1000
 * and above povray 3.7 takes exp(-d (1 - fade_colour) / fade_distance)
 * per channel instead, in view and shadow rays alike: clear slabs 0.25
 * to 2 thick, fade_distance 2, fade_color <0.35, 0.42, 0.85> give -ln T / d
 * = 0.325, 0.29, 0.073 (tests/fade_colour.pov; the mix rule gives 0.5 at
 * every depth on the red channel's a, i.e. too bright with depth).
 * fade_power 999 is the 1 / (1 + ...) figure, 1000 the exponential.
 */
static zr_rgb fade_factor(const zr_interior *in, double d) {
  zr_rgb f = in->fade_colour;
  if (in->fade_power >= 1000.0) {
    if (isinf(d))
      return zr_rgb3(f.r >= 1.0 ? 1.0 : 0.0, f.g >= 1.0 ? 1.0 : 0.0,
                     f.b >= 1.0 ? 1.0 : 0.0);
    double k = -d / in->fade_distance;
    return zr_rgb3(exp(k * (1.0 - f.r)), exp(k * (1.0 - f.g)),
                   exp(k * (1.0 - f.b)));
  }
  /* An endless stretch (d infinite) leaves 0 for powers above 0, half
     for 0, all for negative ones, as the formula does.  A negative
     fade_distance goes in as it is, as povray 3.7 takes it
     (bench/conform/interior_fade_negative.sh): the ratio's odd powers
     make a above 1 for short stretches and below 0 for long ones, which
     takes light away from what else the ray sums (a shadow ray's light
     from the lit point's ambient), and a power that is no integer has
     no real value there: that light is lost. */
  double a = 1.0 / (1.0 + pow(d / in->fade_distance, in->fade_power));
  if (isnan(a))
    return zr_rgb3(0.0, 0.0, 0.0);
  return zr_rgb3(f.r + (1.0 - f.r) * a, f.g + (1.0 - f.g) * a,
                 f.b + (1.0 - f.b) * a);
}

static const zr_interior *stretch_interior(const zr_scene *scene,
                                           const zr_media *media,
                                           const zr_object *part);
static zr_rgb fade_by(const zr_interior *in, double d, zr_rgb c);

/*
 * A shadow ray through objects whose interior fades light loses light
 * by the rule of a camera ray (stretch_interior, zr__media_cross): its
 * path of interiors starts as the path of the ray that met the lit
 * point (start; NULL: empty), and going toward the light, a stretch
 * between two surfaces is faded only where the ray leaves an interior
 * the path holds, by that interior, over the stretch since the surface
 * before (or the lit point).  povray 3.7
 * shadows so (bench/conform/shadow_fade_probe.sh: a floor under clear
 * blocks lit from straight above; tests/test_shadow_fade.sh):
 * - two blocks stacked in a merge, each its own interior, cast no
 *   faded shadow (1.00: entered by one, left by the other), nor do
 *   two copies of one declared block, nor a merge whose own interior
 *   its parts override; a merge whose parts take its interior fades
 *   over the whole (0.333 for 1 unit, fade_distance 0.5);
 * - a clear block inside a fading one splits it: only the stretch
 *   after it is faded (0.625: 0.3 of the 1 unit); overlapping blocks
 *   1..1.7 and 1.3..2 fade 1.3..1.7 by the first and 1.7..2 by the
 *   second (0.2525), so the order is from the lit point to the light;
 * - a floor seen through a fading block it lies inside is lit through
 *   the 2 units up to the block's top (0.2), but not when the block is
 *   no_image (1.00): no camera ray went into it.
 * advanced/wineglass.pov's merge of rim, bowl, beads and stem, each
 * part with its own interior, shadows the table so.
 */
static zr_rgb shadow_fade(const shadow_walk *w, const zr_media *start) {
  shadow_crossing hits[SHADOW_SURFACES_MAX];
  size_t n = w->n_surfaces;
  for (size_t i = 0; i < n; i++) {
    size_t k = i;
    while (k > 0 && hits[k - 1].t > w->surfaces[i].t) {
      hits[k] = hits[k - 1];
      k--;
    }
    hits[k] = w->surfaces[i];
  }
  double len = zr_v3_len(w->ray->dir);
  zr_rgb light = zr_rgb3(1, 1, 1);
  zr_media path, next;
  if (start)
    path = *start;
  else
    path.n = path.passes = 0;
  double before = 0.0;
  for (size_t i = 0; i < n; i++) {
    const zr_interior *in = stretch_interior(w->scene, &path, hits[i].part);
    if (shadow_fades(in))
      light = fade_by(in, (hits[i].t - before) * len, light);
    zr__media_cross(w->scene, &path, hits[i].part, &next);
    path = next;
    before = hits[i].t;
  }
  return light;
}

/*
 * Simulated caustics ("Simulated Caustics" in the manual: a shadow gets
 * brighter where the light ray and the surface normal are nearly
 * parallel, tighter as power grows).  The law is measured, not given:
 * povray 3.7 multiplies the light through each surface crossing by
 * 1 + |cos|^(45 power), cos between the shadow ray and the normal
 * (perturbed by the texture's normal { }), independent of ior and of
 * filter (bench/conform/caustics_probe.sh prints the ratios: 2.000 at
 * normal incidence for every power, 1.2467 at 20 degrees for power
 * 0.5, 1.0609 for power 1, squared through a slab's two faces).
 */
static double fake_caustics(const zr_ray *ray, const zr_hit *hit,
                            zr_vec3 p, double power) {
  zr_hit hs[ZR_MAX_CROSSINGS];
  double eps = 1e-6 * (1.0 + fabs(hit->t));
  int n = zr__intersect(hit->object, ray, hit->t - eps, hit->t + eps, hs);
  if (n <= 0)
    return 1.0;
  zr_vec3 normal = hs[0].normal;
  if (zr_v3_dot(normal, ray->dir) > 0.0)
    normal = zr_v3_neg(normal);
  const zr_texture *tx = hit->object->texture;
  if (tx && !tx->map && !tx->over && tx->normal)
    normal = zr__normal_perturb(tx->normal, p, normal);
  double c = fabs(zr_v3_dot(zr_v3_norm(normal), zr_v3_norm(ray->dir)));
  return 1.0 + pow(c, 45.0 * power);
}

static bool shadow_visit(const zr_hit *hit, void *user) {
  shadow_walk *w = user;
  const zr_object *o = hit->object;
  const zr_object *solid = o->solid ? o->solid : o;
  /* A no_shadow object leaves the light alone: its surface, and the
     media and fading of its interior (povray 3.7: a no_shadow sphere
     of absorbing media or with fade_distance casts no shadow, as
     tests/test_no_shadow_interior.sh checks). */
  if (o->no_shadow)
    return true;
  if (solid->hollow && solid->interior && solid->interior->n_media > 0 &&
      w->n_crossings < ZR_MEDIA_LIST_MAX) {
    /* The walk's hits carry no normals: the ray goes in when a point
       just past the hit is inside. */
    zr_media_crossing *c = &w->crossings[w->n_crossings++];
    zr_vec3 at = zr_v3_madd(w->ray->origin, w->ray->dir, hit->t);
    zr_vec3 past = zr_v3_madd(at, zr_v3_norm(w->ray->dir),
                              1e3 * zr__surface_offset(at));
    c->t = hit->t;
    c->solid = solid;
    c->entering = zr__inside(solid, past);
  }
  if (w->n_surfaces < SHADOW_SURFACES_MAX) {
    w->surfaces[w->n_surfaces].t = hit->t;
    w->surfaces[w->n_surfaces++].part = o;
  }
  w->fades = w->fades || shadow_fades(o->interior);
  if (zr__photons_block_shadow(w->scene, w->source, o)) {
    w->light = zr_rgb3(0, 0, 0);
    w->blocker = o;
    return false; /* the photons bring this light (lib/trace/photons.c) */
  }
  zr_vec3 p = zr_v3_madd(w->ray->origin, w->ray->dir, hit->t);
  const zr_texture *tx = o->texture;
  if (tx->over || tx->map) {
    /* Layered or patterned: lib/scene/texture.c. */
    w->light = zr_rgb_mul(w->light, zr__texture_see_through(tx, p));
  } else {
    /* A uv_mapping pigment filters by its colour at the hit's (u, v). */
    double u, v;
    if ((o->uv_mapping || tx->uv_mapping || tx->pigment->uv_mapping) &&
        zr__hit_uv(hit, p, &u, &v))
      p = zr_v3(u, v, 0.0);
    zr_colour c = zr__pigment_at(tx->pigment, p);
    w->light = zr_rgb_mul(w->light, see_through(c));
  }
  /* The part's interior: a CSG part keeps its own (lib/trace/prepare.c;
     wineglass.pov's merge gives every part caustics 2). */
  if (o->interior && o->interior->caustics > 0.0 && rgb_max(w->light) > 0.0)
    w->light = zr_rgb_scale(w->light, fake_caustics(w->ray, hit, p,
                                                    o->interior->caustics));
  if (rgb_max(w->light) > 0.0)
    return true;
  w->blocker = o;
  return false;
}

/* Whether any crossing of o ends a shadow walk in shadow_visit: o
   casts shadows and is one solid colour that lets no light through
   (see_through gives 0, whatever the point). */
static bool stops_light(const zr_object *o) {
  const zr_texture *tx = o->texture;
  if (o->no_shadow || !tx || tx->over || tx->map || !tx->pigment)
    return false;
  const zr_pigment *pg = tx->pigment;
  return pg->kind == ZR_PIGMENT_SOLID && pg->colour.f == 0.0 &&
         pg->colour.t == 0.0;
}

/* zr__bvh_all_blocked's question for a mesh: whether every object its
   crossings report (one per texture of its texture list) stops the
   walk, so that one crossing, any one, decides the shadow. */
static bool mesh_stops_light(const zr_object *o, void *user) {
  (void)user;
  if (o->u.mesh.textured)
    for (size_t k = 0; k < o->u.mesh.data->n_textures; k++)
      if (!stops_light(&o->u.mesh.textured[k]))
        return false;
  return stops_light(o);
}

/* Whether trying o before the walk costs little: a shape of one closed
   form (a whole CSG object is kept too, see below).  A mesh costs as
   much as the walk it would save, and an unshadowed ray pays both
   (bench/peers.sh's terrain took 15% longer at 2048^2 when its mesh was
   kept). */
static bool cheap_blocker(const zr_object *o) {
  return zr__simple_kind(o->kind) && !o->solid && !o->clip;
}

static unsigned cache_slot(const zr_light *light) {
  return (unsigned)(((uintptr_t)light / sizeof *light) %
                    ZR_SHADOW_CACHE_SLOTS);
}

/* Whether the light's last blocker blocks ray again: its crossings in
   the walk's interval, each visited as the walk would. */
static bool cached_blocker_blocks(const zr_shadow_cache *cache,
                                  const shadow_walk *w, double tmax) {
  unsigned slot = cache_slot(w->source);
  const zr_object *o = cache->blocker[slot];
  if (cache->light[slot] != w->source || !o)
    return false;
  zr_hit h[ZR_MAX_CROSSINGS];
  int n = zr__bvh_crossings_t(o, w->ray, 0.0, tmax, h);
  /* shadow_visit below would stop at the first crossing of such a
     blocker (see stops_light): the crossings need no shading.  A
     quarter of the sphereflake's tries find their blocker again, and
     shading each crossing cost ~160 instructions (callgrind, 512^2). */
  if (cache->stops[slot])
    return n > 0;
  for (int k = 0; k < n; k++) {
    shadow_walk probe;
    probe.ray = w->ray;
    probe.scene = w->scene;
    probe.source = w->source;
    probe.light = zr_rgb3(1, 1, 1);
    probe.n_crossings = 0;
    probe.n_surfaces = 0;
    probe.fades = false;
    probe.blocker = NULL;
    if (!shadow_visit(&h[k], &probe))
      return true;
  }
  return false;
}

zr_rgb zr__shadow_transmission(const zr_tracer *tracer,
                               const zr_light *light, zr_vec3 from,
                               zr_vec3 to) {
  zr_ray ray = {to, zr_v3_sub(from, to)};
  shadow_walk w;
  w.ray = &ray;
  w.scene = tracer->scene;
  w.source = light;
  w.light = zr_rgb3(1, 1, 1);
  w.n_crossings = 0;
  w.n_surfaces = 0;
  w.fades = false;
  w.blocker = NULL;
  tracer->stats->shadow_rays++;
  const double tmax = 1.0 - 1e-6;
  zr_shadow_cache *cache = light ? tracer->shadow_cache : NULL;
  if (cache && cached_blocker_blocks(cache, &w, tmax))
    return zr_rgb3(0, 0, 0);
  /* t runs from the surface point (0) to the light (1).  A surface
     through the light itself does not shadow it: radiosity/cornell.pov
     hangs its area lights in the ceiling's plane, and hits at t = 1
     give or take rounding speckled every wall and banded the back one;
     povray shows neither, so the last millionth of the way is left
     out. */
  if (!zr__bvh_all_blocked(tracer->scene->bvh, &ray, 0.0, tmax,
                           shadow_visit, mesh_stops_light, &w)) {
    /* A part of a CSG object is never tried alone: the CSG's rules may
       remove the part's surface there (lib/trace/csg.c).  The whole
       object is kept instead, as povray's shadow cache does: an area
       light's samples are mostly stopped by the object that stopped the
       one before (the corpus' complexity.pov, 48 shadow rays a point
       among CSG tiles, now finds 1.02 of its 1.14 million blocked rays
       in the cache, povray 1.02 of 1.13).  Trying it is the walk's own
       test of it, so a cached answer is the walk's. */
    const zr_object *whole =
        w.blocker && w.blocker->solid ? w.blocker->solid : w.blocker;
    if (cache && whole &&
        (cheap_blocker(whole) || zr__is_csg(whole->kind))) {
      cache->light[cache_slot(light)] = light;
      cache->blocker[cache_slot(light)] = whole;
      cache->stops[cache_slot(light)] =
          cheap_blocker(whole) && stops_light(whole);
    }
    return zr_rgb3(0, 0, 0);
  }
  if (w.fades && rgb_max(w.light) > 0.0)
    w.light = zr_rgb_mul(w.light, shadow_fade(&w, tracer->shadow_path));
  if (w.n_crossings > 0 && rgb_max(w.light) > 0.0)
    w.light = zr_rgb_mul(
        w.light, tracer->media_start
                     ? zr__media_sample_shadow(tracer, ray.origin, ray.dir,
                                               w.crossings, w.n_crossings,
                                               tracer->media_start)
                     : zr__media_shadow(tracer, ray.origin, ray.dir,
                                        w.crossings, w.n_crossings));
  return w.light;
}

bool zr__refract(zr_vec3 d, zr_vec3 n, double eta, zr_vec3 *out) {
  double cos_i = -zr_v3_dot(d, n);
  double k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
  if (k < 0.0)
    return false;
  *out = zr_v3_norm(
      zr_v3_add(zr_v3_scale(d, eta), zr_v3_scale(n, eta * cos_i - sqrt(k))));
  return true;
}

double zr__fresnel(double cos_i, double n1, double n2) {
  if (n1 == n2)
    return 0.0; /* no boundary (the formula below leaves ~1e-32) */
  double eta = n1 / n2;
  double sin2_t = eta * eta * (1.0 - cos_i * cos_i);
  if (sin2_t >= 1.0)
    return 1.0;
  double cos_t = sqrt(1.0 - sin2_t);
  double rs = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
  double rp = (n1 * cos_t - n2 * cos_i) / (n1 * cos_t + n2 * cos_i);
  return 0.5 * (rs * rs + rp * rp);
}

/* The ior of the medium a ray in media travels through. */
double zr__media_ior(const zr_media *media) {
  if (!media || media->n == 0)
    return 1.0;
  return media->interiors[media->n - 1]->ior;
}

/* Everything shading needs about one surface point. */
typedef struct surface {
  zr_vec3 p;      /* the point */
  zr_vec3 n;      /* unit normal facing the incoming ray */
  zr_vec3 ng;     /* the same before normal { } perturbation */
  double path;    /* distance from the eye to p along the ray path */
  zr_vec3 d;      /* unit direction of the incoming ray */
  bool entering;  /* the ray meets the outer side of the surface */
  const zr_object *object;
  const zr_finish *finish;
  zr_colour colour;
  double offset;  /* distance to move secondary rays off the surface */
  bool layer;     /* an upper layer: the layers below take transmission */
  /* The bottom layer lets light through but the ray is totally
     reflected here: its mirrored ray stands for every layer's
     reflection (shade_layers()). */
  bool tir_below;
  /* uv_mapping ("UV Mapping"): uv_all when every pattern here takes
     (u, v, 0), as under an object's or an outer texture's uv_mapping;
     hu, hv are a mesh hit's coordinates, uvp the point (u, v, 0),
     found only when a pattern first asks (uv_known). */
  bool uv_all, uv_known;
  double hu, hv;
  zr_vec3 uvp;
  /* The interior the ray leaves here and fades (stretch_interior; NULL:
     none), and the length of the stretch it fades: only the light
     transmitted out through the surface is faded (shade()). */
  const zr_interior *leaving;
  double stretch;
} surface;

/* The point a pattern is evaluated at: the hit, or its (u, v, 0). */
static zr_vec3 pattern_point(surface *s, bool uv) {
  if (!uv && !s->uv_all)
    return s->p;
  if (!s->uv_known) {
    zr_hit h;
    h.object = s->object;
    h.u = s->hu;
    h.v = s->hv;
    double u, v;
    zr__hit_uv(&h, s->p, &u, &v); /* lib/trace/intersect.c */
    s->uvp = zr_v3(u, v, 0.0);
    s->uv_known = true;
  }
  return s->uvp;
}

/*
 * The manual's "empirical function that models the reflectivity of
 * metallic surfaces" ("Metallic Highlight Modifier", and metallic in
 * "Specular Reflection": the light's colour at glancing angles, the
 * metal's near the normal).  It gives W, the share of white that is
 * left in the tint at an angle t from the normal; the tint is
 * 1 + m (1 - W) (C - 1) (metallic_tint).  bench/metallic_probe.sh
 * measures POV-Ray 3.7 (reflection { 1 metallic 1 } of a white
 * background by a plane of colour <1, 0.25, 0>, linear output): W is 0
 * facing, 0.0027 at 10 degrees, 0.0341 at 50, 0.1128 at 70, 0.2611
 * at 80, 0.4611 at 85, 0.8358 at 89, rising to 1 grazing; the tint is
 * linear in the colour and in m, and highlights use the angle between
 * the light and the normal (not the viewer's).  We model it, with
 * x = t / 90 degrees, as
 *   W(x) = x^a ((1 - s) / (1 - s x))^n,
 * 0 at x = 0 and 1 at x = 1 for any parameters: a shapes the slow
 * start, the pole at x = 1 / s beyond grazing the steep end.  a, s
 * and n are the least-squares fit of bench/metallic_fit.py to the 25
 * measured angles; its largest error in W is 0.0004, a tenth of an
 * 8-bit output step.
 */
#define METALLIC_A 0.8292
#define METALLIC_S 0.8986
#define METALLIC_N 1.8147

double zr__metallic_white(double cos_angle) {
  double x = acos(fmax(0.0, fmin(1.0, cos_angle))) / (M_PI / 2.0);
  double w = pow(x, METALLIC_A) *
             pow((1.0 - METALLIC_S) / (1.0 - METALLIC_S * x), METALLIC_N);
  return fmin(1.0, w);
}

/* The colour a metallic amount m gives light reflected at an angle with
   cosine cos_angle from a surface of colour c: c facing, white grazing. */
static zr_rgb metallic_tint(double m, zr_rgb c, double cos_angle) {
  double k = m * (1.0 - zr__metallic_white(cos_angle));
  return zr_rgb3(1.0 + k * (c.r - 1.0), 1.0 + k * (c.g - 1.0),
                 1.0 + k * (c.b - 1.0));
}

/*
 * crand ("Crand Graininess"): POV-Ray darkens the diffuse light from
 * light sources by a random fraction up to crand, anew at every sample.
 * Here the fraction is a hash of the point's coordinates, uniform in
 * [0, 1): as grainy, but the same in every render and on every rank.
 */
static double point_random(zr_vec3 p) {
  double c[3] = {p.x, p.y, p.z};
  uint64_t h = 0x9e3779b97f4a7c15u;
  for (int i = 0; i < 3; i++) {
    uint64_t bits;
    memcpy(&bits, &c[i], sizeof bits);
    h ^= bits + 0x9e3779b97f4a7c15u + (h << 6) + (h >> 2);
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdu;
    h ^= h >> 33;
  }
  return (double)(h >> 11) / 9007199254740992.0;
}

/*
 * Iridescence ("Iridescence", "Irid_Wavelength"): a film of thickness t
 * over the surface shifts the light it reflects by the optical path
 * 4 pi t cos / wavelength, and the light source's colour is scaled per
 * channel by 1 + amount * cos(that phase).  POV-Ray 3.7 renders of a
 * plane (amount 0.5 and 1, thickness 0 to 0.5, light along and 60
 * degrees off the normal, tests/test_shade.c) fit this with cos the mean
 * of the cosines toward the light and toward the viewer, to 1%.
 * turbulence u varies the thickness as t (1 + u (2 s - 1)), s the scalar
 * turbulence sum (zr__turbulence_scalar) of 5 octaves, omega 0.5 and
 * lambda 2 at the point (the manual says these are "internally set",
 * "Iridescence"): bench/conform/irid_turbulence_probe.py reads the
 * thickness back from povray 3.7's renders of a plane lit and seen along
 * its normal and fits it to 5e-5 of the turbulence's effect (4 or 6
 * octaves are off by 0.03 and 0.01).
 */
zr_rgb zr__irid_tint(const zr_finish *f, const zr_settings *gs, zr_vec3 p,
                     double cos_light, double cos_eye) {
  double t = f->irid_thickness;
  if (f->irid_turbulence > 0.0)
    t *= 1.0 + f->irid_turbulence *
                   (2.0 * zr__turbulence_scalar(p, 5, 0.5, 2.0) - 1.0);
  double phase = 2.0 * M_PI * t * (cos_light + cos_eye);
  zr_rgb w = gs->irid_wavelength;
  return zr_rgb3(1.0 + f->irid * cos(phase / w.r),
                 1.0 + f->irid * cos(phase / w.g),
                 1.0 + f->irid * cos(phase / w.b));
}

/* Diffuse light and highlights from every light source. */
void zr__tracer_quality(zr_tracer *tracer, int quality) {
  tracer->no_shadows = quality < 4;
  tracer->point_area_lights = quality < 5;
  tracer->no_transmitted = quality < 6;
  tracer->no_reflected = quality < 8;
  /* Measured with povray 3.7.0 (tests/test_quality.sh, quick.pov):
     quick_color shows up to +Q5 and not from +Q6, as the reference
     says; +Q0 and +Q1 show each surface in its colour as it is, without
     ambient, diffuse, highlights, emission or transparency, and a
     layered texture in its bottom layer's. */
  tracer->quick_colours = quality <= 5;
  tracer->flat = quality <= 1;
  if (quality < 9)
    tracer->no_media = true;
}

static zr_rgb direct_light(const zr_tracer *tr, const surface *s,
                           double opacity, const zr_media *media) {
  const zr_finish *f = s->finish;
  const zr_scene *scene = tr->scene;
  zr_rgb sum = zr_rgb3(0, 0, 0);
  zr_rgb c = zr_colour_rgb(s->colour);
  /* Subsurface light transport takes the place of the diffuse term. */
  bool sslt = zr__subsurface_on(tr, f);
  if (sslt && f->diffuse != 0.0 && opacity > 0.0)
    sum = zr__subsurface_light(tr, s->object, f, s->p, s->n, s->d,
                               zr_rgb_scale(c, f->diffuse * opacity));
  /* A finish that takes no light (diffuse 0, no highlights: an
     emitting sky dome such as radiosity2.pov's, which most of the
     irradiance cache's sample rays meet) needs no shadow ray. */
  bool takes = (f->diffuse != 0.0 && opacity > 0.0 && !sslt) ||
               f->diffuse_back > 0.0 || f->phong > 0.0 ||
               (f->specular > 0.0 && f->roughness > 0.0);
  /* The shadow rays start in the interiors the ray that met s is in
     (zr__shadow_transmission). */
  zr_tracer lit;
  const zr_tracer *shadows = tr;
  if (takes && media && media->n > 0) {
    lit = *tr;
    lit.shadow_path = media;
    shadows = &lit;
  }
  /* The ways to the next WAYS lights, asked together (zr_light_way). */
  enum { WAYS = 8 };
  zr_light_way ways[WAYS];
  for (size_t i = 0; takes && i < scene->n_lights; i++) {
    const zr_light *light = &scene->lights[i];
    if (i % WAYS == 0)
      for (size_t k = i; k < scene->n_lights && k < i + WAYS; k++)
        zr__light_way(&scene->lights[k], s->p, &ways[k - i]);
    zr_vec3 l;
    zr_rgb lc;
    if (!zr__light_lights(scene, light, s->object))
      continue; /* a light_group's light, or this object's group's */
    if (!zr__light_arrive_way(light, s->p, &ways[i % WAYS], &l, &lc))
      continue; /* outside a spotlight's cone (lib/trace/lights.c) */
    zr_vec3 n = s->n;
    double n_dot_l = zr_v3_dot(n, l);
    /* Shadow rays leave from the side of the surface the light is on,
       by the unperturbed normal: a bump may turn the shading normal
       away from the viewer, and POV-Ray 3.7 still lights such points
       (wrinkles 1.5 on normal_probe.pov: 10% of the points, which its
       picture shows lit as the perturbed normal predicts, to 2e-5). */
    zr_vec3 from = zr_v3_madd(s->p, s->ng,
                              zr_v3_dot(s->ng, l) >= 0.0 ? s->offset
                                                         : -s->offset);
    if (n_dot_l < 0.0 && s->object->double_illuminate) {
      /* double_illuminate: the back is lit as the front would be. */
      n = zr_v3_neg(n);
      n_dot_l = -n_dot_l;
    }
    /* Light behind the surface only counts with a backside diffuse
       ("diffuse A, B"), and then makes no highlight. */
    bool back = !(n_dot_l > 0.0);
    if (back && !(f->diffuse_back > 0.0 && n_dot_l < 0.0))
      continue;
    /* Skip what the shadow blocks, not what is dark: a light of
       negative colour takes light away (POV-Ray 3.7 darkens a lit
       plane by "light_source { ... color rgb -0.5 }": crater_dat.pov,
       abyss.pov, scenes/negative_light.pov). */
    zr_rgb vis = zr__light_one_ray(shadows, light)
                     ? zr__shadow_transmission(shadows, light,
                                               light->location, from)
                     : zr__light_visibility(shadows, light, s->p, from);
    /* Nothing arrives only when every channel is 0: an interior of
       negative fade_distance can leave a shadow ray less than nothing,
       which povray 3.7 takes from the lit point's other light
       (bench/conform/interior_fade_negative.sh). */
    if (vis.r == 0.0 && vis.g == 0.0 && vis.b == 0.0)
      continue;
    lc = zr_rgb_mul(lc, vis);
    if (back) {
      if (light->media_attenuation)
        lc = zr_rgb_mul(lc, zr__media_light_attenuation(tr, light, s->p));
      double d = f->diffuse_back * opacity *
                 (f->brilliance == 1.0 ? -n_dot_l
                                       : pow(-n_dot_l, f->brilliance));
      sum = zr_rgb_add(sum, zr_rgb_scale(zr_rgb_mul(lc, c), d));
      continue;
    }
    if (light->media_attenuation) /* lib/trace/media.c */
      lc = zr_rgb_mul(lc, zr__media_light_attenuation(tr, light, s->p));
    if (f->irid > 0.0)
      lc = zr_rgb_mul(lc, zr__irid_tint(f, &scene->settings, s->p, n_dot_l,
                                        -zr_v3_dot(n, s->d)));
    if (f->diffuse != 0.0 && opacity > 0.0 && !sslt) {
      double d = f->diffuse * opacity *
                 (f->brilliance == 1.0 ? n_dot_l
                                       : pow(n_dot_l, f->brilliance));
      if (f->crand > 0.0)
        d *= 1.0 - f->crand * point_random(s->p);
      sum = zr_rgb_add(sum, zr_rgb_scale(zr_rgb_mul(lc, c), d));
    }
    /* The manual: shadowless lights cause no highlights. */
    double h = 0.0;
    if (light->shadowless)
      continue;
    if (f->phong > 0.0) {
      double cos_r = zr_v3_dot(zr__reflect(s->d, n), l);
      if (cos_r > 0.0)
        h += f->phong * pow(cos_r, f->phong_size);
    }
    if (f->specular > 0.0 && f->roughness > 0.0) {
      zr_vec3 half = zr_v3_norm(zr_v3_sub(l, s->d));
      double cos_h = zr_v3_dot(n, half);
      if (cos_h > 0.0)
        h += f->specular * pow(cos_h, 1.0 / f->roughness);
    }
    if (h > 0.0)
      sum = zr_rgb_add(
          sum, zr_rgb_scale(zr_rgb_mul(lc, metallic_tint(f->metallic, c,
                                                         n_dot_l)),
                            h));
  }
  return sum;
}

/*
 * The reflection amount at this point: constant, or varying from
 * reflection (facing the viewer) to reflection_max (grazing) by the
 * falloff power of 1 - cos, or by Fresnel's law for the interior's ior
 * (reference, "Specular Reflection").
 */
zr_rgb zr__reflection_amount(const zr_finish *f, zr_colour colour,
                             zr_vec3 d, zr_vec3 n, double n1, double n2) {
  zr_rgb lo = f->reflection, hi = f->reflection_max;
  bool variable = f->reflection_fresnel || lo.r != hi.r || lo.g != hi.g ||
                  lo.b != hi.b;
  zr_rgb amount = lo;
  if (variable) {
    double cos_i = fmin(1.0, fabs(zr_v3_dot(d, n)));
    double w;
    if (f->reflection_fresnel) {
      w = zr__fresnel(cos_i, n1, n2);
    } else {
      w = pow(1.0 - cos_i, f->reflection_falloff);
    }
    amount = zr_rgb3(lo.r + (hi.r - lo.r) * w, lo.g + (hi.g - lo.g) * w,
                     lo.b + (hi.b - lo.b) * w);
  }
  if (f->reflection_metallic != 0.0)
    amount = zr_rgb_mul(amount,
                        metallic_tint(f->reflection_metallic,
                                      zr_colour_rgb(colour),
                                      fabs(zr_v3_dot(d, n))));
  return amount;
}

static zr_rgb reflection_amount(const surface *s, double n1, double n2) {
  /* A constant reflection is what zr__reflection_amount returns
     unchanged (not variable, no metallic), without passing it the
     colour and vectors (~100 instructions a hit). */
  const zr_finish *f = s->finish;
  if (!f->reflection_fresnel && f->reflection.r == f->reflection_max.r &&
      f->reflection.g == f->reflection_max.g &&
      f->reflection.b == f->reflection_max.b &&
      f->reflection_metallic == 0.0)
    return f->reflection;
  return zr__reflection_amount(s->finish, s->colour, s->d, s->n, n1, n2);
}

/* Light c that travelled distance d inside the innermost object of
   media (fade_factor above).  Any fade_power fades a camera ray, 0 too:
   povray 3.7 halves the light through a clear block of fade_distance 1
   and fade_power 0 whatever its thickness, (d / fade_distance)^0 = 1 in
   the formula (bench/conform/fade_power_probe.sh); fade_distance 0 is
   no fading, a negative one fades by the formula too (fade_factor).
   Shadow rays differ (shadow_fades). */
static zr_rgb fade_by(const zr_interior *in, double d, zr_rgb c) {
  if (!in || in->fade_distance == 0.0)
    return c;
  return zr_rgb_mul(c, fade_factor(in, d));
}

zr_rgb zr__interior_fade(const zr_media *media, double d, zr_rgb c) {
  if (!media || media->n == 0)
    return c;
  return fade_by(media->interiors[media->n - 1], d, c);
}

/*
 * A ray's path of media is a list of the interiors it went into, and a
 * crossing goes out of an interior the path holds, else into it,
 * whichever side of the surface the ray meets.  povray 3.7 decides so
 * (tests/test_interior_path.sh measures each case against its renders):
 * - a ray that went into a merge by a clipped (open) part and out
 *   through the cut, where no surface is, goes out of the glass where it
 *   next meets a part of that merge from outside (wineglass.pov's rim
 *   on the bowl); a union that shares one interior does the same;
 * - a part with an interior { } of its own is another interior: meeting
 *   it from outside inside the first one goes in again, and a merge left
 *   through a part of another interior than the one it was entered by
 *   goes into that one (so that stretch is not faded:
 *   tests/test_merge_interior.sh); two objects with interior { I } of
 *   one declared I are two interiors too;
 * - a ray that meets a surface from inside, its path not in the object,
 *   goes in: an upside-down clear height field seen from below its
 *   surface, entered through its open side (tests/test_hf_inside.sh,
 *   advanced/glasschess.pov's board);
 * - a union of triangles or polygons with an interior, which has no
 *   inside of its own, is crossed in and out by turns (the corpus'
 *   diamond.pov, tests/test_flat_interior.sh).
 * An object with the scene's default interior (none given) is held by
 * the object itself: it bends no ray, but fog stays out of a solid
 * (fogged()); a flat one with no interior of its own holds nothing.
 */
static bool holds(const zr_media *media, int i, const zr_object *part,
                  const zr_interior *no_interior) {
  if (part->interior && part->interior != no_interior)
    return media->interiors[i] == part->interior;
  const zr_object *solid = part->solid ? part->solid : part;
  return media->objects[i] == solid && media->interiors[i] == part->interior;
}

/* The entry of media that a crossing of part goes out of, or -1. */
static int held_at(const zr_media *media, const zr_object *part,
                   const zr_interior *no_interior) {
  for (int i = media ? media->n - 1 : -1; i >= 0; i--)
    if (holds(media, i, part, no_interior))
      return i;
  return -1;
}

bool zr__media_cross(const zr_scene *scene, const zr_media *media,
                     const zr_object *part, zr_media *next) {
  const zr_interior *none = scene->default_interior;
  const zr_object *solid = part->solid ? part->solid : part;
  /* The entries in use only: the whole struct is 264 bytes, and its
     copy (a rep movs) was 60% of this function, which every reflected
     ray calls (0.7% of bench/peers.sh's sphereflake at 2048^2, whose
     paths hold no interior).  Nothing reads past n. */
  next->n = media ? media->n : 0;
  next->passes = media ? media->passes : 0;
  for (int k = 0; k < next->n; k++) {
    next->objects[k] = media->objects[k];
    next->interiors[k] = media->interiors[k];
  }
  if (!zr__has_inside(solid) && (!part->interior || part->interior == none))
    return false; /* a flat object has no interior to enter */
  int i = held_at(media, part, none);
  if (i < 0) {
    if (next->n < ZR_MEDIA_MAX) {
      next->objects[next->n] = solid;
      next->interiors[next->n++] = part->interior ? part->interior : none;
    }
    return true;
  }
  for (int j = i; j + 1 < next->n; j++) {
    next->objects[j] = next->objects[j + 1];
    next->interiors[j] = next->interiors[j + 1];
  }
  next->n--;
  return false;
}

/*
 * The interior that fades the stretch of a ray ending where it meets
 * part (NULL: none).  povray 3.7 fades a stretch only where the ray
 * leaves an interior its path holds, by that interior, and only over
 * the stretch since the surface before: behind a clear block of
 * fade_distance 1 with a clear block nested in its middle, 1.5 units of
 * the 4 through the outer block are faded (0.4 of the light, not 0.16);
 * where two overlapping blocks each have an interior, only the stretch
 * from entering the second to leaving the first
 * (tests/test_merge_interior.sh measures these).
 */
static const zr_interior *stretch_interior(const zr_scene *scene,
                                           const zr_media *media,
                                           const zr_object *part) {
  /* A union of flat parts (no inside) is faded from the part a ray went
     in by to the part it leaves by, as a solid: povray 3.7.0.10 fades a
     cube of twelve clear triangles as a box (tests/test_flat_interior.sh
     case 2; the corpus' diamond.pov, fade_distance 1 and fade_power 1001,
     went from SSIM 0.898 to 0.979 with it). */
  int i = held_at(media, part, scene->default_interior);
  if (i < 0)
    return NULL;
  return media->interiors[i];
}

zr_rgb zr__exit_fade(const zr_scene *scene, const zr_media *media,
                     const zr_object *part, double d, zr_rgb c) {
  return fade_by(stretch_interior(scene, media, part), d, c);
}

/* A reflected ray's tracer: it no longer hides no_image objects, and
   hides no_reflection ones; the background it sees is no longer clear
   for +UA ("Output_Alpha": reflections of the background are not
   transparent). */
static zr_tracer reflecting(const zr_tracer *tr) {
  zr_tracer r = *tr;
  r.hide = ZR_HIDE_REFLECTION;
  r.clear = NULL;
  return r;
}

/* tr with its +UA share scaled by k (tr itself when it carries none);
   buf holds the copy. */
static const zr_tracer *clear_scaled(const zr_tracer *tr, double k,
                                     zr_tracer *buf) {
  if (!tr->clear || k == 1.0)
    return tr;
  *buf = *tr;
  buf->clear_weight *= k;
  return buf;
}

/*
 * Where a reflected or refracted ray going dir from s starts: side, s->p
 * moved off the surface along the normal to the side the ray goes, or on
 * a smooth height field s->p moved along dir itself.  A smooth field's
 * normal is blended from its vertices' and stands far from its
 * triangles' across a step: on advanced/glasschess.pov's upside-down
 * glass board (a 256 x 256 checker, steps one sample wide) it is
 * (0, -1, 0) on walls that are nearly vertical, and the point moved
 * along it stayed on the side of the wall the ray came from, so the ray
 * met the same wall again at once and crossed the glass's surface twice
 * (black or bright lines along every step).  POV-Ray 3.7 draws those
 * walls as a ray that leaves the surface where it met it: measured
 * (/tmp probes at 160x120 of a flipped smooth 256 x 256 checker field of
 * ior 1.2 over a chequered box, as in glasschess): filter 1 alone 271
 * pixels off -> 1, reflection { 0, 1 fresnel } alone 687 -> 0,
 * reflection 1 alone 706 -> 0; the whole scene's SSIM 0.908 -> 0.972.
 * The distance is the usual one (zr__surface_offset); 1000 times it
 * drew the same probes (1 pixel fewer off in the filter case).  Other
 * shapes keep the normal's side, with which every other stock scene was
 * measured.
 */
static zr_vec3 ray_start(const surface *s, zr_vec3 side, zr_vec3 dir) {
  const zr_object *o = s->object;
  if (o->kind != ZR_OBJ_HEIGHT_FIELD || !o->u.height_field.smooth)
    return side;
  return zr_v3_madd(s->p, zr_v3_norm(dir), s->offset);
}

static zr_rgb trace_secondary(const zr_tracer *tr, zr_vec3 origin,
                              zr_vec3 dir, int level, double weight,
                              const zr_media *media) {
  zr_ray ray = {origin, dir};
  if (tr->skip_sampled_emission) {
    /* Only the first surface a path tracer's ray meets had its
       emission sampled (lib/gi/path.c). */
    zr_tracer t = *tr;
    t.skip_sampled_emission = false;
    return zr__trace_ray(&t, &ray, level + 1, weight, media);
  }
  return zr__trace_ray(tr, &ray, level + 1, weight, media);
}

/* The media a ray is in after crossing the surface (zr__media_cross). */
static void media_beyond(const zr_tracer *tr, const surface *s,
                         const zr_media *media, zr_media *next) {
  zr__media_cross(tr->scene, media, s->object, next);
}

/*
 * The light a ray refracted at s into or out of a dispersing interior
 * (in1 on this side, in2 beyond) brings: POV-Ray 3.7 splits it into the
 * interior's dispersion_samples colours of the spectrum, each refracted
 * with its own ior and weighted by its colour (lib/trace/dispersion.c,
 * measured).  Where both sides disperse the one beyond gives the count.
 * A colour for which the surface reflects totally goes on as the mirrored
 * ray (then in the media on this side); each colour's ray keeps the
 * whole weight for adc_bailout, a choice no measurement made.
 */
static zr_rgb dispersed(const zr_tracer *tr, const surface *s,
                        const zr_interior *in1, const zr_interior *in2,
                        zr_vec3 above, zr_vec3 below, zr_vec3 mirror,
                        int level, double weight, const zr_media *media,
                        const zr_media *next) {
  int n = zr__disperses(in2) ? in2->dispersion_samples
                             : in1->dispersion_samples;
  zr_tracer one = *tr;
  one.dispersed = true;
  zr_rgb sum = zr_rgb3(0, 0, 0);
  for (int i = 0; i < n; i++) {
    one.dispersion_u = zr__dispersion_u(i, n);
    double n1 = zr__dispersed_ior(in1, one.dispersion_u);
    double n2 = zr__dispersed_ior(in2, one.dispersion_u);
    zr_vec3 dir = s->d;
    zr_rgb c;
    if (n1 != n2 && !zr__refract(s->d, s->n, n1 / n2, &dir))
      c = trace_secondary(&one, ray_start(s, above, mirror), mirror, level,
                          weight, media);
    else
      c = trace_secondary(&one, ray_start(s, below, dir), dir, level,
                          weight, next);
    sum = zr_rgb_add(sum, zr_rgb_mul(zr__dispersion_colour(i, n), c));
  }
  return sum;
}

/*
 * The diffuse light the indirect model brings to s: its cosine-weighted
 * mean incoming radiance times the pigment and diffuse, as POV-Ray's
 * radiosity gives it (measured: a sphere of diffuse 0.6 under a white
 * sky_sphere of 1 renders 0.6, the furnace test in tests/test_gi.c).
 */
static zr_rgb indirect_light(const zr_tracer *tr, const surface *s,
                             zr_rgb c, double opacity) {
  const zr_finish *f = s->finish;
  zr_rgb e;
  if (!tr->indirect || !(f->diffuse > 0.0) || !(opacity > 0.0))
    return zr_rgb3(0, 0, 0);
  zr_indirect_query q;
  q.p = s->p;
  q.n = s->n;
  q.n_geo = s->ng;
  q.path = s->path;
  q.object = s->object;
  q.reflectance = zr_rgb_scale(c, f->diffuse * opacity);
  /* The model's own rays do not make the pixel clear (+UA). */
  zr_tracer opaque;
  if (tr->clear) {
    opaque = *tr;
    opaque.clear = NULL;
    tr = &opaque;
  }
  if (!tr->indirect->irradiance(tr->indirect, tr, &q, &e))
    return zr_rgb3(0, 0, 0);
  return zr_rgb_scale(zr_rgb_mul(e, c), f->diffuse * opacity);
}

/* The caustics the photon map brings to s, lit as a light source's
   diffuse light is (lib/trace/photons.c); objects with collect off get
   none. */
static zr_rgb photon_light(const zr_tracer *tr, const surface *s,
                           zr_rgb c, double opacity) {
  const zr_finish *f = s->finish;
  const zr_photon_object *po = s->object->photons;
  if (!tr->scene->photons || (po && !po->collect) || !(f->diffuse > 0.0) ||
      !(opacity > 0.0))
    return zr_rgb3(0, 0, 0);
  zr_rgb e = zr__photons_gather(tr->scene->photons, s->p, s->n,
                                f->brilliance);
  return zr_rgb_scale(zr_rgb_mul(e, c), f->diffuse * opacity);
}

/* The pigment's colour at p, or its quick_color at +Q5 and below. */
static zr_colour pigment_colour(const zr_tracer *tr, const zr_pigment *pg,
                                zr_vec3 p, zr_vec3 n) {
  if (tr->quick_colours && pg->has_quick)
    return pg->quick;
  return zr__pigment_eval_n(pg, p, n);
}

static zr_rgb shade(const zr_tracer *tr, const surface *s, int level,
                    double weight, const zr_media *media) {
  if (tr->flat) /* +Q0, +Q1: the colour as it is */
    return zr_colour_rgb(s->colour);
  const zr_finish *f = s->finish;
  const zr_settings *gs = &tr->scene->settings;
  zr_colour col = s->colour;
  zr_rgb c = zr_colour_rgb(col);
  /* Not clamped: transmit above 1 makes the surface's own colour count
     negatively, a contrast trick POV-Ray 3.7 renders (advanced/
     bwstripe.pov: rgb 0.5 transmit 100 before the camera). */
  double opacity = 1.0 - col.f - col.t;

  zr_rgb sum;
  zr_rgb diffuse_in;
  if (tr->radiosity &&
      tr->radiosity->radiance(tr->radiosity, s->object, s->p, s->d,
                              &diffuse_in)) {
    /* The solution's radiance already includes the pigment. */
    sum = zr_rgb_scale(diffuse_in, opacity);
    /* A sky-only cache beside it adds the light of the sky, which the
       solution does not carry. */
    sum = zr_rgb_add(sum, indirect_light(tr, s, c, opacity));
  } else if (tr->indirect) {
    /* POV-Ray 3.7 drops ambient under radiosity in scenes that declare
       #version 3.7 (measured: zr_settings.version_given); emission
       stays, and the gathered light replaces ambient. */
    zr_rgb own = f->emission;
    if (tr->skip_sampled_emission && tr->indirect->samples_emission &&
        tr->indirect->samples_emission(tr->indirect, s->object))
      own = zr_rgb3(0, 0, 0); /* the path tracer sampled it already */
    if (!gs->version_given || gs->version < 3.7)
      own = zr_rgb_add(own, zr_rgb_mul(f->ambient, gs->ambient_light));
    sum = zr_rgb_scale(zr_rgb_mul(own, c), opacity);
    sum = zr_rgb_add(sum, indirect_light(tr, s, c, opacity));
  } else {
    zr_rgb own = zr_rgb_add(zr_rgb_mul(f->ambient, gs->ambient_light),
                            f->emission);
    sum = zr_rgb_scale(zr_rgb_mul(own, c), opacity);
  }
  /* A pretrace wants the cache filled, not the camera's colours: the
     light sources' direct light at what the camera sees is left out
     (POV-Ray's -RVP, "Radiosity Vain Pretrace" off). */
  if (!(tr->skip_direct && tr->gi_depth == 0)) {
    sum = zr_rgb_add(sum, direct_light(tr, s, opacity, media));
    sum = zr_rgb_add(sum, photon_light(tr, s, c, opacity));
  }

  /* The indices of refraction on this side (n1) and beyond (n2). */
  zr_rgb trans = s->layer ? zr_rgb3(0, 0, 0) : see_through(col);
  /* The path beyond the surface and the two iors serve Fresnel's law
     and the rays through the surface: an opaque surface with a plain
     reflection (most, the sphereflake's all) needs neither, and
     zr__media_cross, asked for every hit, cost ~110 instructions there
     (callgrind, sphereflake 512^2).  A surface that lets nothing
     through (every channel exactly 0, and no conserve_energy to scale
     it) spawns no transmitted ray below, whatever the path. */
  bool opaque = trans.r == 0.0 && trans.g == 0.0 && trans.b == 0.0 &&
                !f->conserve_energy;
  zr_media next;
  double n1 = 1.0, n2 = 1.0;
  /* The interiors on this side and beyond, when either disperses. */
  const zr_interior *in1 = NULL, *in2 = NULL;
  bool dispersing = false;
  if (opaque && !f->reflection_fresnel) {
    next.n = next.passes = 0;
  } else {
    media_beyond(tr, s, media, &next);
    n1 = zr__media_ior(media);
    n2 = zr__media_ior(&next);
    in1 = media && media->n > 0 ? media->interiors[media->n - 1] : NULL;
    in2 = next.n > 0 ? next.interiors[next.n - 1] : NULL;
    dispersing = zr__disperses(in1) || zr__disperses(in2);
    /* A ray of one colour of a spectrum sees that colour's iors, for
       Fresnel's law too. */
    if (dispersing && tr->dispersed) {
      n1 = zr__dispersed_ior(in1, tr->dispersion_u);
      n2 = zr__dispersed_ior(in2, tr->dispersion_u);
    }
  }
  /* Where a ray goes out of an interior and its path still holds
     another (a glass inside a hollow sky sphere, a solid plane or any
     object the camera is in), povray 3.7 reflects no Fresnel share:
     reflection { 0, 1 fresnel } spawns no ray there and
     reflection { 0.1, 1 fresnel } reflects 0.1, whatever the ior
     beyond, 1 or 1.2, while the refracted ray bends by n1 / n2 and
     total internal reflection is as anywhere.  Entering, and going out
     into the open, reflect by Fresnel's law (tests/exit_fresnel.pov,
     tests/test_exit_fresnel.sh; advanced/glasschess.pov, whose camera
     is inside two sky spheres). */
  bool out_within = media && next.n > 0 && next.n < media->n;
  zr_rgb refl = reflection_amount(s, n1, out_within ? n1 : n2);
  if (f->conserve_energy)
    trans = zr_rgb3(trans.r * (1.0 - refl.r), trans.g * (1.0 - refl.g),
                    trans.b * (1.0 - refl.b));
  /* A model's sample rays carry the bailout of its block (zr_tracer). */
  double bailout = tr->bailout > 0.0 ? tr->bailout : gs->adc_bailout;
  zr_vec3 mirror = zr__reflect(s->d, s->n);
  /* A normal tilted by normal { } can mirror a grazing ray into the
     surface; the ray is then turned back out of it, mirrored in the
     geometric surface (templates/Basic_Scenes/Sea_blue_sky.pov: bumps
     on a chrome plane seen at a grazing angle showed black specks
     where povray 3.7 shows the sky). */
  double into = zr_v3_dot(mirror, s->ng);
  if (into < 0.0)
    mirror = zr_v3_madd(mirror, s->ng, -2.0 * into);
  zr_vec3 above = zr_v3_madd(s->p, s->n, s->offset);
  zr_vec3 below = zr_v3_madd(s->p, s->n, -s->offset);
  zr_vec3 refr_dir = s->d;
  if (rgb_max(trans) > 0.0 && n1 != n2 &&
      !zr__refract(s->d, s->n, n1 / n2, &refr_dir)) {
    /* Total internal reflection.  POV-Ray 3.7 then returns the mirrored
       ray's colour at full strength in place of both the reflected and
       the transmitted light (measured: a surface with transmit 0.2 and
       reflection 0 or 0.3, or filter 0.5 on a coloured pigment, shows
       the mirrored scene untinted at weight 1), yet for adaptive depth
       control the ray weighs what the transmitted one would have: in a
       glass box with filter 0.3 on a colour whose largest component is
       0.8, adc_bailout 0.05 stops the bouncing after three faces. */
    double tw = weight * rgb_max(trans);
    if (!(tw > bailout))
      return sum;
    if (tr->no_transmitted)
      return sum;
    tr->stats->reflected_rays++;
    zr_tracer rt = reflecting(tr);
    zr_rgb r = trace_secondary(&rt, ray_start(s, above, mirror), mirror,
                               level, tw, media);
    if (s->leaving)
      r = fade_by(s->leaving, s->stretch, r);
    return zr_rgb_add(sum, r);
  }

  double rw = weight * rgb_max(refl);
  if (rgb_max(refl) > 0.0 && rw > bailout && !tr->no_reflected &&
      !(s->layer && s->tir_below)) {
    tr->stats->reflected_rays++;
    zr_tracer rt = reflecting(tr);
    zr_rgb r = trace_secondary(&rt, ray_start(s, above, mirror), mirror,
                               level, rw, media);
    if (f->reflection_exponent != 1.0) {
      double k = 1.0 / f->reflection_exponent;
      r = zr_rgb3(pow(fmax(r.r, 0.0), k), pow(fmax(r.g, 0.0), k),
                  pow(fmax(r.b, 0.0), k));
    }
    sum = zr_rgb_add(sum, zr_rgb_mul(refl, r));
  }
  /* A negative transmit is traced too: the surface then shows its own
     colour less what is behind it (povray 3.7, textures/pigments/
     transmitfx.pov: rgb 0.5 transmit -1 with ambient 1 shows 1 - C of
     the scene behind; tests/test_negative_transmit.sh). */
  double tw = weight * rgb_absmax(trans);
  if (rgb_absmax(trans) > 0.0 && tw > bailout && !tr->no_transmitted) {
    /* A ray that goes on unbent is not a new trace level (ZR_PASS_MAX),
       but like any secondary ray it is only spawned below the last
       level. */
    int next_level = level;
    if (n1 == n2) {
      next_level = level - 1;
      next.passes++;
    }
    tr->stats->refracted_rays++;
    if (next.passes <= ZR_PASS_MAX && level < gs->max_trace_level) {
      /* +UA: the background beyond is clear by grey(f C + t) of it. */
      zr_tracer buf;
      const zr_tracer *ttr = clear_scaled(tr, zr__grey(trans), &buf);
      zr_rgb t = dispersing && !tr->dispersed
                     ? dispersed(ttr, s, in1, in2, above, below, mirror,
                                 next_level, tw, media, &next)
                     : trace_secondary(ttr, ray_start(s, below, refr_dir),
                                       refr_dir, next_level, tw, &next);
      /* Leaving a fading interior, only the light that comes through is
         faded, by the stretch the ray travelled inside: povray 3.7.0.10
         fades neither the surface's own light nor its reflection there
         (a clear slab of fade_distance 1 and fade_power 1001, reflection
         0.5, max_trace_level 4, reflects the background into the camera
         faded once, by e^-1 for the 2 units of its way inside, and in a
         wedge by the stretch after the reflection; transmit 0.5 with
         emission 1 shows the back face's own light unfaded: tests/
         test_exit_fade.sh). */
      if (s->leaving)
        t = fade_by(s->leaving, s->stretch, t);
      sum = zr_rgb_add(sum, zr_rgb_mul(trans, t));
    }
  }
  return sum;
}

/*
 * The geometric normal n perturbed by nm at p, before the caller turns
 * it towards the viewer when the ray leaves the surface.  A normal
 * tilts on the viewer's side: POV-Ray 3.7 renders a grey ramp on
 * "plane { z, 0 }" and on "plane { -z, 0 }" seen from -z with the same
 * normal, for a bump map and for a pattern (gradient x tilts the same
 * way seen from either side: bench/conform/normal_probe.sh), so the
 * tilt must not turn with n.
 */
static zr_vec3 perturbed(const zr_normal *nm, zr_vec3 p, zr_vec3 n,
                         bool entering) {
  if (!entering)
    return zr_v3_neg(zr__normal_perturb(nm, p, zr_v3_neg(n)));
  return zr__normal_perturb(nm, p, n);
}

#define MAX_LAYERS 64

static zr_rgb shade_layers(const zr_tracer *tr, const surface *s,
                           zr_vec3 n_geo, const zr_texture *tx, int level,
                           double weight, const zr_media *media);

/*
 * One layer of a texture: a plain one shaded with its own pigment,
 * finish and normal (an upper layer without transmission), a patterned
 * one as the blend of its map's textures' lit colours ("Texture Maps").
 */
static zr_rgb shade_layer(const zr_tracer *tr, const surface *s,
                          zr_vec3 n_geo, const zr_texture *tx, bool upper,
                          int level, double weight, const zr_media *media) {
  if (tx->map && tx->pattern.kind == ZR_PAT_AVERAGE) {
    /* Every entry's lit colour, mixed by its weight ("Average"). */
    surface ls = *s;
    ls.layer = upper;
    zr_rgb sum = zr_rgb3(0, 0, 0);
    double total = 0;
    for (size_t i = 0; i < tx->map->n; i++)
      total += tx->map->entries[i].value;
    if (total <= 0)
      return sum;
    for (size_t i = 0; i < tx->map->n; i++) {
      double w = tx->map->entries[i].value / total;
      zr_tracer buf;
      sum = zr_rgb_add(sum, zr_rgb_scale(
                                shade_layers(clear_scaled(tr, w, &buf), &ls,
                                             n_geo,
                                             tx->map->entries[i].u.texture,
                                             level, weight * w, media),
                                w));
    }
    return sum;
  }
  if (tx->map) {
    const zr_texture *b;
    double t;
    /* The slope pattern picks by the normal on the viewer's side (povray
       3.7 renders a plane seen from its back with the normal turned). */
    zr_vec3 facing = s->entering ? n_geo : zr_v3_neg(n_geo);
    surface ls = *s;
    const zr_texture *a = zr__texture_pick_n(
        tx, pattern_point(&ls, tx->uv_mapping), facing, &b, &t);
    ls.layer = upper;
    ls.uv_all = ls.uv_all || tx->uv_mapping;
    zr_tracer abuf, bbuf;
    zr_rgb c = shade_layers(clear_scaled(tr, b ? 1 - t : 1.0, &abuf), &ls,
                            n_geo, a, level, weight * (1 - t), media);
    if (!b)
      return c;
    return zr_rgb_add(
        zr_rgb_scale(c, 1 - t),
        zr_rgb_scale(shade_layers(clear_scaled(tr, t, &bbuf), &ls, n_geo, b,
                                  level, weight * t, media),
                     t));
  }
  surface ls = *s;
  zr_vec3 n = n_geo;
  bool uv = tx->uv_mapping;
  if (tx->normal)
    n = perturbed(tx->normal,
                  pattern_point(&ls, uv || tx->normal->uv_mapping), n,
                  s->entering);
  ls.n = s->entering ? n : zr_v3_neg(n);
  ls.finish = tx->finish;
  ls.colour = pigment_colour(
      tr, tx->pigment, pattern_point(&ls, uv || tx->pigment->uv_mapping),
      ls.n);
  ls.layer = upper;
  return shade(tr, &ls, level, weight, media);
}

/*
 * Whether the bottom layer of a layered texture lets light through at s
 * and the ray is totally reflected there.  The bottom layer then traces
 * the mirrored ray at full strength in place of its reflection and
 * transmission (shade()), and the upper layers trace no reflection of
 * their own: POV-Ray 3.7 counts one reflected ray per total internal
 * reflection under such a texture (a clear glass superellipsoid with
 * texture { pigment { rgbf 0.9 } } texture { Glass }: 72046 reflected
 * rays at 160x120, 76898 with the Glass layer alone; without this every
 * bounce inside spawned two rays of weight near 1, 7.45 million here),
 * and its picture is the one-layer picture a little lighter
 * (tests/layer_tir.sh; advanced/glasschess.pov).
 */
static bool total_inside(const zr_tracer *tr, const surface *s,
                         const zr_texture *bottom, const zr_media *media) {
  surface us = *s;
  zr_vec3 at = pattern_point(&us, bottom->uv_mapping ||
                                      bottom->pigment->uv_mapping);
  if (!(rgb_max(zr__texture_see_through_layer(bottom, at)) > 0.0))
    return false;
  zr_media next;
  media_beyond(tr, s, media, &next);
  double n1 = zr__media_ior(media), n2 = zr__media_ior(&next);
  zr_vec3 dir;
  return n1 != n2 && !zr__refract(s->d, s->ng, n1 / n2, &dir);
}

/*
 * A layered texture ("Layered Textures"): from the top layer down, each
 * adds its own light, and the layers below show through its filter and
 * transmit (f * C + t), which tint everything under them; only the
 * bottom layer lets light through the surface.  A texture upper in the
 * chain of a layer that is itself upper (s->layer) passes nothing.
 */
static zr_rgb shade_layers(const zr_tracer *tr, const surface *s,
                           zr_vec3 n_geo, const zr_texture *tx, int level,
                           double weight, const zr_media *media) {
  const zr_texture *layers[MAX_LAYERS];
  int n = 0;
  /* +Q0, +Q1 show the bottom layer alone. */
  for (const zr_texture *l = tx; l && n < (tr->flat ? 1 : MAX_LAYERS);
       l = l->over)
    layers[n++] = l;
  surface base = *s;
  if (n > 1 && !s->layer)
    base.tir_below = total_inside(tr, s, layers[0], media);
  zr_rgb sum = zr_rgb3(0, 0, 0);
  zr_rgb through = zr_rgb3(1, 1, 1);
  for (int i = n - 1; i >= 0; i--) {
    bool upper = i > 0 || s->layer;
    zr_tracer buf;
    zr_rgb c = shade_layer(clear_scaled(tr, zr__grey(through), &buf), &base,
                           n_geo, layers[i], upper, level,
                           weight * rgb_max(through), media);
    sum = zr_rgb_add(sum, zr_rgb_mul(through, c));
    if (i == 0)
      break;
    surface us = *s;
    zr_vec3 at = pattern_point(&us, layers[i]->uv_mapping ||
                                        layers[i]->pigment->uv_mapping);
    const zr_pigment *pg = layers[i]->pigment;
    through = zr_rgb_mul(
        through, !layers[i]->map && tr->quick_colours && pg->has_quick
                     ? see_through(pg->quick) /* +Q5 and below */
                     : zr__texture_see_through_layer(layers[i], at));
    if (rgb_max(through) <= 0.0)
      break;
  }
  return sum;
}

/*
 * A blob whose components have textures of their own ("Blob"): the lit
 * colour of each texture, weighted by its components' fields at the
 * point, as measured on POV-Ray 3.7's renders (two spheres' pigments
 * blend in the proportion of their fields where they overlap).  A
 * component without a texture takes the blob's; components whose field
 * is not positive there take no part.  Components that share a texture
 * are shaded once, with their fields added.
 */
#define MAX_BLOB_TEXTURES 16

static zr_rgb shade_blob(const zr_tracer *tr, const surface *s,
                         zr_vec3 n_geo, const zr_object *o, int level,
                         double weight, const zr_media *media) {
  zr_vec3 q = o->transform ? zr__xform_point(o->transform->inv, s->p)
                           : s->p;
  const zr_texture *tex[MAX_BLOB_TEXTURES];
  double w[MAX_BLOB_TEXTURES];
  int n = 0;
  double total = 0.0;
  for (size_t i = 0; i < o->u.blob.n_components; i++) {
    double f = zr__blob_component_density(o, i, q);
    if (!(f > 0.0))
      continue;
    const zr_texture *t = o->u.blob.components[i].texture;
    if (!t)
      t = o->texture;
    int k = 0;
    while (k < n && tex[k] != t)
      k++;
    if (k == n) {
      if (n == MAX_BLOB_TEXTURES)
        k = MAX_BLOB_TEXTURES - 1; /* more than that overlap: rare */
      else
        tex[n++] = t, w[k] = 0.0;
    }
    w[k] += f;
    total += f;
  }
  if (n == 0) /* on the surface some field is positive; rounding */
    return shade_layers(tr, s, n_geo, o->texture, level, weight, media);
  zr_rgb sum = zr_rgb3(0, 0, 0);
  for (int k = 0; k < n; k++) {
    double share = w[k] / total;
    zr_tracer buf;
    sum = zr_rgb_add(sum, zr_rgb_scale(shade_layers(clear_scaled(tr, share,
                                                                 &buf),
                                                    s, n_geo, tex[k],
                                                    level, weight * share,
                                                    media),
                                       share));
  }
  return sum;
}

/* The nearest hit of an object the ray may see (zr_tracer.hide). */
static bool nearest_shown(const zr_tracer *tracer, const zr_ray *ray,
                          double tmax, zr_hit *hit) {
  double from = 0.0;
  for (;;) {
    if (!zr__bvh_nearest(tracer->scene->bvh, ray, from, tmax, hit))
      return false;
    const zr_object *o = hit->object;
    bool hidden = ((tracer->hide & ZR_HIDE_IMAGE) && o->no_image) ||
                  ((tracer->hide & ZR_HIDE_REFLECTION) && o->no_reflection);
    if (!hidden)
      return true;
    from = nextafter(hit->t, INFINITY);
  }
}

/*
 * What the media, fog and fading between a ray's origin and t along it
 * let through of what lies beyond, as a grey share (+UA): the way is
 * affine in the colour behind, so the share is the grey of what it makes
 * of white less what it makes of black.
 */
static double clear_along(const zr_tracer *tracer, const zr_media *media,
                          const zr_ray *ray, double t,
                          const zr_interior *fade) {
  zr_rgb ends[2];
  for (int k = 0; k < 2; k++) {
    zr_rgb c = zr_rgb3(k, k, k);
    c = zr__media_along(tracer, media, ray->origin, ray->dir, t, c);
    c = zr__atmosphere_apply(tracer->scene, ray->origin, ray->dir, t, c);
    c = fade_by(fade, t * zr_v3_len(ray->dir), c);
    ends[k] = c;
  }
  return zr__grey(zr_rgb3(ends[1].r - ends[0].r, ends[1].g - ends[0].g,
                          ends[1].b - ends[0].b));
}

/* Scales what a surface's shading added to the pixel's clear share
   since before by what the way to the surface lets through (+UA). */
static void clear_through_way(const zr_tracer *tracer, double before,
                              const zr_media *media, const zr_ray *ray,
                              double t, const zr_interior *fade) {
  double added = *tracer->clear - before;
  if (added != 0.0)
    *tracer->clear =
        before + added * clear_along(tracer, media, ray, t, fade);
}

/* What zr__trace_ray() sees, with the first surface looked for only up
   to tmax along the ray (a mesh camera's max_distance); beyond it the
   ray sees the background, as in povray. */
/* Fog and rainbows along a ray, unless the ray runs inside a solid
   (not hollow) object: the manual's "Empty and Solid Objects" leaves
   "no room for any other particles like those used by fog" there, and
   povray renders a plane seen from inside a solid plane unfogged and
   from inside the same plane made hollow fogged
   (tests/test_fog_povray.sh). */
static zr_rgb fogged(const zr_tracer *tracer, const zr_media *media,
                     zr_vec3 origin, zr_vec3 dir, double t, zr_rgb c) {
  const zr_scene *scene = tracer->scene;
  /* zr__atmosphere_apply's own first test, without the call (passing
     the vectors cost ~50 instructions a ray where nothing was done). */
  if ((!scene->settings.fogs && !scene->settings.rainbows) ||
      tracer->no_fog)
    return c;
  for (int i = 0; media && i < media->n; i++)
    if (!media->objects[i]->hollow)
      return c;
  return zr__atmosphere_apply(scene, origin, dir, t, c);
}

/* Whether zr__media_along returns the colour it is given at once: no
   media on the ray's path nor in the atmosphere, or none wanted. */
static inline bool no_media_along(const zr_tracer *tracer,
                                  const zr_media *inside) {
  return tracer->no_media || ((!inside || inside->n == 0) &&
                              tracer->scene->settings.n_media == 0);
}

static zr_rgb trace_upto(const zr_tracer *tracer, const zr_ray *ray,
                         int level, double weight, const zr_media *media,
                         double tmax, double *t_hit) {
  const zr_scene *scene = tracer->scene;
  if (t_hit)
    *t_hit = INFINITY;
  if (level > scene->settings.max_trace_level)
    return zr_rgb3(0, 0, 0);
  zr_hit hit;
  bool found = nearest_shown(tracer, ray, tmax, &hit);
  if (found && t_hit)
    *t_hit = hit.t;
  if (!found) {
    /* Atmospheric media reach as far as lib/trace/media.c takes them
       along a ray that meets nothing. */
    double clear = 0.0;
    zr_rgb sky = tracer->clear ? zr__sky_clear(scene, ray->dir, &clear)
                               : zr__sky_colour(scene, ray->dir);
    if (clear > 0.0)
      *tracer->clear += tracer->clear_weight * clear *
                        clear_along(tracer, media, ray, INFINITY,
                                    media && media->n > 0
                                        ? media->interiors[media->n - 1]
                                        : NULL);
    sky = zr__media_along(tracer, media, ray->origin, ray->dir, INFINITY,
                          sky);
    return zr__interior_fade(media, INFINITY,
                         fogged(tracer, media, ray->origin, ray->dir,
                                              INFINITY, sky));
  }
  surface s;
  s.p = zr_v3_madd(ray->origin, ray->dir, hit.t);
  s.d = zr_v3_norm(ray->dir);
  s.entering = zr_v3_dot(hit.normal, s.d) < 0.0;
  s.ng = s.entering ? hit.normal : zr_v3_neg(hit.normal);
  s.path = tracer->path + hit.t * zr_v3_len(ray->dir);
  s.uv_all = hit.object->uv_mapping;
  s.uv_known = false;
  s.leaving = NULL;
  s.stretch = 0.0;
  s.hu = hit.u;
  s.hv = hit.v;
  zr_vec3 n = hit.normal;
  const zr_texture *tx = hit.object->texture;
  /* interior_texture: the inside (back) of the surface ("Interior
     Texture"). */
  if (!s.entering && hit.object->interior_texture)
    tx = hit.object->interior_texture;
  bool blob = hit.object->kind == ZR_OBJ_BLOB &&
              hit.object->u.blob.textured && tx == hit.object->texture;
  if ((tx->over || tx->map || blob) && !tracer->radiosity_only) {
    s.object = hit.object;
    s.offset = zr__surface_offset(s.p);
    s.layer = false;
    s.tir_below = false;
    double before = tracer->clear ? *tracer->clear : 0.0;
    zr_rgb c = blob ? shade_blob(tracer, &s, n, hit.object, level, weight,
                                 media)
                    : shade_layers(tracer, &s, n, tx, level, weight, media);
    if (tracer->clear)
      clear_through_way(tracer, before, media, ray, hit.t, NULL);
    c = zr__media_along(tracer, media, ray->origin, ray->dir, hit.t, c);
    return fogged(tracer, media, ray->origin, ray->dir, hit.t, c);
  }
  s.object = hit.object;
  bool uv = tx->uv_mapping;
  if (tx->normal) /* normal { }: lib/scene/texture.c */
    n = perturbed(tx->normal,
                  pattern_point(&s, uv || tx->normal->uv_mapping), n,
                  s.entering);
  s.n = s.entering ? n : zr_v3_neg(n);
  s.finish = tx->finish;
  s.colour = pigment_colour(
      tracer, tx->pigment, pattern_point(&s, uv || tx->pigment->uv_mapping),
      s.n);
  s.offset = zr__surface_offset(s.p);
  s.layer = false;
  s.tir_below = false;
  if (tracer->radiosity_only) {
    zr_rgb l;
    if (!tracer->radiosity ||
        !tracer->radiosity->radiance(tracer->radiosity, s.object, s.p, s.d,
                                     &l))
      l = zr_rgb3(0, 0, 0); /* no surface in the solution: black */
    return l;
  }
  /* The fading of the interior the ray leaves here, which shade()
     applies to the light transmitted out only, and media, fog and
     rainbows between the ray's origin and the hit. */
  const zr_interior *fade = stretch_interior(scene, media, hit.object);
  if (fade && fade->fade_distance != 0.0) {
    s.leaving = fade;
    s.stretch = hit.t * zr_v3_len(ray->dir);
  }
  double before = tracer->clear ? *tracer->clear : 0.0;
  zr_rgb lit = shade(tracer, &s, level, weight, media);
  if (tracer->clear)
    clear_through_way(tracer, before, media, ray, hit.t, fade);
  /* zr__media_along's and fade_by's first tests written here: most
     rays of most scenes cross no media and leave no fading interior,
     and the calls cost as much as the rest of this function's own
     work (~60 instructions a ray; callgrind, sphereflake 512^2). */
  zr_rgb c = no_media_along(tracer, media)
                 ? lit
                 : zr__media_along(tracer, media, ray->origin, ray->dir,
                                   hit.t, lit);
  return fogged(tracer, media, ray->origin, ray->dir, hit.t, c);
}

zr_rgb zr__trace_ray(const zr_tracer *tracer, const zr_ray *ray, int level,
                     double weight, const zr_media *media) {
  return trace_upto(tracer, ray, level, weight, media, INFINITY, NULL);
}

zr_rgb zr__trace_ray_hit(const zr_tracer *tracer, const zr_ray *ray,
                         int level, double weight, const zr_media *media,
                         double *t_hit) {
  return trace_upto(tracer, ray, level, weight, media, INFINITY, t_hit);
}

zr_rgb zr__trace_camera_ray_within(const zr_tracer *tracer,
                                   const zr_ray *ray, double distance,
                                   const zr_media *media) {
  double len = zr_v3_len(ray->dir);
  return trace_upto(tracer, ray, 1, 1.0, media,
                    len > 0.0 ? distance / len : INFINITY, NULL);
}
