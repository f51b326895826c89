/*
 * noise.c - POV-Ray 3.7's noise, reconstructed from measurements of the
 * povray binary (no source: bench/noise/probe_noise.py derives every
 * table and constant from f_noise3d values that povray prints, and
 * tests/test_noise.c checks thousands of recorded values).
 *
 * The noise of the default noise_generator 2 is a lattice noise with a
 * value and a gradient at every integer point c: at p, the sum over the
 * eight corners of p's unit cell of w(x) w(y) w(z) (v(c) + g(c) . (p - c)),
 * where w is the cubic Hermite weight 3t^2 - 2t^3 of the distance along
 * each axis (t for the far corner, 1 - t for the near one).  (v, g) is
 * entry h & 255 of a 256-entry table, h = T[T[T[x'] ^ y'] ^ z'] with T a
 * permutation of 0..4095 and x' = (x + K) & 4095.  The probe found T, K
 * and the table; they live in bench/noise/noise_tables.h, which the
 * probe writes.  The values come out in about [0.1, 0.9], as povray's do
 * (the manual calls generator 2 "range corrected").  noise_generator 1
 * ("the noise that was used in POV-Ray 3.1") is the same noise mapped by
 * a + b n and clamped to [0, 1] (a and b measured by the same probe).
 *
 * noise_generator 3 ("Perlin noise", bench/noise/probe_gen3.py) is a
 * gradient noise on the lattice shifted by -0.0232: a constant (0.4925)
 * plus the same cubic blend of g(c) . (q - c), q = p + 0.0232, with
 * 2048 gradients of length 0.795; the gradient of corner (x, y, z) is
 * G[(S[(R[x] + y) mod 2048] + z) mod 2048], S and R tables of 2048
 * entries read from povray's output (matched to 1e-8).
 *
 * Turbulence's vector noise has three components of the same form and
 * hash, each with its own table (step 6 of the probe): a point moves by
 * the turbulence vector times the sum over octaves i of omega^i
 * D(lambda^i p), which the probe's turbulence samples match to 1e-11.
 *
 * Far out, POV-Ray's lattice cell is a 32-bit integer: where floor(p)
 * of an axis lies outside [-2^31, 2^31 - 1], povray behaves as if the
 * cell were -2^31 (what an x86 conversion of an out-of-range double
 * gives), so the distance into the cell is huge, the cubic weights are
 * enormous and the noise, clamped to [0, 1], is 0 or 1 by the sign of
 * the sum; just below -2^31 it is an ordinary-looking value again.  The
 * turbulence of a pattern with a large lambda reaches such points
 * (poliana-girl's aug4.pov: lambda 50, six octaves, 50^5 p), and its
 * vector noise follows the same rule: the point moves by a huge amount,
 * so the pattern there is 0 or 1 by its sign.  (gradient y warped so
 * reads 0 or a fixed 0.5500685 whatever the turbulence's size: povray's
 * ramp of a value below -1e17.)  Measured: tests/test_noise.c
 * (noise_far, noise_dfar), values povray prints for
 * bench/noise/probe_far.pov.
 */
#include "core/noise.h"

#include <math.h>
#include <stdint.h>

#include "../../bench/noise/gen3_tables.h"
#include "../../bench/noise/noise_tables.h"

static double smooth(double t) { return t * t * (3 - 2 * t); }

/* POV-Ray's cell of floor value f: f itself in the 32-bit range, -2^31
   outside it (and for NaN). */
static int64_t cell(double f) {
  if (f >= -2147483648.0 && f <= 2147483647.0)
    return (int64_t)f;
  return INT64_C(-2147483648);
}

int64_t zr__noise_cell(double v) { return cell(floor(v)); }

/* The largest distance into a far-out cell (blend()): 1e25, so three
   far axes' weights (about 2 t^3 each) times a distance stay below
   1e308; the six octaves of lambda 50 from 2e9 (5e17 at the last) keep
   povray's sign with it, where 2^52 lost it (noise_dfar). */
#define FAR_T 1e25

unsigned zr__noise_hash(int64_t x, int64_t y, int64_t z, int offset) {
  unsigned a = (unsigned)((x + offset) & 4095);
  unsigned b = (unsigned)((y + offset) & 4095);
  unsigned c = (unsigned)((z + offset) & 4095);
  return noise_hash[noise_hash[noise_hash[a] ^ b] ^ c];
}

