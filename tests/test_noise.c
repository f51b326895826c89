/*
 * test_noise.c - rand() and the noise functions against values recorded
 * from POV-Ray 3.7 by the probe scripts in bench/noise/ (the data files
 * in tests/noise/ are their output; rerunning a script rewrites its file
 * byte for byte).  Every line of a data file is one probe: its inputs and
 * the value POV-Ray printed with str(v, 0, 20).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/noise.h"
#include "scene/pattern.h"
#include "sdl/sdl.h"
#include "test_util.h"

#include "../bench/noise/crackle_tables.h"
#include "../bench/noise/noise_lanes.h"
#include "../bench/noise/noise_tables.h"

/* Opens tests/noise/name in the source tree (ZR_SRCDIR, set by make
   check, or the current folder). */
static FILE *open_data(const char *name) {
  const char *dir = getenv("ZR_SRCDIR");
  char path[4096];
  snprintf(path, sizeof path, "%s/tests/noise/%s", dir ? dir : ".", name);
  FILE *f = fopen(path, "r");
  if (!f)
    fail_msg("cannot open %s", path);
  return f;
}

/* Every value of 16 streams, 40 steps each.  The values are k / (2^32 -
   1) printed with 20 decimals, so 1e-15 allows only printing rounding. */
static void test_noise_rand_streams(void **state) {
  (void)state;
  FILE *f = open_data("rand.txt");
  char line[256];
  unsigned long long s = 0;
  double last_seed = NAN;
  int n = 0;
  while (fgets(line, sizeof line, f)) {
    double seed, value;
    int step;
    if (line[0] == '#' || sscanf(line, "%lf %d %lf", &seed, &step,
                                 &value) != 3)
      continue;
    if (step == 0 || seed != last_seed)
      s = zr__sdl_seed_state(seed);
    last_seed = seed;
    assert_near(zr__sdl_rand_step(&s), value, 1e-15);
    n++;
  }
  fclose(f);
  assert_int_equal(n, 640);
}

