/*
 * test_bitmap.c - pictures wrapped around objects (lib/scene/bitmap.c,
 * the bump_map and material_map helpers of lib/sdl/build_texture.c and
 * their grammar): map_type 5, bump map normals, material map picks and
 * the bad inputs' messages.
 *
 * The expected normals follow the model bitmap.c gives, which POV-Ray
 * 3.7 renders measured (a plane lit from five directions): the normal
 * tilts by bump_size times the slope of the plane through the heights
 * at the point and one pixel below it to either side.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "parse_fixture.h"
#include "scene/bitmap.h"
#include "scene/scene.h"
#include "scene/texture.h"

/* Heights pass through a PGM codec's sRGB decoding and its exact
   undoing in single precision: 1e-6 covers that; the rest is exact
   arithmetic on a few sums. */
#define EPS 1e-6

/* A 4 x 1 palette PNG whose pixel k holds index k (red, green, blue,
   white), as in test_texture.c. */
static const unsigned char palette_png[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d,
    0x49, 0x48, 0x44, 0x52, 0x00, 0x00, 0x00, 0x04, 0x00, 0x00, 0x00, 0x01,
    0x08, 0x03, 0x00, 0x00, 0x00, 0xce, 0xe2, 0xff, 0xff, 0x00, 0x00, 0x00,
    0x0c, 0x50, 0x4c, 0x54, 0x45, 0xff, 0x00, 0x00, 0x00, 0xff, 0x00, 0x00,
    0x00, 0xff, 0xff, 0xff, 0xff, 0xfb, 0x00, 0x60, 0xf6, 0x00, 0x00, 0x00,
    0x0d, 0x49, 0x44, 0x41, 0x54, 0x78, 0xda, 0x63, 0x60, 0x60, 0x64, 0x62,
    0x06, 0x00, 0x00, 0x0f, 0x00, 0x07, 0x5b, 0xd0, 0x8b, 0x7d, 0x00, 0x00,
    0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};

/* Writes bytes to a fresh file under /tmp and returns its path in buf. */
static const char *write_file(char *buf, size_t size, const char *name,
                              const void *bytes, size_t n) {
  snprintf(buf, size, "/tmp/zr-bitmap-%ld-%s", (long)getpid(), name);
  FILE *fp = fopen(buf, "wb");
  assert_non_null(fp);
  assert_int_equal(fwrite(bytes, 1, n, fp), n);
  assert_int_equal(fclose(fp), 0);
  return buf;
}

/* Writes a w x h 8-bit PGM of the given samples (rows top first). */
static const char *write_pgm(char *buf, size_t size, const char *name,
                             int w, int h, const unsigned char *samples) {
  unsigned char bytes[512];
  int head = snprintf((char *)bytes, sizeof bytes, "P5\n%d %d\n255\n", w, h);
  assert_true(head > 0 && (size_t)(head + w * h) <= sizeof bytes);
  memcpy(bytes + head, samples, (size_t)(w * h));
  return write_file(buf, size, name, bytes, (size_t)(head + w * h));
}

/* The normal of the scene's first object. */
static const zr_normal *first_normal(const zr_scene *s) {
  assert_true(s->n_objects >= 1);
  assert_non_null(s->objects[0]->texture->normal);
  return s->objects[0]->texture->normal;
}

/* Asserts that n is the unit vector along (x, y, z). */
static void assert_dir(zr_vec3 n, double x, double y, double z) {
  double len = sqrt(x * x + y * y + z * z);
  assert_true(fabs(n.x - x / len) < EPS);
  assert_true(fabs(n.y - y / len) < EPS);
  assert_true(fabs(n.z - z / len) < EPS);
}

/* A plane facing -z wearing "normal { bump_map { pgm PATH MODS } XF }". */
static const zr_normal *bump(fixture *f, const char *path, const char *mods,
                             const char *xf) {
  char text[1024];
  snprintf(text, sizeof text,
           "plane { -z, 0 normal { bump_map { pgm \"%s\" %s } %s } }", path,
           mods, xf);
  const zr_normal *nm = first_normal(good(f, text));
  assert_non_null(nm->bump_map);
  return nm;
}

static const zr_vec3 facing = {0, 0, -1};