void zr__noise_hash_block(int64_t x, int64_t y, int64_t z, int offset,
                          int reach, unsigned *out) {
  for (int64_t i = -reach; i <= reach; i++) {
    unsigned hx = noise_hash[(unsigned)((x + i + offset) & 4095)];
    for (int64_t j = -reach; j <= reach; j++) {
      unsigned hxy = noise_hash[hx ^ (unsigned)((y + j + offset) & 4095)];
      for (int64_t k = -reach; k <= reach; k++)
        *out++ = noise_hash[hxy ^ (unsigned)((z + k + offset) & 4095)];
    }
  }
}

/* The blend of step 1 of the probe for n_tables tables at once: out[m]
   is the noise of tables[m], the cells taken as POV-Ray takes them far
   out (cell()), for the value noise and turbulence's vector noise
   alike.  Inlined into its two callers so that n_tables is a constant
   there, and summed in locals: through out, which may alias the tables
   for all the compiler knows, each corner's sum went to memory and back
   (56% of benchmark.pov's profile was this function; the same
   operations in the same order, so the same values). */
static inline __attribute__((always_inline)) void
blend(zr_vec3 p, const double (*const *tables)[4], int n_tables,
      double *out) {
  int64_t ix = cell(floor(p.x)), iy = cell(floor(p.y)), iz = cell(floor(p.z));
  double t[3] = {p.x - (double)ix, p.y - (double)iy, p.z - (double)iz};
  /* Far out the distance into the cell is huge and only the sign of
     the sum decides (0 or 1); past FAR_T its cube, times the other
     axes', would overflow to inf - inf = NaN (povray itself prints
     -nan for f_noise3d(1e40, 1e40, 1e40) and for f_ridged_mf with 100
     octaves), so the distance stops there: the sign povray gives where
     its sum is finite (tests/test_noise.c, noise_far: 1e12 to 1e20),
     and a finite 0 or 1 beyond, for any double or NaN. */
  for (int a = 0; a < 3; a++)
    if (!(fabs(t[a]) <= FAR_T))
      t[a] = t[a] < 0 ? -FAR_T : FAR_T;
  double w[3][2];
  for (int a = 0; a < 3; a++) {
    w[a][1] = smooth(t[a]);
    w[a][0] = 1 - w[a][1];
  }
  /* The corners' hashes, zr__noise_hash(x, y, z, NOISE_HASH_OFFSET) &
     255, with the lookups the corners share made once (14, not 24). */
  unsigned hz[2], hxy[2][2];
  for (int a = 0; a < 2; a++) {
    unsigned hx = noise_hash[(unsigned)((ix + a + NOISE_HASH_OFFSET) & 4095)];
    for (int b = 0; b < 2; b++)
      hxy[a][b] =
          noise_hash[hx ^ (unsigned)((iy + b + NOISE_HASH_OFFSET) & 4095)];
    hz[a] = (unsigned)((iz + a + NOISE_HASH_OFFSET) & 4095);
  }
  double sum[3] = {0, 0, 0};
  for (int i = 0; i < 2; i++)
    for (int j = 0; j < 2; j++)
      for (int k = 0; k < 2; k++) {
        unsigned h = noise_hash[hxy[i][j] ^ hz[k]] & 255u;
        double wc = w[0][i] * w[1][j] * w[2][k];
        double dx = t[0] - i, dy = t[1] - j, dz = t[2] - k;
        for (int m = 0; m < n_tables; m++) {
          const double *e = tables[m][h];
          sum[m] += wc * (e[0] + e[1] * dx + e[2] * dy + e[3] * dz);
        }
      }
  for (int m = 0; m < n_tables; m++)
    out[m] = sum[m];
}

/* The two noises of a plain x86-64 build, and of other processors. */
static inline __attribute__((always_inline)) double lattice_at(zr_vec3 p) {
  const double (*tables[1])[4] = {noise_lattice};
  double n;
  blend(p, tables, 1, &n);
  /* [0.1, 0.9] in the lattice's range; 0 or 1 far out (see above). */
  return n < 0 ? 0 : n > 1 ? 1 : n;
}

static inline __attribute__((always_inline)) zr_vec3 dlattice_at(zr_vec3 p) {
  const double (*tables[3])[4] = {dnoise_lattice[0], dnoise_lattice[1],
                                  dnoise_lattice[2]};
  double d[3];
  blend(p, tables, 3, d);
  return zr_v3(d[0], d[1], d[2]);
}

