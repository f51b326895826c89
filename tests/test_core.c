/*
 * test_core.c - vectors, transforms, strings, arena and diagnostics.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>

#include "core/arena.h"
#include "core/context.h"
#include "core/strbuf.h"
#include "core/transform.h"
#include "core/vec.h"
#include "test_util.h"

/* Exact arithmetic on small integers and quarter turns: 1e-12 covers the
   rounding of cos/sin products. */
#define EPS 1e-12

static void test_core_vec_cross_left_handed(void **state) {
  (void)state;
  /* x cross y is z in any handedness; the handedness is in the meaning. */
  assert_vec(zr_v3_cross(zr_v3(1, 0, 0), zr_v3(0, 1, 0)), 0, 0, 1, EPS);
  assert_vec(zr_v3_norm(zr_v3(3, 0, 4)), 0.6, 0, 0.8, EPS);
  assert_vec(zr_v3_norm(zr_v3(0, 0, 0)), 0, 0, 0, EPS);
}

/* zr_min and zr_max give libm's fmin and fmax bit for bit (the sign of
   a zero included) on every pair of special values, and a NaN where
   both are NaNs; volatile keeps the compiler from folding libm's. */
static void test_core_min_max_as_libm(void **state) {
  (void)state;
  static volatile double v[] = {0.0,       -0.0,      1.0,    -1.0,
                                1e-310,    -1e-310,   1e300,  -1e300,
                                INFINITY,  -INFINITY, NAN,    -NAN,
                                0x1p-1074, 2.5};
  size_t n = sizeof v / sizeof v[0];
  for (size_t i = 0; i < n; i++)
    for (size_t j = 0; j < n; j++) {
      double a = v[i], b = v[j];
      double got[2] = {zr_min(a, b), zr_max(a, b)};
      double want[2] = {fmin(a, b), fmax(a, b)};
      for (int k = 0; k < 2; k++) {
        if (isnan(want[k])) {
          assert_true(isnan(got[k]));
          continue;
        }
        if (memcmp(&got[k], &want[k], sizeof got[k]) != 0)
          fail_msg("%s(%g, %g): %g, libm %g", k ? "zr_max" : "zr_min", a,
                   b, got[k], want[k]);
      }
    }
  assert_vec(zr_v3_min(zr_v3(1, -2, NAN), zr_v3(NAN, 3, 4)), 1, -2, 4, 0);
  assert_vec(zr_v3_max(zr_v3(1, -2, NAN), zr_v3(NAN, 3, 4)), 1, 3, 4, 0);
  assert_true(zr_v3_max_comp(zr_v3(-1, 7, 3)) == 7.0);
  assert_true(zr_v3_min_comp(zr_v3(-1, 7, 3)) == -1.0);
}

static void test_core_rotate_matches_povray(void **state) {
  (void)state;
  zr_transform t;
  zr__transform_identity(&t);
  zr__transform_rotate(&t, zr_v3(0, 90, 0));
  /* POV-Ray: rotate y*90 takes +x to -z. */
  assert_vec(zr__xform_point(t.m, zr_v3(1, 0, 0)), 0, 0, -1, EPS);
  zr__transform_identity(&t);
  zr__transform_rotate(&t, zr_v3(90, 0, 0));
  assert_vec(zr__xform_point(t.m, zr_v3(0, 1, 0)), 0, 0, 1, EPS);
  zr__transform_identity(&t);
  zr__transform_rotate(&t, zr_v3(0, 0, 90));
  assert_vec(zr__xform_point(t.m, zr_v3(1, 0, 0)), 0, 1, 0, EPS);
}

static void test_core_transform_order_and_inverse(void **state) {
  (void)state;
  zr_transform t;
  zr__transform_identity(&t);
  zr__transform_scale(&t, zr_v3(2, 3, 4));
  zr__transform_translate(&t, zr_v3(1, 0, 0));
  zr__transform_rotate(&t, zr_v3(0, 0, 90));
  zr_vec3 p = zr__xform_point(t.m, zr_v3(1, 1, 1));
  /* scale -> (2,3,4), translate -> (3,3,4), rotate z 90 -> (-3,3,4) */
  assert_vec(p, -3, 3, 4, EPS);
  assert_vec(zr__xform_point(t.inv, p), 1, 1, 1, EPS);
  /* A normal stays perpendicular to a transformed tangent. */
  zr_vec3 n = zr__xform_normal(t.inv, zr_v3(1, 0, 0));
  zr_vec3 tangent = zr__xform_dir(t.m, zr_v3(0, 1, 0));
  assert_true(fabs(zr_v3_dot(n, tangent)) < EPS);
}

