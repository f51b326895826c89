/*
 * pattern.c - POV-Ray 3.7's patterns (reference manual, "Pattern",
 * "Pattern Modifiers", "Frequency and Phase", "Waveforms", "Turbulence").
 *
 * A pattern maps a point of pattern space to a number, and a colour map
 * (lib/scene/texture.c) turns the number into a colour.  The patterns
 * with a closed-form definition follow the manual exactly and were
 * checked against POV-Ray renders (tests/test_pattern.c and the golden
 * scene scenes/patterns.pov):
 *   checker   (floor x + floor y + floor z) mod 2;
 *   hexagon   hexagons of side 1 in the x-z plane, colour 1 centred at
 *             the origin, colour 2 one row along +z, colour 3 beside;
 *   brick     bricks of brick_size (<8,3,4.5>) with mortar at the high
 *             end of each brick along every axis; rows with an odd
 *             floor(y / size.y) are shifted half a brick along x, the
 *             others half a brick along z (measured on POV-Ray renders);
 *   gradient  p . v / |v|;  radial: the angle about +y from +x toward
 *             -z over 360 degrees;  onion |p|;  wood |(x, y)|;
 *             marble x;  leopard ((sin x + sin y + sin z) / 3)^2;
 *   planar, spherical, cylindrical, boxed: 1 - min(1, distance);
 *   slope     1 - angle(normal, direction) / pi, ranges and altitude
 *             as the manual's "Slope Pattern" says, measured against
 *             POV-Ray renders; the only pattern that needs the surface
 *             normal (zr__pattern_eval_n; a zero normal elsewhere).
 * Block patterns evaluate at the point moved by 1e-9 along every axis,
 * so a plane lying exactly on a cell boundary (y = 0) shows one cell as
 * it does in POV-Ray, not rounding noise.
 *
 * Noise is POV-Ray's, reconstructed from measurements of the povray
 * binary without its source (lib/core/noise.c; bench/noise/ holds the
 * probe scripts, tests/test_noise.c checks 6400 recorded values to
 * 1e-9).  The noise patterns, each formula found by
 * bench/noise/probe_patterns.py for noise_generator 2 (c(n) is 2 n - 0.5
 * clamped to [0, 1]):
 * (for noise_generator 1, c(n) is generator 1's noise itself):
 *   bozo, spotted, bumps  n(p);  dents  n(p)^3;
 *   wrinkles   half the sum over 10 octaves of c(n(2^i p)) / 2^i;
 *   granite    the sum over 6 octaves of |c(n(4 2^i p)) - 0.5| / 2^i;
 *   agate      (0.5 + 0.5 sin(2 pi (1.1 z + 1.3 agate_turb s)))^0.77, s
 *              = c(n(p)) + the sum over octaves 1..5 of (2 n(2^i p) -
 *              0.5) / 2^i;
 *   cells      one value per unit cell: the x coordinate of crackle's
 *              feature point of that cell (bench/noise/probe_cells.py);
 *   crackle    distance to the second nearest minus the nearest of one
 *              feature point per unit cell (form <-1,1,0>, metric 2),
 *              the points measured (bench/noise/probe_crackle.py);
 *              form weighs the three nearest distances, metric m
 *              measures them as (|dx|^m + |dy|^m + |dz|^m)^(1/m),
 *              offset is a fourth coordinate of every distance, solid
 *              gives the noise at the nearest point ("Crackle");
 *   ripples, waves  sines of the distance to ten centres on the unit
 *              sphere, each wave of waves with a frequency of its own
 *              (measured, see wave_sum());
 *   quilted    a cubic Bezier of the distance to the middle of each unit
 *              cube (control0, control1 its inner control points) times
 *              the mean distance along the axes, see quilted().
 * Turbulence displaces the point by the turbulence vector times the sum
 * over octaves of omega^i D(p lambda^i), D POV-Ray's vector noise
 * (measured), before the pattern's transforms, as the manual's
 * "Turbulence versus Turbulence Warp" says; marble and wood have
 * turbulences of their own (measured, see turbulent_point()).
 * noise_generator 1, 2 and 3 are POV-Ray's for every noise pattern
 * (measured; generator 3 to 1e-7).
 *
 * Patterns the manual describes only in words, with our definitions:
 *   pigment_pattern  the grey 0.297 r + 0.589 g + 0.114 b of a pigment
 *              evaluated at the point (the weights of POV-Ray's grey);
 *   spiral1    arms around the z axis whose phase grows with the angle
 *              times the number of arms, with the distance from the axis
 *              and with z (a screw), through a triangle wave by default;
 *   spiral2    the mean of two such spirals turning opposite ways;
 *   average    no value of its own: its map's entries are mixed by
 *              weight (lib/scene/texture.c).
 */
#include "scene/pattern.h"

#include <math.h>
#include <stdint.h>

#include "scene/bitmap.h"
#include "scene/df3.h"
#include "core/noise.h"