static zr_vec3 dturbulence_at(zr_vec3 p, int octaves, double omega,
                              double lambda) {
  zr_vec3 sum = zr_v3(0, 0, 0);
  double amp = 1.0, scale = 1.0;
  for (int i = 0; i < octaves; i++) {
    sum = zr_v3_madd(sum, dlattice_at(zr_v3_scale(p, scale)), amp);
    amp *= omega;
    scale *= lambda;
  }
  return sum;
}

/* crackle's loop over the 27 cells (zr__noise_nearest2), one cell after
   another. */
static void nearest2_plain(zr_vec3 p, const double (*points)[3], int offset,
                           double d[2]) {
  int64_t fx = (int64_t)floor(p.x), fy = (int64_t)floor(p.y),
          fz = (int64_t)floor(p.z);
  double d1 = INFINITY, d2 = INFINITY;
  unsigned h[27], *hp = h;
  zr__noise_hash_block(fx, fy, fz, offset, 1, h);
  for (int i = -1; i <= 1; i++)
    for (int j = -1; j <= 1; j++)
      for (int k = -1; k <= 1; k++) {
        const double *o = points[*hp++];
        zr_vec3 f = zr_v3((double)(fx + i) + o[0], (double)(fy + j) + o[1],
                          (double)(fz + k) + o[2]);
        zr_vec3 r = zr_v3_sub(p, f);
        double v = zr_v3_dot(r, r);
        if (v < d1) {
          d2 = d1;
          d1 = v;
        } else if (v < d2) {
          d2 = v;
        }
      }
  d[0] = d1;
  d[1] = d2;
}

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#include <immintrin.h>

#include "../../bench/noise/noise_lanes.h"

/* One axis of four points, one a lane (or of one point's three axes,
   lanes 0-2): blend()'s cell c = cell(floor(p)) as a double (an integer
   of 32 bits, so exact), t = p - c clamped to +-FAR_T (NaN to FAR_T),
   t - 1, the weights w1 = smooth(t) and w0 = 1 - w1, and the cells as
   32-bit integers (the hash wants their low 12 bits, which arithmetic
   modulo 2^32 keeps): the same operations a lane as blend()'s a
   coordinate. */
__attribute__((target("avx2"))) static inline void
axis4(__m256d pv, __m256d *t, __m256d *tm1, __m256d w[2], unsigned ic[4]) {
  __m256d f = _mm256_floor_pd(pv);
  __m256d in = _mm256_and_pd(
      _mm256_cmp_pd(f, _mm256_set1_pd(-2147483648.0), _CMP_GE_OQ),
      _mm256_cmp_pd(f, _mm256_set1_pd(2147483647.0), _CMP_LE_OQ));
  __m256d c = _mm256_blendv_pd(_mm256_set1_pd(-2147483648.0), f, in);
  __m256d d = _mm256_sub_pd(pv, c);
  __m256d abs_d = _mm256_andnot_pd(_mm256_set1_pd(-0.0), d);
  __m256d near = _mm256_cmp_pd(abs_d, _mm256_set1_pd(FAR_T), _CMP_LE_OQ);
  __m256d far = _mm256_blendv_pd(
      _mm256_set1_pd(FAR_T), _mm256_set1_pd(-FAR_T),
      _mm256_cmp_pd(d, _mm256_setzero_pd(), _CMP_LT_OQ));
  d = _mm256_blendv_pd(far, d, near);
  w[1] = _mm256_mul_pd(
      _mm256_mul_pd(d, d),
      _mm256_sub_pd(_mm256_set1_pd(3), _mm256_mul_pd(_mm256_set1_pd(2), d)));
  w[0] = _mm256_sub_pd(_mm256_set1_pd(1), w[1]);
  *t = d;
  *tm1 = _mm256_sub_pd(d, _mm256_set1_pd(1));
  _mm_storeu_si128((__m128i *)ic, _mm256_cvtpd_epi32(c));
}

/* Four rows of four doubles, transposed: e[c] holds element c of each
   row (lane r from row r).  The lattice sums read a corner's table row
   for each of four points, the crackle search a feature point's
   coordinates for four cells. */