static void test_core_matrix_keyword(void **state) {
  (void)state;
  zr_transform t;
  zr__transform_identity(&t);
  /* matrix <1,0,0, 0,1,0, 0,0,1, 5,6,7> is translate <5,6,7>. */
  const double v[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 5, 6, 7};
  assert_true(zr__transform_matrix(&t, v));
  assert_vec(zr__xform_point(t.m, zr_v3(1, 1, 1)), 6, 7, 8, EPS);
  assert_vec(zr__xform_point(t.inv, zr_v3(6, 7, 8)), 1, 1, 1, EPS);
  /* A shear: x' = x + y. POV-Ray's second row is the image of y. */
  const double shear[12] = {1, 0, 0, 1, 1, 0, 0, 0, 1, 0, 0, 0};
  zr__transform_identity(&t);
  assert_true(zr__transform_matrix(&t, shear));
  assert_vec(zr__xform_point(t.m, zr_v3(0, 1, 0)), 1, 1, 0, EPS);
  assert_vec(zr__xform_point(t.inv, zr_v3(1, 1, 0)), 0, 1, 0, EPS);
  const double singular[12] = {0};
  assert_false(zr__transform_matrix(&t, singular));
}

static void test_core_strbuf_and_arena(void **state) {
  (void)state;
  zr_strbuf sb;
  zr__strbuf_init(&sb);
  for (int i = 0; i < 1000; i++)
    zr__strbuf_printf(&sb, "%d,", i);
  assert_int_equal(strncmp(zr__strbuf_cstr(&sb), "0,1,2,", 6), 0);
  char *s = zr__strbuf_take(&sb);
  assert_non_null(s);
  free(s);
  zr_arena a;
  zr__arena_init(&a);
  for (int i = 0; i < 10000; i++) {
    double *d = zr__arena_alloc(&a, sizeof(double) * (size_t)(i % 50 + 1));
    assert_non_null(d);
    assert_true(d[0] == 0.0);
  }
  char *big = zr__arena_alloc(&a, 1 << 20);
  assert_non_null(big);
  assert_string_equal(zr__arena_strdup(&a, "sphere"), "sphere");
  /* Only the last allocation can be given back; the next one reuses it. */
  char *x = zr__arena_alloc(&a, 40);
  char *y = zr__arena_alloc(&a, 40);
  assert_false(zr__arena_give_back(&a, x, 40));
  assert_true(zr__arena_give_back(&a, y, 40));
  assert_ptr_equal(zr__arena_alloc(&a, 40), y);
  zr__arena_free(&a);
}

/* An array grown by doubling keeps its rows and, once large, costs its
   final size alone: its own block is resized, not left behind (issue
   13).  A small one is copied; small allocations around it are kept. */
static void test_core_arena_grow(void **state) {
  (void)state;
  zr_arena a;
  zr__arena_init(&a);
  int *small = zr__arena_alloc(&a, 4 * sizeof *small);
  assert_non_null(small);
  small[3] = 7;
  size_t cap = 4;
  int *rows = zr__arena_grow(&a, NULL, 0, cap * sizeof *rows);
  assert_non_null(rows);
  for (size_t n = 0; n < 1000000; n++) {
    if (n == cap) {
      int *grown = zr__arena_grow(&a, rows, cap * sizeof *rows,
                                  2 * cap * sizeof *rows);
      assert_non_null(grown);
      rows = grown;
      cap *= 2;
      /* Every row written so far is still there. */
      for (size_t i = 0; i < n; i += 4099)
        assert_int_equal(rows[i], (int)i);
      assert_int_equal(rows[n - 1], (int)(n - 1));
    }
    rows[n] = (int)n;
  }
  assert_int_equal(small[3], 7);
  /* 2^20 rows of 4 bytes, plus the small allocations and the copies
     made while the array was small (under two 64 KB blocks). */
  assert_true(a.used >= cap * sizeof *rows);
  assert_true(a.used < cap * sizeof *rows + 131072);
  /* Shrinking or keeping the size returns the same room. */
  assert_ptr_equal(zr__arena_grow(&a, rows, 64, 32), rows);
  zr__arena_free(&a);
}

/* Big buffers in huge pages (core/arena.h): zr__huge_grow keeps an
   array's contents as it doubles across ZR__HUGE_FROM, from there on
   in a block aligned on 2 MiB that it keeps while the rounding has
   room; an arena that has handed out ZR__HUGE_FROM bytes takes its
   next block of small allocations as one aligned 2 MiB block. */