#include "scene/waves_tables.h" /* made by bench/conform/waves_probe.py */
#include "../../bench/noise/crackle_tables.h"
#include "scene/texture.h"
#include "scene/warp.h"

#define PI 3.14159265358979323846

/* How far block patterns nudge the point off cell boundaries. */
#define BLOCK_EPS 1e-9

void zr__pattern_set_kind(zr_pattern *pt, zr_pattern_kind kind) {
  pt->kind = kind;
  pt->vector = kind == ZR_PAT_BRICK ? zr_v3(8, 3, 4.5) : zr_v3(1, 0, 0);
  pt->mortar = 0.5;
  pt->agate_turb = 1.0;
  pt->arms = 0;
  pt->waves = 10;
  pt->control0 = 1.0;
  pt->control1 = 1.0;
  pt->noise_generator = 0;
  pt->pigment = NULL;
  pt->fractal.iterations = 0;
  pt->fractal.exponent = 2;
  pt->fractal.magnet = 0;
  pt->fractal.c[0] = pt->fractal.c[1] = 0;
  pt->fractal.interior = 0;
  pt->fractal.exterior = 1;
  pt->fractal.interior_factor = pt->fractal.exterior_factor = 1;
  pt->fn = NULL;
  pt->object = NULL;
  pt->image = NULL;
  pt->crackle_form = zr_v3(-1, 1, 0);
  pt->crackle_metric = 2;
  pt->crackle_offset = 0;
  pt->crackle_solid = false;
  pt->slope.direction = pt->slope.altitude = zr_v3(0, 0, 0);
  pt->slope.lo = pt->slope.alt_lo = 0.0;
  pt->slope.hi = pt->slope.alt_hi = 1.0;
}

void zr__pattern_init(zr_pattern *pt, zr_pattern_kind kind) {
  zr__pattern_set_kind(pt, kind);
  pt->turbulence = zr_v3(0, 0, 0);
  pt->octaves = 6;
  pt->omega = 0.5;
  pt->lambda = 2.0;
  pt->frequency = 1.0;
  pt->phase = 0.0;
  pt->wave = ZR_WAVE_DEFAULT;
  pt->wave_exponent = 1.0;
  pt->warps = NULL;
  pt->n_warps = 0;
}

bool zr__pattern_is_block(zr_pattern_kind kind) {
  return kind == ZR_PAT_CHECKER || kind == ZR_PAT_HEXAGON ||
         kind == ZR_PAT_BRICK || kind == ZR_PAT_OBJECT;
}

/* ---- noise ---- */

double zr__noise(zr_vec3 p) { return zr__noise_lattice(p); }

double zr__noise_gen(zr_vec3 p, int generator) {
  return zr__noise_generator(p, generator);
}

zr_vec3 zr__dnoise(zr_vec3 p) { return zr__dnoise_lattice(p); }

zr_vec3 zr__dturbulence(zr_vec3 p, int octaves, double omega,
                        double lambda) {
  /* omega and lambda act as single-precision numbers: omega 0.7 differs
     from the double 0.7 by the float's rounding in the probe's
     measurements (bench/noise/probe_patterns.py). */
  return zr__dturbulence_lattice(p, octaves, (float)omega, (float)lambda);
}

static double clamp01(double v) { return v < 0 ? 0 : v > 1 ? 1 : v; }

/* The octave term of wrinkles, granite and agate from the noise n of
   its point (measured: bench/noise/probe_patterns.py): for
   noise_generator 1 the noise (which is clamped to [0, 1]), for the
   others 2 n - 0.5, clamped to [0, 1] unless clamp is false (agate's
   later octaves). */
static double octave_of(double n, int generator, bool clamp) {
  if (generator == 1)
    return n;
  double v = 2 * n - 0.5;
  return clamp ? clamp01(v) : v;
}

/* The noises of the octaves i to i + count - 1 (count at most 4) of a
   sum whose octave i is at p f_i, f_i = f_{i-1} step: *f holds f_i and
   is advanced past them (with at_p the first of them is p itself and
   *f holds the next one's factor).  The octaves' points are independent, so
   zr__noise_generator_n computes them together (granite's six octaves
   were 11% of organ.pov's profile one noise after another); the same
   values, so the sums below add the same terms in the same order. */
static void octave_noises(zr_vec3 p, double *f, double step, int count,
                          int generator, bool at_p, double out[4]) {
  zr_vec3 q[4];
  for (int l = 0; l < count; l++) {
    if (at_p && l == 0) {
      q[0] = p;
      continue;
    }
    q[l] = zr_v3_scale(p, *f);
    *f *= step;
  }
  zr__noise_generator_n(q, count, generator, out);
}

/* wrinkles: half the sum over 10 octaves i of octave(2^i p) / 2^i
   (measured to 1e-14 for noise_generators 1 and 2, 1e-7 for 3). */
