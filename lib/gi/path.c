/*
 * path.c - the path-traced reference (--gi=path, issue 11): an unbiased
 * Monte Carlo estimate of the image the other models of global
 * illumination approximate, so that their error can be measured
 * without an outside renderer.
 *
 * The estimator is Kajiya's rendering equation (Kajiya 1986) solved
 * for the lighting model the tracer implements, not for a physically
 * based one: a path tracer that used its own materials would be the
 * ground truth of another scene.  Each camera sample is traced by the
 * tracer (lib/trace/shade.c) with this file as its indirect-light
 * model (zr_indirect), and each finish term keeps the meaning it has
 * under POV-Ray's radiosity:
 *   - diffuse (times the pigment and the opacity) reflects the light
 *     arriving from every direction, cosine-weighted: this is the term
 *     the path tracer samples, one ray a bounce, drawn with density
 *     cos / pi about the shading normal, so that the ray's radiance is
 *     itself the estimate of the mean radiance (irradiance / pi) that
 *     the tracer multiplies by diffuse * pigment;
 *   - brilliance, crand, phong, specular and metallic shape the light
 *     of light sources only, as in POV-Ray (a highlight is the image of
 *     a point light; POV-Ray's radiosity gathers no highlight of an
 *     emitting surface): they stay the tracer's, evaluated exactly at
 *     every vertex of the path, and so the cache, the hierarchical
 *     solution and this estimate all model them alike;
 *   - reflection and refraction (transmit, filter, ior, fresnel) are
 *     followed by the tracer's own mirror and refracted rays at every
 *     vertex, up to max_trace_level and adc_bailout as the scene says;
 *   - light sources (point, spot, cylinder, area) are the tracer's
 *     direct light at every vertex (next-event estimation); an area
 *     light, which the manual defines as a grid of point lights, shines
 *     from one point of its grid picked at random (jittered as the
 *     scene says), an unbiased estimate of the grid's mean where the
 *     tracer samples the grid adaptively at camera hits and from its
 *     centre for an irradiance cache's rays (lib/trace/lights.c);
 *   - emission (times the pigment and the opacity) is light the surface
 *     sends from either side, as the tracer shows it; under a scene
 *     without "#version 3.7" ambient * ambient_light counts as emission
 *     too, as POV-Ray's radiosity treats it (lib/trace/shade.c);
 *     finish { energy } is not counted here (it is the hierarchical
 *     solver's own source, given as a power): zr_path_new warns;
 *   - the sky_sphere and the background are what a ray that escapes
 *     sees, so they light the scene;
 *   - the rays that gather light pass through fog unchanged, and
 *     through media unchanged unless the radiosity block has media on,
 *     as povray's radiosity rays do and as the other models do (the
 *     camera's rays keep both): in a closed room lit by an emitting
 *     panel, a black fog of distance 3 leaves 0.488 of the floor's
 *     linear light in povray's picture and in the hierarchical
 *     solution's, and left 0.123 here while gathering rays were fogged
 *     (tests/test_gi_room.sh).
 * Emitting triangles are also sampled directly at each diffuse vertex
 * (next-event estimation, Shirley's area sampling: a triangle picked
 * with probability proportional to its area times its emission, a point
 * uniform on it, weighed by cos * cos' / d^2 over the density), and the
 * ray shot from that vertex then leaves their emission out at its
 * first hit (zr_tracer.skip_sampled_emission), so each path is counted
 * once.  Only triangles whose emission is the same function at both
 * ends are sampled: a plain texture with no normal, no uv mapping, not
 * clipped or part of a CSG solid, in a scene whose gathering rays cross
 * no media (which the sampled segment would skip); any other emitter
 * is found by the rays that hit it.
 *
 * Paths are unbiased up to a length of MAX_BOUNCES diffuse bounces;
 * from RR_START on, a path goes on with probability q = min(0.9, the
 * surface's largest reflectance) and its light is divided by q
 * (Russian roulette, Arvo and Kirk 1990).  What the cut leaves out is
 * the light of paths longer than MAX_BOUNCES, at most rho^MAX_BOUNCES
 * of the total for reflectance rho (1e-8 for rho = 0.75).
 *
 * Every random number of sample k of pixel p is a hash of (seed, p, k,
 * n), n counting the numbers the sample has drawn so far, so the image
 * depends on nothing but the scene and the samples asked for: the same
 * bytes for any rank or thread count, and samples may be taken in
 * pieces (progressive rendering).  The sample positions are uniform
 * over the pixel (a box filter), so no antialiasing pass is needed.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/context.h"
#include "gi/gi.h"
#include "radiosity/radiosity.h"
#include "scene/texture.h"
#include "trace/bvh.h"
#include "trace/render.h"

/* See the essay above. */
#define RR_START 3
#define MAX_BOUNCES 64