/* Pixel (i, j) of a w x h map's centre in map space. */
static zr_vec3 at_pixel(int i, int j, int w, int h) {
  return zr_v3((i + 0.5) / w, 1 - (j + 0.5) / h, 0);
}

static void test_bitmap_bump_map_step(void **state) {
  fixture *f = *state;
  char path[256];
  static const unsigned char step[] = {0, 0, 255, 255};
  write_pgm(path, sizeof path, "step.pgm", 4, 1, step);
  /* Pixel 1: heights 0 here, 1 to its lower right (pixel 2, the row
     wrapping onto itself), 0 to its lower left: slope 1/2 along u and
     -1/2 along v.  bump_size 0.5 (the default) tilts the normal by
     -0.5 times that: POV-Ray measured a = -0.125, b = +0.125 for
     bump_size 0.25 on such a step. */
  const zr_normal *nm = bump(f, path, "", "");
  assert_true(fabs(nm->amount - 0.5) < 1e-12);
  assert_dir(zr__normal_perturb(nm, at_pixel(1, 0, 4, 1), facing), -0.25,
             0.25, -1);
  /* Pixel 2: 1 here, 1 lower right, 0 lower left: along u 1/2, along v
     +1/2; bump_size 2 given in the block. */
  nm = bump(f, path, "bump_size 2", "");
  assert_dir(zr__normal_perturb(nm, at_pixel(2, 0, 4, 1), facing), -1, -1,
             -1);
  /* The tilt does not turn with the surface's normal. */
  assert_dir(zr__normal_perturb(nm, at_pixel(2, 0, 4, 1), zr_v3(0, 0, 1)),
             -1, -1, 1);
  /* A uniform scale leaves the per-pixel slope alone; "scale <1/4, 1,
     1>" makes it four times steeper along x (both measured). */
  nm = bump(f, path, "bump_size 2", "scale 4");
  assert_dir(zr__normal_perturb(nm, zr_v3(10.5, 2, 0), facing), -1, -1, -1);
  nm = bump(f, path, "bump_size 2", "scale <0.25, 1, 1>");
  assert_dir(zr__normal_perturb(nm, zr_v3(2.5 / 16, 0.5, 0), facing), -4,
             -1, -1);
  /* Off a "once" picture the normal is left alone. */
  nm = bump(f, path, "once", "");
  zr_vec3 n = zr__normal_perturb(nm, zr_v3(1.375, 0.5, 0), facing);
  assert_dir(n, 0, 0, -1);
  n = zr__normal_perturb(nm, zr_v3(0.375, 0.5, 0), facing);
  assert_dir(n, -0.25, 0.25, -1);
  unlink(path);
}

/* A single bright pixel tilts itself along -v and its two upper
   neighbours diagonally (their lower neighbours are it), and nothing
   else: the measured stencil. */
static void test_bitmap_bump_map_impulse(void **state) {
  fixture *f = *state;
  char path[256];
  static const unsigned char dot[] = {0, 0, 0, 0, 255, 0, 0, 0, 0};
  write_pgm(path, sizeof path, "dot.pgm", 3, 3, dot);
  const zr_normal *nm = bump(f, path, "bump_size 1", "");
  assert_dir(zr__normal_perturb(nm, at_pixel(1, 1, 3, 3), facing), 0, -1,
             -1);
  assert_dir(zr__normal_perturb(nm, at_pixel(0, 0, 3, 3), facing), -0.5,
             0.5, -1);
  assert_dir(zr__normal_perturb(nm, at_pixel(2, 0, 3, 3), facing), 0.5,
             0.5, -1);
  assert_dir(zr__normal_perturb(nm, at_pixel(1, 0, 3, 3), facing), 0, 0,
             -1);
  assert_dir(zr__normal_perturb(nm, at_pixel(0, 1, 3, 3), facing), 0, 0,
             -1);
  assert_dir(zr__normal_perturb(nm, at_pixel(1, 2, 3, 3), facing), 0, 0,
             -1);
  /* interpolate 2: a quarter pixel right of the centre of pixel (0, 0)
     its lower right neighbour's height is bilinear between pixels (1, 1)
     and (2, 1): 0.75, its lower left one's 0 (pixel (2, 1) wrapped and
     (0, 1)); the point's own is 0. */
  nm = bump(f, path, "bump_size 1 interpolate 2", "");
  zr_vec3 p = zr_v3(0.75 / 3, 1 - 0.5 / 3, 0);
  assert_dir(zr__normal_perturb(nm, p, facing), -0.375, 0.375, -1);
  unlink(path);
}

