/*
 * render.c - the public rendering calls: camera rays through pixels and
 * POV-Ray's non-recursive adaptive antialiasing (reference, "Anti-Aliasing
 * Options", sampling method 1).
 *
 * A pixel (x, y) of a W x H image looks along
 *   direction + u * right + v * up,  u = (x + 0.5) / W - 0.5,
 *                                    v = 0.5 - (y + 0.5) / H,
 * from the camera's location.  POV-Ray 3.7 does not adapt `right` to the
 * image's aspect ratio (a 200 x 100 render of the default camera stretches
 * a sphere to twice its width), and neither does this.  Other
 * projections map (u, v) to rays in lib/trace/camera.c; focal blur
 * averages lens samples drawn from a hash of the pixel and sample
 * number, stopping by the camera's confidence and variance.
 *
 * Antialiasing runs in two passes so that every pixel's result depends
 * only on the scene and the complete image of pixel centres: pass 1 traces
 * the centres; pass 2 compares each centre with its four neighbours
 * (the manual's method 1 compares with the left and upper ones and
 * supersamples both pixels of a pair that differ, 3.2.8.7, which is the
 * same as looking at all four, except that povray renders in 32 x 32
 * blocks, 3.2.8.2, and, as its renders show, never returns to a
 * finished block, so a right or lower neighbour across a block border
 * does not count: tests/test_render.c) after the antialiasing gamma,
 * and where the
 * difference exceeds the threshold averages the centre with an
 * aa_depth x aa_depth grid of samples over the pixel.  povray also
 * compares with neighbours already supersampled, which depends on the
 * order pixels are traced in; this does not, and so picks a slightly
 * different set: on the golden scenes at 160 x 120 the sets agree on
 * 96-98% of the pixels either picks, and the supersampled values agree
 * exactly.  Jitter moves each sample by a pseudo-random amount drawn from
 * a hash of the pixel index and sample number, never from shared state,
 * so the picture does not depend on how pixels are split among threads
 * and processes.
 */
#include <stdalign.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include "core/context.h"
#include "core/parallel.h"
#include "trace/render.h"
#include "trace/shade.h"

ZR_API void zr_render_params_init(zr_render_params *p) {
  memset(p, 0, sizeof *p);
  p->size = sizeof *p;
  p->width = 320;
  p->height = 240;
  p->antialias = 0;
  p->aa_threshold = 0.3;
  p->aa_depth = 3;
  p->jitter = 0;
  p->jitter_amount = 1.0;
  p->radiosity = NULL;
  p->radiosity_only = 0;
  p->gi_cache = NULL;
  p->aa_method = 1;
  p->quality = 9;
  p->path = NULL;
  p->path_samples = 16;
  p->path_first_sample = 0;
  p->threads = 1;
  p->context = NULL;
  p->alpha = 0;
}

ZR_API void zr_render_stats_add(zr_render_stats *a,
                                const zr_render_stats *b) {
  a->camera_rays += b->camera_rays;
  a->supersample_rays += b->supersample_rays;
  a->reflected_rays += b->reflected_rays;
  a->refracted_rays += b->refracted_rays;
  a->shadow_rays += b->shadow_rays;
  a->supersampled_pixels += b->supersampled_pixels;
}

zr_ray zr__camera_ray(const zr_camera *camera, int width, int height,
                      double x, double y) {
  double u = x / width - 0.5, v = 0.5 - y / height;
  zr_ray ray = {camera->location, zr_v3(0, 0, 0)};
  if (camera->kind == ZR_CAMERA_MESH
          ? !zr__camera_mesh_ray(camera, width, height, x, y, 0, &ray)
          : !zr__camera_project(camera, u, v, &ray))
    ray.dir = zr_v3(0, 0, 0); /* no ray here: the caller renders black */
  return ray;
}

static double clip01(double v) { return v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v; }

double zr__colour_difference(const float *a, const float *b,
                             double exponent) {
  double d = 0.0;
  for (int k = 0; k < 3; k++)
    d += fabs(pow(clip01(a[k]), exponent) - pow(clip01(b[k]), exponent));
  return d;
}

