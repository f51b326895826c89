/*
 * test_text.c - the text object and the TrueType reader: a font built
 * here with one known glyph (a parabolic arch, so both lines and
 * quadratic curves are traced) checked against its analytic crossings,
 * POV-Ray's own fonts laid out, and broken font files rejected with a
 * clear message.
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
#include <unistd.h>

#include "config.h"
#include "scene/scene.h"
#include "scene/ttf.h"
#include "trace/bvh.h"
#include "trace/intersect.h"
#include "trace/obj_text.h"
#include "zrcube.h"
#include "parse_fixture.h"
#include "test_util.h"

/* The crossings below are closed forms evaluated by a few products and
   one square root: 1e-9 is rounding room that still catches mistakes. */
#define EPS 1e-9

/* ---- a font made here ---- */

typedef struct bytes {
  uint8_t b[1024];
  size_t n;
} bytes;

static void put16(bytes *o, unsigned v) {
  o->b[o->n++] = (uint8_t)(v >> 8);
  o->b[o->n++] = (uint8_t)v;
}

static void put32(bytes *o, uint32_t v) {
  put16(o, v >> 16);
  put16(o, v & 0xFFFF);
}

static void pad_to(bytes *o, size_t n) {
  while (o->n < n)
    o->b[o->n++] = 0;
}

/*
 * A font of 1000 units per em with glyph 1 for 'A': the contour on
 * (0, 0), off (500, 1000), on (1000, 0), closed by the base line, i.e.
 * the arch y = 2000 s (1 - s), x = 1000 s.  Advance widths 500 (glyph
 * 0) and 1200 ('A').
 */
static void make_font(bytes *o) {
  static const char *const tags[] = {"cmap", "glyf", "head", "hhea",
                                     "hmtx", "loca", "maxp"};
  bytes t[7];
  memset(t, 0, sizeof t);
  /* cmap: one Windows Unicode format 4 map, 'A' -> 1. */
  put16(&t[0], 0);
  put16(&t[0], 1);
  put16(&t[0], 3);
  put16(&t[0], 1);
  put32(&t[0], 12);
  put16(&t[0], 4);
  put16(&t[0], 32); /* length */
  put16(&t[0], 0);
  put16(&t[0], 4); /* segCountX2 */
  put16(&t[0], 4);
  put16(&t[0], 1);
  put16(&t[0], 0);
  put16(&t[0], 'A'); /* end codes */
  put16(&t[0], 0xFFFF);
  put16(&t[0], 0);
  put16(&t[0], 'A'); /* start codes */
  put16(&t[0], 0xFFFF);
  put16(&t[0], (1 - 'A') & 0xFFFF); /* deltas */
  put16(&t[0], 1);
  put16(&t[0], 0); /* range offsets */
  put16(&t[0], 0);
  /* glyf: glyph 1. */
  put16(&t[1], 1);
  put16(&t[1], 0);
  put16(&t[1], 0);
  put16(&t[1], 1000);
  put16(&t[1], 1000);
  put16(&t[1], 2); /* end point of the contour */
  put16(&t[1], 0); /* no instructions */
  t[1].b[t[1].n++] = 1;
  t[1].b[t[1].n++] = 0;
  t[1].b[t[1].n++] = 1;
  put16(&t[1], 0); /* x deltas */
  put16(&t[1], 500);
  put16(&t[1], 500);
  put16(&t[1], 0); /* y deltas */
  put16(&t[1], 1000);
  put16(&t[1], (unsigned)-1000 & 0xFFFF);
  size_t glyph_len = t[1].n;
  /* head: units per em at 18, long loca at 50. */
  put32(&t[2], 0x00010000);
  pad_to(&t[2], 18);
  put16(&t[2], 1000);
  pad_to(&t[2], 50);
  put16(&t[2], 1);
  put16(&t[2], 0);
  /* hhea: two horizontal metrics. */
  put32(&t[3], 0x00010000);
  pad_to(&t[3], 34);
  put16(&t[3], 2);
  /* hmtx */
  put16(&t[4], 500);
  put16(&t[4], 0);
  put16(&t[4], 1200);
  put16(&t[4], 0);
  /* loca (long) */
  put32(&t[5], 0);
  put32(&t[5], 0);
  put32(&t[5], (uint32_t)glyph_len);
  /* maxp 0.5 */
  put32(&t[6], 0x00005000);
  put16(&t[6], 2);
  o->n = 0;
  put32(o, 0x00010000);
  put16(o, 7);
  put16(o, 64);
  put16(o, 2);
  put16(o, 48);
  size_t off = 12 + 16 * 7;
  for (int i = 0; i < 7; i++) {
    memcpy(o->b + o->n, tags[i], 4);
    o->n += 4;
    put32(o, 0);
    put32(o, (uint32_t)off);
    put32(o, (uint32_t)t[i].n);
    off += (t[i].n + 3) & ~(size_t)3;
  }
  for (int i = 0; i < 7; i++) {
    memcpy(o->b + o->n, t[i].b, t[i].n);
    o->n += t[i].n;
    pad_to(o, (o->n + 3) & ~(size_t)3);
  }
}