__attribute__((target("avx2"))) static inline void
transpose4(__m256d r0, __m256d r1, __m256d r2, __m256d r3, __m256d e[4]) {
  __m256d lo01 = _mm256_unpacklo_pd(r0, r1);
  __m256d hi01 = _mm256_unpackhi_pd(r0, r1);
  __m256d lo23 = _mm256_unpacklo_pd(r2, r3);
  __m256d hi23 = _mm256_unpackhi_pd(r2, r3);
  e[0] = _mm256_permute2f128_pd(lo01, lo23, 0x20);
  e[1] = _mm256_permute2f128_pd(hi01, hi23, 0x20);
  e[2] = _mm256_permute2f128_pd(lo01, lo23, 0x31);
  e[3] = _mm256_permute2f128_pd(hi01, hi23, 0x31);
}

/* AVX2 processors get a blend of the four tables in the four lanes of
   one register, chosen at each call by the processor's features (GCC's
   target_clones would export the functions from the library, whatever
   their visibility): lanes 0-2 the vector noise's components, lane 3
   the value noise (noise_lanes.h interleaves the tables).  Each lane
   is blend()'s double operations in the same order, no fused
   multiply-add (AVX2 does not bring FMA, and -std=c11 contracts
   nothing), so the same values: tests/test_noise.c
   (noise_blend_reference) checks them against a plain copy of the sum,
   bit for bit.  The scalar blend of three tables went through memory a
   corner and a table at a time: 43% of
   camera/mesh_camera/ess/ess-ortho-camera.pov's profile (crackle with
   turbulence). */
__attribute__((target("avx2"))) static inline __m256d blend_lanes(zr_vec3 p) {
  /* blend()'s cells, distances and weights, the three axes in lanes
     0-2 (axis4's lanes: the same operations a lane as blend()'s a
     coordinate). */
  __m256d t, tm1, wv[2];
  _Alignas(16) unsigned ic[4];
  axis4(_mm256_set_pd(0, p.z, p.y, p.x), &t, &tm1, wv, ic);
  _Alignas(32) double d[2][4], w[2][4];
  _mm256_store_pd(d[0], t);
  _mm256_store_pd(d[1], tm1);
  _mm256_store_pd(w[0], wv[0]);
  _mm256_store_pd(w[1], wv[1]);
  unsigned hz[2], hxy[2][2];
  for (unsigned a = 0; a < 2; a++) {
    unsigned hx = noise_hash[(ic[0] + a + NOISE_HASH_OFFSET) & 4095u];
    for (unsigned b = 0; b < 2; b++)
      hxy[a][b] = noise_hash[hx ^ ((ic[1] + b + NOISE_HASH_OFFSET) & 4095u)];
    hz[a] = (ic[2] + a + NOISE_HASH_OFFSET) & 4095u;
  }
  __m256d sum = _mm256_setzero_pd();
#pragma GCC unroll 2
  for (int i = 0; i < 2; i++)
#pragma GCC unroll 2
    for (int j = 0; j < 2; j++) {
      double wij = w[i][0] * w[j][1];
#pragma GCC unroll 2
      for (int k = 0; k < 2; k++) {
        unsigned h = noise_hash[hxy[i][j] ^ hz[k]] & 255u;
        const double(*e)[4] = noise_lanes[h];
        __m256d v = _mm256_add_pd(
            _mm256_load_pd(e[0]),
            _mm256_mul_pd(_mm256_load_pd(e[1]), _mm256_broadcast_sd(&d[i][0])));
        v = _mm256_add_pd(v, _mm256_mul_pd(_mm256_load_pd(e[2]),
                                           _mm256_broadcast_sd(&d[j][1])));
        v = _mm256_add_pd(v, _mm256_mul_pd(_mm256_load_pd(e[3]),
                                           _mm256_broadcast_sd(&d[k][2])));
        sum = _mm256_add_pd(sum,
                            _mm256_mul_pd(_mm256_set1_pd(wij * w[k][2]), v));
      }
    }
  return sum;
}

/* The value noise of four points, one a lane: blend()'s operations for
   one table, in the same order a lane (so the same values), the four
   points' sums advancing together instead of one corner after another
   (granite's and wrinkles' octaves are independent points). */
