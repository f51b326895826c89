/*
 * test_height_field.c - the height field from scene text and image files
 * through the parser (lib/sdl/build_hf.c, lib/image/heights.c) to the
 * tracer's crossings, normals, inside tests and bounds
 * (lib/trace/obj_height_field.c).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "config.h"
#include "core/arena.h"
#include "scene/scene.h"
#include "scene/shapes.h"
#include "trace/intersect.h"
#include "trace/obj_isosurface.h"
#include "zrcube.h"
#include "parse_fixture.h"
#include "test_util.h"

/* The first crossing straight down onto (x, z), in object space. */
static int down(const zr_object *o, double x, double z,
                zr_hit h[ZR_MAX_CROSSINGS]) {
  zr_ray r = {zr_v3(x, 5, z), zr_v3(0, -1, 0)};
  return zr__intersect(o, &r, 0, INFINITY, h);
}

/* Samples are stored as floats: 1e-6 is their rounding and more.  Rays
   aimed at a grid point are moved EDGE inside, off the mesh's border,
   which changes the height by no more than EDGE times the slope. */
#define SAMPLE_EPS 1e-6
#define EDGE 1e-9

static const vfile files[] = {
    /* Row 0 (the back, z = 1) rises to the left; 16-bit samples. */
    {"a.pgm", "P2\n3 3\n65535\n65535 32768 0\n0 0 0\n0 0 13107\n"},
    /* A colour file holds 256 r + g. */
    {"c.ppm", "P3\n2 2\n255\n1 2 0  0 0 0\n0 0 0  255 255 255\n"},
    {"t.tif", "not read"},
    {NULL, NULL}};

static void test_height_field_image_layout(void **state) {
  fixture *f = *state;
  f->files = files;
  const zr_object *o = only(f, "height_field { pgm \"a.pgm\" }\n");
  assert_int_equal(o->kind, ZR_OBJ_HEIGHT_FIELD);
  assert_int_equal(o->u.height_field.w, 3);
  assert_int_equal(o->u.height_field.h, 3);
  zr_hit h[ZR_MAX_CROSSINGS];
  /* Image pixel (0, 0) is at x = 0, z = 1; (2, 2) at x = 1, z = 0. */
  assert_int_equal(down(o, EDGE, 1 - EDGE, h), 1);
  assert_near(h[0].t, 5 - 1, SAMPLE_EPS);
  assert_int_equal(down(o, 0.5, 1 - EDGE, h), 1);
  assert_near(h[0].t, 5 - 32768.0 / 65535, SAMPLE_EPS);
  assert_int_equal(down(o, 1 - EDGE, EDGE, h), 1);
  assert_near(h[0].t, 5 - 0.2, SAMPLE_EPS);
  /* Flat ground faces up. */
  assert_int_equal(down(o, 0.3, 0.3, h), 1);
  assert_near(h[0].t, 5, SAMPLE_EPS);
  assert_vec(h[0].normal, 0, 1, 0, 1e-12);
  assert_near(zr__height_field_height(o, 0.25, 1), 0.75, 1e-4);
  assert_true(zr__inside(o, zr_v3(0.05, 0.5, 0.95)));
  assert_false(zr__inside(o, zr_v3(0.9, 0.5, 0.95)));
  assert_false(zr__inside(o, zr_v3(1.2, 0.01, 0.5)));
  zr_vec3 lo, hi;
  assert_true(zr__object_bounds(o, &lo, &hi));
  assert_vec(lo, 0, 0, 0, 1e-6);
  assert_vec(hi, 1, 1, 1, 1e-6);
  /* Without a type keyword the file says what it is. */
  o = only(f, "height_field { \"c.ppm\" scale <2, 3, 2> }\n");
  assert_int_equal(down(o, EDGE, 2 - EDGE, h), 1);
  assert_near(h[0].t, 5 - 3 * 258.0 / 65535, 1e-6);
  assert_int_equal(down(o, 2 - EDGE, EDGE, h), 1);
  assert_near(h[0].t, 5 - 3, 1e-6);
}

/* function W, H { f(x, y) }: sample (i, j) at x = i / (W - 1),
   y = j / (H - 1), placed like image pixel (i, j); clamped to [0, 1]. */