static double wrinkles(zr_vec3 p, int generator) {
  double sum = 0, amp = 1, f = 1, n[4];
  for (int i = 0; i < 10; i += 4) {
    int count = 10 - i < 4 ? 10 - i : 4;
    octave_noises(p, &f, 2, count, generator, false, n);
    for (int l = 0; l < count; l++) {
      sum += amp * octave_of(n[l], generator, true);
      amp *= 0.5;
    }
  }
  return sum / 2;
}

/* granite: the sum over 6 octaves i of |octave(4 2^i p) - 0.5| / 2^i
   (measured to 1e-14 for noise_generators 1 and 2, 1e-7 for 3). */
static double granite(zr_vec3 p, int generator) {
  double sum = 0, amp = 1, f = 4, n[4];
  for (int i = 0; i < 6; i += 4) {
    int count = 6 - i < 4 ? 6 - i : 4;
    octave_noises(p, &f, 2, count, generator, false, n);
    for (int l = 0; l < count; l++) {
      sum += amp * fabs(octave_of(n[l], generator, true) - 0.5);
      amp *= 0.5;
    }
  }
  return sum;
}

/* agate: (0.5 + 0.5 sin(2 pi (1.1 z + 1.3 agate_turb s)))^0.77, s the sum
   over 6 octaves i of octave(2^i p) / 2^i with only the first octave
   clamped for generators 2 and 3 (measured to 1e-13 for generators 1
   and 2, 1e-7 for 3;
   agate_turb acts as a single-precision number). */
static double agate_sum(zr_vec3 p, int generator, int octaves, double omega,
                        double lambda) {
  double s = 0, amp = omega, f = lambda, n[4];
  for (int i = 0; i < (octaves > 1 ? octaves : 1); i += 4) {
    int left = (octaves > 1 ? octaves : 1) - i;
    int count = left < 4 ? left : 4;
    octave_noises(p, &f, lambda, count, generator, i == 0, n);
    for (int l = 0; l < count; l++) {
      if (i + l == 0) {
        s = octave_of(n[0], generator, true);
        continue;
      }
      s += amp * octave_of(n[l], generator, false);
      amp *= omega;
    }
  }
  return s;
}

double zr__turbulence_scalar(zr_vec3 p, int octaves, double omega,
                             double lambda) {
  /* omega and lambda as single-precision numbers, as zr__dturbulence. */
  return agate_sum(p, 2, octaves, (float)omega, (float)lambda);
}

static double agate(zr_vec3 p, double agate_turb, int generator) {
  double s = agate_sum(p, generator, 6, 0.5, 2.0);
  double v = 0.5 + 0.5 * sin(2 * PI * (1.1 * p.z + 1.3 * (float)agate_turb *
                                                        s));
  return pow(v < 0 ? 0 : v, 0.77);
}

/* cells: one value per unit cell, measured to be the x coordinate of
   crackle's feature point of the same cell within it, cells past the
   32-bit range taken as -2^31 as the noise takes them
   (bench/noise/probe_cells.py, tests/test_noise.c noise_cells). */
static double cells(zr_vec3 p) {
  int64_t x = zr__noise_cell(p.x), y = zr__noise_cell(p.y),
          z = zr__noise_cell(p.z);
  return crackle_points[zr__noise_hash(x, y, z, CRACKLE_HASH_OFFSET)][0];
}

/* The feature point of crackle's cell (x, y, z), measured: one a cell,
   placed by the noise's hash h of the cell with crackle's offset
   (bench/noise/probe_crackle.py writes the table). */
static zr_vec3 crackle_point(int64_t x, int64_t y, int64_t z, unsigned h) {
  const double *o = crackle_points[h];
  return zr_v3((double)x + o[0], (double)y + o[1], (double)z + o[2]);
}

/* The hashes of the cells within reach of (x, y, z) in the loops'
   order (i, j, k from -reach to reach, k fastest). */
static void crackle_hashes(int64_t x, int64_t y, int64_t z, int reach,
                           unsigned *h) {
  zr__noise_hash_block(x, y, z, CRACKLE_HASH_OFFSET, reach, h);
}

/* The smaller of a and b, a when b is NaN, without a libm call (fmin's
   value wherever a is a number). */
static inline double min_of(double a, double b) { return b < a ? b : a; }

/* A distance in crackle's metric m, with its offset as a fourth
   coordinate ("Crackle": offset "displaces the pattern along a fourth
   dimension"). */
static double crackle_distance(zr_vec3 d, double m, double offset) {
  if (m == 2)
    return sqrt(d.x * d.x + d.y * d.y + d.z * d.z + offset * offset);
  if (m == 1)
    return fabs(d.x) + fabs(d.y) + fabs(d.z) + fabs(offset);
  return pow(pow(fabs(d.x), m) + pow(fabs(d.y), m) + pow(fabs(d.z), m) +
                 pow(fabs(offset), m),
             1 / m);
}

/* Crackle with its form, metric, offset and solid: the weighted sum of
   the distances to the three nearest feature points (one per unit cell),
   clamped to [0, 1], or with solid the noise at the nearest point (all
   measured to 1e-12, bench/noise/probe_crackle.py). */
