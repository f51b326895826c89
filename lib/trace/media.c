/*
 * media.c - participating media (reference manual, "Media", "Object
 * Media", "Atmospheric Media", "Empty and Solid Objects", "Sampling
 * Parameters & Methods"), integrated from the volume rendering equation.
 *
 * Along a ray x(s) = origin + s dir (dir unit, 0 <= s <= D) a medium has
 * at each point, per colour channel,
 *     extinction  k(s) = density (absorption + extinction * scattering)
 *     source      j(s) = density (emission + scattering * sum over the
 *                        lights of light(x) * phase(cos))
 * summed over the media that overlap there (the manual: several media
 * in one container add), density being the product of the medium's
 * density { } colours (1 without any).  What reaches the origin is
 *     L = C T(0, D) + integral_0^D T(0, s) j(s) ds,
 *     T(a, b) = exp(-integral_a^b k),
 * C being the colour behind the media (Beer-Lambert transmittance and
 * the emission integral; see any text on radiative transfer, e.g.
 * Chandrasekhar, "Radiative Transfer", 1950).
 *
 * Quadrature.  k and j are sampled at points along the ray.  Shadow
 * rays and methods 1 and 2 take them as varying linearly between
 * neighbouring points and as constant between an end of an interval
 * and the sample nearest to it; over a span of length h whose mean
 * extinction is k and mean source j this is exact:
 *     T_span = exp(-k h),  emitted = j (1 - exp(-k h)) / k  (j h at k 0),
 * and spans combine front to back (the light of a span is dimmed by the
 * transmittance of the spans before it).  Method 3 on rays that gather
 * light sums cells as POV-Ray 3.7 does instead (measured: see
 * gather_cell()): a cell's light is its mean source times its length,
 * dimmed only by the cells before it, which is brighter than the exact
 * value when a cell is optically thick (what POV-Ray's pictures show).
 *
 * Where the points go (the manual's sampling parameters):
 *   - The ray is first cut where it enters or leaves the cone of a
 *     spotlight or the tube of a cylinder light that lights the media
 *     (a ray-cone or ray-cylinder intersection), so a beam is never
 *     stepped over, and a piece's samples ask only the beams that hold
 *     its middle for their light.  Each piece gets one interval, and
 *     the rest of the `intervals` are dealt out one at a time to the
 *     piece whose share is then the smallest for its weight: length
 *     times ratio for lit pieces, length times (1 - ratio) for the
 *     others.
 *   - method 3: an interval is cut into n = floor(max(min samples,
 *     3) / 2) + 1 cells, each sampled at its ends and middle; the
 *     samples take the coefficients of the first n / (n + 1) of the
 *     interval stretched over all of it (reach()); jitter moves each
 *     inner cell end by up to jitter / 2 of a cell.  With min samples 3
 *     or more (the manual: adaptive sampling only then) a cell whose
 *     middle sample differs from the mean of its ends (change()) is
 *     halved, up to aa_level - 1 times, and takes the mean of its
 *     halves' coefficients (gather_cell() gives the measurements).  Shadow
 *     rays take the same first n / (n + 1) of each interval with 2 n
 *     cells and no halving, as measured of POV-Ray
 *     (bench/media_shadow.py, see reach()).  A shadow ray stops once it
 *     keeps less than 1e-6 of the light (our own cut: below what 16-bit
 *     output resolves).
 *   - method 2: min samples evenly spread through the interval (each in
 *     the middle of its share, moved by up to jitter / 2 of it); method
 *     1: min samples at random.  Then, up to max samples, more random
 *     ones while the spread of the samples leaves the interval's mean
 *     unsure: with n samples of spread s^2 (of the largest channel of j
 *     plus that of k, times the interval's length) the variance of the
 *     mean is below, with probability `confidence`,
 *     (n - 1) s^2 / (n chi2_(1 - confidence)(n - 1)), the usual upper
 *     confidence bound of a normal variance; sampling stops once that
 *     bound is under `variance`.
 * Several media on one ray sample with the largest intervals, samples
 * and aa_level and the smallest aa_threshold among them; the first
 * one's method and ratio; the largest jitter, confidence and the
 * smallest variance.
 *
 * Random numbers come from a hash of the ray (its origin and direction,
 * so of the pixel and its sample) and a counter: an image is the same
 * for any number of threads and ranks.
 *
 * Phase functions, cos being the cosine between the direction toward
 * the light and the ray's direction (cos 1: the light shines straight
 * at the viewer), as forms of the literature (Nishita, Miyawaki and
 * Nakamae 1987 for the two Mie approximations; Rayleigh's 1 + cos^2;
 * Henyey and Greenstein 1941), each times a scale.  POV-Ray's manual
 * gives the shapes only as plots; the scales were measured with
 * bench/media_phase.sh (povray 3.7.0, exact to the 5 digits given):
 *   isotropic          1                                    scale 1
 *   Henyey-Greenstein  (1 - g^2) / (1 + g^2 - 2 g cos)^1.5  scale 1
 *   Rayleigh           1 + cos^2                            0.79936
 *   Mie hazy           1 + 9 ((1 + cos) / 2)^8              0.57666
 *   Mie murky          1 + 50 ((1 + cos) / 2)^32            0.49571
 * Isotropic and Henyey-Greenstein with scale 1 integrate to 4 pi over
 * the sphere (the convention: the mean over all directions is 1).  The
 * other three do not: their means over the sphere would be 1 with the
 * scales 3/4 (the mean of 1 + mu^2 for mu uniform in [-1, 1] is
 * 1 + 1/3), 1/2 (the mean of ((1 + mu) / 2)^n is 1 / (n + 1), so
 * 1 + 9/9 = 2) and 33/83 (1 + 50/33); the measured scales are 1.0658,
 * 1.1533 and 1.2467 times those.  tests/test_media.c integrates each.
 *
 * Media inside objects are seen only by rays inside hollow objects
 * (every object the ray is in must be hollow) and only up to a surface.
 * A ray to the sky crosses atmospheric media out to 2e10 units, and a
 * spotlight or cylinder light lights none of them past 1e7 units along
 * a ray: both measured from povray renders by bench/media_sky.sh (the
 * manual says media need a finite ray; the background then shows
 * through absorbing haze as exp(-absorption 2e10)).
 */