__attribute__((target("avx2"))) static void lattice4_avx2(const zr_vec3 p[4],
                                                         double out[4]) {
  __m256d d[3][2], w[3][2];
  unsigned ic[3][4];
  axis4(_mm256_set_pd(p[3].x, p[2].x, p[1].x, p[0].x), &d[0][0], &d[0][1],
        w[0], ic[0]);
  axis4(_mm256_set_pd(p[3].y, p[2].y, p[1].y, p[0].y), &d[1][0], &d[1][1],
        w[1], ic[1]);
  axis4(_mm256_set_pd(p[3].z, p[2].z, p[1].z, p[0].z), &d[2][0], &d[2][1],
        w[2], ic[2]);
  /* Each point's eight corner hashes, in blend()'s corner order. */
  unsigned h[4][8];
  for (int l = 0; l < 4; l++) {
    unsigned hz[2] = {(ic[2][l] + NOISE_HASH_OFFSET) & 4095u,
                      (ic[2][l] + 1 + NOISE_HASH_OFFSET) & 4095u};
    for (unsigned a = 0; a < 2; a++) {
      unsigned hx = noise_hash[(ic[0][l] + a + NOISE_HASH_OFFSET) & 4095u];
      for (unsigned b = 0; b < 2; b++) {
        unsigned hxy =
            noise_hash[hx ^ ((ic[1][l] + b + NOISE_HASH_OFFSET) & 4095u)];
        for (unsigned k = 0; k < 2; k++)
          h[l][a * 4 + b * 2 + k] = noise_hash[hxy ^ hz[k]] & 255u;
      }
    }
  }
  __m256d sum = _mm256_setzero_pd();
#pragma GCC unroll 2
  for (int i = 0; i < 2; i++)
#pragma GCC unroll 2
    for (int j = 0; j < 2; j++) {
      __m256d wij = _mm256_mul_pd(w[0][i], w[1][j]);
#pragma GCC unroll 2
      for (int k = 0; k < 2; k++) {
        int n = i * 4 + j * 2 + k;
        /* The four points' table rows, transposed: e[c] holds
           coefficient c of each point's corner. */
        __m256d r0 = _mm256_loadu_pd(noise_lattice[h[0][n]]);
        __m256d r1 = _mm256_loadu_pd(noise_lattice[h[1][n]]);
        __m256d r2 = _mm256_loadu_pd(noise_lattice[h[2][n]]);
        __m256d r3 = _mm256_loadu_pd(noise_lattice[h[3][n]]);
        __m256d e[4];
        transpose4(r0, r1, r2, r3, e);
        __m256d v = _mm256_add_pd(e[0], _mm256_mul_pd(e[1], d[0][i]));
        v = _mm256_add_pd(v, _mm256_mul_pd(e[2], d[1][j]));
        v = _mm256_add_pd(v, _mm256_mul_pd(e[3], d[2][k]));
        sum = _mm256_add_pd(sum,
                            _mm256_mul_pd(_mm256_mul_pd(wij, w[2][k]), v));
      }
    }
  _mm256_storeu_pd(out, sum);
  for (int l = 0; l < 4; l++)
    out[l] = out[l] < 0 ? 0 : out[l] > 1 ? 1 : out[l];
}

__attribute__((target("avx2"))) static double lattice_avx2(zr_vec3 p) {
  __m128d hi = _mm256_extractf128_pd(blend_lanes(p), 1);
  double n = _mm_cvtsd_f64(_mm_unpackhi_pd(hi, hi));
  return n < 0 ? 0 : n > 1 ? 1 : n;
}

__attribute__((target("avx2"))) static zr_vec3 dlattice_avx2(zr_vec3 p) {
  double d[4];
  _mm256_storeu_pd(d, blend_lanes(p));
  return zr_v3(d[0], d[1], d[2]);
}

/* The octaves' sum in lanes too: sum + D amp a lane, as zr_v3_madd. */
__attribute__((target("avx2"))) static zr_vec3
dturbulence_avx2(zr_vec3 p, int octaves, double omega, double lambda) {
  __m256d sum = _mm256_setzero_pd();
  double amp = 1.0, scale = 1.0;
  for (int i = 0; i < octaves; i++) {
    __m256d d = blend_lanes(zr_v3_scale(p, scale));
    sum = _mm256_add_pd(sum, _mm256_mul_pd(d, _mm256_set1_pd(amp)));
    amp *= omega;
    scale *= lambda;
  }
  double s[4];
  _mm256_storeu_pd(s, sum);
  return zr_v3(s[0], s[1], s[2]);
}

double zr__noise_lattice(zr_vec3 p) {
  return __builtin_cpu_supports("avx2") ? lattice_avx2(p) : lattice_at(p);
}

zr_vec3 zr__dnoise_lattice(zr_vec3 p) {
  return __builtin_cpu_supports("avx2") ? dlattice_avx2(p) : dlattice_at(p);
}