/* An emitting triangle, in world space. */
typedef struct path_emitter {
  const zr_object *object;
  zr_vec3 p0, e1, e2; /* p0 + a e1 + b e2, a, b >= 0, a + b <= 1 */
  zr_vec3 n;          /* unit, (e1 x e2) */
  double area;
  double cdf;         /* cumulative selection weight, the last is 1 */
} path_emitter;

struct zr_path {
  const zr_scene *scene;
  zr_path_params params;
  path_emitter *emitters;
  size_t n_emitters;
  double total_weight; /* sum of area * largest emission channel */
  zr_indirect indirect; /* the provider; scratch set per sample */
  bool media; /* the radiosity block has media on: gathering rays see
                 media (manual, "Media and Radiosity") */
};

/* One camera sample's random stream. */
typedef struct path_sample {
  uint64_t key;
  uint64_t drawn;
  uint64_t rays;
} path_sample;

static uint64_t mix64(uint64_t z) {
  /* The splitmix64 finaliser (Steele, Lea and Flood 2014). */
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
  return z ^ (z >> 31);
}

static double next_uniform(path_sample *s) {
  uint64_t h = mix64(s->key + 0x9e3779b97f4a7c15u * ++s->drawn);
  return (double)(h >> 11) * (1.0 / 9007199254740992.0);
}

static double path_uniform(const zr_indirect *self) {
  return next_uniform(self->scratch);
}

static double rgb_max(zr_rgb c) { return fmax(c.r, fmax(c.g, c.b)); }

static bool positive(zr_rgb c) { return c.r > 0.0 || c.g > 0.0 || c.b > 0.0; }

/* Whether the emission of o is sampled directly (see the essay). */
static bool samplable(const zr_object *o) {
  const zr_texture *tx = o->texture;
  if (o->kind != ZR_OBJ_TRIANGLE || !tx || o->solid || o->clip)
    return false;
  if (tx->over || tx->map || tx->normal || !tx->finish || !tx->pigment ||
      o->interior_texture || o->uv_mapping || tx->uv_mapping ||
      tx->pigment->uv_mapping)
    return false;
  return positive(tx->finish->emission);
}

static bool path_samples_emission(const zr_indirect *self,
                                  const zr_object *object) {
  const zr_path *pt = self->provider;
  return pt->n_emitters > 0 && samplable(object);
}

/* The emitter the number u picks (binary search of the cdf). */
static const path_emitter *pick(const zr_path *pt, double u) {
  size_t lo = 0, hi = pt->n_emitters - 1;
  while (lo < hi) {
    size_t mid = (lo + hi) / 2;
    if (pt->emitters[mid].cdf > u)
      hi = mid;
    else
      lo = mid + 1;
  }
  return &pt->emitters[lo];
}

/*
 * Next-event estimation of the emitting triangles' light at a vertex:
 * an estimate of (1 / pi) * the integral over their points y of
 * L_e(y) cos cos' / d^2, with L_e the radiance the tracer gives y
 * (emission * pigment * opacity).  The shadow test is the same
 * nearest-hit query the gathering ray makes, so the two estimators
 * split the paths between them exactly.
 */