/* zRcube's value for one case of bench/noise/probe_patterns.py. */
static double case_value(const char *name, zr_vec3 p) {
  if (strcmp(name, "noise") == 0)
    return zr__noise(p);
  if (strcmp(name, "noise1") == 0)
    return zr__noise_gen(p, 1);
  if (strcmp(name, "noise3") == 0)
    return zr__noise_gen(p, 3);
  static const struct {
    const char *name;
    zr_pattern_kind kind;
    int generator;
  } kinds[] = {
      {"bozo", ZR_PAT_BOZO, 0},         {"bozo1", ZR_PAT_BOZO, 1},
      {"spotted", ZR_PAT_SPOTTED, 0},   {"bumps", ZR_PAT_BUMPS, 0},
      {"dents", ZR_PAT_DENTS, 0},       {"dents1", ZR_PAT_DENTS, 1},
      {"wrinkles", ZR_PAT_WRINKLES, 0}, {"granite", ZR_PAT_GRANITE, 0},
      {"wrinkles1", ZR_PAT_WRINKLES, 1}, {"granite1", ZR_PAT_GRANITE, 1},
      {"agate1", ZR_PAT_AGATE, 1},      {"bozo3", ZR_PAT_BOZO, 3},
      {"dents3", ZR_PAT_DENTS, 3},      {"wrinkles3", ZR_PAT_WRINKLES, 3},
      {"granite3", ZR_PAT_GRANITE, 3},  {"agate3", ZR_PAT_AGATE, 3},
      {"agate", ZR_PAT_AGATE, 0},       {"agate04", ZR_PAT_AGATE, 0},
      {"turbx", ZR_PAT_GRADIENT, 0},    {"turby", ZR_PAT_GRADIENT, 0},
      {"turbz", ZR_PAT_GRADIENT, 0},    {"bozoturb", ZR_PAT_BOZO, 0},
      {"crackle", ZR_PAT_CRACKLE, 0},   {"crackle100", ZR_PAT_CRACKLE, 0},
      {"crackle011", ZR_PAT_CRACKLE, 0}, {"crackle_m1", ZR_PAT_CRACKLE, 0},
      {"crackle_m3", ZR_PAT_CRACKLE, 0}, {"crackle_off", ZR_PAT_CRACKLE, 0},
      {"crackle_solid", ZR_PAT_CRACKLE, 0},
      {"marbleturb", ZR_PAT_MARBLE, 0}, {"marbleturb1", ZR_PAT_MARBLE, 1},
      {"woodturb", ZR_PAT_WOOD, 0},     {"woodturb2", ZR_PAT_WOOD, 0},
  };
  for (size_t i = 0; i < sizeof kinds / sizeof kinds[0]; i++) {
    if (strcmp(name, kinds[i].name) != 0)
      continue;
    zr_pattern pt;
    zr__pattern_init(&pt, kinds[i].kind);
    pt.noise_generator = kinds[i].generator;
    if (strcmp(name, "agate04") == 0)
      pt.agate_turb = 0.4;
    if (strcmp(name, "turbx") == 0) {
      pt.turbulence = zr_v3(0.3, 0.3, 0.3);
    } else if (strcmp(name, "turby") == 0) {
      pt.vector = zr_v3(0, 1, 0);
      pt.turbulence = zr_v3(0.2, 0.4, 0.1);
      pt.octaves = 3;
      pt.omega = 0.7;
      pt.lambda = 2.5;
    } else if (strcmp(name, "turbz") == 0) {
      pt.vector = zr_v3(0, 0, 1);
      pt.turbulence = zr_v3(0.25, 0.25, 0.25);
      pt.octaves = 8;
    } else if (strcmp(name, "bozoturb") == 0) {
      pt.turbulence = zr_v3(0.5, 0.5, 0.5);
    } else if (strcmp(name, "crackle100") == 0) {
      pt.crackle_form = zr_v3(1, 0, 0);
    } else if (strcmp(name, "crackle011") == 0) {
      pt.crackle_form = zr_v3(0, 1, 1);
    } else if (strcmp(name, "crackle_m1") == 0) {
      pt.crackle_metric = 1;
    } else if (strcmp(name, "crackle_m3") == 0) {
      pt.crackle_metric = 3;
    } else if (strcmp(name, "crackle_off") == 0) {
      pt.crackle_offset = 0.5;
    } else if (strcmp(name, "crackle_solid") == 0) {
      pt.crackle_solid = true;
    } else if (strcmp(name, "marbleturb") == 0) {
      pt.turbulence = zr_v3(0.7, 0.7, 0.7);
      pt.octaves = 3;
      pt.omega = 0.6;
      pt.lambda = 2.3;
    } else if (strcmp(name, "marbleturb1") == 0) {
      pt.turbulence = zr_v3(0.3, 0.3, 0.3);
    } else if (strcmp(name, "woodturb") == 0) {
      pt.turbulence = zr_v3(0.1, 0.5, 1);
      pt.octaves = 5;
    } else if (strcmp(name, "woodturb2") == 0) {
      pt.turbulence = zr_v3(0.04, 0.04, 0.04);
      pt.octaves = 3;
    }
    return zr__pattern_eval(&pt, p);
  }
  fail_msg("unknown case %s", name);
  return 0;
}

/* Every recorded point of every case (generator 3 to 1e-7, marble and
   wood to 2e-4, see below).  The formulas are POV-Ray's to double
   rounding (1e-13 in the probes) but the tables hold values fitted to
   1e-12 and printed with 11 to 14 digits, and single-precision omega and
   agate_turb follow the float's rounding: 1e-9 is far below anything a
   picture shows and far above what the reconstruction leaves. */
