/*
 * media.c - participating media (reference manual, "Media", "Object
 * Media", "Atmospheric Media", "Empty and Solid Objects"), integrated
 * the way POV-Ray 3.7 does it so that pictures match.
 *
 * A ray segment from its origin (distance 0) to the surface it hits
 * (distance D) is sampled.  At a point the media's coefficients are
 * their colours times the product of their densities' colours there
 * (no density: 1); the extinction is absorption + extinction factor *
 * scattering, the source is emission plus, for scattering media, the
 * light of every light source with media_interaction that reaches the
 * point (after shadows, which the media of crossed containers dim)
 * times the scattering colour and the phase function's value for the
 * angle between the light and the ray: 1 (isotropic), Mie hazy
 * 0.576655375 (1 + 9 ((1 + a) / 2)^8), Mie murky
 * 0.495714547 (1 + 50 ((1 + a) / 2)^32), Rayleigh
 * 0.799372013 (1 + a^2) and Henyey-Greenstein
 * (1 - g^2) / (1 + g^2 - 2 g a)^1.5, a the cosine between the
 * direction toward the light and the ray's, averaged over the media.
 *
 * The segment is cut into intervals.  Spotlights and cylinder lights
 * light stretches of it (where it crosses their cone or tube), which
 * get intervals of their own, shared out by ratio between lit and unlit
 * stretches; otherwise `intervals` equal ones (one for constant media
 * not lit by anything).  Each interval then takes:
 *   - method 3 (the default): samples at the ends of sub-intervals
 *     and, recursively, at midpoints where two neighbouring samples
 *     differ by more than aa_threshold (the sum of the channels'
 *     differences), up to aa_level deep, averaging 1:1:1 at the deepest
 *     level and 2:1 / 1:2 elsewhere, as POV-Ray 3.7 weighs them; min
 *     samples sets the number of sub-intervals (adaptive() below says
 *     how, with the quirks of povray 3.7.0 that renders show); jitter
 *     moves each point by up to jitter times its spacing.
 *   - methods 1 and 2: min samples at random points (1) or evenly
 *     spread, jittered, ones (2), each source sample dimmed by
 *     exp(-extinction * its distance into the interval), then more
 *     random samples up to max while the variance of the samples is
 *     above variance scaled by the chi-square quantile for confidence.
 * The intervals then combine front to back:
 *     seen = colour * exp(-sum od) + sum_i te_i exp(-sum_{j<i} od_j)
 * with od and te an interval's mean optical depth and source times its
 * length.  For one interval of constant media with absorption a and
 * emission e, method 3 and the default samples 10 this is
 * colour exp(-a D) + e D (1/6) sum_{j<6} exp(-j a D / 6), which
 * tests/test_media.c checks.
 *
 * Media inside objects are seen only by rays inside hollow objects
 * (every object the ray is in must be hollow), as POV-Ray renders them,
 * and only up to a surface; atmospheric media likewise, and on a ray
 * that hits nothing out to 2e10 units, POV-Ray's BOUND_HUGE: the manual
 * says no media show against the background, and indeed their
 * extinction hides it (povray 3.7 renders a background seen through
 * scattering haze black, with a spotlight's beam across it; a cone the
 * ray never leaves ends at 1e7, povray's MAX_DISTANCE).  Random numbers
 * (method 1, jitter) come from a hash of the ray and the sample's
 * number, so an image is the same for any number of threads and ranks.
 */
#include "trace/media.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "scene/texture.h"
#include "trace/lights.h"

#define MAX_LIGHTS 64
#define MAX_INTERVALS 512
/* POV-Ray's lengths for a ray that hits nothing (BOUND_HUGE) and for a
   spotlight's cone or a cylinder light's tube that the ray never leaves
   (MAX_DISTANCE). */
#define SKY_DEPTH 2e10
#define LIGHT_REACH 1e7

typedef struct lit_span {
  bool lit;
  double s0, s1;
} lit_span;

typedef struct interval {
  bool lit;
  double s0, ds;
  zr_rgb od, te, te2;
  int samples;
} interval;