/* Colours bump by their grey, 0.297 r + 0.589 g + 0.114 b (measured);
   use_index by the palette index itself. */
static void test_bitmap_bump_map_colour_and_index(void **state) {
  fixture *f = *state;
  char path[256], text[1024];
  write_file(path, sizeof path, "pal.png", palette_png, sizeof palette_png);
  /* Pixel 1 (green): lower right blue 0.114, lower left red 0.297. */
  snprintf(text, sizeof text, "plane { -z, 0 normal { bump_map { png "
           "\"%s\" bump_size 1 } } }", path);
  const zr_normal *nm = first_normal(good(f, text));
  double du = (0.114 - 0.297) / 2, dv = (2 * 0.589 - 0.114 - 0.297) / 2;
  assert_dir(zr__normal_perturb(nm, at_pixel(1, 0, 4, 1), facing), -du,
             -dv, -1);
  /* use_index: index 1 here, 2 lower right, 0 lower left. */
  snprintf(text, sizeof text, "plane { -z, 0 normal { bump_map { png "
           "\"%s\" use_index bump_size 0.25 } } }", path);
  nm = first_normal(good(f, text));
  assert_dir(zr__normal_perturb(nm, at_pixel(1, 0, 4, 1), facing), -0.25,
             0, -1);
  /* use_color after it takes the colours back. */
  snprintf(text, sizeof text, "plane { -z, 0 normal { bump_map { png "
           "\"%s\" use_index use_colour bump_size 1 } } }", path);
  nm = first_normal(good(f, text));
  assert_dir(zr__normal_perturb(nm, at_pixel(1, 0, 4, 1), facing), -du,
             -dv, -1);
  unlink(path);
}

static void test_bitmap_bump_map_bad_input(void **state) {
  fixture *f = *state;
  char path[256], text[1024], message[512];
  bad(f, "plane { z, 0 normal { bump_map { png \"no-such.png\" } } }",
      ZR_ENOTFOUND, "bump_map file 'no-such.png' not found",
      "t.pov:1:38: error: bump_map file 'no-such.png' not found\n"
      "    1 | plane { z, 0 normal { bump_map { png \"no-such.png\" } } }\n"
      "      |                                      ^~~~~~~~~~~~~\n");
  static const unsigned char flat[] = {10, 20};
  write_pgm(path, sizeof path, "flat.pgm", 2, 1, flat);
  snprintf(text, sizeof text, "plane { z, 0 normal { bump_map { pgm \"%s\" "
           "map_type 3 } } }", path);
  bad(f, text, ZR_ESCENE, "map_type 3 is not supported (0, 1, 2 or 5)",
      NULL);
  /* POV-Ray 3.7 bumps an image without a palette by its grey even with
     use_index (measured); we say so. */
  snprintf(text, sizeof text, "plane { z, 0 normal { bump_map { pgm \"%s\" "
           "use_index } } }", path);
  good(f, text);
  assert_int_equal(f->diag.warnings, 1);
  snprintf(message, sizeof message, "use_index needs a palette image; '%s' "
           "has none, so its grey is used", path);
  assert_non_null(strstr(f->diag.warning, message));
  /* The file comes first (the list of what may start it follows the
     image formats the grammar knows). */
  assert_int_equal(
      parse(f, "plane { z, 0 normal { bump_map { bump_size 2 } } }"),
      ZR_ESYNTAX);
  assert_int_equal(strncmp(f->diag.message, "unexpected 'bump_size', "
                           "expected string, ", 34), 0);
  unlink(path);
}

/* ---- material_map ---- */

/* The texture the first object's material map picks at p (map space). */
static const zr_texture *picked(const zr_scene *s, zr_vec3 p) {
  const zr_texture *second;
  double t;
  const zr_texture *tx = zr__texture_pick(s->objects[0]->texture, p,
                                          &second, &t);
  assert_null(second);
  return tx;
}