static void test_noise_patterns(void **state) {
  (void)state;
  FILE *f = open_data("patterns.txt");
  char line[256], name[32], last_bad[32] = "";
  int n = 0, bad = 0;
  double worst = 0;
  while (fgets(line, sizeof line, f)) {
    double x, y, z, value;
    if (line[0] == '#' ||
        sscanf(line, "%31s %lf %lf %lf %lf", name, &x, &y, &z, &value) != 5)
      continue;
    double got = case_value(name, zr_v3(x, y, z));
    double err = fabs(got - value);
    /* Marble's and wood's triangle wave in POV-Ray is off by 1e-5 times
       the value's whole part (under 5 here, after the turbulence, times
       the wave's slope 2): the wave, not the noise. */
    double tol = strncmp(name, "marble", 6) == 0 ||
                         strncmp(name, "wood", 4) == 0
                     ? 2e-4
                     : 1e-9;
    /* Generator 3 carries POV-Ray's rounding (about 1e-8 at random
       points; bench/noise/probe_gen3.py): its values pass to 1e-7. */
    if (name[strlen(name) - 1] == '3' && strncmp(name, "crackle", 7) != 0)
      tol = 1e-7;
    if (!(err <= tol)) {
      if (strcmp(name, last_bad) != 0) /* the first of each case */
        print_error("%s at <%g, %g, %g>: %.17g, POV-Ray %.17g\n", name, x,
                    y, z, got, value);
      snprintf(last_bad, sizeof last_bad, "%s", name);
      bad++;
    }
    if (err > worst && tol < 1e-8)
      worst = err;
    n++;
  }
  fclose(f);
  print_message("%d points, largest difference %.3g (generator 3, marble "
                "and wood aside)\n",
                n, worst);
  assert_int_equal(bad, 0);
  assert_true(n > 8000);
}

/* Far from the origin POV-Ray's lattice cell leaves the 32-bit range:
   the noise is 0 or 1 there, and an ordinary value again just below
   -2^31 (lib/core/noise.c).  The values povray 3.7 printed for
   bench/noise/probe_far.pov. */
static void test_noise_far(void **state) {
  (void)state;
  static const double probe[][4] = {
      {2.1e9, 0.3, 0.7, 0.573254598658},
      {2147483000, 0.5, 0.7, 0.352295679030},
      {2147483647.5, 1.2, 0.7, 0.410299219130},
      {2147483648.0, 0.3, 0.7, 0.0},
      {2147483648.0, 0.75, 0.7, 1.0},
      {3e9, 0.3, 0.7, 0.0},
      {3e9, 1.0, 0.7, 1.0},
      {-3e9, 1.0, 0.7, 1.0},
      {-2147483648.5, 0.75, 0.7, 0.160726623185},
      {-2147483648.5, 1.1, 0.7, 0.109375214303},
      {0.5, 0.7, 3e9, 1.0},
      {1e12, 0.75, 0.7, 1.0},
      /* povray 3.7 printed these too (bench/noise/probe_far.pov's
         points moved out); at 1e40 on all three axes it prints -nan,
         which zRcube keeps finite (lib/core/noise.c, blend()). */
      {1e16, 0.75, 0.7, 1.0},
      {1e20, 0.75, 0.7, 1.0},
  };
  double v = zr__noise_lattice(zr_v3(1e40, 1e40, 1e40));
  assert_true(v == 0 || v == 1);
  v = zr__noise_lattice(zr_v3(NAN, 0.5, 0.5));
  assert_true(v == 0 || v == 1);
  for (size_t i = 0; i < sizeof probe / sizeof probe[0]; i++) {
    double v = zr__noise_lattice(zr_v3(probe[i][0], probe[i][1], probe[i][2]));
    if (fabs(v - probe[i][3]) > 5e-12)
      fail_msg("noise(%.17g, %g, %g) = %.12f, povray printed %.12f",
               probe[i][0], probe[i][1], probe[i][2], v, probe[i][3]);
  }
}

/* Turbulence far out: its vector noise takes cells past the 32-bit
   range as -2^31 too, so the point moves by a huge amount and the noise
   there is 0 or 1 (lib/core/noise.c).  bumps with turbulence 1 and
   lambda 50 (six octaves reach 50^5 p, as poliana-girl's aug4.pov does)
   and bumps with warp { turbulence 0.001 octaves 1 }: the values povray
   3.7 printed for bench/noise/probe_far.pov ("dfar" lines).  Before,
   the vector noise kept its plain cell there: (-7.9, 0.4, -5.5) with
   lambda 50 gave 0.5858 for povray's 0, and aug4.pov scored SSIM 0.60
   (1.00 now). */