static zr_rgb sample_emitters(const zr_path *pt, const zr_tracer *tracer,
                              path_sample *st, zr_vec3 origin, zr_vec3 n) {
  const path_emitter *e = pick(pt, next_uniform(st));
  double a = next_uniform(st), b = next_uniform(st);
  if (a + b > 1.0) {
    a = 1.0 - a;
    b = 1.0 - b;
  }
  zr_vec3 y = zr_v3_add(e->p0, zr_v3_add(zr_v3_scale(e->e1, a),
                                         zr_v3_scale(e->e2, b)));
  zr_vec3 to = zr_v3_sub(y, origin);
  double d2 = zr_v3_dot(to, to);
  if (!(d2 > 0.0))
    return zr_rgb3(0, 0, 0);
  double d = sqrt(d2);
  zr_vec3 w = zr_v3_scale(to, 1.0 / d);
  double cos_x = zr_v3_dot(n, w);
  double cos_y = zr_v3_dot(e->n, w);
  if (!(cos_x > 0.0) || cos_y == 0.0)
    return zr_rgb3(0, 0, 0);
  zr_ray ray = {origin, to};
  zr_hit hit;
  st->rays++;
  tracer->stats->shadow_rays++;
  if (!zr__bvh_nearest(tracer->scene->bvh, &ray, 0.0, INFINITY, &hit) ||
      hit.object != e->object)
    return zr_rgb3(0, 0, 0);
  const zr_texture *tx = e->object->texture;
  /* The normal facing the arriving ray, as the tracer evaluates the
     pigment (the slope pattern reads it). */
  zr_vec3 facing = cos_y > 0.0 ? zr_v3_neg(e->n) : e->n;
  zr_colour c = zr__pigment_eval_n(tx->pigment, y, facing);
  double opacity = 1.0 - c.f - c.t;
  zr_rgb le = zr_rgb_scale(zr_rgb_mul(tx->finish->emission, zr_colour_rgb(c)),
                           opacity);
  double select = e->area * rgb_max(tx->finish->emission) /
                  pt->total_weight; /* probability of this triangle */
  double pdf = select / e->area;   /* per unit area */
  double g = cos_x * fabs(cos_y) / d2;
  return zr_rgb_scale(le, g / (pdf * M_PI));
}

/*
 * The tracer's question at a diffuse vertex: the mean radiance arriving
 * there (irradiance / pi), estimated by the emitters' sampled light and
 * one cosine-distributed ray.
 */
static bool path_irradiance(const zr_indirect *self, const zr_tracer *tracer,
                            const zr_indirect_query *q, zr_rgb *out) {
  const zr_path *pt = self->provider;
  path_sample *st = self->scratch;
  int d = tracer->gi_depth;
  if (!st || d >= MAX_BOUNCES)
    return false;
  double survive = 1.0;
  if (d >= RR_START) {
    survive = fmin(0.9, rgb_max(q->reflectance));
    if (!(survive > 0.0) || next_uniform(st) >= survive)
      return false;
  }
  zr_vec3 n = q->n;
  zr_vec3 origin = zr_v3_madd(q->p, q->n_geo, zr__surface_offset(q->p));
  if (zr_v3_dot(q->n_geo, n) < 0.0)
    origin = zr_v3_madd(q->p, n, zr__surface_offset(q->p));
  zr_rgb sum = zr_rgb3(0, 0, 0);
  if (pt->n_emitters > 0)
    sum = sample_emitters(pt, tracer, st, origin, n);

  double u = next_uniform(st), v = next_uniform(st);
  double r = sqrt(u), phi = 2.0 * M_PI * v;
  zr_vec3 t1, t2;
  zr_v3_frame(n, &t1, &t2); /* lib/core/vec.h */
  zr_vec3 dir = zr_v3_add(zr_v3_add(zr_v3_scale(t1, r * cos(phi)),
                                    zr_v3_scale(t2, r * sin(phi))),
                          zr_v3_scale(n, sqrt(fmax(0.0, 1.0 - u))));
  zr_tracer sub = *tracer;
  sub.indirect = self;
  sub.skip_direct = false;
  sub.skip_sampled_emission = pt->n_emitters > 0;
  sub.gi_depth = d + 1;
  sub.path = q->path;
  sub.hide = 0;
  /* The gathering ray is the reference for the models' sample rays and
     the hierarchical solver's transfer, and goes through what they go
     through: fog never dims it (povray's radiosity rays are not fogged,
     tests/test_gi_fog.sh and tests/test_gi_room.sh), media only where
     the radiosity block has media on. */
  sub.no_fog = true;
  sub.no_media = tracer->no_media || !pt->media;
  zr_ray ray = {origin, dir};
  st->rays++;
  sum = zr_rgb_add(sum, zr__trace_ray(&sub, &ray, 1, 1.0, NULL));
  *out = zr_rgb_scale(sum, 1.0 / survive);
  return true;
}