/* How far p is from the outside of the block of cells within reach
   cells of its own, along the nearest axis: no point outside the block
   is nearer than this in any metric of at least 1. */
static double block_margin(zr_vec3 p, int reach) {
  double c[3] = {p.x, p.y, p.z}, m = INFINITY;
  for (int a = 0; a < 3; a++) {
    double f = floor(c[a]);
    m = min_of(m, min_of(c[a] - (f - reach), f + reach + 1 - c[a]));
  }
  return m;
}

/* The three smallest distances from p to the feature points of the cells
   within reach cells of p's own, in crackle's metric, and the nearest
   point.  For a positive metric m the cells are ranked by the sum of the
   coordinates' m-th powers (the distance before its 1/m-th root, which
   keeps the order), so the root is taken three times instead of once a
   cell, and a cell is left as soon as the part of its sum found so far
   reaches the third smallest: crackle3.pov's metric 2.5 spent three
   quarters of its time in pow().  The distances are the same numbers as
   crackle_distance() gives. */
static void nearest_three(const zr_pattern *pt, zr_vec3 p, int reach,
                          double d[3], zr_vec3 *near) {
  int64_t fx = (int64_t)floor(p.x), fy = (int64_t)floor(p.y),
          fz = (int64_t)floor(p.z);
  double m = pt->crackle_metric, off = pt->crackle_offset;
  bool ranked = m > 0;
  bool general = ranked && m != 2 && m != 1;
  double off_m = general ? pow(fabs(off), m) : 0.0;
  d[0] = d[1] = d[2] = INFINITY;
  unsigned h[125], *hp = h;
  crackle_hashes(fx, fy, fz, reach, h);
  for (int64_t i = -reach; i <= reach; i++)
    for (int64_t j = -reach; j <= reach; j++)
      for (int64_t k = -reach; k <= reach; k++) {
        zr_vec3 f = crackle_point(fx + i, fy + j, fz + k, *hp++);
        zr_vec3 r = zr_v3_sub(p, f);
        double v;
        if (!ranked) {
          v = crackle_distance(r, m, off);
        } else if (m == 2) {
          v = r.x * r.x + r.y * r.y + r.z * r.z + off * off;
        } else if (m == 1) {
          v = fabs(r.x) + fabs(r.y) + fabs(r.z) + fabs(off);
        } else {
          /* Partial sums only grow (each term is at least 0 and a
             rounded sum is monotonic in its terms), so a part at or
             past d[2] means the whole is too. */
          double ax = pow(fabs(r.x), m);
          if (ax + off_m >= d[2])
            continue;
          double axy = ax + pow(fabs(r.y), m);
          if (axy + off_m >= d[2])
            continue;
          v = axy + pow(fabs(r.z), m) + off_m;
        }
        if (v < d[0]) {
          d[2] = d[1];
          d[1] = d[0];
          d[0] = v;
          *near = f;
        } else if (v < d[1]) {
          d[2] = d[1];
          d[1] = v;
        } else if (v < d[2]) {
          d[2] = v;
        }
      }
  if (!ranked || m == 1)
    return;
  for (int i = 0; i < 3; i++)
    d[i] = m == 2 ? sqrt(d[i]) : pow(d[i], 1 / m);
}

static double crackle_general(const zr_pattern *pt, zr_vec3 p) {
  double d[3];
  zr_vec3 near = p;
  /* The 27 cells around p, or 125 when the third nearest point of those
     lies farther than the 27 cells reach: POV-Ray finds points two cells
     away (measured with metric 1). */
  nearest_three(pt, p, 1, d, &near);
  if (d[2] > block_margin(p, 1))
    nearest_three(pt, p, 2, d, &near);
  if (pt->crackle_solid) /* the noise at the nearest point (measured) */
    return zr__noise(near);
  zr_vec3 w = pt->crackle_form;
  return clamp01(w.x * d[0] + w.y * d[1] + w.z * d[2]);
}

/* Voronoi distances to the nearest and second nearest feature point
   among the 27 cells around p (crackle_general when they may not hold
   the two nearest).  The cells are ranked by squared distance and the
   root taken of the two smallest only: the root is monotonic, so these
   are the two smallest of the 27 distances, the same numbers as a root
   a cell gave (interior/media/micro.pov: 27 roots a sample were a
   tenth of its time). */
static double crackle(const zr_pattern *pt, zr_vec3 p) {
  double d[2];
  zr__noise_nearest2(p, crackle_points, CRACKLE_HASH_OFFSET, d);
  double d1 = d[0], d2 = d[1];
  d1 = sqrt(d1);
  d2 = sqrt(d2);
  if (d2 > block_margin(p, 1))
    return crackle_general(pt, p);
  return clamp01(d2 - d1);
}