/* A 32-bit integer mix (the "lowbias32" finaliser by Chris Wellons). */
static uint32_t mix32(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

double zr__hash_uniform(uint32_t pixel, uint32_t sample, uint32_t axis) {
  uint32_t h = mix32(pixel ^ 0x9e3779b9U);
  h = mix32(h ^ (sample * 0x85ebca6bU));
  h = mix32(h ^ (axis * 0xc2b2ae35U + 0x27d4eb2fU));
  return (double)(h >> 8) * (1.0 / 16777216.0);
}

/* What one call renders with: the tracer and the media around the
   camera. */
typedef struct pixel_job {
  zr_tracer tracer;
  zr_media camera_media;
  /* +UA: the clear share the sample being traced adds up
     (tracer.clear points here). */
  double clear;
} pixel_job;

/*
 * The objects the camera is inside, so that a camera under water or in
 * glass sees out through the right index of refraction, as POV-Ray's
 * does (a camera inside a glass sphere of ior 1.3 renders the same as in
 * povray only with this).
 */
void zr__camera_media(const zr_scene *scene, zr_media *media) {
  media->n = 0;
  media->passes = 0;
  /* A mesh camera's rays start on its faces, not at its location. */
  if (scene->camera.kind == ZR_CAMERA_MESH)
    return;
  /* zr__scene_finish found them. */
  for (int i = 0; i < scene->n_camera_inside && media->n < ZR_MEDIA_MAX;
       i++) {
    media->objects[media->n] = scene->camera_inside[i];
    media->interiors[media->n++] = scene->camera_inside[i]->interior;
  }
}

/* The normal quantile for a two-sided confidence c (0.9 -> 1.645), by
   bisection on erf: focal blur stops when the mean is this many
   standard errors within the variance asked for. */
static double normal_quantile(double c) {
  double lo = 0.0, hi = 10.0;
  for (int i = 0; i < 60; i++) {
    double mid = 0.5 * (lo + hi);
    if (erf(mid / sqrt(2.0)) < c)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

/*
 * Focal blur: samples jittered over the pixel and the lens from hashes
 * of (pixel, sample), at least blur_min and at most blur_samples, and
 * stops once z^2 * (sample variance) / n < variance in every channel,
 * z the normal quantile of the confidence (POV-Ray's adaptive rule in
 * the manual's words; its exact statistic is not documented).
 */
static zr_rgb focal_blur(const pixel_job *job, const zr_render_params *p,
                         double x, double y) {
  const zr_tracer *tr = &job->tracer;
  const zr_camera *c = &tr->scene->camera;
  uint32_t pixel = (uint32_t)floor(y) * (uint32_t)p->width +
                   (uint32_t)floor(x);
  /* Supersamples of one pixel differ in their sub-pixel offset. */
  uint32_t salt = (uint32_t)((x - floor(x)) * 65536.0) * 65537U ^
                  (uint32_t)((y - floor(y)) * 65536.0);
  double z = normal_quantile(c->confidence);
  int max = c->blur_samples, min = c->blur_min > 0 ? c->blur_min : 1;
  zr_rgb sum = zr_rgb3(0, 0, 0), sum2 = zr_rgb3(0, 0, 0);
  int n = 0;
  for (int k = 0; k < max; k++) {
    uint32_t s = (uint32_t)k * 7919U + salt;
    double jx = k == 0 ? 0.0 : zr__hash_uniform(pixel, s, 2) - 0.5;
    double jy = k == 0 ? 0.0 : zr__hash_uniform(pixel, s, 3) - 0.5;
    zr_ray ray = zr__camera_ray(c, p->width, p->height, x + jx, y + jy);
    zr_rgb col = zr_rgb3(0, 0, 0);
    if (zr_v3_len(ray.dir) > 0.0) {
      zr__camera_focal_sample(c, &ray, zr__hash_uniform(pixel, s, 4),
                              zr__hash_uniform(pixel, s, 5));
      col = zr__trace_ray(tr, &ray, 1, 1.0, &job->camera_media);
    }
    sum = zr_rgb_add(sum, col);
    sum2 = zr_rgb_add(sum2, zr_rgb_mul(col, col));
    n++;
    if (n >= min && n > 1) {
      double worst = 0.0;
      double m[3] = {sum.r / n, sum.g / n, sum.b / n};
      double q[3] = {sum2.r / n, sum2.g / n, sum2.b / n};
      for (int i = 0; i < 3; i++)
        worst = fmax(worst, fmax(0.0, q[i] - m[i] * m[i]) * n / (n - 1));
      if (z * z * worst / n < c->variance)
        break;
    }
  }
  tr->stats->supersample_rays += (uint64_t)(n > 0 ? n - 1 : 0);
  if (tr->clear) /* the samples' mean */
    *tr->clear /= n;
  return zr_rgb_scale(sum, 1.0 / n);
}

/*
 * A mesh camera's sample: the average of the rays that have a face
 * (lib/trace/camera_mesh.c); black when none has, which povray leaves
 * black and transparent.
 */
static zr_rgb mesh_sample(const pixel_job *job, const zr_render_params *p,
                          double x, double y) {
  const zr_tracer *tr = &job->tracer;
  const zr_camera *c = &tr->scene->camera;
  zr_rgb sum = zr_rgb3(0, 0, 0);
  int n = 0, rays = zr__camera_mesh_rays(c);
  for (int k = 0; k < rays; k++) {
    zr_ray ray;
    if (!zr__camera_mesh_ray(c, p->width, p->height, x, y, k, &ray))
      continue;
    zr_rgb col = c->mesh->max_distance > 0.0
                     ? zr__trace_camera_ray_within(tr, &ray,
                                                   c->mesh->max_distance,
                                                   &job->camera_media)
                     : zr__trace_ray(tr, &ray, 1, 1.0, &job->camera_media);
    sum = zr_rgb_add(sum, col);
    n++;
  }
  if (n > 1)
    tr->stats->supersample_rays += (uint64_t)(n - 1);
  if (tr->clear) /* the mean of the rays, clear without any */
    *tr->clear = n > 0 ? *tr->clear / n : 1.0;
  return n > 0 ? zr_rgb_scale(sum, 1.0 / n) : sum;
}

/* The colour at (x, y), and in *alpha its alpha (1 without +UA). */
static void trace_point_clear(const pixel_job *job,
                              const zr_render_params *p, double x,
                              double y, zr_rgb *out) {
  const zr_tracer *tr = &job->tracer;
  const zr_camera *c = &tr->scene->camera;
  if (c->kind == ZR_CAMERA_MESH) {
    *out = mesh_sample(job, p, x, y);
    return;
  }
  if (c->aperture > 0.0 && c->blur_samples > 0) {
    *out = focal_blur(job, p, x, y);
    return;
  }
  zr_ray ray = zr__camera_ray(c, p->width, p->height, x, y);
  if (zr_v3_len(ray.dir) == 0.0) {
    /* Outside a fisheye's circle: black, and clear (measured). */
    *out = zr_rgb3(0, 0, 0);
    if (tr->clear)
      *tr->clear = 1.0;
    return;
  }
  *out = zr__trace_ray(tr, &ray, 1, 1.0, &job->camera_media);
}

static void trace_point(const pixel_job *job, const zr_render_params *p,
                        double x, double y, zr_rgb *out, double *alpha) {
  double *clear = job->tracer.clear;
  if (clear)
    *clear = 0.0;
  trace_point_clear(job, p, x, y, out);
  *alpha = clear ? 1.0 - fmin(1.0, fmax(0.0, *clear)) : 1.0;
}

/* A pixel's floats: the colour, then with +UA the alpha. */
static void store(float *dst, zr_rgb c, double alpha, int channels) {
  dst[0] = (float)c.r;
  dst[1] = (float)c.g;
  dst[2] = (float)c.b;
  if (channels == 4)
    dst[3] = (float)alpha;
}

/* Whether the centre of pixel (x, y) differs from a neighbour's by more
   than the threshold. */
static bool needs_supersampling(const zr_render_params *p,
                                const float *centres, int x, int y,
                                double exponent) {
  static const int dx[4] = {-1, 1, 0, 0}, dy[4] = {0, 0, -1, 1};
  size_t ch = p->alpha ? 4 : 3;
  const float *c = centres + ch * ((size_t)y * p->width + x);
  for (int k = 0; k < 4; k++) {
    int nx = x + dx[k], ny = y + dy[k];
    if (nx < 0 || ny < 0 || nx >= p->width || ny >= p->height)
      continue;
    /* A right or lower neighbour in the next render block was traced
       after this pixel was finished, so povray never goes back to it. */
    if ((dx[k] > 0 && nx % ZR_AA_BLOCK == 0) ||
        (dy[k] > 0 && ny % ZR_AA_BLOCK == 0))
      continue;
    const float *n = centres + ch * ((size_t)ny * p->width + nx);
    if (zr__colour_difference(c, n, exponent) > p->aa_threshold)
      return true;
  }
  return false;
}

/*
 * The average of the pixel's centre sample and an n x n grid of samples
 * at the centres of its sub-squares, which is what povray 3.7 +AM1 -J
 * computes: renders of the same scene agree with it exactly, while grids
 * through the pixel's corners or without the centre differ by up to 0.16.
 */
static zr_rgb supersample(const pixel_job *job, const zr_render_params *p,
                          const float *centre, uint32_t pixel, int x,
                          int y, double *alpha) {
  int n = p->aa_depth;
  zr_rgb sum = zr_rgb3(centre[0], centre[1], centre[2]);
  double alpha_sum = p->alpha ? centre[3] : 1.0;
  for (int j = 0; j < n; j++)
    for (int i = 0; i < n; i++) {
      double sx = (i + 0.5) / n, sy = (j + 0.5) / n;
      if (p->jitter) {
        uint32_t k = (uint32_t)(j * n + i);
        sx += (zr__hash_uniform(pixel, k, 0) - 0.5) * p->jitter_amount / n;
        sy += (zr__hash_uniform(pixel, k, 1) - 0.5) * p->jitter_amount / n;
      }
      zr_rgb c;
      double a;
      trace_point(job, p, x + sx, y + sy, &c, &a);
      sum = zr_rgb_add(sum, c);
      alpha_sum += a;
    }
  const zr_tracer *tr = &job->tracer;
  tr->stats->supersample_rays += (uint64_t)n * (uint64_t)n;
  tr->stats->supersampled_pixels++;
  *alpha = alpha_sum / (n * n + 1); /* povray averages it (measured) */
  return zr_rgb_scale(sum, 1.0 / (n * n + 1));
}

/*
 * +AM2 ("Anti-Aliasing Options": adaptive and recursive): the mean of the
 * square's four corner samples, or, when two corners differ by more than
 * the threshold and levels remain, the mean of its four quarters done
 * the same way.  Corners are traced anew for each square (the manual's
 * cache of shared corners changes the cost, not the result); jitter
 * moves every sample but the pixel's corners by up to half the square.
 */
typedef struct aa_square {
  const pixel_job *job;
  const zr_render_params *p;
  uint32_t pixel;
  uint32_t samples;
  double exponent;
} aa_square;

static zr_rgb corner(aa_square *q, double x, double y, double size,
                     bool pixel_corner, double *alpha) {
  const zr_render_params *p = q->p;
  if (p->jitter && !pixel_corner) {
    uint32_t k = q->samples;
    x += (zr__hash_uniform(q->pixel, k, 0) - 0.5) * p->jitter_amount * size;
    y += (zr__hash_uniform(q->pixel, k, 1) - 0.5) * p->jitter_amount * size;
  }
  q->samples++;
  zr_rgb c;
  trace_point(q->job, p, x, y, &c, alpha);
  return c;
}

/* The square's colour, and its alpha in *alpha from the corners' a. */
static zr_rgb recursive_square(aa_square *q, double x, double y,
                               double size, int level, const zr_rgb c[4],
                               const double a[4], double *alpha) {
  float f[4][3];
  for (int i = 0; i < 4; i++)
    f[i][0] = (float)c[i].r, f[i][1] = (float)c[i].g, f[i][2] = (float)c[i].b;
  bool split = false;
  for (int i = 0; i < 4 && !split; i++)
    for (int j = i + 1; j < 4 && !split; j++)
      split = zr__colour_difference(f[i], f[j], q->exponent) >
              q->p->aa_threshold;
  if (!split || level >= q->p->aa_depth) {
    zr_rgb sum = zr_rgb_add(zr_rgb_add(c[0], c[1]), zr_rgb_add(c[2], c[3]));
    *alpha = 0.25 * (a[0] + a[1] + a[2] + a[3]);
    return zr_rgb_scale(sum, 0.25);
  }
  /* The five new points: the edges' middles and the centre. */
  double h = 0.5 * size;
  double at, al, am, ar, ab;
  zr_rgb top = corner(q, x + h, y, h, false, &at);
  zr_rgb left = corner(q, x, y + h, h, false, &al);
  zr_rgb mid = corner(q, x + h, y + h, h, false, &am);
  zr_rgb right = corner(q, x + size, y + h, h, false, &ar);
  zr_rgb bottom = corner(q, x + h, y + size, h, false, &ab);
  zr_rgb q0[4] = {c[0], top, left, mid};
  zr_rgb q1[4] = {top, c[1], mid, right};
  zr_rgb q2[4] = {left, mid, c[2], bottom};
  zr_rgb q3[4] = {mid, right, bottom, c[3]};
  double a0[4] = {a[0], at, al, am}, a1[4] = {at, a[1], am, ar};
  double a2[4] = {al, am, a[2], ab}, a3[4] = {am, ar, ab, a[3]};
  double s0, s1, s2, s3;
  zr_rgb sum = recursive_square(q, x, y, h, level + 1, q0, a0, &s0);
  sum = zr_rgb_add(sum, recursive_square(q, x + h, y, h, level + 1, q1, a1,
                                         &s1));
  sum = zr_rgb_add(sum, recursive_square(q, x, y + h, h, level + 1, q2, a2,
                                         &s2));
  sum = zr_rgb_add(sum, recursive_square(q, x + h, y + h, h, level + 1, q3,
                                         a3, &s3));
  *alpha = 0.25 * (s0 + s1 + s2 + s3);
  return zr_rgb_scale(sum, 0.25);
}

static zr_rgb supersample_recursive(const pixel_job *job,
                                    const zr_render_params *p,
                                    uint32_t pixel, int x, int y,
                                    double exponent, double *alpha) {
  aa_square q = {job, p, pixel, 0, exponent};
  double a[4];
  zr_rgb c[4] = {corner(&q, x, y, 1.0, true, &a[0]),
                 corner(&q, x + 1, y, 1.0, true, &a[1]),
                 corner(&q, x, y + 1, 1.0, true, &a[2]),
                 corner(&q, x + 1, y + 1, 1.0, true, &a[3])};
  zr_rgb v = recursive_square(&q, x, y, 1.0, 0, c, a, alpha);
  const zr_tracer *tr = &job->tracer;
  tr->stats->supersample_rays += q.samples;
  if (q.samples > 4)
    tr->stats->supersampled_pixels++;
  return v;
}

/* Whether the parameters can render scene: ZR_OK, or the status with
   why in *what. */
static zr_status check_params(const zr_scene *scene,
                              const zr_render_params *p, const char **what) {
  *what = NULL;
  if (!scene)
    *what = "no scene";
  else if (p->width <= 0 || p->height <= 0 ||
           (uint64_t)p->width * (uint64_t)p->height > UINT32_MAX)
    *what = "the image size must be at least 1 x 1 and at most 2^32 pixels";
  else if (p->antialias && (p->aa_depth < 1 || p->aa_depth > 9 ||
                            !(p->aa_threshold >= 0.0)))
    *what = "antialiasing needs a depth of 1 to 9 and a threshold >= 0";
  else if (p->aa_method != 1 && p->aa_method != 2)
    *what = "the antialiasing method must be 1 or 2";
  else if (p->threads < 0)
    *what = "threads must be >= 0";
  /* A solution holds object addresses of the scene it was solved for. */
  else if (p->radiosity &&
           zr__radiance_source(p->radiosity)->scene != scene)
    *what = "the radiosity solution was solved for another scene";
  else if (p->radiosity_only && !p->radiosity)
    *what = "radiosity_only needs a radiosity solution";
  else if (p->gi_cache && !zr__gi_indirect_for(p->gi_cache, scene))
    *what = "the irradiance cache was made for another scene";
  else if (p->path && (!zr__path_for(p->path, scene) || p->radiosity ||
                       p->gi_cache || p->path_samples < 1 ||
                       p->path_first_sample < 0))
    *what = "the path tracer is for another scene, is combined with "
            "radiosity or a cache, or has no samples";
  else if (p->alpha != 0 && p->alpha != 1)
    *what = "alpha must be 0 or 1";
  else if (p->alpha && p->path)
    *what = "alpha (+UA) is not supported with the path tracer";
  if (*what)
    return ZR_EINVAL;
  if (!scene->bvh && scene->n_primitives > 0) {
    *what = "the scene was not finished"; /* zr__scene_finish() */
    return ZR_ESCENE;
  }
  return ZR_OK;
}

/* The size of zr_render_params in the first release that had a size
   member (zr__params_take): freeze it at the offset of the first member
   added after this release. */
#define RENDER_PARAMS_MIN_SIZE sizeof(zr_render_params)

/* The caller's parameters, taken into p and checked; report: say why
   not through p->context (zr_render_pixels runs on the caller's threads,
   several at once, so it only returns the status). */
static zr_status take_params(const zr_scene *scene,
                             const zr_render_params *params,
                             zr_render_params *p, bool report) {
  zr_render_params_init(p);
  if (zr__params_take(p, sizeof *p, params, RENDER_PARAMS_MIN_SIZE) !=
      ZR_OK) {
    /* No context to tell (it is a member): the status says it. */
    return ZR_EINVAL;
  }
  const char *what;
  zr_status s = check_params(scene, p, &what);
  if (s != ZR_OK && report)
    zr__diag(p->context, ZR_DIAG_ERROR, s, NULL, "render: %s", what);
  return s;
}

/* zr_render_pixels() on parameters checked and taken already.
   camera_media: zr__camera_media() of the scene, or NULL to find it
   here (it looks at every primitive, so a loop over rows finds it
   once). */
static zr_status render_pixels(const zr_scene *scene,
                               const zr_render_params *params,
                               const uint32_t *pixels, size_t count,
                               const float *centres, float *rgb,
                               zr_render_stats *stats,
                               const zr_media *camera_media) {
  if (count > 0 && (!pixels || !rgb))
    return ZR_EINVAL;
  uint32_t total = (uint32_t)params->width * (uint32_t)params->height;
  for (size_t i = 0; i < count; i++)
    if (pixels[i] >= total)
      return ZR_EINVAL;
  zr_render_stats local = {0};
  pixel_job job;
  job.tracer.scene = scene;
  job.tracer.stats = &local;
  job.tracer.radiosity = zr__radiance_source(params->radiosity);
  job.tracer.radiosity_only = params->radiosity_only;
  job.tracer.hide = ZR_HIDE_IMAGE;
  job.tracer.indirect = params->gi_cache
                            ? zr__gi_indirect_for(params->gi_cache, scene)
                            : NULL;
  job.tracer.gi_depth = 0;
  job.tracer.path = 0.0;
  job.tracer.no_media = false;
  job.tracer.no_fog = false;
  job.tracer.skip_direct = false;
  zr__tracer_quality(&job.tracer, params->quality);
  job.tracer.skip_sampled_emission = false;
  job.tracer.bailout = 0.0; /* the scene's adc_bailout */
  job.clear = 0.0;
  job.tracer.clear = params->alpha ? &job.clear : NULL;
  job.tracer.clear_weight = 1.0;
  /* One cache for this call's pixels: a row's neighbours tend to be
     shadowed by the same object. */
  zr_shadow_cache shadow_cache;
  memset(&shadow_cache, 0, sizeof shadow_cache);
  job.tracer.shadow_cache = &shadow_cache;
  job.tracer.shadow_path = NULL;
  job.tracer.media_start = NULL;
  job.tracer.dispersed = false;
  job.tracer.dispersion_u = 0.0;
  if (camera_media)
    job.camera_media = *camera_media;
  else
    zr__camera_media(scene, &job.camera_media);
  /* POV-Ray compares colours after undoing the scene's working gamma and
     applying its antialiasing gamma, 2.5 by default (reference,
     "Anti-Aliasing Options"), so dark edges are refined as readily as
     bright ones.  With gamma correction off (a legacy scene without
     assumed_gamma) the colours count as linear: povray's threshold for
     an edge between red 0.01 and 0.05 is 0.143 there, |0.05^0.4 -
     0.01^0.4|, as under assumed_gamma 1, not 0.054 as under 2.2
     (bench/conform/legacy_gamma_probe.py --section aa). */
  double working = scene->settings.gamma_correction_off
                       ? 1.0
                       : scene->settings.assumed_gamma;
  double exponent = working / ZR_AA_GAMMA;
  int ch = params->alpha ? 4 : 3;
  for (size_t i = 0; i < count; i++) {
    uint32_t pixel = pixels[i];
    int x = (int)(pixel % (uint32_t)params->width);
    int y = (int)(pixel / (uint32_t)params->width);
    float *out = rgb + (size_t)ch * i;
    const float *centre = centres ? centres + (size_t)ch * pixel : NULL;
    double a = 1.0;
    if (params->path && !centres) {
      /* The path tracer samples the pixel's area itself (lib/gi). */
      store(out, zr__path_pixel(params->path, &job.tracer,
                                &job.camera_media, params, pixel, x, y),
            a, ch);
      local.camera_rays += (uint64_t)params->path_samples;
    } else if (params->path) {
      memcpy(out, centre, (size_t)ch * sizeof *out);
    } else if (!centres) {
      zr_rgb c;
      trace_point(&job, params, x + 0.5, y + 0.5, &c, &a);
      local.camera_rays++;
      store(out, c, a, ch);
    } else if (params->antialias && params->aa_method == 2) {
      zr_rgb c = supersample_recursive(&job, params, pixel, x, y, exponent,
                                       &a);
      store(out, c, a, ch);
    } else if (params->antialias &&
               needs_supersampling(params, centres, x, y, exponent)) {
      zr_rgb c = supersample(&job, params, centre, pixel, x, y, &a);
      store(out, c, a, ch);
    } else {
      memcpy(out, centre, (size_t)ch * sizeof *out);
    }
  }
  if (stats)
    zr_render_stats_add(stats, &local);
  return ZR_OK;
}

ZR_API zr_status zr_render_pixels(const zr_scene *scene,
                                  const zr_render_params *params,
                                  const uint32_t *pixels, size_t count,
                                  const float *centres, float *rgb,
                                  zr_render_stats *stats) {
  zr_render_params p;
  zr_status s = take_params(scene, params, &p, false);
  if (s != ZR_OK)
    return s;
  if (zr__cancelled(p.context))
    return ZR_ECANCELLED;
  return render_pixels(scene, &p, pixels, count, centres, rgb, stats,
                       NULL);
}

/*
 * zr_render_image's rows: each thread takes rows from the loop's
 * counter and renders them into their own place of out, so the picture
 * does not depend on which thread took which row; statistics go to the
 * thread's own slot (padded against false sharing) and are added in
 * thread order at the end, integers, so their sum has no order either.
 */
typedef struct row_stats {
  alignas(64) zr_render_stats stats;
} row_stats;

typedef struct image_job {
  const zr_scene *scene;
  const zr_render_params *params;
  const float *centres; /* NULL in pass 1 */
  float *out;
  row_stats *slots;
  zr_media camera_media;
  atomic_int stop;      /* non-zero: no thread starts another row */
  atomic_int failure;   /* the first failure */
  atomic_ullong rows_done;
  atomic_flag reporting; /* one thread at a time tells the callback */
  uint64_t rows_total;
} image_job;

static void fail(image_job *job, zr_status s) {
  int ok = ZR_OK;
  atomic_compare_exchange_strong(&job->failure, &ok, (int)s);
  atomic_store(&job->stop, 1);
}

/* Tells the callback how many rows are done, unless another thread is
   telling it now (it will say as much or more soon). */
static void report_rows(image_job *job) {
  zr_context *ctx = job->params->context;
  if (!ctx)
    return;
  if (atomic_flag_test_and_set(&job->reporting))
    return;
  uint64_t done = atomic_load(&job->rows_done);
  zr_status s = zr__progress(ctx, ZR_PHASE_RENDER, done, job->rows_total);
  atomic_flag_clear(&job->reporting);
  if (s != ZR_OK)
    fail(job, s);
}

static void render_rows(void *user, size_t begin, size_t end, int worker) {
  image_job *job = user;
  int width = job->params->width;
  uint32_t pixels[256];
  for (size_t y = begin; y < end; y++) {
    if (atomic_load_explicit(&job->stop, memory_order_relaxed))
      return;
    if (zr__cancelled(job->params->context)) {
      fail(job, ZR_ECANCELLED);
      return;
    }
    /* A row in pieces of 256 pixels: no allocation per row. */
    for (int x0 = 0; x0 < width; x0 += 256) {
      int n = width - x0 < 256 ? width - x0 : 256;
      for (int k = 0; k < n; k++)
        pixels[k] = (uint32_t)(y * (size_t)width + (size_t)(x0 + k));
      size_t ch = job->params->alpha ? 4 : 3;
      float *dst = job->out + ch * (y * (size_t)width + (size_t)x0);
      zr_status s = render_pixels(job->scene, job->params, pixels,
                                  (size_t)n, job->centres, dst,
                                  &job->slots[worker].stats,
                                  &job->camera_media);
      if (s != ZR_OK) {
        fail(job, s);
        return;
      }
    }
    atomic_fetch_add(&job->rows_done, 1);
    report_rows(job);
  }
}

/* One pass over every row with the params' threads. */
static zr_status image_pass(image_job *job, const float *centres,
                            float *out, int threads) {
  job->centres = centres;
  job->out = out;
  (void)zr__parallel_for(threads, (size_t)job->params->height, 1,
                         render_rows, job, &job->stop);
  return (zr_status)atomic_load(&job->failure);
}

ZR_API zr_status zr_render_image(const zr_scene *scene,
                                 const zr_render_params *params, float *rgb,
                                 zr_render_stats *stats) {
  zr_render_params p;
  zr_status s = take_params(scene, params, &p, true);
  if (s != ZR_OK)
    return s;
  if (!rgb)
    return ZR_EINVAL;
  if (zr__cancelled(p.context))
    return ZR_ECANCELLED;
  int threads = p.threads < 1 ? 1
                : p.threads > ZR__MAX_THREADS ? ZR__MAX_THREADS
                                               : p.threads;
  size_t n = (size_t)p.width * (size_t)p.height;
  size_t ch = p.alpha ? 4 : 3;
  float *centres = p.antialias ? malloc(n * ch * sizeof *centres) : NULL;
  row_stats *slots = aligned_alloc(64, (size_t)threads * sizeof *slots);
  if ((p.antialias && !centres) || !slots) {
    free(centres);
    free(slots);
    return ZR_ENOMEM;
  }
  memset(slots, 0, (size_t)threads * sizeof *slots);
  image_job job;
  memset(&job, 0, sizeof job);
  job.scene = scene;
  job.params = &p;
  job.slots = slots;
  zr__camera_media(scene, &job.camera_media);
  atomic_init(&job.stop, 0);
  atomic_init(&job.failure, ZR_OK);
  atomic_init(&job.rows_done, 0);
  atomic_flag_clear(&job.reporting);
  job.rows_total = (uint64_t)p.height * (p.antialias ? 2u : 1u);
  s = zr__progress(p.context, ZR_PHASE_RENDER, 0, job.rows_total);
  if (s == ZR_OK && !p.antialias) {
    s = image_pass(&job, NULL, rgb, threads);
  } else if (s == ZR_OK) {
    s = image_pass(&job, NULL, centres, threads);
    if (s == ZR_OK)
      s = image_pass(&job, centres, rgb, threads);
  }
  /* The last row's report may have met another thread's: say the
     end once more. */
  if (s == ZR_OK)
    s = zr__progress(p.context, ZR_PHASE_RENDER, job.rows_total,
                     job.rows_total);
  if (s == ZR_ECANCELLED)
    zr__diag(p.context, ZR_DIAG_ERROR, s, NULL, "render: cancelled");
  if (stats)
    for (int i = 0; i < threads; i++)
      zr_render_stats_add(stats, &slots[i].stats);
  free(slots);
  free(centres);
  return s;
}