#include "trace/media.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "scene/texture.h"
#include "trace/atmosphere.h"
#include "trace/lights.h"
#include "trace/photons.h"

/* Measured by bench/media_sky.sh (see above). */
#define SKY_DEPTH 2e10
#define BEAM_REACH 1e7

/* Bounds on the work one ray may ask for. */
#define MAX_PIECES 64      /* lit and unlit stretches of a ray */
#define MAX_INTERVALS 1024 /* intervals over all pieces */
#define MAX_RANDOM 512     /* samples of one interval, methods 1 and 2 */
#define MAX_CELLS 4096     /* cells of one interval, method 3 */

/* The coefficients at one point of the ray. */
typedef struct sample {
  double s;       /* distance along the ray */
  zr_rgb k;       /* extinction */
  zr_rgb j;       /* source: emitted and scattered toward the origin */
} sample;

/* How the media of one ray are sampled (see the essay). */
typedef struct plan {
  int method, intervals, min_samples, max_samples, aa_level;
  double ratio, jitter, aa_threshold, confidence, variance;
} plan;

/* One integration in progress. */
typedef struct march {
  const zr_tracer *tr;
  const zr_medium *const *list;
  size_t n;
  zr_vec3 origin, dir;
  bool shadow;   /* extinction only */
  bool lights;   /* some medium scatters and the ray is not a shadow */
  /* The spotlights and cylinder lights (bit i: the scene's light i)
     whose beam holds the piece of the ray being sampled; beams_known
     false when the ray was not cut at every beam (then all are asked). */
  bool beams_known;
  uint64_t beams;
  /* With beams_known: the point lights that light media (bit i: light
     i), so that a sample asks these and the piece's beams, not all the
     scene's lights (media2: 37 spotlights, a few of them per piece). */
  uint64_t points;
  bool varies;   /* the coefficients may change along the ray */
  uint64_t seed;
  uint64_t draws;
  plan pl;
  double reach;          /* method 3: see reach() */
  double interval_start; /* method 3: s0 of the interval being sampled */
  double interval_length; /* method 3: its length */
  /* What is known so far: transmittance from the origin to the end of
     the last span, and the light gathered. */
  zr_rgb t, light;
} march;

static double rgb_max(zr_rgb c) { return fmax(c.r, fmax(c.g, c.b)); }

static bool rgb_zero(zr_rgb c) {
  return c.r == 0.0 && c.g == 0.0 && c.b == 0.0;
}

/* ----- random numbers ------------------------------------------------ */

/* A 64-bit finaliser (the one of the splitmix64 generator): every input
   bit flips about half of the output bits. */
static uint64_t scramble(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
  return z ^ (z >> 31);
}

static uint64_t bits_of(double v) {
  uint64_t u;
  memcpy(&u, &v, sizeof u);
  return u;
}

static uint64_t ray_key(zr_vec3 o, zr_vec3 d) {
  uint64_t h = 0x6a09e667f3bcc908u;
  double v[6] = {o.x, o.y, o.z, d.x, d.y, d.z};
  for (int i = 0; i < 6; i++)
    h = scramble(h ^ bits_of(v[i]));
  return h;
}

/* Uniform in [0, 1). */
static double uniform(march *m) {
  uint64_t z = scramble(m->seed + 0x9e3779b97f4a7c15u * ++m->draws);
  return (double)(z >> 11) * 0x1.0p-53;
}

/* ----- phase functions ----------------------------------------------- */

double zr__media_phase(const zr_medium *medium, double cos_angle) {
  double c = fmax(-1.0, fmin(1.0, cos_angle));
  switch (medium->scattering_type) {
  case ZR_SCATTER_MIE_HAZY:
    return 0.57666 * (1.0 + 9.0 * pow(0.5 * (1.0 + c), 8.0));
  case ZR_SCATTER_MIE_MURKY:
    return 0.49571 * (1.0 + 50.0 * pow(0.5 * (1.0 + c), 32.0));
  case ZR_SCATTER_RAYLEIGH:
    return 0.79936 * (1.0 + c * c);
  case ZR_SCATTER_HENYEY_GREENSTEIN: {
    double g = medium->eccentricity;
    double q = 1.0 + g * g - 2.0 * g * c;
    return q > 0.0 ? (1.0 - g * g) / (q * sqrt(q)) : 0.0;
  }
  case ZR_SCATTER_ISOTROPIC:
  default:
    return 1.0;
  }
}

/* ----- the coefficients at a point ------------------------------------ */

/* The product of the medium's densities at p.  Once it is zero in every
   channel the densities left cannot change it, so they are not
   evaluated (benchmark.pov's clouds: the first density's colour_map is
   black over half its range, and the second is a seven-octave
   turbulence). */
static zr_rgb density_at(const zr_medium *medium, zr_vec3 p) {
  zr_rgb d = zr_rgb3(1, 1, 1);
  for (size_t i = 0; i < medium->n_density; i++) {
    d = zr_rgb_mul(d, zr_colour_rgb(zr__pigment_eval(medium->density[i], p)));
    if (rgb_zero(d))
      break;
  }
  return d;
}

zr_rgb zr__media_density(const zr_medium *medium, zr_vec3 p) {
  return density_at(medium, p);
}

/* Whether light may light the media of this ray at distance s. */
static bool lights_media(const zr_light *light, double s) {
  /* A light_group's lights light no media: zRcube does not yet tell a
     group's media from the others.  A shadowless light lights none
     either: povray 3.7 renders a box of scattering media, and
     atmospheric scattering media, lit by a shadowless light byte for
     byte as with media_interaction off or a black light
     (tests/test_media_shell.sh); advanced/benchmark/benchmark.pov's
     shadowless fill light (rgb 0.35) lit its clouds through 30000
     units of them here, where povray's stay dark. */
  if (!light->media_interaction || light->light_group != 0 ||
      light->shadowless)
    return false;
  return light->kind == ZR_LIGHT_POINT || s <= BEAM_REACH;
}

/* The light that light scatters towards the ray's origin at p (distance
   s), added to out->j; density[i] is medium i's at p. */