static void test_height_field_function(void **state) {
  fixture *f = *state;
  const zr_object *o = only(
      f, "#declare F = function { 0.25 + 0.5 * x + 2 * (y > 0.9) }\n"
         "height_field { function 5, 3 { F(x, y, z) } smooth }\n");
  assert_int_equal(o->u.height_field.w, 5);
  assert_int_equal(o->u.height_field.h, 3);
  assert_true(o->u.height_field.smooth);
  zr_hit h[ZR_MAX_CROSSINGS];
  /* y = 0 is the back row (z = 1). */
  /* The samples are 16-bit codes rounded down, as POV-Ray keeps them:
     0.5 is 32767 / 65535. */
  assert_int_equal(down(o, 0.5, 1 - EDGE, h), 1);
  assert_near(h[0].t, 5 - 32767.0 / 65535, SAMPLE_EPS);
  /* y = 1 went past 1 and is clamped, at the front (z = 0). */
  assert_int_equal(down(o, 0.5, EDGE, h), 1);
  assert_near(h[0].t, 5 - 1, SAMPLE_EPS);
  /* smooth: the normal in the middle of the back row has POV-Ray's
     slope for a ramp of 0.5 over 5 samples, 2/3, not 0.5 (its normals
     are kept as multiples of 1/32767 in grid units: obj_height_field.c
     vertex_normal; tests/test_hf_smooth.sh has povray's values). */
  assert_int_equal(down(o, 0.5, 1 - EDGE, h), 1);
  double n = sqrt(1 + 4.0 / 9);
  assert_vec(h[0].normal, -(2.0 / 3) / n, 1 / n, 0, 1e-4);
}

/* water_level hides the surface below it. */
static void test_height_field_water(void **state) {
  fixture *f = *state;
  f->files = files;
  const zr_object *o =
      only(f, "height_field { pgm \"a.pgm\" water_level 0.1 hierarchy off }\n");
  zr_hit h[ZR_MAX_CROSSINGS];
  assert_int_equal(down(o, 0.3, 0.3, h), 0);
  assert_int_equal(down(o, EDGE, 1 - EDGE, h), 1);
  /* A ray along the ground under the water meets nothing. */
  zr_ray r = {zr_v3(-1, 0.05, 0.3), zr_v3(1, 0, 0)};
  assert_int_equal(zr__intersect(o, &r, 0, INFINITY, h), 0);
}

static void test_height_field_bad_input(void **state) {
  fixture *f = *state;
  f->files = files;
  bad(f, "height_field { \"t.exr\" }\n", ZR_EUNSUPPORTED,
      "height_field: 'exr' files are not supported yet (use png, gif, pot, "
      "tga, bmp, tiff, pgm, ppm or jpeg)",
      "t.pov:1:16: error: height_field: 'exr' files are not supported yet "
      "(use png, gif, pot, tga, bmp, tiff, pgm, ppm or jpeg)\n"
      "    1 | height_field { \"t.exr\" }\n"
      "      |                ^~~~~~~\n");
  bad(f, "height_field { hdr \"t.hdr\" }\n", ZR_EUNSUPPORTED,
      "height_field: 'hdr' files are not supported yet (use png, gif, pot, "
      "tga, bmp, tiff, pgm, ppm or jpeg)", NULL);
  bad(f, "height_field { png \"none.png\" }\n", ZR_ENOTFOUND,
      "height_field file 'none.png' not found", NULL);
  bad(f, "height_field { function 1, 10 { x } }\n", ZR_ESCENE,
      "a height_field's resolution must be 2 to 65536", NULL);
  bad(f, "height_field { function 4, 4 { x } water_level <1, 2> }\n",
      ZR_ESYNTAX, "expected a float, got a 2-D vector", NULL);
}

/* hf_gray_16 in global_settings has been an output option since 3.7. */
static void test_height_field_hf_gray_16(void **state) {
  fixture *f = *state;
  good(f, "global_settings { hf_gray_16 on }\n");
  assert_int_equal(f->diag.warnings, 1);
  assert_non_null(strstr(f->diag.warning, "'hf_gray_16' is ignored"));
}


/* The block hierarchy against every triangle: on grids of 8 and 16-bit
   codes and floats whose sides are not multiples of the 8-square leaf
   block (several levels), random rays from every side, the nearest
   crossing from the walk equals the nearest of a brute-force test of
   all 2 (w - 1)(h - 1) triangles (to 1e-9: the same arithmetic, but a
   ray through an edge may be found in either triangle). */