static char dir[64];

static void write_file(const char *name, const uint8_t *data, size_t n,
                       char *path, size_t size) {
  snprintf(path, size, "%s/%s", dir, name);
  FILE *fp = fopen(path, "wb");
  assert_non_null(fp);
  assert_int_equal(fwrite(data, 1, n, fp), n);
  fclose(fp);
}

static int group_setup(void **state) {
  (void)state;
  snprintf(dir, sizeof dir, "/tmp/zr-text-XXXXXX");
  return mkdtemp(dir) ? 0 : -1;
}

static int group_teardown(void **state) {
  (void)state;
  char cmd[128];
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
  return system(cmd) == 0 ? 0 : -1;
}

static const struct zr_text *only_text(const zr_scene *s) {
  assert_int_equal(s->n_primitives, 1);
  assert_int_equal(s->primitives[0]->kind, ZR_OBJ_TEXT);
  return s->primitives[0]->u.text.data;
}

static zr_scene *arch_scene(fixture *f, const char *string,
                            const char *rest) {
  bytes font;
  make_font(&font);
  char path[128], scene[512];
  write_file("arch.ttf", font.b, font.n, path, sizeof path);
  snprintf(scene, sizeof scene, "text { ttf \"%s\" \"%s\" %s }\n", path,
           string, rest);
  return good(f, scene);
}

static void test_text_reader(void **state) {
  (void)state;
  bytes font;
  make_font(&font);
  zr_ttf t;
  assert_null(zr__ttf_open(&t, font.b, font.n));
  assert_int_equal(t.units_per_em, 1000);
  assert_int_equal(zr__ttf_glyph(&t, 'A'), 1);
  assert_int_equal(zr__ttf_glyph(&t, 'B'), 0);
  assert_int_equal(zr__ttf_advance(&t, 1), 1200);
  assert_int_equal(zr__ttf_advance(&t, 0), 500);
}