static void scatter_light(const march *m, const zr_light *light, double s,
                          zr_vec3 p, const zr_rgb *density, sample *out) {
  if (!lights_media(light, s))
    return;
  zr_vec3 toward;
  zr_rgb arriving;
  if (!zr__light_arrive(light, p, &toward, &arriving) ||
      rgb_max(arriving) <= 0.0)
    return;
  arriving = zr_rgb_mul(arriving, zr__light_visibility(m->tr, light, p, p));
  if (rgb_max(arriving) <= 0.0)
    return;
  arriving =
      zr_rgb_mul(arriving, zr__media_light_attenuation(m->tr, light, p));
  double c = zr_v3_dot(toward, m->dir);
  for (size_t i = 0; i < m->n; i++) {
    const zr_medium *md = m->list[i];
    if (rgb_zero(md->scattering))
      continue;
    zr_rgb sc = zr_rgb_mul(density[i], md->scattering);
    out->j = zr_rgb_add(out->j, zr_rgb_scale(zr_rgb_mul(sc, arriving),
                                             zr__media_phase(md, c)));
  }
}

static sample sample_at(const march *m, double s) {
  sample out = {s, zr_rgb3(0, 0, 0), zr_rgb3(0, 0, 0)};
  zr_vec3 p = zr_v3_madd(m->origin, m->dir, s);
  zr_rgb density[ZR_MEDIA_LIST_MAX];
  bool scatters = false;
  for (size_t i = 0; i < m->n; i++) {
    const zr_medium *md = m->list[i];
    density[i] = density_at(md, p);
    zr_rgb k = zr_rgb_madd(md->absorption, md->scattering, md->extinction);
    out.k = zr_rgb_add(out.k, zr_rgb_mul(density[i], k));
    if (!m->shadow) {
      out.j = zr_rgb_add(out.j, zr_rgb_mul(density[i], md->emission));
      scatters = scatters || !rgb_zero(md->scattering);
    }
  }
  const zr_scene *scene = m->tr->scene;
  /* The light media photons bring (lib/trace/photons.c). */
  if (scatters && zr__photons_in_media(scene->photons))
    out.j = zr_rgb_add(out.j, zr__photons_media_light(scene->photons, p,
                                                      m->dir, m->list, m->n,
                                                      density));
  if (!scatters || !m->lights)
    return out;
  if (m->beams_known) {
    /* A beam lights all of a piece or none of it (the pieces are cut
       where the ray crosses its boundary): the piece's beams and the
       point lights, in the scene's order as below. */
    for (uint64_t todo = m->points | m->beams; todo; todo &= todo - 1)
      scatter_light(m, &scene->lights[__builtin_ctzll(todo)], s, p,
                    density, &out);
    return out;
  }
  for (size_t li = 0; li < scene->n_lights; li++)
    scatter_light(m, &scene->lights[li], s, p, density, &out);
  return out;
}

/* ----- spans ------------------------------------------------------------ */

/* (1 - exp(-x)) / x, 1 at 0, without cancellation for small x. */
static double grow(double x) {
  return fabs(x) < 1e-8 ? 1.0 - 0.5 * x : -expm1(-x) / x;
}

/* Adds the span from a to b (a before b), its coefficients the means
   of those at its ends. */
static void add_span(march *m, const sample *a, const sample *b) {
  double h = b->s - a->s;
  if (!(h > 0.0))
    return;
  double k[3] = {0.5 * (a->k.r + b->k.r), 0.5 * (a->k.g + b->k.g),
                 0.5 * (a->k.b + b->k.b)};
  double j[3] = {0.5 * (a->j.r + b->j.r), 0.5 * (a->j.g + b->j.g),
                 0.5 * (a->j.b + b->j.b)};
  double *t[3] = {&m->t.r, &m->t.g, &m->t.b};
  double *l[3] = {&m->light.r, &m->light.g, &m->light.b};
  for (int c = 0; c < 3; c++) {
    double depth = k[c] * h;
    if (j[c] != 0.0)
      *l[c] += *t[c] * j[c] * h * grow(depth);
    *t[c] *= exp(-depth);
  }
}

/* A sample at s with the coefficients of another (an interval's end
   takes those of the sample nearest to it). */
static sample moved(const sample *from, double s) {
  sample out = *from;
  out.s = s;
  return out;
}

/* How far the coefficients of a cell's middle sample mid lie from the
   mean of its ends a and b: the largest channel of |j_mid - (j_a +
   j_b) / 2| + |k_mid - (k_a + k_b) / 2|, what method 3 weighs against
   aa_threshold (see gather_cell()): a density that changes linearly
   along the ray is never halved. */
static double change(const sample *a, const sample *mid,
                     const sample *b) {
  zr_rgb dj = zr_rgb3(fabs(mid->j.r - 0.5 * (a->j.r + b->j.r)),
                      fabs(mid->j.g - 0.5 * (a->j.g + b->j.g)),
                      fabs(mid->j.b - 0.5 * (a->j.b + b->j.b)));
  zr_rgb dk = zr_rgb3(fabs(mid->k.r - 0.5 * (a->k.r + b->k.r)),
                      fabs(mid->k.g - 0.5 * (a->k.g + b->k.g)),
                      fabs(mid->k.b - 0.5 * (a->k.b + b->k.b)));
  return rgb_max(zr_rgb_add(dj, dk));
}

/* Adds the cell from a to b whose middle sample is mid as POV-Ray's
   method 3 does on rays that gather light (measured, see
   gather_cell()): its coefficients are the mean of the three samples',
   its light is that mean source times its length, dimmed by the
   transmittance up to the cell's start only, and the transmittance
   then falls by exp(-mean extinction * length). */
static void add_cell(march *m, const sample *a, const sample *mid,
                     const sample *b) {
  double h = b->s - a->s;
  if (!(h > 0.0))
    return;
  const double third = 1.0 / 3.0;
  double k[3] = {(a->k.r + mid->k.r + b->k.r) * third,
                 (a->k.g + mid->k.g + b->k.g) * third,
                 (a->k.b + mid->k.b + b->k.b) * third};
  double j[3] = {(a->j.r + mid->j.r + b->j.r) * third,
                 (a->j.g + mid->j.g + b->j.g) * third,
                 (a->j.b + mid->j.b + b->j.b) * third};
  double *t[3] = {&m->t.r, &m->t.g, &m->t.b};
  double *l[3] = {&m->light.r, &m->light.g, &m->light.b};
  for (int c = 0; c < 3; c++) {
    *l[c] += *t[c] * j[c] * h;
    *t[c] *= exp(-k[c] * h);
  }
}