/* What one integration needs. */
typedef struct walk {
  const zr_tracer *tr;
  const zr_medium *const *list;
  size_t n;
  zr_vec3 origin, dir; /* dir unit */
  bool shadow;
  bool scattering; /* some medium scatters and the ray is not a shadow */
  uint64_t seed;
  uint64_t draws;
} walk;

static double rgb_max(zr_rgb c) { return fmax(c.r, fmax(c.g, c.b)); }

static zr_rgb rgb_exp_neg(zr_rgb c) {
  return zr_rgb3(exp(-c.r), exp(-c.g), exp(-c.b));
}

static bool rgb_is_zero(zr_rgb c) {
  return c.r == 0.0 && c.g == 0.0 && c.b == 0.0;
}

static uint64_t mix64(uint64_t h) {
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdu;
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53u;
  h ^= h >> 33;
  return h;
}

/* The ray's seed: a hash of its origin and direction. */
static uint64_t ray_seed(zr_vec3 o, zr_vec3 d) {
  double c[6] = {o.x, o.y, o.z, d.x, d.y, d.z};
  uint64_t h = 0x9e3779b97f4a7c15u;
  for (int i = 0; i < 6; i++) {
    uint64_t bits;
    memcpy(&bits, &c[i], sizeof bits);
    h = mix64(h ^ (bits + 0x9e3779b97f4a7c15u + (h << 6)));
  }
  return h;
}

/* The walk's next number in [0, 1). */
static double next_random(walk *w) {
  uint64_t h = mix64(w->seed + 0x9e3779b97f4a7c15u * ++w->draws);
  return (double)(h >> 11) / 9007199254740992.0;
}

static double phase(const zr_medium *m, double a) {
  switch (m->scattering_type) {
  case ZR_SCATTER_RAYLEIGH:
    return 0.799372013 * (1.0 + a * a);
  case ZR_SCATTER_MIE_HAZY:
    return 0.576655375 * (1.0 + 9.0 * pow(0.5 * (1.0 + a), 8.0));
  case ZR_SCATTER_MIE_MURKY:
    return 0.495714547 * (1.0 + 50.0 * pow(0.5 * (1.0 + a), 32.0));
  case ZR_SCATTER_HENYEY_GREENSTEIN: {
    double g = m->eccentricity;
    return (1.0 - g * g) / pow(1.0 + g * g - 2.0 * g * a, 1.5);
  }
  default:
    return 1.0;
  }
}

/* The product of the medium's densities at p. */
static zr_rgb density_at(const zr_medium *m, zr_vec3 p) {
  zr_rgb d = zr_rgb3(1, 1, 1);
  for (size_t i = 0; i < m->n_density; i++)
    d = zr_rgb_mul(d, zr_colour_rgb(zr__pigment_eval(m->density[i], p)));
  return d;
}

/* Light scattered toward the ray's origin at p by scattering sc. */
static zr_rgb in_scattered(const walk *w, zr_vec3 p, zr_rgb sc) {
  const zr_scene *scene = w->tr->scene;
  zr_rgb sum = zr_rgb3(0, 0, 0);
  for (size_t i = 0; i < scene->n_lights; i++) {
    const zr_light *light = &scene->lights[i];
    /* A light_group's lights light no media: zRcube does not yet tell
       a group's media from others. */
    if (!light->media_interaction || light->light_group != 0)
      continue;
    zr_vec3 l;
    zr_rgb lc;
    if (!zr__light_arrive(light, p, &l, &lc) || rgb_max(lc) <= 0.0)
      continue;
    lc = zr_rgb_mul(lc, zr__light_visibility(w->tr, light, p, p));
    if (rgb_max(lc) <= 0.0)
      continue;
    lc = zr_rgb_mul(lc, zr__media_light_attenuation(w->tr, light, p));
    double a = zr_v3_dot(l, w->dir), k = 0.0;
    for (size_t j = 0; j < w->n; j++)
      k += phase(w->list[j], a);
    k /= (double)w->n;
    sum = zr_rgb_add(sum, zr_rgb_scale(zr_rgb_mul(sc, lc), k));
  }
  return sum;
}