static void test_bitmap_material_map_picks(void **state) {
  fixture *f = *state;
  char path[256], text[1024];
  write_file(path, sizeof path, "pal.png", palette_png, sizeof palette_png);
  /* Indices 0 .. 3 pick textures 0, 1, 2 and 3 mod 3 = 0; the
     transform inside the block moves picture and textures. */
  snprintf(text, sizeof text,
           "sphere { 0, 1 texture { material_map { png \"%s\"\n"
           "  texture { pigment { rgb 0.25 } }\n"
           "  texture { pigment { rgb 0.5 } }\n"
           "  texture { pigment { rgb 0.75 } } scale 2 } } }", path);
  zr_scene *s = good(f, text);
  const zr_texture *tx = s->objects[0]->texture;
  assert_non_null(tx->material);
  static const double grey[] = {0.25, 0.5, 0.75, 0.25};
  for (int k = 0; k < 4; k++) {
    zr_vec3 p = zr_v3(2 * (k + 0.5) / 4, 1, 0);
    zr_colour c = zr__pigment_eval(picked(s, p)->pigment, p);
    assert_true(fabs(c.r - grey[k]) < 1e-12);
  }
  /* Plain code wants one texture: the first. */
  assert_true(fabs(tx->pigment->colour.r - 0.25) < 1e-12);
  /* once: off the picture the first texture holds. */
  snprintf(text, sizeof text,
           "sphere { 0, 1 texture { material_map { png \"%s\" once\n"
           "  texture { pigment { rgb 0.25 } }\n"
           "  texture { pigment { rgb 0.5 } } } } }", path);
  s = good(f, text);
  zr_colour c = zr__pigment_eval(picked(s, zr_v3(1.375, 0.5, 0))->pigment,
                                 zr_v3(0, 0, 0));
  assert_true(fabs(c.r - 0.25) < 1e-12);
  c = zr__pigment_eval(picked(s, zr_v3(0.375, 0.5, 0))->pigment,
                       zr_v3(0, 0, 0));
  assert_true(fabs(c.r - 0.5) < 1e-12);
  /* interpolate 2 blends the indices bilinearly, wrapping, and the
     blend rounded down picks ("the color index is interpolated before
     the texture is chosen"): a POV-Ray 3.7 render of this map with four
     textures picks 1, 0 and 1 at pixel coordinates 0.1, 1.3 and 3.9
     (indices 1.2, 0.8 and 1.8 here). */
  snprintf(text, sizeof text,
           "sphere { 0, 1 texture { material_map { png \"%s\" interpolate"
           " 2\n texture { pigment { rgb 0 } } texture { pigment { rgb 1 } }"
           "\n texture { pigment { rgb 2 } } texture { pigment { rgb 3 } }"
           " } } }", path);
  s = good(f, text);
  static const double at[] = {0.1, 1.3, 3.9}, index[] = {1, 0, 1};
  for (int k = 0; k < 3; k++) {
    c = zr__pigment_eval(picked(s, zr_v3(at[k] / 4, 0.5, 0))->pigment,
                         zr_v3(0, 0, 0));
    assert_true(fabs(c.r - index[k]) < 1e-12);
  }
  unlink(path);
  /* Without a palette the red sample (0 .. 255) is the index. */
  static const unsigned char codes[] = {1, 2};
  write_pgm(path, sizeof path, "idx.pgm", 2, 1, codes);
  snprintf(text, sizeof text,
           "sphere { 0, 1 texture { material_map { pgm \"%s\"\n"
           "  texture { pigment { rgb 0 } } texture { pigment { rgb 1 } }\n"
           "  texture { pigment { rgb 2 } } } } }", path);
  s = good(f, text);
  c = zr__pigment_eval(picked(s, zr_v3(0.25, 0.5, 0))->pigment,
                       zr_v3(0, 0, 0));
  assert_true(fabs(c.r - 1) < 1e-12);
  c = zr__pigment_eval(picked(s, zr_v3(0.75, 0.5, 0))->pigment,
                       zr_v3(0, 0, 0));
  assert_true(fabs(c.r - 2) < 1e-12);
  unlink(path);
}