/* The measure whose spread decides methods 1 and 2: the light of an
   interval of length len were the coefficients everywhere as at a. */
static double measure(const sample *a, double len) {
  return (rgb_max(a->j) + rgb_max(a->k)) * len;
}

/* ----- method 3 ---------------------------------------------------------- */

/*
 * How far into an interval POV-Ray 3.7's method 3 looks, measured
 * black-box by bench/media_steps.py (bench/results/media_steps.txt): a
 * camera ray through an emitting slab whose density steps from 1 to 0
 * at a depth T shows, as T runs over the slab, a staircase whose steps
 * are the samples.  With intervals 1 and min samples 3, 5, 9 and 17 the
 * last step lies at 2/3, 3/4, 5/6 and 9/10 of the slab and the staircase
 * still sums to the whole slab: the samples cover the first
 * n / (n + 1) of the interval, n = floor(min samples / 2) + 1, and
 * stand for all of it.  Rays that gather light do the same here (the
 * coefficients of the point at s0 + reach (s - s0) are used at s), so
 * media whose density varies along the ray look as in POV-Ray's
 * pictures at the scenes' own settings.
 *
 * Shadow rays do the same, measured by bench/media_shadow.py: light
 * crossing a slab whose absorbing density rises linearly from 0 to 1
 * along the shadow ray reaches a floor as if the mean density were
 * 0.344, 0.382 and 0.421 (min samples 3, 5, 9; intervals 1), 0.422
 * (intervals 2, samples 3) and 0.461 (intervals 3, samples 5), where
 * the exact mean is 0.5 and samples over the first n / (n + 1) give
 * 1/3, 3/8, 5/12, 0.417 and 0.458.  A density step scanned across the
 * slab (the same script's step cases) puts povray's shadow samples at
 * the ends and middles of n cells of 1 / (n + 1) of the interval:
 * 2 n cells here.  What povray adds beyond that (about 0.01 of weight
 * on the interval's far end, varying with the ray) is not reproduced.
 * Min samples 1 and 2 give the same as 3 in povray's shadows, as n
 * says.
 */
static int reach_cells(const march *m) {
  return (m->pl.min_samples < 3 ? 3 : m->pl.min_samples) / 2 + 1;
}

static double reach(const march *m) {
  double n = reach_cells(m);
  return n / (n + 1);
}

static sample reach_sample(const march *m, double s0, double s) {
  sample out = sample_at(m, s0 + m->reach * (s - s0));
  out.s = s;
  return out;
}

/* reach_sample() with its coefficients taken up to shove further on. */
static sample jittered(march *m, double s0, double s, double shove) {
  if (!(shove > 0.0))
    return reach_sample(m, s0, s);
  sample out = sample_at(m, s0 + m->reach * (s - s0) + shove * uniform(m));
  out.s = s;
  return out;
}

/*
 * A cell of a ray that gathers light, as POV-Ray 3.7's method 3 takes
 * it, measured black-box by bench/media_quadrature.py (see its output
 * in bench/results/media-quadrature-2026-12-02.txt):
 *   - an interval is cut into n = floor(max(min samples, 3) / 2) + 1
 *     cells (n cells of length D / n: an absorbing, emitting slab of
 *     depth D gives e h sum_{i<n} exp(-a i h), h = D / n, for min
 *     samples 1 to 9, where the exact value is e (1 - exp(-a D)) / a;
 *     so a medium whose cells are optically thick comes out brighter
 *     than the exact integral: scattering {1, 1} absorption 1 in a
 *     2-unit box, default samples, is 1.37 times it, and 1.03 with
 *     samples 50);
 *   - a cell samples its two ends and its middle (with the reach of
 *     reach() above) and takes the mean of the three: an emitting
 *     slab whose density is a step scanned through it with
 *     aa_threshold 100 steps at 0, 1/6, 1/3, 1/2 and 2/3 with weights
 *     1/6, 1/6, 1/3, 1/6, 1/6 (min samples 3), and densities z, 1 - z,
 *     z^2, z^3 and sqrt(z) agree to 1e-5 with that rule;
 *   - a cell whose middle sample is not the mean of its ends is
 *     halved, each half sampled the same way, at most aa_level - 1
 *     times (the step scan shows 5, 9, 17 and 65 steps for aa_level 1,
 *     2, 3 and 5, and 17 without aa_level); povray halves the cell with
 *     a step of height e in an interval of length D when e D is 0.05
 *     or more and not when it is 0.03 or less (D 0.25, 1 and 4, with or
 *     without absorption), so the test here is change() (e / 2 for a
 *     step) times the interval's length against aa_threshold / 6,
 *     inside that bracket.  A density rising linearly along the ray is
 *     not halved at all, and one rising as z^2 is, and the halved cell
 *     adds its light once, with the mean of its halves' coefficients,
 *     dimmed by the cells before it (bench/conform/
 *     media_curvature_probe.py: 0.24814 and 0.13707 against povray's
 *     0.24814 and 0.13701; halving on any difference between
 *     neighbouring samples and summing halves one after the other gave
 *     0.18184 and 0.11306).
 */
/* The mean coefficients of the cell from a to b: of its two ends and
   middle, or, where the cell is halved, the mean of its halves'. */