static void test_noise_dfar(void **state) {
  (void)state;
  static const double probe[][5] = {
      {50, 0.37, -0.20, -3.00, 0.452725144585},
      {1, 0.37, -0.20, -3.00, 0.519401790215},
      {50, 2.30, 1.10, -0.70, 0.572212887812},
      {1, 2.30, 1.10, -0.70, 0.623876833580},
      {50, -4.10, 2.20, 0.90, 0.418918099436},
      {1, -4.10, 2.20, 0.90, 0.499285280935},
      {50, 6.50, -1.30, 2.20, 0.672439568599},
      {1, 6.50, -1.30, 2.20, 0.529473001598},
      {50, -7.90, 0.40, -5.50, 0.000000000000},
      {1, -7.90, 0.40, -5.50, 0.566222654438},
      {50, 9.60, 3.30, 4.10, 1.000000000000},
      {1, 9.60, 3.30, 4.10, 0.576143450412},
      {50, 2100000000.00, 0.50, 0.70, 1.000000000000},
      {1, 2100000000.00, 0.50, 0.70, 0.539458738320},
      {50, 3000000000.00, 0.30, 0.70, 1.000000000000},
      {1, 3000000000.00, 0.30, 0.70, 1.000000000000},
      {50, -3000000000.00, 5.20, 3.10, 0.000000000000},
      {1, -3000000000.00, 5.20, 3.10, 1.000000000000},
      {50, 0.30, 0.20, 3000000000.00, 1.000000000000},
      {1, 0.30, 0.20, 3000000000.00, 0.000000000000},
      {50, -2147483649.50, 0.50, 0.70, 1.000000000000},
      {1, -2147483649.50, 0.50, 0.70, 0.000000000000},
      {50, 2147483648.30, 0.50, 0.70, 1.000000000000},
      {1, 2147483648.30, 0.50, 0.70, 1.000000000000},
  };
  for (size_t i = 0; i < sizeof probe / sizeof probe[0]; i++) {
    zr_pattern pt;
    zr__pattern_init(&pt, ZR_PAT_BUMPS);
    if (probe[i][0] == 50) {
      pt.turbulence = zr_v3(1, 1, 1);
      pt.lambda = 50;
    } else {
      pt.turbulence = zr_v3(0.001, 0.001, 0.001);
      pt.octaves = 1;
    }
    zr_vec3 p = zr_v3(probe[i][1], probe[i][2], probe[i][3]);
    double v = zr__pattern_eval(&pt, p);
    /* povray printed 12 decimals. */
    if (fabs(v - probe[i][4]) > 2e-12)
      fail_msg("case %g at (%.17g, %g, %g): %.12f, povray printed %.12f",
               probe[i][0], p.x, p.y, p.z, v, probe[i][4]);
  }
}

/* cells: POV-Ray 3.7's values at 600 random points up to 3000 away and
   4 past the 32-bit range (cell -2^31),
   recorded by bench/noise/probe_cells.py (tests/noise/cells.txt); the
   crackle table they come from holds its points to about 1e-12.  Before,
   cells was a hash of our own (GSprites_Floors_demo.pov's boards came
   out in other colours). */
static void test_noise_cells(void **state) {
  (void)state;
  FILE *f = open_data("cells.txt");
  char line[256];
  int n = 0;
  zr_pattern pt;
  zr__pattern_init(&pt, ZR_PAT_CELLS);
  while (fgets(line, sizeof line, f)) {
    double x, y, z, value;
    if (line[0] == '#' || sscanf(line, "%lf %lf %lf %lf", &x, &y, &z,
                                 &value) != 4)
      continue;
    double v = zr__pattern_eval(&pt, zr_v3(x, y, z));
    if (fabs(v - value) > 1e-9)
      fail_msg("cells(%g, %g, %g) = %.17g, povray printed %.17g", x, y, z,
               v, value);
    n++;
  }
  fclose(f);
  assert_int_equal(n, 604);
}

/* The lattice noise's sum written plainly (noise.c, blend()), compiled
   with the test's default flags: the library's noises, which may run
   as their AVX2 copies, must give the same bits at ordinary points. */
static double ref_smooth(double t) { return t * t * (3 - 2 * t); }