/* The arch's curved wall, its base wall and its caps. */
static void test_text_arch_crossings(void **state) {
  fixture *f = *state;
  zr_scene *s = arch_scene(f, "A", "0.5, 0");
  const struct zr_text *tx = only_text(s);
  assert_int_equal(tx->n_glyphs, 1);
  assert_near(tx->thickness, 0.5, EPS);
  /* Along +x at height 0.25: the curve at s = (1 - sqrt(0.5)) / 2. */
  double s0 = (1 - sqrt(0.5)) / 2;
  zr_ray ray = {zr_v3(-1, 0.25, 0.25), zr_v3(1, 0, 0)};
  zr_hit hit;
  assert_true(zr__bvh_nearest(s->bvh, &ray, 0, INFINITY, &hit));
  assert_near(hit.t, 1 + s0, EPS);
  /* The outward normal there is (-y'(s), x'(s)) normalised. */
  double tx_ = 1000, ty = 2000 - 4000 * s0, len = hypot(tx_, ty);
  assert_near(hit.normal.x, -ty / len, EPS);
  assert_near(hit.normal.y, tx_ / len, EPS);
  assert_near(hit.normal.z, 0, EPS);
  /* Both crossings: in at s0, out at 1 - s0. */
  zr_hit h[ZR_MAX_CROSSINGS];
  assert_int_equal(zr__intersect(s->primitives[0], &ray, 0, INFINITY, h), 2);
  assert_near(h[1].t, 1 + (1 - s0), EPS);
  /* Down onto the front cap at x = 0.5, y = 0.1, then out the back. */
  zr_ray down = {zr_v3(0.5, 0.1, -2), zr_v3(0, 0, 1)};
  assert_int_equal(zr__intersect(s->primitives[0], &down, 0, INFINITY, h),
                   2);
  assert_near(h[0].t, 2, EPS);
  assert_near(h[0].normal.z, -1, EPS);
  assert_near(h[1].t, 2.5, EPS);
  assert_near(h[1].normal.z, 1, EPS);
  /* Up through the base line from below. */
  zr_ray up = {zr_v3(0.3, -1, 0.1), zr_v3(0, 1, 0)};
  assert_true(zr__bvh_nearest(s->bvh, &up, 0, INFINITY, &hit));
  assert_near(hit.t, 1, EPS);
  assert_near(hit.normal.y, -1, EPS);
  /* Above the arch's top (0.5) there is nothing. */
  zr_ray over = {zr_v3(0.5, 0.55, -2), zr_v3(0, 0, 1)};
  assert_false(zr__bvh_nearest(s->bvh, &over, 0, INFINITY, &hit));
  /* Inside: under the curve and between the caps. */
  assert_true(zr__inside(s->primitives[0], zr_v3(0.5, 0.4, 0.25)));
  assert_false(zr__inside(s->primitives[0], zr_v3(0.05, 0.4, 0.25)));
  assert_false(zr__inside(s->primitives[0], zr_v3(0.5, 0.4, 0.75)));
}

/* Glyphs advance by their width plus the offset vector. */
static void test_text_layout(void **state) {
  fixture *f = *state;
  zr_scene *s = arch_scene(f, "AA", "1, <0.25, 0.5, 0>");
  const struct zr_text *tx = only_text(s);
  assert_int_equal(tx->n_glyphs, 2);
  assert_near(tx->glyphs[1].lo[0], 1.2 + 0.25, EPS);
  assert_near(tx->glyphs[1].lo[1], 0.5, EPS);
  assert_near(tx->hi.x, 1.45 + 1.0, EPS);
  /* Commas may separate the font, the string and the thickness. */
  bytes font;
  make_font(&font);
  char path[128], scene[256];
  write_file("arch.ttf", font.b, font.n, path, sizeof path);
  snprintf(scene, sizeof scene, "text { ttf \"%s\", \"AA\", 1, 0 }\n",
           path);
  assert_int_equal(only_text(good(f, scene))->n_glyphs, 2);
}

/* POV-Ray's fonts, found where POV-Ray installs them. */
static void test_text_stock_fonts(void **state) {
  fixture *f = *state;
  static const char *const fonts[] = {"timrom.ttf", "cyrvetic.ttf",
                                      "crystal.ttf", "povlogo.ttf"};
  /* No include path given: POV-Ray's include directory is searched
     last, as for #include. */
  const char *inc = ZR_POVRAY_INCLUDE_DIR;
  if (access(inc, R_OK) != 0)
    skip();
  for (int i = 0; i < 4; i++) {
    char scene[256];
    snprintf(scene, sizeof scene, "text { ttf \"%s\" \"%s\" 1, 0 }\n",
             fonts[i], i == 3 ? "P" : "POV-Ray");
    zr_scene *s = good(f, scene);
    const struct zr_text *tx = only_text(s);
    assert_int_equal(tx->n_glyphs, i == 3 ? 1 : 7);
    /* Capitals stand on the baseline, about 0.5 to 0.75 units tall;
       the logo font's one glyph fills its em square. */
    if (!(tx->hi.y > 0.5 && tx->hi.y < 1.01 && tx->lo.y > -0.3))
      fail_msg("%s: y from %g to %g", fonts[i], tx->lo.y, tx->hi.y);
  }
  zr_scene *s = good(f, "text { internal 1 \"POV-Ray\" 1, 0 }\n");
  assert_int_equal(only_text(s)->n_glyphs, 7);
  /* cyrvetic.ttf's kerning pairs are not in the sorted order the
     specification asks for; "AV" is still kerned (by -81 units). */
  char path[256];
  snprintf(path, sizeof path, "%s/cyrvetic.ttf", inc);
  FILE *fp = fopen(path, "rb");
  assert_non_null(fp);
  static uint8_t data[65536];
  size_t n = fread(data, 1, sizeof data, fp);
  fclose(fp);
  zr_ttf t;
  assert_null(zr__ttf_open(&t, data, n));
  assert_int_equal(zr__ttf_kerning(&t, zr__ttf_glyph(&t, 'A'),
                                   zr__ttf_glyph(&t, 'V')),
                   -81);
}