static void cell_means(march *m, const sample *a, const sample *b,
                       int levels, double j[3], double k[3]) {
  sample mid = reach_sample(m, m->interval_start, 0.5 * (a->s + b->s));
  if (levels > 0 &&
      change(a, &mid, b) * m->interval_length > m->pl.aa_threshold / 6.0) {
    double j1[3], k1[3], j2[3], k2[3];
    cell_means(m, a, &mid, levels - 1, j1, k1);
    cell_means(m, &mid, b, levels - 1, j2, k2);
    for (int c = 0; c < 3; c++) {
      j[c] = 0.5 * (j1[c] + j2[c]);
      k[c] = 0.5 * (k1[c] + k2[c]);
    }
    return;
  }
  const double third = 1.0 / 3.0;
  j[0] = (a->j.r + mid.j.r + b->j.r) * third;
  j[1] = (a->j.g + mid.j.g + b->j.g) * third;
  j[2] = (a->j.b + mid.j.b + b->j.b) * third;
  k[0] = (a->k.r + mid.k.r + b->k.r) * third;
  k[1] = (a->k.g + mid.k.g + b->k.g) * third;
  k[2] = (a->k.b + mid.k.b + b->k.b) * third;
}

static void gather_cell(march *m, const sample *a, const sample *b,
                        int levels) {
  double h = b->s - a->s;
  if (!(h > 0.0))
    return;
  double j[3], k[3];
  cell_means(m, a, b, levels, j, k);
  double *t[3] = {&m->t.r, &m->t.g, &m->t.b};
  double *l[3] = {&m->light.r, &m->light.g, &m->light.b};
  for (int c = 0; c < 3; c++) {
    *l[c] += *t[c] * j[c] * h;
    *t[c] *= exp(-k[c] * h);
  }
}

static void adaptive_interval(march *m, double s0, double s1) {
  double len = s1 - s0;
  m->reach = reach(m);
  m->interval_start = s0;
  m->interval_length = len;
  /* Both kinds of ray take reach_cells() cells; a shadow ray samples
     the ends and middles of its cells as the ends of 2 n cells
     (measured, see reach()).  Shadow rays are not refined: their
     transmittance is smooth in the coefficients, and each sample of a
     lit medium sends one (or an area light's grid of them). */
  int cells = reach_cells(m) * (m->shadow ? 2 : 1);
  int levels = m->pl.min_samples >= 3 && !m->shadow ? m->pl.aa_level - 1 : 0;
  double h = len / cells;
  /* Shadow rays' jitter moves where each sample's coefficients are
     taken forward by up to jitter / (n + 1) of the interval (n =
     reach_cells()): bench/media_shadow.py's "jitter 0.5" case, where
     povray's mean density rises from 0.344 to 0.429, a shift of 0.085
     against 0.5 * 0.5 / 3 = 0.083 for samples 3. */
  double shove = m->shadow ? m->pl.jitter * len / (reach_cells(m) + 1) : 0.0;
  sample a = jittered(m, s0, s0, shove);
  for (int i = 1; i <= cells; i++) {
    /* A shadow ray that keeps less than 1e-6 of the light stops (our
       own cut: 1/65535 is 1.5e-5). */
    if (m->shadow && rgb_max(m->t) < 1e-6)
      return;
    double s = i == cells ? s1 : s0 + i * h;
    if (!m->shadow && i < cells && m->pl.jitter > 0.0)
      s += m->pl.jitter * h * (uniform(m) - 0.5);
    sample b = jittered(m, s0, s, shove);
    if (m->shadow)
      add_span(m, &a, &b);
    else
      gather_cell(m, &a, &b, levels);
    a = b;
  }
}

/* ----- methods 1 and 2 --------------------------------------------------- */

/* The standard normal quantile for p in (0, 1): Abramowitz and Stegun,
   "Handbook of Mathematical Functions", 26.2.23 (error below 4.5e-4). */
static double normal_quantile(double p) {
  bool upper = p > 0.5;
  double q = upper ? 1.0 - p : p;
  if (q <= 0.0)
    return upper ? INFINITY : -INFINITY;
  double t = sqrt(-2.0 * log(q));
  double z = t - (2.515517 + t * (0.802853 + t * 0.010328)) /
                     (1.0 + t * (1.432788 + t * (0.189269 + t * 0.001308)));
  return upper ? z : -z;
}

/* The p-quantile of chi-square with df degrees of freedom: Wilson and
   Hilferty's cube-root normal approximation (1931). */
static double chi2_quantile(double p, double df) {
  double a = 2.0 / (9.0 * df);
  double x = 1.0 - a + normal_quantile(p) * sqrt(a);
  return x > 0.0 ? df * x * x * x : 0.0;
}

/* Whether n samples with these sums pin the mean down well enough. */
static bool settled(const march *m, int n, double sum, double sum2) {
  if (n < 2)
    return false;
  double mean = sum / n;
  double spread = fmax(0.0, (sum2 - n * mean * mean) / (n - 1));
  if (spread == 0.0)
    return true;
  double q = chi2_quantile(1.0 - m->pl.confidence, n - 1);
  if (!(q > 0.0))
    return false;
  return (n - 1) * spread / (q * n) <= m->pl.variance;
}

static int by_distance(const void *a, const void *b) {
  double sa = ((const sample *)a)->s, sb = ((const sample *)b)->s;
  return (sa > sb) - (sa < sb);
}

static void random_interval(march *m, double s0, double s1) {
  double len = s1 - s0;
  sample pts[MAX_RANDOM];
  int lo = m->pl.min_samples < 1 ? 1 : m->pl.min_samples;
  int hi = m->pl.max_samples < lo ? lo : m->pl.max_samples;
  if (hi > MAX_RANDOM)
    hi = MAX_RANDOM;
  if (lo > hi)
    lo = hi;
  double sum = 0.0, sum2 = 0.0;
  int n = 0;
  for (; n < lo; n++) {
    double u = m->pl.method == 1
                   ? uniform(m)
                   : (n + 0.5 + m->pl.jitter * (uniform(m) - 0.5)) / lo;
    pts[n] = sample_at(m, s0 + len * u);
    double x = measure(&pts[n], len);
    sum += x;
    sum2 += x * x;
  }
  while (n < hi && !settled(m, n, sum, sum2)) {
    pts[n] = sample_at(m, s0 + len * uniform(m));
    double x = measure(&pts[n], len);
    sum += x;
    sum2 += x * x;
    n++;
  }
  qsort(pts, (size_t)n, sizeof pts[0], by_distance);
  sample first = moved(&pts[0], s0), last = moved(&pts[n - 1], s1);
  add_span(m, &first, &pts[0]);
  for (int i = 1; i < n; i++)
    add_span(m, &pts[i - 1], &pts[i]);
  add_span(m, &pts[n - 1], &last);
}