/*
 * One sample at fraction f of interval iv: *source is the light the
 * media send toward the origin there times the interval's length
 * (dimmed within the interval for methods 1 and 2), *od the optical
 * depth the interval would have were the media everywhere as here.
 */
static void sample(walk *w, interval *iv, double f, int method,
                   zr_rgb *source, zr_rgb *od) {
  double into = f * iv->ds;
  zr_vec3 p = zr_v3_madd(w->origin, w->dir, iv->s0 + into);
  zr_rgb ext = zr_rgb3(0, 0, 0), em = ext, sc = ext;
  for (size_t i = 0; i < w->n; i++) {
    const zr_medium *m = w->list[i];
    zr_rgb d = density_at(m, p);
    zr_rgb e = zr_rgb_madd(m->absorption, m->scattering, m->extinction);
    ext = zr_rgb_add(ext, zr_rgb_mul(d, e));
    if (!w->shadow) {
      em = zr_rgb_add(em, zr_rgb_mul(d, m->emission));
      sc = zr_rgb_add(sc, zr_rgb_mul(d, m->scattering));
    }
  }
  *od = zr_rgb_scale(ext, iv->ds);
  if (w->scattering && iv->lit && !rgb_is_zero(sc))
    em = zr_rgb_add(em, in_scattered(w, p, sc));
  if (method == 3) {
    em = zr_rgb_scale(em, iv->ds);
  } else {
    em = zr_rgb_mul(zr_rgb_scale(em, iv->ds),
                    rgb_exp_neg(zr_rgb_scale(ext, into)));
    iv->od = zr_rgb_add(iv->od, *od);
    iv->te = zr_rgb_add(iv->te, em);
    iv->te2 = zr_rgb_add(iv->te2, zr_rgb_mul(em, em));
  }
  *source = em;
  iv->samples++;
}

static double colour_distance(zr_rgb a, zr_rgb b) {
  return fabs(a.r - b.r) + fabs(a.g - b.g) + fabs(a.b - b.b);
}

/* Method 3 between fractions f1 and f3 with samples c1, c3 there. */
static void sample_recursive(walk *w, interval *iv, double f1, double f3,
                             zr_rgb c1, zr_rgb c3, zr_rgb od1, zr_rgb od3,
                             int depth, double jitter, double threshold,
                             zr_rgb *result, zr_rgb *od_result) {
  double f2 = 0.5 * (f1 + f3) + jitter * (f3 - f1) * (next_random(w) - 0.5);
  zr_rgb c2, od2;
  sample(w, iv, f2, 3, &c2, &od2);
  if (depth <= 0) {
    *result = zr_rgb_scale(zr_rgb_add(zr_rgb_add(c1, c2), c3), 1.0 / 3.0);
    *od_result =
        zr_rgb_scale(zr_rgb_add(zr_rgb_add(od1, od2), od3), 1.0 / 3.0);
    return;
  }
  zr_rgb r, o;
  if (colour_distance(c1, c2) > threshold) {
    sample_recursive(w, iv, f1, f2, c1, c2, od1, od2, depth - 1, jitter,
                     threshold, &r, &o);
    *result = zr_rgb_scale(r, 0.5);
    *od_result = zr_rgb_scale(o, 0.5);
  } else {
    *result = zr_rgb_add(zr_rgb_scale(c1, 1.0 / 3.0),
                         zr_rgb_scale(c2, 1.0 / 6.0));
    *od_result = zr_rgb_add(zr_rgb_scale(od1, 1.0 / 3.0),
                            zr_rgb_scale(od2, 1.0 / 6.0));
  }
  if (colour_distance(c2, c3) > threshold) {
    sample_recursive(w, iv, f2, f3, c2, c3, od2, od3, depth - 1, jitter,
                     threshold, &r, &o);
    *result = zr_rgb_madd(*result, r, 0.5);
    *od_result = zr_rgb_madd(*od_result, o, 0.5);
  } else {
    *result = zr_rgb_add(*result, zr_rgb_add(zr_rgb_scale(c2, 1.0 / 6.0),
                                             zr_rgb_scale(c3, 1.0 / 3.0)));
    *od_result =
        zr_rgb_add(*od_result, zr_rgb_add(zr_rgb_scale(od2, 1.0 / 6.0),
                                          zr_rgb_scale(od3, 1.0 / 3.0)));
  }
}