/* The cells' offsets from p's own cell, four cells a group in the
   loop's order (i, j, k from -1 to 1, k fastest), the 28th a pad. */
static const _Alignas(32) double cell_steps[7][3][4] = {
    {{-1, -1, -1, -1}, {-1, -1, -1, 0}, {-1, 0, 1, -1}},
    {{-1, -1, -1, -1}, {0, 0, 1, 1}, {0, 1, -1, 0}},
    {{-1, 0, 0, 0}, {1, -1, -1, -1}, {1, -1, 0, 1}},
    {{0, 0, 0, 0}, {0, 0, 0, 1}, {-1, 0, 1, -1}},
    {{0, 0, 1, 1}, {1, 1, -1, -1}, {0, 1, -1, 0}},
    {{1, 1, 1, 1}, {-1, 0, 0, 0}, {1, -1, 0, 1}},
    {{1, 1, 1, 1}, {1, 1, 1, 1}, {-1, 0, 1, 1}},
};

/* The 27 cells four at a time: their feature points transposed into x,
   y and z registers, the squared distances (x^2 + y^2) + z^2 a lane as
   zr_v3_dot, and in each lane the smallest and second smallest so far
   (min and max pick values exactly, so the two smallest of the 27 are
   the numbers the plain loop finds). */
__attribute__((target("avx2"))) static void
nearest2_avx2(zr_vec3 p, const double (*points)[3], int offset, double d[2]) {
  int64_t fx = (int64_t)floor(p.x), fy = (int64_t)floor(p.y),
          fz = (int64_t)floor(p.z);
  unsigned h[28];
  zr__noise_hash_block(fx, fy, fz, offset, 1, h);
  h[27] = h[26];
  /* (double)(fx + i) is (double)fx + i: integers below 2^52. */
  __m256d cx = _mm256_set1_pd((double)fx), cy = _mm256_set1_pd((double)fy),
          cz = _mm256_set1_pd((double)fz);
  __m256d px = _mm256_set1_pd(p.x), py = _mm256_set1_pd(p.y),
          pz = _mm256_set1_pd(p.z);
  __m256i three = _mm256_set_epi64x(0, -1, -1, -1);
  __m256d m1 = _mm256_set1_pd(INFINITY), m2 = m1;
  for (int g = 0; g < 7; g++) {
    const unsigned *hg = h + 4 * g;
    __m256d r0 = _mm256_maskload_pd(points[hg[0]], three);
    __m256d r1 = _mm256_maskload_pd(points[hg[1]], three);
    __m256d r2 = _mm256_maskload_pd(points[hg[2]], three);
    __m256d r3 = _mm256_maskload_pd(points[hg[3]], three);
    __m256d o[4];
    transpose4(r0, r1, r2, r3, o);
    __m256d ox = o[0], oy = o[1], oz = o[2];
    __m256d fxv = _mm256_add_pd(
        _mm256_add_pd(cx, _mm256_load_pd(cell_steps[g][0])), ox);
    __m256d fyv = _mm256_add_pd(
        _mm256_add_pd(cy, _mm256_load_pd(cell_steps[g][1])), oy);
    __m256d fzv = _mm256_add_pd(
        _mm256_add_pd(cz, _mm256_load_pd(cell_steps[g][2])), oz);
    __m256d rx = _mm256_sub_pd(px, fxv), ry = _mm256_sub_pd(py, fyv),
            rz = _mm256_sub_pd(pz, fzv);
    __m256d v = _mm256_add_pd(
        _mm256_add_pd(_mm256_mul_pd(rx, rx), _mm256_mul_pd(ry, ry)),
        _mm256_mul_pd(rz, rz));
    if (g == 6) /* the pad */
      v = _mm256_blend_pd(v, _mm256_set1_pd(INFINITY), 8);
    m2 = _mm256_min_pd(m2, _mm256_max_pd(m1, v));
    m1 = _mm256_min_pd(m1, v);
  }
  double a[4], b[4];
  _mm256_storeu_pd(a, m1);
  _mm256_storeu_pd(b, m2);
  int lo = 0;
  for (int l = 1; l < 4; l++)
    if (a[l] < a[lo])
      lo = l;
  double second = INFINITY;
  for (int l = 0; l < 4; l++) {
    if (l != lo && a[l] < second)
      second = a[l];
    if (b[l] < second)
      second = b[l];
  }
  d[0] = a[lo];
  d[1] = second;
}