/* ----- lit pieces of the ray ---------------------------------------------- */

/* Adds the roots in (0, depth) of a t^2 + b t + c to cuts. */
static int add_roots(double a, double b, double c, double depth,
                     double *cuts, int n) {
  double r[2];
  int k = 0;
  if (fabs(a) < 1e-14) { /* ours: a below rounding, the linear case */
    if (b != 0.0)
      r[k++] = -c / b;
  } else {
    double disc = b * b - 4.0 * a * c;
    if (disc >= 0.0) {
      /* The root of larger magnitude first, the other from the product
         of the roots, which keeps both precise. */
      double q = -0.5 * (b + copysign(sqrt(disc), b));
      r[k++] = q / a;
      if (q != 0.0)
        r[k++] = c / q;
    }
  }
  for (int i = 0; i < k; i++)
    if (r[i] > 0.0 && r[i] < depth && n < MAX_PIECES - 1)
      cuts[n++] = r[i];
  return n;
}

/* The distances where the ray crosses the boundary of the light's cone
   (spotlight: the angle to the axis equals falloff) or tube (cylinder
   light: the distance to the axis equals falloff, and the plane of the
   light's location), and where it passes BEAM_REACH. */
static int light_cuts(const march *m, const zr_light *light, double depth,
                      double *cuts, int n) {
  /* No beam when point_at is the location (its derived axis is then
     <0,1,0>, which lights_media() does not single out). */
  if (!(zr_v3_len(zr_v3_sub(light->point_at, light->location)) > 0.0))
    return n;
  zr_vec3 axis = zr_v3_scale(light->axis, -1.0);
  zr_vec3 w = zr_v3_sub(m->origin, light->location);
  double dw = zr_v3_dot(m->dir, axis), ww = zr_v3_dot(w, axis);
  if (light->kind == ZR_LIGHT_SPOT) {
    /* (w + t d) . axis = cos(falloff) |w + t d|, squared. */
    double cf = light->cos_falloff;
    double c2 = cf * cf;
    n = add_roots(dw * dw - c2, 2.0 * (dw * ww - c2 * zr_v3_dot(w, m->dir)),
                  ww * ww - c2 * zr_v3_dot(w, w), depth, cuts, n);
    if (fabs(dw) > 1e-14)
      n = add_roots(0.0, dw, ww, depth, cuts, n); /* the apex's plane */
  } else {
    /* |(w + t d) - ((w + t d) . axis) axis|^2 = falloff^2. */
    zr_vec3 pd = zr_v3_madd(m->dir, axis, -dw), pw = zr_v3_madd(w, axis, -ww);
    n = add_roots(zr_v3_dot(pd, pd), 2.0 * zr_v3_dot(pd, pw),
                  zr_v3_dot(pw, pw) - light->falloff * light->falloff, depth,
                  cuts, n);
    n = add_roots(0.0, dw, ww, depth, cuts, n);
  }
  if (BEAM_REACH < depth && n < MAX_PIECES - 1)
    cuts[n++] = BEAM_REACH;
  return n;
}