static void test_core_huge_alloc(void **state) {
  (void)state;
  const uintptr_t huge = (uintptr_t)2 << 20;
  char *small = zr__huge_alloc(100);
  assert_non_null(small);
  memset(small, 1, 100);
  free(small);
  size_t cap = 64;
  unsigned *v = zr__huge_grow(NULL, 0, cap * sizeof *v);
  assert_non_null(v);
  int moves_above = 0;
  for (unsigned n = 0; n < (3u << 20) / sizeof *v; n++) {
    if (n == cap) {
      unsigned *grown = zr__huge_grow(v, cap * sizeof *v,
                                      2 * cap * sizeof *v);
      assert_non_null(grown);
      if (cap * sizeof *v >= ZR__HUGE_FROM)
        moves_above += grown != v;
      v = grown;
      cap *= 2;
      for (unsigned i = 0; i < n; i += 977)
        assert_int_equal(v[i], i * 3u);
      assert_int_equal(v[n - 1], (n - 1) * 3u);
      if (cap * sizeof *v >= ZR__HUGE_FROM)
        assert_int_equal((uintptr_t)v & (huge - 1), 0);
    }
    v[n] = n * 3u;
  }
  /* From ZR__HUGE_FROM up to 2 MiB one 2 MiB block holds the array; 4 MiB
     needs two. */
  assert_int_equal(moves_above, 1);
  /* Shrinking below the threshold keeps the start. */
  unsigned *less = zr__huge_grow(v, cap * sizeof *v, 100 * sizeof *v);
  assert_non_null(less);
  assert_int_equal(less[99], 99u * 3u);
  free(less);
  char *whole = zr__huge_alloc(ZR__HUGE_FROM);
  assert_non_null(whole);
  assert_int_equal((uintptr_t)whole & (huge - 1), 0);
  memset(whole, 2, huge); /* rounded up to a whole huge page */
  free(whole);
  zr_arena a;
  zr__arena_init(&a);
  while (a.used < ZR__HUGE_FROM)
    assert_non_null(zr__arena_alloc(&a, 200));
  /* The next block starts a huge page (its data behind a header).  It
     is found by the jump from the last allocation of the block before:
     an allocation of that (malloc'ed) block may itself happen to sit
     just past a 2 MiB boundary (where the heap lies varies from run to
     run), which made a test by address alone fail at random: once in
     session 16's CI, never in 220 runs here. */
  char *prev = zr__arena_alloc(&a, 200), *b = NULL;
  assert_non_null(prev);
  for (int i = 0; i < 1000 && !b; i++) {
    char *d = zr__arena_alloc(&a, 200);
    assert_non_null(d);
    if (d < prev || d > prev + 256)
      b = d;
    prev = d;
  }
  assert_non_null(b);
  assert_true((uintptr_t)b % huge < 64);
  /* The next 5,000 (1 MiB) fit in it, zeroed. */
  for (int i = 0; i < 5000; i++) {
    char *d = zr__arena_alloc(&a, 200);
    assert_non_null(d);
    assert_int_equal(d[0] | d[199], 0);
    assert_true((uintptr_t)d / huge == (uintptr_t)b / huge);
    memset(d, 3, 200);
  }
  zr__arena_free(&a);
}

/* Whether the 4 KiB page holding p is mapped (mincore fails with ENOMEM
   on an address no mapping covers). */
static bool page_mapped(const void *p) {
  unsigned char in_core;
  void *page = (void *)((uintptr_t)p & ~(uintptr_t)4095);
  return mincore(page, 4096, &in_core) == 0;
}

/* Blocks in mappings of their own (core/arena.h, zr__map_*): an array
   that doubles from 256 bytes to 16 MiB keeps its rows at every step,
   lies on a huge page from ZR__MAP_FROM on, and leaves no mapping
   behind where it moved; a block freed or shrunk below ZR__MAP_FROM is
   unmapped; an arena's array grown past ZR__MAP_FROM keeps its rows in
   a mapping that zr__arena_free unmaps. */