static bool tri_hit(zr_vec3 org, zr_vec3 dir, zr_vec3 p0, zr_vec3 p1,
                    zr_vec3 p2, double *t) {
  zr_vec3 e1 = zr_v3_sub(p1, p0), e2 = zr_v3_sub(p2, p0);
  zr_vec3 pv = zr_v3_cross(dir, e2);
  double det = zr_v3_dot(e1, pv);
  if (det == 0.0)
    return false;
  zr_vec3 tv = zr_v3_sub(org, p0);
  double u = zr_v3_dot(tv, pv) / det;
  zr_vec3 qv = zr_v3_cross(tv, e1);
  double v = zr_v3_dot(dir, qv) / det;
  if (u < 0.0 || u > 1.0 || v < 0.0 || u + v > 1.0)
    return false;
  *t = zr_v3_dot(e2, qv) / det;
  return *t > 0.0;
}

static double brute_nearest(int w, int h, const double *y, zr_vec3 org,
                            zr_vec3 dir) {
  double best = INFINITY, dx = 1.0 / (w - 1), dz = 1.0 / (h - 1);
  for (int j = 0; j + 1 < h; j++)
    for (int i = 0; i + 1 < w; i++) {
      /* y[] is in z order (row j at z = j / (h - 1)). */
      zr_vec3 a = zr_v3(i * dx, y[j * w + i], j * dz);
      zr_vec3 b = zr_v3((i + 1) * dx, y[j * w + i + 1], j * dz);
      zr_vec3 c = zr_v3(i * dx, y[(j + 1) * w + i], (j + 1) * dz);
      zr_vec3 d = zr_v3((i + 1) * dx, y[(j + 1) * w + i + 1], (j + 1) * dz);
      double t;
      if (tri_hit(org, dir, a, c, b, &t))
        best = fmin(best, t);
      if (tri_hit(org, dir, b, c, d, &t))
        best = fmin(best, t);
    }
  return best;
}

static void test_height_field_hierarchy_vs_brute(void **state) {
  (void)state;
  static const int sizes[][3] = {{2, 2, 8},   {9, 9, 16},  {70, 45, 8},
                                 {17, 130, 16}, {33, 33, 32}};
  uint64_t seed = 12345;
  for (size_t c = 0; c < sizeof sizes / sizeof sizes[0]; c++) {
    int w = sizes[c][0], h = sizes[c][1], bits = sizes[c][2];
    zr_arena arena;
    zr__arena_init(&arena);
    void *codes = zr__arena_alloc(&arena, (size_t)w * h * 4);
    double *y = zr__arena_alloc(&arena, (size_t)w * h * sizeof *y);
    assert_non_null(codes);
    for (int r = 0; r < h; r++) /* image row r is grid row h - 1 - r */
      for (int i = 0; i < w; i++) {
        seed = seed * 6364136223846793005ull + 1442695040888963407ull;
        unsigned v = (unsigned)(seed >> 40);
        size_t k = (size_t)r * w + i, g = (size_t)(h - 1 - r) * w + i;
        if (bits == 8) {
          ((uint8_t *)codes)[k] = (uint8_t)v;
          y[g] = (uint8_t)v / 255.0;
        } else if (bits == 16) {
          ((uint16_t *)codes)[k] = (uint16_t)v;
          y[g] = (uint16_t)v / 65535.0;
        } else {
          ((float *)codes)[k] = (float)((v & 0xffff) / 65536.0);
          y[g] = ((float *)codes)[k];
        }
      }
    const struct zr_hf_grid *grid = NULL;
    assert_int_equal(zr__height_field_grid(&arena, codes, bits, w, h, &grid),
                     ZR_OK);
    zr_object o;
    memset(&o, 0, sizeof o);
    o.kind = ZR_OBJ_HEIGHT_FIELD;
    o.u.height_field.grid = grid;
    o.u.height_field.w = w;
    o.u.height_field.h = h;
    int hits = 0;
    for (int k = 0; k < 3000; k++) {
      double q[6];
      for (int m = 0; m < 6; m++) {
        seed = seed * 6364136223846793005ull + 1442695040888963407ull;
        q[m] = (double)(seed >> 11) / 9007199254740992.0;
      }
      /* From a point around the unit cube toward a point inside it. */
      zr_vec3 org = zr_v3(3 * q[0] - 1, 2.5 * q[1] - 0.5, 3 * q[2] - 1);
      zr_vec3 to = zr_v3(q[3], q[4], q[5]);
      if (k % 4 == 0) /* straight down */
        org = zr_v3(q[3], 2, q[5]);
      if (k % 4 == 1) /* nearly level */
        org.y = to.y + 0.01 * (q[1] - 0.5);
      zr_vec3 dir = zr_v3_sub(to, org);
      double t[4];
      zr_vec3 n[4];
      int found =
          zr__height_field_crossings(&o, org, dir, 0.0, INFINITY, t, n);
      double want = brute_nearest(w, h, y, org, dir);
      if (want == INFINITY) {
        assert_int_equal(found, 0);
        continue;
      }
      hits++;
      assert_true(found >= 1);
      assert_near(t[0], want, 1e-9);
      if (found == 2)
        assert_true(t[1] > t[0]);
    }
    assert_true(hits > 500);
    zr__arena_free(&arena);
  }
}