static int by_value(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* Cuts [0, depth] into pieces (ends[0] = 0 < ends[1] < ... = depth) and
   tells which ones a spotlight or cylinder light lights; their number. */
static int pieces(march *m, double depth, double *ends, bool *lit,
                  uint64_t *beams) {
  int n = 0;
  ends[n++] = 0.0;
  const zr_scene *scene = m->tr->scene;
  bool beams_any = false;
  if (m->lights)
    for (size_t i = 0; i < scene->n_lights; i++) {
      const zr_light *light = &scene->lights[i];
      if (light->kind == ZR_LIGHT_POINT || !lights_media(light, 0.0))
        continue;
      beams_any = true;
      n = light_cuts(m, light, depth, ends, n);
    }
  /* Every cut was kept (none fell off the end of ends) and every light
     fits in a mask: the masks can be trusted. */
  m->beams_known = n < MAX_PIECES - 1 && scene->n_lights <= 64;
  m->points = 0;
  if (m->beams_known)
    for (size_t i = 0; i < scene->n_lights; i++)
      if (scene->lights[i].kind == ZR_LIGHT_POINT &&
          lights_media(&scene->lights[i], 0.0))
        m->points |= (uint64_t)1 << i;
  ends[n++] = depth;
  qsort(ends, (size_t)n, sizeof ends[0], by_value);
  int k = 1;
  for (int i = 1; i < n; i++)
    if (ends[i] > ends[k - 1])
      ends[k++] = ends[i];
  /* A piece is lit when its middle is inside some beam. */
  for (int i = 0; i + 1 < k; i++) {
    lit[i] = false;
    beams[i] = 0;
    if (!beams_any)
      continue;
    double mid = 0.5 * (ends[i] + ends[i + 1]);
    zr_vec3 p = zr_v3_madd(m->origin, m->dir, mid);
    for (size_t li = 0; li < scene->n_lights; li++) {
      const zr_light *light = &scene->lights[li];
      if (light->kind != ZR_LIGHT_POINT && lights_media(light, mid) &&
          zr__light_cone(light, p) > 0.0) {
        lit[i] = true;
        if (li < 64)
          beams[i] |= (uint64_t)1 << li;
      }
    }
  }
  return k - 1;
}

/* ----- one integration ---------------------------------------------------- */

static plan plan_of(const zr_medium *const *list, size_t n) {
  plan p = {list[0]->method, 1, 1, 1, 0, list[0]->ratio, 0.0, INFINITY,
            0.0, INFINITY};
  for (size_t i = 0; i < n; i++) {
    const zr_medium *m = list[i];
    p.intervals = m->intervals > p.intervals ? m->intervals : p.intervals;
    p.min_samples =
        m->min_samples > p.min_samples ? m->min_samples : p.min_samples;
    p.max_samples =
        m->max_samples > p.max_samples ? m->max_samples : p.max_samples;
    p.aa_level = m->aa_level > p.aa_level ? m->aa_level : p.aa_level;
    p.aa_threshold = fmin(p.aa_threshold, m->aa_threshold);
    p.jitter = fmax(p.jitter, m->jitter);
    p.confidence = fmax(p.confidence, m->confidence);
    p.variance = fmin(p.variance, m->variance);
  }
  if (p.aa_level > 30)
    p.aa_level = 30;
  if (p.intervals > MAX_INTERVALS)
    p.intervals = MAX_INTERVALS;
  return p;
}

static void run_interval(march *m, double s0, double s1) {
  if (!(s1 > s0))
    return;
  if (!m->varies && m->pl.method == 3 && !m->shadow) {
    /* Constant coefficients: the cells of gather_cell() without
       sampling again (no cell is halved). */
    m->reach = reach(m);
    int cells = reach_cells(m);
    double h = (s1 - s0) / cells;
    sample a = sample_at(m, s0);
    for (int i = 0; i < cells; i++) {
      sample from = moved(&a, s0 + i * h);
      sample to = moved(&a, i + 1 == cells ? s1 : s0 + (i + 1) * h);
      add_cell(m, &from, &from, &to);
    }
  } else if (!m->varies) {
    /* Constant coefficients: one span is exact. */
    sample a = sample_at(m, s0), b = moved(&a, s1);
    add_span(m, &a, &b);
  } else if (m->pl.method == 3) {
    adaptive_interval(m, s0, s1);
  } else {
    random_interval(m, s0, s1);
  }
}

zr_rgb zr__media_integrate(const zr_tracer *tracer,
                           const zr_medium *const *list, size_t n,
                           zr_vec3 origin, zr_vec3 dir, double depth,
                           bool shadow, zr_rgb colour) {
  if (n == 0 || !(depth > 0.0))
    return colour;
  if (n > ZR_MEDIA_LIST_MAX)
    n = ZR_MEDIA_LIST_MAX;
  march m = {.tr = tracer, .list = list, .n = n, .origin = origin,
             .dir = dir, .shadow = shadow, .t = zr_rgb3(1, 1, 1),
             .light = zr_rgb3(0, 0, 0)};
  m.pl = plan_of(list, n);
  bool scatters = false;
  for (size_t i = 0; i < n; i++) {
    scatters = scatters || !rgb_zero(list[i]->scattering);
    m.varies = m.varies || list[i]->n_density > 0;
  }
  m.lights = scatters && !shadow && tracer->scene->n_lights > 0;
  /* Lit media change along the ray with distance, shadows and cones. */
  m.varies = m.varies || m.lights;
  m.seed = ray_key(origin, dir);

  double ends[MAX_PIECES + 1];
  bool lit[MAX_PIECES];
  uint64_t beams[MAX_PIECES];
  int np = pieces(&m, depth, ends, lit, beams);
  /* Deal the intervals out: each piece one, then one at a time to the
     piece with the fewest for its weight. */
  int count[MAX_PIECES];
  double weight[MAX_PIECES];
  for (int i = 0; i < np; i++) {
    count[i] = 1;
    double r = lit[i] ? m.pl.ratio : 1.0 - m.pl.ratio;
    /* ratio 0 or 1 would leave a piece no weight: 1e-6 (ours) keeps
       every piece in the deal without changing a real share. */
    weight[i] = (ends[i + 1] - ends[i]) * fmax(r, 1e-6);
  }
  /* Every interval counts in method 3 on rays that gather light, even
     in constant media (their cells are not exact: add_cell()). */
  if (m.varies || (m.pl.method == 3 && !shadow))
    for (int left = m.pl.intervals - np; left > 0; left--) {
      int best = 0;
      for (int i = 1; i < np; i++)
        if (weight[i] * count[best] > weight[best] * count[i])
          best = i;
      count[best]++;
    }
  for (int i = 0; i < np; i++) {
    double h = (ends[i + 1] - ends[i]) / count[i];
    m.beams = beams[i];
    for (int k = 0; k < count[i]; k++) {
      double s0 = ends[i] + k * h;
      double s1 = k + 1 == count[i] ? ends[i + 1] : s0 + h;
      run_interval(&m, s0, s1);
    }
  }
  return zr_rgb_add(zr_rgb_mul(colour, m.t), m.light);
}

/* ----- the ray's media ---------------------------------------------------- */

zr_rgb zr__media_along(const zr_tracer *tracer, const zr_media *inside,
                       zr_vec3 origin, zr_vec3 dir, double t,
                       zr_rgb colour) {
  const zr_settings *settings = &tracer->scene->settings;
  if (tracer->no_media)
    return colour; /* radiosity { media off }'s sample rays */
  const zr_medium *list[ZR_MEDIA_LIST_MAX];
  size_t n = 0;
  for (int i = 0; inside && i < inside->n; i++) {
    const zr_object *o = inside->objects[i];
    if (!o->hollow)
      return colour; /* a solid object holds no media a ray sees */
    const zr_interior *in = inside->interiors[i];
    for (size_t k = 0; in && k < in->n_media && n < ZR_MEDIA_LIST_MAX; k++)
      list[n++] = in->media[k];
  }
  if (n == 0 && settings->n_media == 0)
    return colour;
  double len = zr_v3_len(dir);
  if (!(len > 0.0))
    return colour;
  zr_vec3 unit = zr_v3_scale(dir, 1.0 / len);
  bool sky = isinf(t);
  double depth = sky ? SKY_DEPTH : t * len;
  /* Interior media only up to a surface; the atmosphere's beyond.  The
     samples' shadow rays start in the ray's interiors
     (zr__media_sample_shadow). */
  if (n > 0 && !sky) {
    zr_tracer sampling = *tracer;
    sampling.media_start = inside;
    colour = zr__media_integrate(&sampling, list, n, origin, unit, depth,
                                 false, colour);
  }
  if (settings->n_media > 0)
    colour = zr__media_integrate(tracer, settings->media, settings->n_media,
                                 origin, unit, depth, false, colour);
  return colour;
}

zr_rgb zr__media_light_attenuation(const zr_tracer *tracer,
                                   const zr_light *light, zr_vec3 p) {
  const zr_settings *settings = &tracer->scene->settings;
  zr_rgb one = zr_rgb3(1, 1, 1);
  if (!light->media_attenuation ||
      (settings->n_media == 0 && !settings->fogs))
    return one;
  zr_vec3 to_light = zr_v3_sub(light->location, p);
  double len = zr_v3_len(to_light);
  if (!(len > 0.0))
    return one;
  zr_vec3 unit = zr_v3_scale(to_light, 1.0 / len);
  /* Fog dims the light too (lib/trace/atmosphere.c). */
  one = zr__fog_attenuate(tracer->scene, p, unit, len, one);
  if (settings->n_media == 0)
    return one;
  return zr__media_integrate(tracer, settings->media, settings->n_media, p,
                             unit, len, true, one);
}

static int by_crossing(const void *a, const void *b) {
  double ta = ((const zr_media_crossing *)a)->t;
  double tb = ((const zr_media_crossing *)b)->t;
  return (ta > tb) - (ta < tb);
}

/* A shadow ray's stretch from a to b (fractions of dir, whose length is
   len and direction unit): the media of every container k with in[k]
   add up there, as on a camera ray; kept is the light that reached a. */
static zr_rgb shadow_stretch(const zr_tracer *tracer,
                             const zr_object *const *box, const bool *in,
                             int nb, zr_vec3 origin, zr_vec3 dir,
                             zr_vec3 unit, double a, double b, double len,
                             zr_rgb kept) {
  const zr_medium *list[ZR_MEDIA_LIST_MAX];
  size_t nl = 0;
  for (int k = 0; k < nb; k++) {
    const zr_interior *it = box[k]->interior;
    for (size_t q = 0; in[k] && it && q < it->n_media &&
                       nl < ZR_MEDIA_LIST_MAX;
         q++)
      list[nl++] = it->media[q];
  }
  if (nl == 0)
    return kept;
  return zr__media_integrate(tracer, list, nl, zr_v3_madd(origin, dir, a),
                             unit, (b - a) * len, true, kept);
}

/* The most containers one shadow ray follows at once. */
#define SHADOW_CONTAINERS 32

/*
 * The walk shared by both kinds of shadow ray (below): the containers
 * the crossings meet, whether the ray is in each at its start, then
 * from crossing to crossing the media of every container it is in add
 * up there (as on a camera ray).  A plain shadow ray (sample false) is
 * in from the start those containers whose first crossing leaves them,
 * and each crossing puts it where the crossing says; a media sample's
 * (sample true) starts in the containers of start and follows the rule
 * described at zr__media_sample_shadow.
 */
static zr_rgb shadow_walk(const zr_tracer *tracer, zr_vec3 origin,
                          zr_vec3 dir, zr_media_crossing *crossings,
                          size_t n, bool sample, const zr_media *start) {
  zr_rgb kept = zr_rgb3(1, 1, 1);
  double len = zr_v3_len(dir);
  if (n == 0 || !(len > 0.0))
    return kept;
  zr_vec3 unit = zr_v3_scale(dir, 1.0 / len);
  qsort(crossings, n, sizeof *crossings, by_crossing);
  /* The surface a sample lies on: crossings nearer than the margin
     shadow_visit (lib/trace/shade.c) looks past a hit by.  The walk
     finds that surface again 1e-7 to 2e-6 units away in the shell
     described at zr__media_sample_shadow (0.3 to 4 of
     zr__surface_offset). */
  double near = sample ? 1e3 * zr__surface_offset(origin) / len : 0.0;
  const zr_object *box[SHADOW_CONTAINERS];
  bool in[SHADOW_CONTAINERS];
  int nb = 0;
  for (size_t i = 0; i < n; i++) {
    int k = 0;
    while (k < nb && box[k] != crossings[i].solid)
      k++;
    if (k == nb && nb < SHADOW_CONTAINERS) {
      box[nb] = crossings[i].solid;
      in[nb] = !sample && !crossings[i].entering;
      for (int q = 0; sample && start && q < start->n; q++)
        if (start->objects[q] == box[nb])
          in[nb] = true;
      nb++;
    }
  }
  double from = 0.0;
  for (size_t i = 0; i <= n; i++) {
    if (sample && i < n && crossings[i].t <= near)
      continue;
    double to = i < n ? fmin(fmax(crossings[i].t, 0.0), 1.0) : 1.0;
    if (to > from) {
      kept = shadow_stretch(tracer, box, in, nb, origin, dir, unit, from,
                            to, len, kept);
      from = to;
    }
    if (i < n)
      for (int k = 0; k < nb; k++)
        if (box[k] == crossings[i].solid)
          in[k] = sample ? !in[k] && crossings[i].entering
                         : crossings[i].entering;
  }
  return kept;
}

zr_rgb zr__media_shadow(const zr_tracer *tracer, zr_vec3 origin,
                        zr_vec3 dir, zr_media_crossing *crossings,
                        size_t n) {
  return shadow_walk(tracer, origin, dir, crossings, n, false, NULL);
}

/*
 * A media sample's shadow ray, as povray 3.7 takes it: it starts inside
 * the containers the sampled ray is in; a crossing of a container's
 * surface takes it out of a container it is in, whichever side it
 * meets, and into one it is not in only where it goes in; the surface a
 * sample lies on (the first sample of a ray's stretch, where the ray
 * went in) is no crossing.  Away from surfaces this is what
 * zr__media_shadow finds.  On the surface it is not: a sample on the
 * inner surface of a shell of media (a difference of two spheres, the
 * camera in the hole) whose shadow ray heads back into the hole counts
 * the hole up to its far side as medium, and the shell behind it and
 * the way beyond as clear.  A model of the camera rays of such a scene
 * (scaled <1, 1, 0.4>, light <-10, 12, 3>; 4 cells of method 3, the
 * first sample's light by this rule) gives povray's pixels to the
 * level along a row, 78 79 81 83 86 89 93 98 105 114 where the rule of
 * zr__media_shadow gives 74 ... 87, and so does zRcube now
 * (tests/test_media_shell.sh case 7; toggling at every crossing, which
 * goes back into the shell past its outer surface, gave 70 ... 85).
 */
zr_rgb zr__media_sample_shadow(const zr_tracer *tracer, zr_vec3 origin,
                               zr_vec3 dir, zr_media_crossing *crossings,
                               size_t n, const zr_media *start) {
  return shadow_walk(tracer, origin, dir, crossings, n, true, start);
}