/* Ripples and waves (bench/conform/waves_probe.py, exact to 1e-15 at
   1500 points of POV-Ray 3.7's values): ten centres c_k on the unit
   sphere, the same for both, waves of centre k with a spatial frequency
   s_k of its own:
     ripples  0.5 + 0.05 sum_k sin(2 pi (f |p - c_k| + phase)),
     waves    0.5 + 0.02 sum_k sin(2 pi (f s_k |p - c_k| + phase)) / s_k,
   f and phase the pattern's frequency and phase; zr__pattern_wave()
   applies them once more to the value, as POV-Ray does.  The weights
   0.05 and 0.02 are the fit's.  global_settings { number_of_waves }
   changes neither value (measured with 1, 3 and 20). */
static double wave_sum(const zr_pattern *pt, zr_vec3 p, bool ripples) {
  enum { N_WAVES = sizeof zr__wave_centres / sizeof zr__wave_centres[0] };
  double sum = 0;
  for (int k = 0; k < N_WAVES; k++) {
    const double *c = zr__wave_centres[k];
    double s = ripples ? 1 : c[3];
    double d = zr_v3_len(zr_v3_sub(p, zr_v3(c[0], c[1], c[2])));
    sum += sin(2 * PI * (pt->frequency * s * d + pt->phase)) / s;
  }
  return 0.5 + (ripples ? 0.05 : 0.02) * sum;
}

/* The order in which povray 3.7's normals take the centres above when
   number_of_waves N is below 10: the first N of this list (measured,
   bench/conform/waves_normal_fit.py with number_of_waves 1 to 9: the
   fit's non-zero sines, each -amount / N). */
static const int wave_order[10] = {7, 8, 3, 5, 4, 9, 6, 2, 1, 0};

int zr__pattern_wave_count(const zr_pattern *pt) {
  enum { N_WAVES = sizeof zr__wave_centres / sizeof zr__wave_centres[0] };
  return pt->waves >= 1 && pt->waves < N_WAVES ? pt->waves : N_WAVES;
}

zr_vec3 zr__pattern_wave_normal(const zr_pattern *pt, zr_vec3 p) {
  int n_waves = zr__pattern_wave_count(pt);
  bool ripples = pt->kind == ZR_PAT_RIPPLES;
  zr_vec3 sum = zr_v3(0, 0, 0);
  for (int i = 0; i < n_waves; i++) {
    const double *c = zr__wave_centres[wave_order[i]];
    double s = ripples ? 1 : c[3];
    zr_vec3 r = zr_v3_sub(p, zr_v3(c[0], c[1], c[2]));
    double d = zr_v3_len(r);
    if (d == 0)
      continue;
    double w = sin(2 * PI * (pt->frequency * s * d + pt->phase)) / s;
    sum = zr_v3_madd(sum, r, w / d);
  }
  return zr_v3_scale(sum, 1.0 / n_waves);
}

/* Quilted (bench/conform/quilted_probe.py, exact to 1e-9 at 300 random
   points for seven control pairs, probed with POV-Ray 3.7's functions of
   a quilted pattern): each unit cube's offset d from its centre, of
   length r, is scaled by the cubic Bezier B(r) with control points 0,
   control0, control1, 1 and divided by the distance to a corner
   (sqrt 3 / 2); the value is the mean of the absolute components:
   |B(r)| (|dx| + |dy| + |dz|) 2 / (3 sqrt 3).  0 in the middle of a
   cube, 3/8 at its corners with both controls 0; not clamped (controls
   5, 5 give 1.118 at a corner), negative B counts as positive. */
static double quilted(const zr_pattern *pt, zr_vec3 p) {
  double c0 = pt->control0, c1 = pt->control1;
  double dx = fabs(p.x - floor(p.x) - 0.5), dy = fabs(p.y - floor(p.y) - 0.5),
         dz = fabs(p.z - floor(p.z) - 0.5);
  double r = sqrt(dx * dx + dy * dy + dz * dz), u = 1 - r;
  double b = 3 * c0 * r * u * u + 3 * c1 * r * r * u + r * r * r;
  return fabs(b) * (dx + dy + dz) * 2 / (3 * sqrt(3.0));
}

/* The relief of a quilted normal under a slope_map, the only place it
   is still taken: without one POV-Ray adds a vector to the normal
   (lib/scene/texture.c quilt_push, measured), and a quilted normal with
   a slope_map is not measured.  The mean over the axes of a cubic
   Bezier profile across each unit cube, 0 at the seam and 1 in the
   middle, control0 and control1 its inner control points. */
static double quilt_profile(double c, double c0, double c1) {
  double f = c - floor(c);
  double t = 2 * (f < 0.5 ? f : 1 - f); /* 0 at the seam, 1 mid-cell */
  double u = 1 - t;
  return 3 * u * u * t * c0 + 3 * u * t * t * c1 + t * t * t;
}

double zr__pattern_quilt_relief(const zr_pattern *pt, zr_vec3 p) {
  double c0 = pt->control0, c1 = pt->control1;
  return zr__pattern_wave(
      pt, clamp01((quilt_profile(p.x, c0, c1) + quilt_profile(p.y, c0, c1) +
                   quilt_profile(p.z, c0, c1)) / 3));
}