/* The nearest-surface search (zr__intersect_first: the first crossing
   alone, with or without its normal, the walk stopping there and at
   each leaf block's box) finds the two-crossing search's first
   crossing and normal, smooth or not, on a nearly flat field like
   pneumaticBoat's sand (heights 0.5 to 0.525), for rays from above,
   nearly level ones and rays leaving the surface upwards. */
static void test_height_field_first_vs_two(void **state) {
  (void)state;
  enum { W = 300, H = 260 };
  zr_arena arena;
  zr__arena_init(&arena);
  float *codes = zr__arena_alloc(&arena, (size_t)W * H * sizeof *codes);
  assert_non_null(codes);
  uint64_t seed = 777;
  for (size_t k = 0; k < (size_t)W * H; k++) {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    codes[k] = (float)(0.5 + 0.025 * (double)(seed >> 11) /
                                 9007199254740992.0);
  }
  const struct zr_hf_grid *grid = NULL;
  assert_int_equal(zr__height_field_grid(&arena, codes, 32, W, H, &grid),
                   ZR_OK);
  int hits = 0, up = 0;
  for (int smooth = 0; smooth < 2; smooth++) {
    zr_object o;
    memset(&o, 0, sizeof o);
    o.kind = ZR_OBJ_HEIGHT_FIELD;
    o.u.height_field.grid = grid;
    o.u.height_field.w = W;
    o.u.height_field.h = H;
    o.u.height_field.smooth = smooth;
    for (int k = 0; k < 4000; k++) {
      double q[6];
      for (int m = 0; m < 6; m++) {
        seed = seed * 6364136223846793005ull + 1442695040888963407ull;
        q[m] = (double)(seed >> 11) / 9007199254740992.0;
      }
      zr_vec3 org = zr_v3(q[0], 0.6 + q[1], q[2]);
      zr_vec3 dir = zr_v3_sub(zr_v3(q[3], 0.5 + 0.025 * q[4], q[5]), org);
      if (k % 3 == 1) /* nearly level, through the slab */
        org.y = 0.5125 + 0.02 * (q[1] - 0.5), dir.y = 0.01 * (q[4] - 0.5);
      if (k % 3 == 2) {
        /* From just above the surface, up at an angle or nearly level:
           the sample rays of a radiosity record. */
        double hgt = zr__height_field_height(&o, q[0], q[2]);
        org = zr_v3(q[0], hgt + 1e-7, q[2]);
        dir = zr_v3(q[3] - 0.5, 0.002 + 0.05 * q[4], q[5] - 0.5);
      }
      double t[4];
      zr_vec3 n[4];
      int found =
          zr__height_field_crossings(&o, org, dir, 0.0, INFINITY, t, n);
      zr_ray ray = {org, dir};
      zr_hit a[ZR_MAX_CROSSINGS], b[ZR_MAX_CROSSINGS];
      int na = zr__intersect_first(&o, &ray, 0.0, INFINITY, false, a);
      int nb = zr__intersect_first(&o, &ray, 0.0, INFINITY, true, b);
      assert_int_equal(na, found > 0);
      assert_int_equal(nb, found > 0);
      if (found == 0)
        continue;
      hits++;
      up += k % 3 == 2;
      assert_true(a[0].t == t[0]);
      assert_true(b[0].t == t[0]);
      zr_vec3 want = zr_v3_norm(n[0]);
      assert_near(b[0].normal.x, want.x, 1e-12);
      assert_near(b[0].normal.y, want.y, 1e-12);
      assert_near(b[0].normal.z, want.z, 1e-12);
    }
  }
  assert_true(hits > 3000);
  assert_true(up > 300);
  zr__arena_free(&arena);
}

#define TEST(fn) cmocka_unit_test_setup_teardown(fn, setup, teardown)

int main(void) {
  const struct CMUnitTest tests[] = {
      TEST(test_height_field_image_layout),
      TEST(test_height_field_function),
      TEST(test_height_field_water),
      TEST(test_height_field_bad_input),
      TEST(test_height_field_hf_gray_16),
      cmocka_unit_test(test_height_field_hierarchy_vs_brute),
      cmocka_unit_test(test_height_field_first_vs_two),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