ZR_API void zr_path_params_init(zr_path_params *p) {
  if (!p)
    return;
  memset(p, 0, sizeof *p);
  p->seed = 0;
  p->light_sampling = 1;
}

static zr_status collect_emitters(zr_path *pt) {
  const zr_scene *scene = pt->scene;
  size_t n = 0;
  for (size_t i = 0; i < scene->n_primitives; i++)
    n += samplable(scene->primitives[i]);
  /* No sampled segments to emitters where something acts along a
     gathering ray between two surfaces, which such a segment would
     skip: media, when the radiosity block has media on (fog and
     rainbows never act on gathering rays). */
  if (n == 0 || !pt->params.light_sampling || zr__rad_media_counts(scene))
    return ZR_OK;
  pt->emitters = calloc(n, sizeof *pt->emitters);
  if (!pt->emitters)
    return ZR_ENOMEM;
  double total = 0.0;
  for (size_t i = 0; i < scene->n_primitives; i++) {
    const zr_object *o = scene->primitives[i];
    if (!samplable(o))
      continue;
    zr_vec3 p[3];
    for (int k = 0; k < 3; k++)
      p[k] = o->transform ? zr__xform_point(o->transform->m,
                                            o->u.triangle.p[k])
                          : o->u.triangle.p[k];
    path_emitter *e = &pt->emitters[pt->n_emitters];
    e->object = o;
    e->p0 = p[0];
    e->e1 = zr_v3_sub(p[1], p[0]);
    e->e2 = zr_v3_sub(p[2], p[0]);
    zr_vec3 c = zr_v3_cross(e->e1, e->e2);
    double len = zr_v3_len(c);
    if (!(len > 0.0) || !isfinite(len))
      continue; /* no area: rays never hit it either */
    e->n = zr_v3_scale(c, 1.0 / len);
    e->area = 0.5 * len;
    total += e->area * rgb_max(o->texture->finish->emission);
    e->cdf = total;
    pt->n_emitters++;
  }
  for (size_t i = 0; i < pt->n_emitters; i++)
    pt->emitters[i].cdf /= total;
  if (pt->n_emitters > 0)
    pt->emitters[pt->n_emitters - 1].cdf = 1.0;
  pt->total_weight = total;
  return ZR_OK;
}

static void warn_energy(zr_context *ctx, const zr_scene *scene) {
  for (size_t i = 0; i < scene->n_primitives; i++) {
    const zr_object *o = scene->primitives[i];
    for (const zr_texture *t = o->texture; t; t = t->over)
      if (t->finish && positive(t->finish->energy)) {
        zr_diag_place where;
        memset(&where, 0, sizeof where);
        where.file = o->where.file;
        where.line = o->where.line;
        where.column = o->where.column;
        (void)zr__diag(ctx, ZR_DIAG_WARNING, ZR_OK, &where,
                       "the path-traced reference does not count "
                       "finish { energy } (a power for the hierarchical "
                       "solver); give emission instead");
        return;
      }
  }
}