/* One spiral's phase: arms turns per revolution, the angle counted from
   -y towards +x, one per unit of radius and of z.  POV-Ray 3.7's values
   (#debug of a ramp_wave spiral1 pigment function, bench/conform/
   spiral_probe.pov): 0.55 at <0.3, 0, 0> with one arm, 0.8 with two,
   0.05 with three; +arms/16 every 1/16 turn, +0.05 every 0.05 of r
   and of z. */
static double spiral_phase(zr_vec3 p, double arms) {
  double a = atan2(p.y, p.x) / (2 * PI) + 0.25;
  return arms * a + sqrt(p.x * p.x + p.y * p.y) + p.z;
}

static double triangle01(double v) {
  double f = v - floor(v);
  return f < 0.5 ? 2 * f : 2 - 2 * f;
}

/* The grey POV-Ray takes of a colour. */
static double grey(zr_colour c) {
  return 0.297 * c.r + 0.589 * c.g + 0.114 * c.b;
}

/* ---- block patterns ---- */

static int mod_int(int64_t v, int n) { return (int)(((v % n) + n) % n); }

static int checker(zr_vec3 p) {
  int64_t s = (int64_t)floor(p.x + BLOCK_EPS) +
              (int64_t)floor(p.y + BLOCK_EPS) +
              (int64_t)floor(p.z + BLOCK_EPS);
  return mod_int(s, 2);
}

/*
 * Hexagons of side 1 with a vertex on +x: their centres form the lattice
 * i a + j b with a = (0, sqrt 3) and b = (1.5, sqrt 3 / 2) in (x, z).
 * Each point of the 60-degree rhombus cell is nearest to one of its four
 * corners (the rhombus is two equilateral Delaunay triangles).  Going
 * round a hexagon its neighbours alternate between the two other
 * colours, which (i + 2 j) mod 3 does: colour 2 at +a (+z).
 */
static int hexagon(zr_vec3 p) {
  const double s3 = sqrt(3.0);
  double j = p.x / 1.5;
  double i = (p.z - j * s3 / 2) / s3;
  int64_t i0 = (int64_t)floor(i), j0 = (int64_t)floor(j);
  double best = INFINITY;
  int64_t bi = 0, bj = 0;
  for (int di = 0; di <= 1; di++)
    for (int dj = 0; dj <= 1; dj++) {
      int64_t ci = i0 + di, cj = j0 + dj;
      double cx = 1.5 * (double)cj;
      double cz = s3 * (double)ci + s3 / 2 * (double)cj;
      double d = (p.x - cx) * (p.x - cx) + (p.z - cz) * (p.z - cz);
      if (d < best) {
        best = d;
        bi = ci;
        bj = cj;
      }
    }
  return mod_int(bi + 2 * bj, 3);
}

static double wrap(double v, double size) {
  return v - size * floor(v / size);
}

static int brick(const zr_pattern *pt, zr_vec3 p) {
  zr_vec3 s = pt->vector;
  double m = pt->mortar;
  double x = p.x + BLOCK_EPS, y = p.y + BLOCK_EPS, z = p.z + BLOCK_EPS;
  int64_t row = (int64_t)floor(y / s.y);
  if (mod_int(row, 2) == 1)
    x += s.x / 2;
  else
    z += s.z / 2;
  if (wrap(x, s.x) >= s.x - m || wrap(y, s.y) >= s.y - m ||
      wrap(z, s.z) >= s.z - m)
    return 0;
  return 1;
}

/* ---- evaluation ---- */

double zr__pattern_wave(const zr_pattern *pt, double v) {
  zr_wave_kind wave = pt->wave;
  if (wave == ZR_WAVE_DEFAULT)
    wave = pt->kind == ZR_PAT_MARBLE || pt->kind == ZR_PAT_WOOD ||
                   pt->kind == ZR_PAT_SPIRAL1 || pt->kind == ZR_PAT_SPIRAL2
               ? ZR_WAVE_TRIANGLE
               : ZR_WAVE_RAMP;
  double f;
  if (pt->kind == ZR_PAT_GRADIENT) {
    /* POV-Ray 3.7's gradient, measured (bench/conform/gradient_wrap_probe.sh,
       to float precision): a value above 1 keeps its fraction (1 stays
       1), then t = v frequency + phase wraps as fmod(t, 1.00001), plus 1
       while that is negative (-0 stays 0): -1.5 gives 0.50001, -7.3
       0.70007, -1e9 - 0.5 gives 0.4, -1.000005 gives 0.999995 (fmod
       -1.000005, plus 1 twice); with frequency 3, 0.5 gives 0.49999
       and 1 gives 0.99998. */
    if (v > 1.0)
      v -= floor(v);
    f = fmod(v * pt->frequency + pt->phase, 1.00001);
    if (f < 0.0)
      f += 1.0;
    if (f < 0.0)
      f += 1.0;
  } else if (pt->frequency == 1.0 && pt->phase == 0.0 && v >= 0 && v <= 1) {
    /* Already in range: keep 1 as 1 rather than wrapping it to 0, so a
       pattern at its maximum takes the map's last colour. */
    f = v;
  } else {
    double t = v * pt->frequency + pt->phase;
    f = t - floor(t);
  }
  switch (wave) {
  case ZR_WAVE_TRIANGLE:
    return f < 0.5 ? 2 * f : 2 - 2 * f;
  case ZR_WAVE_SINE:
    return 0.5 + 0.5 * sin(2 * PI * f);
  case ZR_WAVE_SCALLOP:
    return fabs(sin(PI * f));
  case ZR_WAVE_CUBIC:
    return f * f * (3 - 2 * f);
  case ZR_WAVE_POLY:
    return pow(f, pt->wave_exponent);
  default:
    return f;
  }
}