void zr__noise_nearest2(zr_vec3 p, const double (*points)[3], int offset,
                        double d[2]) {
  /* Far out (or NaN) the plain loop, whose cells are not all exact
     doubles there. */
  if (__builtin_cpu_supports("avx2") && fabs(p.x) < 0x1p52 &&
      fabs(p.y) < 0x1p52 && fabs(p.z) < 0x1p52)
    nearest2_avx2(p, points, offset, d);
  else
    nearest2_plain(p, points, offset, d);
}

static void lattice_n(const zr_vec3 *p, int n, double *out) {
  if (!__builtin_cpu_supports("avx2")) {
    for (int i = 0; i < n; i++)
      out[i] = lattice_at(p[i]);
    return;
  }
  for (int i = 0; i < n; i += 4) {
    /* A last group of fewer than four fills its lanes with its first
       point (computed and dropped). */
    zr_vec3 q[4];
    double v[4];
    for (int l = 0; l < 4; l++)
      q[l] = p[i + (i + l < n ? l : 0)];
    lattice4_avx2(q, v);
    for (int l = 0; l < 4 && i + l < n; l++)
      out[i + l] = v[l];
  }
}

zr_vec3 zr__dturbulence_lattice(zr_vec3 p, int octaves, double omega,
                                double lambda) {
  return __builtin_cpu_supports("avx2")
             ? dturbulence_avx2(p, octaves, omega, lambda)
             : dturbulence_at(p, octaves, omega, lambda);
}
#else
double zr__noise_lattice(zr_vec3 p) { return lattice_at(p); }

zr_vec3 zr__dnoise_lattice(zr_vec3 p) { return dlattice_at(p); }

zr_vec3 zr__dturbulence_lattice(zr_vec3 p, int octaves, double omega,
                                double lambda) {
  return dturbulence_at(p, octaves, omega, lambda);
}

static void lattice_n(const zr_vec3 *p, int n, double *out) {
  for (int i = 0; i < n; i++)
    out[i] = lattice_at(p[i]);
}

void zr__noise_nearest2(zr_vec3 p, const double (*points)[3], int offset,
                        double d[2]) {
  nearest2_plain(p, points, offset, d);
}
#endif

double zr__noise_gen3(zr_vec3 p) {
  zr_vec3 q = zr_v3(p.x + GEN3_OFFSET, p.y + GEN3_OFFSET, p.z + GEN3_OFFSET);
  double fx = floor(q.x), fy = floor(q.y), fz = floor(q.z);
  int64_t ix = (int64_t)fx, iy = (int64_t)fy, iz = (int64_t)fz;
  double t[3] = {q.x - fx, q.y - fy, q.z - fz};
  double w[3][2];
  for (int a = 0; a < 3; a++) {
    w[a][1] = smooth(t[a]);
    w[a][0] = 1 - w[a][1];
  }
  double sum = GEN3_CONSTANT;
  for (int i = 0; i < 2; i++)
    for (int j = 0; j < 2; j++)
      for (int k = 0; k < 2; k++) {
        unsigned a = gen3_r[(ix + i) & 2047];
        unsigned h = (unsigned)((gen3_s[(a + (uint64_t)(iy + j)) & 2047] +
                                 (uint64_t)(iz + k)) &
                                2047);
        const double *g = gen3_gradient[h];
        sum += w[0][i] * w[1][j] * w[2][k] *
               (g[0] * (t[0] - i) + g[1] * (t[1] - j) + g[2] * (t[2] - k));
      }
  return sum;
}

/* noise_generator 1 from the lattice noise n. */
static double gen1_of(double n) {
  n = NOISE_GEN1_A + NOISE_GEN1_B * n;
  return n < 0 ? 0 : n > 1 ? 1 : n;
}

double zr__noise_generator(zr_vec3 p, int generator) {
  if (generator == 3)
    return zr__noise_gen3(p);
  double n = zr__noise_lattice(p);
  return generator == 1 ? gen1_of(n) : n;
}

void zr__noise_generator_n(const zr_vec3 *p, int n, int generator,
                           double *out) {
  if (generator == 3) {
    for (int i = 0; i < n; i++)
      out[i] = zr__noise_gen3(p[i]);
    return;
  }
  lattice_n(p, n, out);
  if (generator == 1)
    for (int i = 0; i < n; i++)
      out[i] = gen1_of(out[i]);
}