ZR_API zr_status zr_path_new(zr_context *ctx, const zr_scene *scene,
                             const zr_path_params *params, zr_path **out) {
  if (!out)
    return ZR_EINVAL;
  *out = NULL;
  if (!scene)
    return ZR_EINVAL;
  zr_path *pt = calloc(1, sizeof *pt);
  if (!pt)
    return ZR_ENOMEM;
  pt->scene = scene;
  pt->media = scene->settings.radiosity.on &&
              scene->settings.radiosity.media == 1;
  if (params)
    pt->params = *params;
  else
    zr_path_params_init(&pt->params);
  zr_status s = collect_emitters(pt);
  if (s != ZR_OK) {
    zr_path_free(pt);
    return s;
  }
  pt->indirect.irradiance = path_irradiance;
  pt->indirect.provider = pt;
  pt->indirect.scratch = NULL;
  pt->indirect.samples_emission = path_samples_emission;
  pt->indirect.next_uniform = path_uniform;
  if (ctx)
    warn_energy(ctx, scene);
  *out = pt;
  return ZR_OK;
}

ZR_API void zr_path_free(zr_path *path) {
  if (!path)
    return;
  free(path->emitters);
  free(path);
}

ZR_API size_t zr_path_emitters(const zr_path *path) {
  return path ? path->n_emitters : 0;
}

bool zr__path_for(const zr_path *path, const zr_scene *scene) {
  return path && path->scene == scene;
}

/* One camera sample through a point of the pixel (and of the lens). */
static zr_rgb camera_sample(const zr_tracer *tr, const zr_media *media,
                            const zr_render_params *params,
                            path_sample *st, int x, int y) {
  const zr_camera *c = &tr->scene->camera;
  double sx = x + next_uniform(st), sy = y + next_uniform(st);
  double la = next_uniform(st), lb = next_uniform(st);
  zr_ray ray;
  if (c->kind == ZR_CAMERA_MESH) {
    if (!zr__camera_mesh_ray(c, params->width, params->height, sx, sy, 0,
                             &ray))
      return zr_rgb3(0, 0, 0);
  } else {
    ray = zr__camera_ray(c, params->width, params->height, sx, sy);
    if (zr_v3_len(ray.dir) == 0.0)
      return zr_rgb3(0, 0, 0); /* outside a fisheye's circle */
    if (c->aperture > 0.0 && c->blur_samples > 0)
      zr__camera_focal_sample(c, &ray, la, lb);
  }
  return zr__trace_ray(tr, &ray, 1, 1.0, media);
}

zr_rgb zr__path_pixel(const zr_path *path, const zr_tracer *base,
                      const zr_media *camera_media,
                      const zr_render_params *params, uint32_t pixel,
                      int x, int y) {
  path_sample st;
  zr_indirect ind = path->indirect;
  ind.scratch = &st;
  zr_tracer tr = *base;
  tr.indirect = &ind;
  tr.gi_depth = 0;
  tr.skip_direct = false;
  tr.skip_sampled_emission = false;
  uint64_t pixel_key = mix64(((uint64_t)path->params.seed << 32) ^ pixel);
  double sum[3] = {0, 0, 0};
  int n = params->path_samples;
  for (int k = 0; k < n; k++) {
    uint64_t index = (uint64_t)params->path_first_sample + (uint64_t)k;
    st.key = mix64(pixel_key ^ mix64(index + 0x632be59bd9b4e019u));
    st.drawn = 0;
    st.rays = 0;
    zr_rgb c = camera_sample(&tr, camera_media, params, &st, x, y);
    /* A sample that is not a number (0 * inf on a degenerate path)
       would spoil the whole pixel: it counts as black. */
    if (isfinite(c.r) && isfinite(c.g) && isfinite(c.b)) {
      sum[0] += c.r;
      sum[1] += c.g;
      sum[2] += c.b;
    }
  }
  return zr_rgb3(sum[0] / n, sum[1] / n, sum[2] / n);
}