/*
 * slope ("Slope Pattern"): 1 - angle(n, D) / pi, 0 where the normal
 * points against D, 0.5 across, 1 along it (linear in the angle, as
 * POV-Ray 3.7 renders it: 0.8353 at 30 degrees, 0.6667 at 60, 0.1686
 * at 150, where a cosine would give 0.93, 0.75, 0.07), mapped so lo
 * gives 0 and hi 1; with an
 * altitude A, the mean of that and (p . A / |A| - alt_lo) / (alt_hi -
 * alt_lo), weighted by |D| and |A|.  Both parts are clamped to [0, 1],
 * which keeps a texture_map's ends where the manual's examples put them.
 */
static double ramp01(double v, double lo, double hi) {
  return hi == lo ? (v >= hi ? 1.0 : 0.0) : clamp01((v - lo) / (hi - lo));
}

static double slope_value(const zr_slope *sl, zr_vec3 p, zr_vec3 n) {
  double wd = zr_v3_len(sl->direction), wa = zr_v3_len(sl->altitude);
  double s = 0.5;
  if (wd > 0.0) {
    double c = zr_v3_dot(n, sl->direction) / wd;
    s = 1.0 - acos(c < -1.0 ? -1.0 : c > 1.0 ? 1.0 : c) / PI;
  }
  s = ramp01(s, sl->lo, sl->hi);
  if (!(wa > 0.0))
    return s;
  double a = ramp01(zr_v3_dot(p, sl->altitude) / wa, sl->alt_lo,
                    sl->alt_hi);
  return (wd * s + wa * a) / (wd + wa);
}

/* The pattern function before frequency, phase and wave. */
static double raw_value(const zr_pattern *pt, zr_vec3 p) {
  switch (pt->kind) {
  case ZR_PAT_AGATE:
    return agate(p, pt->agate_turb, pt->noise_generator);
  case ZR_PAT_BOXED:
    return 1 - fmin(1, zr_v3_max_comp(zr_v3(fabs(p.x), fabs(p.y),
                                            fabs(p.z))));
  case ZR_PAT_CELLS:
    return cells(p);
  case ZR_PAT_PIGMENT_PATTERN:
    return pt->pigment ? clamp01(grey(zr__pigment_eval(pt->pigment, p)))
                       : 0;
  case ZR_PAT_IMAGE:
    return pt->image ? zr__bitmap_pattern(pt->image, p) : 0;
  case ZR_PAT_QUILTED:
    return quilted(pt, p);
  case ZR_PAT_SPIRAL1:
    return spiral_phase(p, pt->arms);
  case ZR_PAT_SPIRAL2:
    /* The spiral's triangle wave plus the triangle wave of the radius,
       then the pattern's wave (triangle by default): POV-Ray 3.7's ramp
       values (spiral_probe.pov) rise and fall by 2 per turn and per unit
       of z, by 4, 0 or -4 per unit of radius, and are 0.5 at <0.3, 0, 0>
       with one arm (0.9 + 0.6), 0.795147 (triangle) at <0.3, 0.1, 0>. */
    return triangle01(spiral_phase(p, pt->arms)) +
           triangle01(sqrt(p.x * p.x + p.y * p.y));
  case ZR_PAT_BOZO:
  case ZR_PAT_SPOTTED:
  case ZR_PAT_BUMPS:
    return zr__noise_gen(p, pt->noise_generator);
  case ZR_PAT_DENTS: {
    /* The cube of the noise (measured to 1e-14). */
    double n = zr__noise_gen(p, pt->noise_generator);
    return n * n * n;
  }
  case ZR_PAT_CRACKLE:
    if (pt->crackle_metric == 2 && pt->crackle_offset == 0 &&
        !pt->crackle_solid && pt->crackle_form.x == -1 &&
        pt->crackle_form.y == 1 && pt->crackle_form.z == 0)
      return crackle(pt, p);
    return crackle_general(pt, p);
  case ZR_PAT_CYLINDRICAL:
    return 1 - fmin(1, sqrt(p.x * p.x + p.z * p.z));
  case ZR_PAT_GRADIENT:
    return zr_v3_dot(p, pt->vector);
  case ZR_PAT_GRANITE:
    return granite(p, pt->noise_generator);
  case ZR_PAT_LEOPARD: {
    double s = (sin(p.x) + sin(p.y) + sin(p.z)) / 3;
    return s * s;
  }
  case ZR_PAT_MARBLE:
    return p.x;
  case ZR_PAT_ONION:
    return zr_v3_len(p);
  case ZR_PAT_PLANAR:
    return 1 - fmin(1, fabs(p.y));
  case ZR_PAT_RADIAL: {
    double a = atan2(-p.z, p.x) / (2 * PI);
    return a < 0 ? a + 1 : a;
  }
  case ZR_PAT_SPHERICAL:
    return 1 - fmin(1, zr_v3_len(p));
  case ZR_PAT_WOOD:
    return sqrt(p.x * p.x + p.y * p.y);
  case ZR_PAT_WRINKLES:
    return wrinkles(p, pt->noise_generator);
  case ZR_PAT_MANDEL:
  case ZR_PAT_JULIA:
    return zr__pattern_fractal(pt, p);
  case ZR_PAT_FUNCTION:
    return zr__pattern_function(pt, p);
  case ZR_PAT_DENSITY_FILE:
    return zr__df3_value(pt->density_file, p); /* lib/scene/df3.c */
  case ZR_PAT_TILING:
    return zr__pattern_tiling(pt->tiling, p);
  default:
    return 0;
  }
}