/*
 * Method 3 over one interval as POV-Ray 3.7.0 does it: s = max(2,
 * min / 2 + 1) sub-intervals of 1 / (s + 1) of the interval each (so
 * the last stretch of it is not sampled), sub-interval j's source
 * dimmed by exp(-od / s) for the optical depth od gathered before it.
 * povray 3.7.0 renders of constant media match this to 1e-4 (for
 * absorption a, emission e and length d, samples 10 gives
 * e d (1/6) sum_{j<6} exp(-j a d / 6)).
 */
static void adaptive(walk *w, interval *iv, const zr_medium *im,
                     double threshold) {
  int subs = im->min_samples / 2 + 1;
  if (subs < 2)
    subs = 2;
  double dd = 1.0 / (subs + 1), n = 1.0 / subs;
  zr_rgb c0, od0, c1, od1, r, o;
  sample(w, iv, dd * im->jitter * (next_random(w) - 0.5), 3, &c0, &od0);
  iv->te = iv->od = zr_rgb3(0, 0, 0);
  for (int j = 1; j <= subs; j++) {
    double f1 = j * dd;
    sample(w, iv, f1 + dd * im->jitter * (next_random(w) - 0.5), 3, &c1,
           &od1);
    sample_recursive(w, iv, f1 - dd, f1, c0, c1, od0, od1,
                     im->aa_level - 1, im->jitter, threshold, &r, &o);
    iv->te = zr_rgb_add(iv->te, zr_rgb_mul(r, rgb_exp_neg(
                                                  zr_rgb_scale(iv->od, n))));
    iv->od = zr_rgb_add(iv->od, o);
    c0 = c1;
    od0 = od1;
  }
  iv->samples = subs;
}

/*
 * The inverse of the upper tail of the chi-square distribution with df
 * degrees of freedom: the x with P(X > x) = q, by Wilson and Hilferty's
 * cube-root normal approximation (good to a few percent from df = 1,
 * enough for a stopping threshold).
 */
static double normal_quantile(double p) {
  /* Acklam's rational approximation of the inverse normal CDF. */
  static const double a[] = {-3.969683028665376e+01, 2.209460984245205e+02,
                             -2.759285104469687e+02, 1.383577518672690e+02,
                             -3.066479806614716e+01, 2.506628277459239e+00};
  static const double b[] = {-5.447609879822406e+01, 1.615858368580409e+02,
                             -1.556989798598866e+02, 6.680131188771972e+01,
                             -1.328068155288572e+01};
  static const double c[] = {-7.784894002430293e-03, -3.223964580411365e-01,
                             -2.400758277161838e+00, -2.549732539343734e+00,
                             4.374664141464968e+00, 2.938163982698783e+00};
  static const double d[] = {7.784695709041462e-03, 3.224671290700398e-01,
                             2.445134137142996e+00, 3.754408661907416e+00};
  if (p <= 0.0)
    return -INFINITY;
  if (p >= 1.0)
    return INFINITY;
  if (p < 0.02425) {
    double q = sqrt(-2.0 * log(p));
    return (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q +
            c[5]) /
           ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
  }
  if (p > 1.0 - 0.02425)
    return -normal_quantile(1.0 - p);
  double q = p - 0.5, r = q * q;
  return (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r +
          a[5]) *
         q /
         (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0);
}

static double chi2_upper_inverse(double df, double q) {
  double z = normal_quantile(1.0 - q);
  double k = 2.0 / (9.0 * df);
  double x = 1.0 - k + z * sqrt(k);
  return x > 0.0 ? df * x * x * x : 0.0;
}

/* POV-Ray's threshold on the variance after n samples. */
static double sample_threshold(const zr_medium *im, int n) {
  if (im->max_samples <= 1)
    return 0.0;
  double t = chi2_upper_inverse(im->max_samples - 1, im->confidence);
  t = t > 0.0 ? im->variance / t : im->variance * 1e-10;
  return t * chi2_upper_inverse(n, im->confidence);
}