static double ref_blend(zr_vec3 p, const double (*tab)[4]) {
  double f[3] = {floor(p.x), floor(p.y), floor(p.z)};
  int64_t c[3] = {(int64_t)f[0], (int64_t)f[1], (int64_t)f[2]};
  double t[3] = {p.x - (double)c[0], p.y - (double)c[1], p.z - (double)c[2]};
  double w[3][2];
  for (int a = 0; a < 3; a++) {
    w[a][1] = ref_smooth(t[a]);
    w[a][0] = 1 - w[a][1];
  }
  double sum = 0;
  for (int i = 0; i < 2; i++)
    for (int j = 0; j < 2; j++)
      for (int k = 0; k < 2; k++) {
        unsigned h = zr__noise_hash(c[0] + i, c[1] + j, c[2] + k,
                                    NOISE_HASH_OFFSET) & 255u;
        double wc = w[0][i] * w[1][j] * w[2][k];
        const double *e = tab[h];
        sum += wc * (e[0] + e[1] * (t[0] - i) + e[2] * (t[1] - j) +
                     e[3] * (t[2] - k));
      }
  return sum;
}

static void test_noise_blend_reference(void **state) {
  (void)state;
  uint64_t s = 12345;
  for (int n = 0; n < 20000; n++) {
    double v[3];
    for (int a = 0; a < 3; a++) {
      s = s * 6364136223846793005u + 1442695040888963407u;
      v[a] = ((double)(s >> 11) / 9007199254740992.0 - 0.5) * 2000.0;
    }
    zr_vec3 p = zr_v3(v[0], v[1], v[2]);
    double want = ref_blend(p, noise_lattice);
    want = want < 0 ? 0 : want > 1 ? 1 : want;
    double got = zr__noise_lattice(p);
    assert_memory_equal(&got, &want, sizeof got);
    zr_vec3 d = zr__dnoise_lattice(p);
    double dg[3] = {d.x, d.y, d.z};
    for (int m = 0; m < 3; m++) {
      double dw = ref_blend(p, dnoise_lattice[m]);
      assert_memory_equal(&dg[m], &dw, sizeof dw);
    }
  }
}

/* The AVX2 blend's interleaved table (bench/noise/lanes.py) holds the
   same doubles as the measured tables, bit for bit. */
static void test_noise_lanes(void **state) {
  (void)state;
  for (int h = 0; h < 256; h++)
    for (int c = 0; c < 4; c++) {
      for (int m = 0; m < 3; m++)
        assert_memory_equal(&noise_lanes[h][c][m], &dnoise_lattice[m][h][c],
                            sizeof(double));
      assert_memory_equal(&noise_lanes[h][c][3], &noise_lattice[h][c],
                          sizeof(double));
    }
}

/* Turbulence's octave sum (zr__dturbulence_lattice, which keeps the
   octaves in the AVX2 blend's lanes) against the plain sum of
   ref_blend's octaves, bit for bit, for stones2.inc's lambda 2.5 and
   omega 0.75 (as floats, as patterns give them) and the defaults. */
static void test_noise_dturbulence_reference(void **state) {
  (void)state;
  const double params[][3] = {{5, 0.75f, 2.5f}, {6, 0.5f, 2.0f},
                              {1, 0.5f, 2.0f}, {0, 0.5f, 2.0f}};
  uint64_t s = 777;
  for (int n = 0; n < 5000; n++) {
    double v[3];
    for (int a = 0; a < 3; a++) {
      s = s * 6364136223846793005u + 1442695040888963407u;
      v[a] = ((double)(s >> 11) / 9007199254740992.0 - 0.5) * 200.0;
    }
    zr_vec3 p = zr_v3(v[0], v[1], v[2]);
    for (size_t q = 0; q < sizeof params / sizeof params[0]; q++) {
      int octaves = (int)params[q][0];
      double want[3] = {0, 0, 0}, amp = 1, scale = 1;
      for (int i = 0; i < octaves; i++) {
        zr_vec3 ps = zr_v3_scale(p, scale);
        for (int m = 0; m < 3; m++)
          want[m] = want[m] + ref_blend(ps, dnoise_lattice[m]) * amp;
        amp *= params[q][1];
        scale *= params[q][2];
      }
      zr_vec3 d = zr__dturbulence_lattice(p, octaves, params[q][1],
                                          params[q][2]);
      double got[3] = {d.x, d.y, d.z};
      assert_memory_equal(got, want, sizeof got);
    }
  }
}