static void test_core_map_alloc(void **state) {
  (void)state;
  const uintptr_t huge = (uintptr_t)2 << 20;
  char *small = zr__map_alloc(100);
  assert_non_null(small);
  memset(small, 1, 100);
  zr__map_free(small, 100);
  size_t cap = 64;
  unsigned *v = zr__map_grow(NULL, 0, cap * sizeof *v);
  assert_non_null(v);
  for (unsigned n = 0; n < (16u << 20) / sizeof *v; n++) {
    if (n == cap) {
      unsigned *old = v;
      size_t old_size = cap * sizeof *v;
      v = zr__map_grow(v, old_size, 2 * old_size);
      assert_non_null(v);
      cap *= 2;
      for (unsigned i = 0; i < n; i += 977)
        assert_int_equal(v[i], i * 3u);
      assert_int_equal(v[n - 1], (n - 1) * 3u);
      if (cap * sizeof *v >= ZR__MAP_FROM) {
        assert_int_equal((uintptr_t)v & (huge - 1), 0);
        assert_true(page_mapped(v) && page_mapped(v + cap - 1));
      }
      /* A mapping that moved is gone from where it was. */
      if (old_size >= ZR__MAP_FROM && v != old) {
        assert_false(page_mapped(old));
      }
    }
    v[n] = n * 3u;
  }
  assert_int_equal(cap * sizeof *v, 16u << 20);
  /* Shrinking below ZR__MAP_FROM keeps the start and unmaps the rest. */
  unsigned *less = zr__map_grow(v, cap * sizeof *v, 100 * sizeof *v);
  assert_non_null(less);
  assert_int_equal(less[99], 99u * 3u);
  assert_false(page_mapped(v) || page_mapped(v + cap - 1));
  zr__map_free(less, 100 * sizeof *less);
  char *whole = zr__map_alloc(ZR__MAP_FROM);
  assert_non_null(whole);
  assert_int_equal((uintptr_t)whole & (huge - 1), 0);
  assert_int_equal(zr__map_room(ZR__MAP_FROM), huge);
  memset(whole, 2, huge); /* rounded up to a whole huge page */
  zr__map_free(whole, ZR__MAP_FROM);
  assert_false(page_mapped(whole) || page_mapped(whole + huge - 1));

  zr_arena a;
  zr__arena_init(&a);
  for (int i = 0; i < 100; i++)
    assert_non_null(zr__arena_alloc(&a, 48));
  size_t rows_cap = 16;
  double *rows = zr__arena_grow(&a, NULL, 0, rows_cap * sizeof *rows);
  assert_non_null(rows);
  for (size_t n = 0; n < (6u << 20) / sizeof *rows; n++) {
    if (n == rows_cap) {
      rows = zr__arena_grow(&a, rows, rows_cap * sizeof *rows,
                            2 * rows_cap * sizeof *rows);
      assert_non_null(rows);
      rows_cap *= 2;
      for (size_t i = 0; i < n; i += 499)
        assert_true(rows[i] == (double)i);
      assert_true(rows[n - 1] == (double)(n - 1));
    }
    rows[n] = (double)n;
  }
  /* The block is a mapping: its rows start a huge page, behind the
     block's header. */
  assert_true((uintptr_t)rows % huge < 64);
  assert_true(page_mapped(rows) && page_mapped(rows + rows_cap - 1));
  /* Its last rows stay in place when it grows a little (room in the
     rounding), and small allocations still work beside it. */
  assert_non_null(zr__arena_alloc(&a, 5000));
  zr__arena_free(&a);
  assert_false(page_mapped(rows) || page_mapped(rows + rows_cap - 1));
}

typedef struct captured {
  char text[512];
  int count;
} captured;

static void capture(const zr_diag *d, void *user) {
  captured *c = user;
  snprintf(c->text, sizeof c->text, "%s", d->text);
  c->count++;
}

static void test_core_diag_format(void **state) {
  (void)state;
  zr_context *ctx;
  assert_int_equal(zr_context_new(&ctx), ZR_OK);
  captured c = {{0}, 0};
  zr_context_set_diag(ctx, capture, &c);
  const char *line = "sphere { <0,0,0>, foo }";
  zr_diag_place place = {"scene.pov", 3, 19, line, strlen(line), 3, NULL, 0, 0};
  zr_status s = zr__diag(ctx, ZR_DIAG_ERROR, ZR_EUNDEFINED, &place,
                         "undefined identifier '%s'", "foo");
  assert_int_equal(s, ZR_EUNDEFINED);
  assert_string_equal(c.text,
                      "scene.pov:3:19: error: undefined identifier 'foo'\n"
                      "    3 | sphere { <0,0,0>, foo }\n"
                      "      |                   ^~~\n");
  assert_string_equal(zr_context_last_error(ctx), c.text);
  assert_string_equal(zr_status_str(ZR_ESYNTAX), "syntax error");
  zr_context_free(ctx);
  zr_context_free(NULL);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_core_vec_cross_left_handed),
      cmocka_unit_test(test_core_min_max_as_libm),
      cmocka_unit_test(test_core_rotate_matches_povray),
      cmocka_unit_test(test_core_transform_order_and_inverse),
      cmocka_unit_test(test_core_matrix_keyword),
      cmocka_unit_test(test_core_strbuf_and_arena),
      cmocka_unit_test(test_core_arena_grow),
      cmocka_unit_test(test_core_huge_alloc),
      cmocka_unit_test(test_core_map_alloc),
      cmocka_unit_test(test_core_diag_format),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