static void regular(walk *w, interval *ivs, int n_iv, const zr_medium *im,
                    bool one_sample) {
  zr_rgb c, od;
  for (int i = 0; i < n_iv; i++)
    for (int j = 0; j < im->min_samples; j++) {
      double f = im->method == 2
                     ? (j + 0.5) / im->min_samples +
                           next_random(w) * im->jitter / im->min_samples
                     : next_random(w);
      sample(w, &ivs[i], f, im->method == 2 ? 2 : 1, &c, &od);
      if (one_sample)
        break;
    }
  if (w->shadow || im->max_samples <= im->min_samples)
    return;
  for (int i = 0; i < n_iv; i++) {
    interval *iv = &ivs[i];
    for (;;) {
      double k = 1.0 / iv->samples;
      zr_rgb m = zr_rgb_scale(iv->te, k);
      zr_rgb va = zr_rgb_scale(zr_rgb_madd(zr_rgb_scale(iv->te2, k),
                                           zr_rgb_mul(m, m), -1.0),
                               k);
      double limit = sample_threshold(im, iv->samples);
      if (va.r < limit && va.g < limit && va.b < limit)
        break;
      sample(w, iv, next_random(w), 1, &c, &od);
      if (iv->samples > im->max_samples)
        break;
    }
  }
}

/* ---- which stretches of the ray lights shine on ---- */

/* Whether point q is lit by the spot or cylinder light's shape. */
static bool in_light_shape(const zr_light *light, zr_vec3 axis, zr_vec3 q) {
  zr_vec3 v = zr_v3_sub(q, light->location);
  double along = zr_v3_dot(v, axis);
  if (light->kind == ZR_LIGHT_SPOT) {
    double c = cos(light->falloff * M_PI / 180.0);
    double len = zr_v3_len(v);
    return along > 0.0 && along >= c * len;
  }
  zr_vec3 off = zr_v3_madd(v, axis, -along);
  return along > 0.0 && zr_v3_len(off) <= light->falloff;
}

/*
 * The stretch [*s0, *s1] of [0, depth] inside a spotlight's cone or a
 * cylinder light's tube: both are convex, so it is one stretch, found
 * from the roots of the surface's quadratic and the plane through the
 * light across its axis.
 */
static bool light_span(const walk *w, const zr_light *light, double depth,
                       double *s0, double *s1) {
  zr_vec3 axis = zr_v3_norm(zr_v3_sub(light->point_at, light->location));
  zr_vec3 v = zr_v3_sub(w->origin, light->location);
  double k1 = zr_v3_dot(w->dir, axis), k2 = zr_v3_dot(v, axis);
  double k3 = zr_v3_dot(v, w->dir), k4 = zr_v3_dot(v, v);
  double qa, qb, qc;
  if (light->kind == ZR_LIGHT_SPOT) {
    double c = cos(light->falloff * M_PI / 180.0), c2 = c * c;
    qa = k1 * k1 - c2;
    qb = 2.0 * (k1 * k2 - c2 * k3);
    qc = k2 * k2 - c2 * k4;
  } else {
    double r = light->falloff;
    qa = 1.0 - k1 * k1;
    qb = 2.0 * (k3 - k1 * k2);
    qc = k4 - k2 * k2 - r * r;
  }
  double cuts[5];
  int n = 0;
  cuts[n++] = 0.0;
  if (fabs(qa) > 1e-12) {
    double disc = qb * qb - 4.0 * qa * qc;
    if (disc >= 0.0) {
      double sq = sqrt(disc);
      cuts[n++] = (-qb - sq) / (2.0 * qa);
      cuts[n++] = (-qb + sq) / (2.0 * qa);
    }
  } else if (fabs(qb) > 1e-12) {
    cuts[n++] = -qc / qb;
  }
  if (fabs(k1) > 1e-12)
    cuts[n++] = -k2 / k1;
  /* Sort the cuts inside [0, depth] and test each piece's middle. */
  double pts[7];
  int m = 0;
  for (int i = 0; i < n; i++)
    if (cuts[i] >= 0.0 && cuts[i] <= depth)
      pts[m++] = cuts[i];
  double end = fmin(depth, LIGHT_REACH);
  for (int i = 0; i < m; i++)
    pts[i] = fmin(pts[i], end);
  pts[m++] = end;
  for (int i = 1; i < m; i++)
    for (int j = i; j > 0 && pts[j - 1] > pts[j]; j--) {
      double t = pts[j];
      pts[j] = pts[j - 1];
      pts[j - 1] = t;
    }
  bool found = false;
  for (int i = 0; i + 1 < m; i++) {
    if (!(pts[i + 1] > pts[i]))
      continue;
    zr_vec3 mid = zr_v3_madd(w->origin, w->dir, 0.5 * (pts[i] + pts[i + 1]));
    if (!in_light_shape(light, axis, mid))
      continue;
    if (!found)
      *s0 = pts[i];
    *s1 = pts[i + 1];
    found = true;
  }
  return found;
}