static void test_bitmap_material_map_bad_input(void **state) {
  fixture *f = *state;
  bad(f, "sphere { 0, 1 texture { material_map { png \"gone.png\" texture "
         "{ } } } }",
      ZR_ENOTFOUND, "material_map file 'gone.png' not found", NULL);
  char path[256], text[1024];
  write_file(path, sizeof path, "pal.png", palette_png, sizeof palette_png);
  snprintf(text, sizeof text, "sphere { 0, 1 texture { material_map { png "
           "\"%s\" } } }", path);
  bad(f, text, ZR_ESYNTAX,
      "unexpected '}', expected 'interpolate', 'map_type', 'once' or "
      "'texture'", NULL);
  snprintf(text, sizeof text, "sphere { 0, 1 texture { material_map { png "
           "\"%s\" map_type 4 texture { } } } }", path);
  bad(f, text, ZR_ESCENE, "map_type 4 is not supported (0, 1, 2 or 5)",
      NULL);
  unlink(path);
}

/* ---- map_type 5 ---- */

/* POV-Ray 3.7 renders of a picture holding its own u and v as red and
   green on "torus { 1, 0.4 }" read u = 0.125 at 45 degrees from +x to
   +z on top of the tube, where v = 0.75; v = 0.5 on the outer equator
   and 0.25 under the tube; the picture wraps both ways.  1e-9 covers
   rounding. */
static void test_bitmap_torus_map(void **state) {
  (void)state;
  zr_image_map im;
  memset(&im, 0, sizeof im);
  im.width = 200;
  im.height = 100;
  im.map_type = 5;
  im.once = true; /* means nothing to a torus */
  double px, py;
  bool rx, ry;
  double c = sqrt(0.5);
  assert_true(zr__bitmap_where(&im, zr_v3(c, 0.4, c), &px, &py, &rx, &ry));
  assert_true(fabs(px - 0.125 * 200) < 1e-9);
  assert_true(fabs(py - 0.25 * 100) < 1e-9);
  assert_true(rx && ry);
  assert_true(zr__bitmap_where(&im, zr_v3(0, -0.4, -1), &px, &py, &rx, &ry));
  assert_true(fabs(px - 0.75 * 200) < 1e-9);
  assert_true(fabs(py - 0.75 * 100) < 1e-9);
  /* Outer equator at 1.4 and 45 degrees up the tube. */
  assert_true(zr__bitmap_where(&im, zr_v3(-1.4, 0, 0), &px, &py, &rx, &ry));
  assert_true(fabs(px - 0.5 * 200) < 1e-9);
  assert_true(fabs(py - 0.5 * 100) < 1e-9);
  assert_true(zr__bitmap_where(&im, zr_v3(1 + 0.4 * c, 0.4 * c, 0), &px,
                               &py, &rx, &ry));
  assert_true(fabs(py - (1 - 0.625) * 100) < 1e-9);
}

static void test_bitmap_torus_image_map_parses(void **state) {
  fixture *f = *state;
  char path[256], text[1024];
  write_file(path, sizeof path, "pal.png", palette_png, sizeof palette_png);
  snprintf(text, sizeof text, "torus { 1, 0.4 pigment { image_map { png "
           "\"%s\" map_type 5 } } }", path);
  zr_scene *s = good(f, text);
  const zr_pigment *pg = s->objects[0]->texture->pigment;
  assert_int_equal(pg->image->map_type, 5);
  /* u = 0.625 (225 degrees): pixel 2, blue. */
  double c = sqrt(0.5);
  zr_colour col = zr__pigment_eval(pg, zr_v3(-1.4 * c, 0, -1.4 * c));
  assert_true(col.r < 1e-9 && col.g < 1e-9 && fabs(col.b - 1) < 1e-9);
  snprintf(text, sizeof text, "torus { 1, 0.4 pigment { image_map { png "
           "\"%s\" map_type 3 } } }", path);
  bad(f, text, ZR_ESCENE, "map_type 3 is not supported (0, 1, 2 or 5)",
      NULL);
  unlink(path);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_bitmap_bump_map_step),
      cmocka_unit_test(test_bitmap_bump_map_impulse),
      cmocka_unit_test(test_bitmap_bump_map_colour_and_index),
      cmocka_unit_test(test_bitmap_bump_map_bad_input),
      cmocka_unit_test(test_bitmap_material_map_picks),
      cmocka_unit_test(test_bitmap_material_map_bad_input),
      cmocka_unit_test(test_bitmap_torus_map),
      cmocka_unit_test(test_bitmap_torus_image_map_parses),
  };
  return cmocka_run_group_tests(tests, setup, teardown);
}