/* Leading spaces keep their width: POV-Ray 3.7 finds the left edge of
   the A of " A" and "  A" in timrom.ttf 0.26 and 0.514 further right
   than that of "A" (trace() along z at y = 0.05, steps of 0.002, so
   0.004 room; the space is 0.25 wide and the A's left side bearing
   about 0.01). */
static void test_text_leading_spaces(void **state) {
  fixture *f = *state;
  if (access(ZR_POVRAY_INCLUDE_DIR, R_OK) != 0)
    skip();
  double left[3];
  static const char *const strings[] = {"A", " A", "  A"};
  for (int i = 0; i < 3; i++) {
    char scene[256];
    snprintf(scene, sizeof scene, "text { ttf \"timrom.ttf\" \"%s\" 1, 0 }\n",
             strings[i]);
    const struct zr_text *tx = only_text(good(f, scene));
    assert_int_equal(tx->n_glyphs, 1);
    left[i] = tx->glyphs[0].lo[0];
  }
  assert_near(left[0], 0.0, EPS);
  assert_near(left[1] - left[0], 0.26, 0.004);
  assert_near(left[2] - left[0], 0.514, 0.006);
}

static void expect_broken(fixture *f, const uint8_t *data, size_t n,
                          const char *why) {
  char path[128], scene[256], message[512];
  write_file("broken.ttf", data, n, path, sizeof path);
  snprintf(scene, sizeof scene, "text { ttf \"%s\" \"A\" 1, 0 }\n", path);
  snprintf(message, sizeof message, "cannot use font '%s': %s", path, why);
  bad(f, scene, ZR_ESCENE, message, NULL);
}

static void test_text_broken_fonts(void **state) {
  fixture *f = *state;
  bytes font;
  make_font(&font);
  const uint8_t junk[] = "this is not a font at all";
  expect_broken(f, junk, sizeof junk, "it is not a TrueType font");
  expect_broken(f, font.b, 8, "it is too short to be a TrueType font");
  expect_broken(f, font.b, 100, "its table directory is truncated");
  /* Every table cut short: the directory points past the end. */
  expect_broken(f, font.b, font.n - 40,
                "its maxp table is missing or truncated");
  /* loca pointing past glyf. */
  bytes bad_loca = font;
  size_t loca = 0;
  for (int i = 0; i < 7; i++)
    if (memcmp(bad_loca.b + 12 + 16 * i, "loca", 4) == 0)
      loca = (size_t)bad_loca.b[12 + 16 * i + 10] << 8 |
             bad_loca.b[12 + 16 * i + 11];
  bad_loca.b[loca + 8] = 0x7F;
  expect_broken(f, bad_loca.b, bad_loca.n,
                "a glyph's loca entry points outside the glyf table");
  /* Every prefix of the font: a message or success, never a crash
     (run under the sanitizers, this also checks no read strays). */
  for (size_t n = 0; n < font.n; n += 7) {
    char path[128], scene[256];
    write_file("prefix.ttf", font.b, n, path, sizeof path);
    snprintf(scene, sizeof scene, "text { ttf \"%s\" \"A\" 1, 0 }\n",
             path);
    zr_status st = parse(f, scene);
    assert_true(st == ZR_OK || st == ZR_ESCENE);
  }
  bad(f, "text { ttf \"no-such-font.ttf\" \"A\" 1, 0 }\n", ZR_ENOTFOUND,
      "cannot find font 'no-such-font.ttf'", NULL);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_text_reader),
      cmocka_unit_test_setup_teardown(test_text_arch_crossings, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_text_layout, setup, teardown),
      cmocka_unit_test_setup_teardown(test_text_stock_fonts, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_text_leading_spaces, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_text_broken_fonts, setup,
                                      teardown),
  };
  return cmocka_run_group_tests(tests, group_setup, group_teardown);
}