static void sort_doubles(double *a, int n) {
  for (int i = 1; i < n; i++)
    for (int j = i; j > 0 && a[j - 1] > a[j]; j--) {
      double t = a[j];
      a[j] = a[j - 1];
      a[j - 1] = t;
    }
}

/* The lit and unlit stretches of [0, depth], as POV-Ray 3.7 forms them
   (the starts and the ends of the lights' stretches sorted apart). */
static int lit_spans(const walk *w, double depth, lit_span *out) {
  double s0[MAX_LIGHTS], s1[MAX_LIGHTS];
  int n = 0;
  const zr_scene *scene = w->tr->scene;
  for (size_t i = 0; i < scene->n_lights && n < MAX_LIGHTS; i++) {
    const zr_light *light = &scene->lights[i];
    /* A light_group's lights light no media: zRcube does not yet tell
       a group's media from others. */
    if (!light->media_interaction || light->light_group != 0)
      continue;
    if (light->kind == ZR_LIGHT_POINT) {
      s0[n] = 0.0;
      s1[n++] = depth;
    } else if (light_span(w, light, depth, &s0[n], &s1[n])) {
      n++;
    }
  }
  if (n == 0) {
    out[0] = (lit_span){false, 0.0, depth};
    return 1;
  }
  sort_doubles(s0, n);
  sort_doubles(s1, n);
  int k = 0;
  if (s0[0] > 0.0)
    out[k++] = (lit_span){false, 0.0, s0[0]};
  out[k++] = (lit_span){true, s0[0], s1[0]};
  for (int i = 1; i < n; i++) {
    if (s0[i] > out[k - 1].s1) {
      out[k] = (lit_span){false, out[k - 1].s1, s0[i]};
      k++;
      out[k++] = (lit_span){true, s0[i], s1[i]};
    } else if (s1[i] > out[k - 1].s1) {
      out[k - 1].s1 = s1[i];
    }
  }
  if (out[k - 1].s1 < depth) {
    out[k] = (lit_span){false, out[k - 1].s1, depth};
    k++;
  }
  return k;
}

static int add_interval(interval *ivs, int n, bool lit, double s0,
                        double ds) {
  if (n >= MAX_INTERVALS)
    return n;
  memset(&ivs[n], 0, sizeof ivs[n]);
  ivs[n].lit = lit;
  ivs[n].s0 = s0;
  ivs[n].ds = ds;
  return n + 1;
}