/* zr__noise_generator_n (with AVX2 four points in the lanes of one
   register) gives zr__noise_generator's values bit for bit, for each
   generator and any count (groups of four and a rest), near, far out
   (the 32-bit cell rule) and at NaN. */
static void test_noise_generator_n(void **state) {
  (void)state;
  uint64_t s = 4242;
  zr_vec3 p[11];
  for (int n = 0; n < 3000; n++) {
    for (int i = 0; i < 11; i++) {
      double v[3];
      for (int a = 0; a < 3; a++) {
        s = s * 6364136223846793005u + 1442695040888963407u;
        v[a] = ((double)(s >> 11) / 9007199254740992.0 - 0.5) * 500.0;
      }
      p[i] = zr_v3(v[0], v[1], v[2]);
    }
    /* Generator 3 takes no far points (its cell conversion is a plain
       one, undefined past the 64-bit range). */
    bool far = n % 7 == 0 || n % 13 == 0 || n % 17 == 0;
    if (n % 7 == 0)
      p[n % 11].y = 3e9 * (n % 2 ? 1 : -1);
    if (n % 13 == 0)
      p[n % 11].z = 1e30;
    if (n % 17 == 0)
      p[n % 11].x = NAN;
    for (int g = 1; g <= (far ? 2 : 3); g++) {
      int count = 1 + n % 11;
      double got[11];
      zr__noise_generator_n(p, count, g, got);
      for (int i = 0; i < count; i++) {
        double want = zr__noise_generator(p[i], g);
        assert_memory_equal(&got[i], &want, sizeof want);
      }
    }
  }
}

/* zr__noise_nearest2 (with AVX2 four cells at a time) against crackle's
   plain loop written out here: the same two smallest squared distances,
   bit for bit, at points near and far (2^40, 2^53: the plain loop) and
   on cell boundaries. */
static void test_noise_nearest2(void **state) {
  (void)state;
  uint64_t s = 99;
  for (int n = 0; n < 20000; n++) {
    double v[3];
    for (int a = 0; a < 3; a++) {
      s = s * 6364136223846793005u + 1442695040888963407u;
      v[a] = ((double)(s >> 11) / 9007199254740992.0 - 0.5) * 600.0;
    }
    if (n % 5 == 0)
      v[n % 3] = floor(v[n % 3]);
    if (n % 11 == 0)
      v[n % 3] *= 0x1p40;
    if (n % 23 == 0)
      v[n % 3] = 0x1p53 + 2 * n;
    zr_vec3 p = zr_v3(v[0], v[1], v[2]);
    int64_t c[3] = {(int64_t)floor(p.x), (int64_t)floor(p.y),
                    (int64_t)floor(p.z)};
    double want[2] = {INFINITY, INFINITY};
    for (int i = -1; i <= 1; i++)
      for (int j = -1; j <= 1; j++)
        for (int k = -1; k <= 1; k++) {
          const double *o = crackle_points[zr__noise_hash(
              c[0] + i, c[1] + j, c[2] + k, CRACKLE_HASH_OFFSET)];
          double r[3] = {p.x - ((double)(c[0] + i) + o[0]),
                         p.y - ((double)(c[1] + j) + o[1]),
                         p.z - ((double)(c[2] + k) + o[2])};
          double d = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
          if (d < want[0]) {
            want[1] = want[0];
            want[0] = d;
          } else if (d < want[1]) {
            want[1] = d;
          }
        }
    double got[2];
    zr__noise_nearest2(p, crackle_points, CRACKLE_HASH_OFFSET, got);
    assert_memory_equal(got, want, sizeof got);
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_noise_rand_streams),
      cmocka_unit_test(test_noise_patterns),
      cmocka_unit_test(test_noise_far),
      cmocka_unit_test(test_noise_dfar),
      cmocka_unit_test(test_noise_cells),
      cmocka_unit_test(test_noise_blend_reference),
      cmocka_unit_test(test_noise_lanes),
      cmocka_unit_test(test_noise_dturbulence_reference),
      cmocka_unit_test(test_noise_generator_n),
      cmocka_unit_test(test_noise_nearest2),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