/* The point a pattern's own turbulence moves p to (measured,
   bench/noise/probe_patterns.py).  Most patterns move it by the
   turbulence vector times the vector turbulence; marble and wood have
   their own: marble moves x alone, by turbulence.x times the sum over
   octaves i of omega^i octave(lambda^i p) (only the first octave clamped
   for generator 2, as agate's), and wood moves each coordinate a by
   sin(2 pi turbulence.a (a + D.a)), D the vector turbulence. */
static zr_vec3 turbulent_point(const zr_pattern *pt, zr_vec3 p) {
  zr_vec3 t = pt->turbulence;
  if (pt->kind == ZR_PAT_MARBLE) {
    double s = agate_sum(p, pt->noise_generator, pt->octaves,
                         (float)pt->omega, (float)pt->lambda);
    p.x += t.x * s;
    return p;
  }
  zr_vec3 d = zr__dturbulence(p, pt->octaves, pt->omega, pt->lambda);
  if (pt->kind == ZR_PAT_WOOD)
    return zr_v3(p.x + sin(2 * PI * t.x * (p.x + d.x)),
                 p.y + sin(2 * PI * t.y * (p.y + d.y)),
                 p.z + sin(2 * PI * t.z * (p.z + d.z)));
  return zr_v3_add(p, zr_v3_mul(t, d));
}

zr_vec3 zr__pattern_point(const zr_pattern *pt, zr_vec3 p) {
  /* Warps, or without them the cut to +-1e17 (lib/scene/warp.c). */
  p = pt->n_warps > 0 ? zr__warp_point(pt->warps, pt->n_warps, p)
                      : zr__warp_cut(p);
  zr_vec3 t = pt->turbulence;
  if (t.x != 0 || t.y != 0 || t.z != 0)
    p = turbulent_point(pt, p);
  return p;
}

double zr__pattern_eval(const zr_pattern *pt, zr_vec3 p) {
  p = zr__pattern_point(pt, p);
  switch (pt->kind) {
  case ZR_PAT_CHECKER:
    return checker(p);
  case ZR_PAT_HEXAGON:
    return hexagon(p);
  case ZR_PAT_BRICK:
    return brick(pt, p);
  case ZR_PAT_OBJECT:
    return zr__pattern_object(pt, p);
  case ZR_PAT_RIPPLES:
    return zr__pattern_wave(pt, wave_sum(pt, p, true));
  case ZR_PAT_WAVES:
    return zr__pattern_wave(pt, wave_sum(pt, p, false));
  case ZR_PAT_AVERAGE:
    return 0;
  case ZR_PAT_SLOPE:
    return zr__pattern_wave(pt, slope_value(&pt->slope, p, zr_v3(0, 0, 0)));
  default:
    return zr__pattern_wave(pt, raw_value(pt, p));
  }
}

double zr__pattern_eval_n(const zr_pattern *pt, zr_vec3 p, zr_vec3 n) {
  if (pt->kind != ZR_PAT_SLOPE)
    return zr__pattern_eval(pt, p);
  /* Warps and turbulence move the point, so only the altitude part. */
  if (pt->n_warps > 0)
    p = zr__warp_point(pt->warps, pt->n_warps, p);
  zr_vec3 t = pt->turbulence;
  if (t.x != 0 || t.y != 0 || t.z != 0)
    p = zr_v3_add(p, zr_v3_mul(t, zr__dturbulence(p, pt->octaves,
                                                  pt->omega, pt->lambda)));
  return zr__pattern_wave(pt, slope_value(&pt->slope, p, n));
}