/* The sampling intervals over the stretches ("Sampling Parameters"). */
static int make_intervals(const lit_span *spans, int n_spans,
                          const zr_medium *im, bool constant, double depth,
                          interval *ivs) {
  int n = 0;
  int count = im->intervals > n_spans ? im->intervals : n_spans;
  if (count > MAX_INTERVALS)
    count = MAX_INTERVALS;
  if (n_spans == 1) {
    double ds = spans[0].s1 - spans[0].s0;
    if (!spans[0].lit && constant)
      return add_interval(ivs, 0, false, spans[0].s0, ds);
    for (int i = 0; i < count; i++)
      n = add_interval(ivs, n, spans[0].lit,
                       spans[0].s0 + ds * i / count, ds / count);
  } else {
    double sum = 0.0;
    for (int i = 0; i < n_spans; i++)
      sum += spans[i].lit ? im->ratio : 1.0 - im->ratio;
    int remaining = count;
    for (int i = 0; i < n_spans; i++) {
      double weight = spans[i].lit ? im->ratio : 1.0 - im->ratio;
      int k = (int)(weight / sum * count) + 1;
      int r = remaining - n_spans + i + 1;
      if (k > r)
        k = r;
      if (k < 1)
        k = 1;
      double ds = (spans[i].s1 - spans[i].s0) / k;
      for (int j = 0; j < k; j++)
        n = add_interval(ivs, n, spans[i].lit, spans[i].s0 + ds * j, ds);
      remaining -= k;
    }
  }
  /* Cover the ends, as POV-Ray does. */
  if (n > 0 && ivs[0].s0 > 0.0 && n < MAX_INTERVALS) {
    memmove(&ivs[1], &ivs[0], (size_t)n * sizeof *ivs);
    n++;
    memset(&ivs[0], 0, sizeof ivs[0]);
    ivs[0].ds = ivs[1].s0;
  }
  double end = n > 0 ? ivs[n - 1].s0 + ivs[n - 1].ds : 0.0;
  if (end < depth)
    n = add_interval(ivs, n, false, end, depth - end);
  return n;
}

zr_rgb zr__media_integrate(const zr_tracer *tracer,
                           const zr_medium *const *list, size_t n,
                           zr_vec3 origin, zr_vec3 dir, double depth,
                           bool shadow, zr_rgb colour) {
  if (n == 0 || !(depth > 0.0) || isinf(depth))
    return colour;
  walk w = {tracer, list, n, origin, dir, shadow, false,
            ray_seed(origin, dir), 0};
  const zr_medium *im = list[0];
  double threshold = INFINITY;
  bool extinction = false, constant = true;
  for (size_t i = 0; i < n; i++) {
    const zr_medium *m = list[i];
    if (m->intervals > im->intervals)
      im = m;
    threshold = fmin(threshold, m->aa_threshold);
    extinction = extinction || !rgb_is_zero(m->absorption) ||
                 !rgb_is_zero(m->scattering);
    w.scattering = w.scattering || (!shadow && !rgb_is_zero(m->scattering));
    constant = constant && m->n_density == 0;
  }
  if (shadow && !extinction)
    return colour;
  lit_span spans[2 * MAX_LIGHTS + 2];
  int n_spans = 1;
  spans[0] = (lit_span){false, 0.0, depth};
  if (!shadow)
    n_spans = lit_spans(&w, depth, spans);
  interval ivs[MAX_INTERVALS + 2];
  int n_iv = make_intervals(spans, n_spans, im, im->n_density == 0, depth,
                            ivs);
  bool one_sample = shadow && constant;
  if (im->method == 3 && !one_sample) {
    for (int i = 0; i < n_iv; i++)
      adaptive(&w, &ivs[i], im, threshold);
  } else {
    regular(&w, ivs, n_iv, im, one_sample);
  }
  zr_rgb od = zr_rgb3(0, 0, 0), te = od;
  for (int i = 0; i < n_iv; i++) {
    double k = ivs[i].samples > 0 ? 1.0 / ivs[i].samples : 0.0;
    te = zr_rgb_add(te, zr_rgb_mul(zr_rgb_scale(ivs[i].te, k),
                                   rgb_exp_neg(od)));
    od = zr_rgb_madd(od, ivs[i].od, k);
  }
  return zr_rgb_add(zr_rgb_mul(colour, rgb_exp_neg(od)), te);
}

/* Appends the media of in to list (n so far); the new count. */
static size_t gather(const zr_interior *in, const zr_medium **list,
                     size_t n) {
  for (size_t i = 0; in && i < in->n_media && n < ZR_MEDIA_LIST_MAX; i++)
    list[n++] = in->media[i];
  return n;
}

zr_rgb zr__media_along(const zr_tracer *tracer, const zr_media *inside,
                       zr_vec3 origin, zr_vec3 dir, double t,
                       zr_rgb colour) {
  const zr_settings *s = &tracer->scene->settings;
  if (tracer->no_media)
    return colour; /* radiosity { media off }'s sample rays */
  int depth_n = inside ? inside->n : 0;
  const zr_medium *list[ZR_MEDIA_LIST_MAX];
  size_t n = 0;
  for (int i = 0; i < depth_n; i++) {
    const zr_object *o = inside->objects[i];
    if (!o->hollow)
      return colour; /* a solid object blocks all media */
    n = gather(o->interior, list, n);
  }
  if (n == 0 && s->n_media == 0)
    return colour;
  double len = zr_v3_len(dir);
  if (!(len > 0.0))
    return colour;
  zr_vec3 unit = zr_v3_scale(dir, 1.0 / len);
  /* A ray to the sky sees no interior media (povray samples those only
     up to a surface), and atmospheric media out to SKY_DEPTH: their
     extinction hides the background, as povray renders it. */
  bool sky = isinf(t);
  double depth = sky ? SKY_DEPTH : t * len;
  if (n > 0 && !sky)
    colour = zr__media_integrate(tracer, list, n, origin, unit, depth, false,
                                 colour);
  if (s->n_media > 0)
    colour = zr__media_integrate(tracer, s->media, s->n_media, origin, unit,
                                 depth, false, colour);
  return colour;
}

zr_rgb zr__media_light_attenuation(const zr_tracer *tracer,
                                   const zr_light *light, zr_vec3 p) {
  const zr_settings *s = &tracer->scene->settings;
  if (!light->media_attenuation || s->n_media == 0)
    return zr_rgb3(1, 1, 1);
  zr_vec3 d = zr_v3_sub(light->location, p);
  double len = zr_v3_len(d);
  if (!(len > 0.0))
    return zr_rgb3(1, 1, 1);
  return zr__media_integrate(tracer, s->media, s->n_media, p,
                             zr_v3_scale(d, 1.0 / len), len, true,
                             zr_rgb3(1, 1, 1));
}

static int by_t(const void *a, const void *b) {
  double ta = ((const zr_media_crossing *)a)->t;
  double tb = ((const zr_media_crossing *)b)->t;
  return (ta > tb) - (ta < tb);
}

zr_rgb zr__media_shadow(const zr_tracer *tracer, zr_vec3 origin,
                        zr_vec3 dir, zr_media_crossing *crossings,
                        size_t n) {
  zr_rgb light = zr_rgb3(1, 1, 1);
  double len = zr_v3_len(dir);
  if (n == 0 || !(len > 0.0))
    return light;
  zr_vec3 unit = zr_v3_scale(dir, 1.0 / len);
  qsort(crossings, n, sizeof *crossings, by_t);
  /* Each container on its own: from where the ray is inside it (from
     the start when its first crossing leaves it) to where it leaves. */
  for (size_t i = 0; i < n; i++) {
    const zr_object *solid = crossings[i].solid;
    bool seen = false;
    for (size_t j = 0; j < i && !seen; j++)
      seen = crossings[j].solid == solid;
    if (seen)
      continue;
    const zr_interior *in = solid->interior;
    double start = crossings[i].entering ? -1.0 : 0.0;
    for (size_t j = i; j < n; j++) {
      if (crossings[j].solid != solid)
        continue;
      if (crossings[j].entering) {
        start = crossings[j].t;
        continue;
      }
      if (start >= 0.0) {
        zr_vec3 o = zr_v3_madd(origin, dir, start);
        light = zr__media_integrate(tracer, in->media, in->n_media, o, unit,
                                    (crossings[j].t - start) * len, true,
                                    light);
      }
      start = -1.0;
    }
    if (start >= 0.0) {
      zr_vec3 o = zr_v3_madd(origin, dir, start);
      light = zr__media_integrate(tracer, in->media, in->n_media, o, unit,
                                  (1.0 - start) * len, true, light);
    }
  }
  return light;
}
