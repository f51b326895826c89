/*
 * test_texture.c - maps, layered and patterned textures, materials and
 * the patterns added with them (lib/scene/texture.c, lib/scene/pattern.c,
 * lib/sdl/build_texture.c and their grammar), parsed from scene text and
 * evaluated directly.
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
#include "scene/pattern.h"
#include "scene/scene.h"
#include "scene/texture.h"
#include "trace/intersect.h"

/* Colours here are a few products and sums of exact decimals: 1e-9
   covers their rounding. */
#define EPS 1e-9

/* The texture of the scene's first object. */
static const zr_texture *first_texture(const zr_scene *s) {
  assert_true(s->n_objects >= 1);
  assert_non_null(s->objects[0]->texture);
  return s->objects[0]->texture;
}

static void assert_colour(zr_colour c, double r, double g, double b,
                          double f, double t) {
  assert_true(fabs(c.r - r) < EPS);
  assert_true(fabs(c.g - g) < EPS);
  assert_true(fabs(c.b - b) < EPS);
  assert_true(fabs(c.f - f) < EPS);
  assert_true(fabs(c.t - t) < EPS);
}

static void test_texture_pigment_map_blends(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "sphere { 0, 1 pigment { gradient x pigment_map {"
                        " [0.2 rgb <1, 0, 0>] [0.6 rgb <0, 0, 1>] } } }");
  const zr_pigment *pg = first_texture(s)->pigment;
  assert_non_null(pg->pigment_map);
  assert_int_equal(pg->pigment_map->n, 2);
  /* x = 0.3 is a quarter of the way from 0.2 to 0.6. */
  assert_colour(zr__pigment_eval(pg, zr_v3(0.3, 0, 0)), 0.75, 0, 0.25, 0,
                0);
  /* Below the first entry its pigment holds. */
  assert_colour(zr__pigment_eval(pg, zr_v3(0.1, 0, 0)), 1, 0, 0, 0, 0);
}

static void test_texture_block_pigments_and_transform(void **state) {
  fixture *f = *state;
  /* The outer scale moves the inner gradient too: inner pigments are
     evaluated in the outer pigment's space. */
  zr_scene *s = good(f, "plane { y, 0 pigment { checker"
                        " pigment { rgb 1 }"
                        " pigment { gradient x color_map { [0 rgb 0]"
                        " [1 rgb <0, 1, 0>] } } scale 2 } }");
  const zr_pigment *pg = first_texture(s)->pigment;
  /* Point (0.5, 0.5, 0.5) * 2: cell (0,0,0) of the checker, entry 0. */
  assert_colour(zr__pigment_eval(pg, zr_v3(1, 1, 1)), 1, 1, 1, 0, 0);
  /* (3, 1, 1) is pattern point (1.5, .5, .5): entry 1, gradient 0.5. */
  assert_colour(zr__pigment_eval(pg, zr_v3(3, 1, 1)), 0, 0.5, 0, 0, 0);
}

/* POV-Ray 3.7 renders "checker rgb 1 rgb <1,0,0>" white and red: a
   second rgb starts the next colour of the list, while component items
   after an rgb change it ("rgb <0,1,0> red 1" is yellow). */
static void test_texture_colour_lists_without_commas(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "plane { y, 0 pigment { checker rgb 1"
                        " rgb <1, 0, 0> } }");
  const zr_pigment *pg = first_texture(s)->pigment;
  assert_colour(pg->list[0], 1, 1, 1, 0, 0);
  assert_colour(pg->list[1], 1, 0, 0, 0, 0);
  s = good(f, "plane { y, 0 pigment { checker rgb <0, 1, 0> red 1"
              " rgbt 0.5 } }");
  pg = first_texture(s)->pigment;
  assert_colour(pg->list[0], 1, 1, 0, 0, 0);
  assert_colour(pg->list[1], 0.5, 0.5, 0.5, 0, 0.5);
}

/* gamma_showcase.pov writes "reflection { 0.0 1.0 fresnel on }": the
   maximum may follow without a comma when it is a plain number. */
static void test_texture_reflection_without_comma(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "sphere { 0, 1 finish { reflection { 0.1 0.9 "
                        "fresnel on } } }");
  const zr_finish *fin = first_texture(s)->finish;
  assert_true(fabs(fin->reflection.r - 0.1) < EPS);
  assert_true(fabs(fin->reflection_max.g - 0.9) < EPS);
  assert_true(fin->reflection_fresnel);
}

/* terrain.inc writes "slope -z": the direction without braces reads as
   "slope { -z }". */
static void test_texture_slope_without_braces(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "plane { y, 0 pigment { slope -z } }");
  const zr_slope *a = &first_texture(s)->pigment->pattern.slope;
  zr_slope bare = *a;
  s = good(f, "plane { y, 0 pigment { slope { -z } } }");
  assert_memory_equal(&bare, &first_texture(s)->pigment->pattern.slope,
                      sizeof bare);
  assert_true(bare.direction.z < 0.0);
}

static void test_texture_average_weights(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "sphere { 0, 1 pigment { average pigment_map {"
                        " [1 rgb <1, 0, 0>] [3 rgb <0, 0, 1>] } } }");
  assert_colour(zr__pigment_eval(first_texture(s)->pigment,
                                 zr_v3(0.3, 0.2, 0.1)),
                0.25, 0, 0.75, 0, 0);
}

/* An average's pigment_map entry may leave out its weight when its
   pigment starts with a pattern or a transformation (qtvrpanorama.pov:
   "[gradient y color_map { ... }]"); povray 3.7 mixes this one to
   <0.2, 0, 0.6> (measured). */
static void test_texture_average_without_weights(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "sphere { 0, 1 pigment { average pigment_map {"
                        " [gradient x color_map { [0 rgb <1, 0, 0>]"
                        " [1 rgb <1, 0, 0>] }] [3 rgb <0, 0, 1>]"
                        " [checker rgb 0 rgb 0 scale 2] } } }");
  const zr_pigment *pg = first_texture(s)->pigment;
  assert_int_equal(pg->pigment_map->n, 3);
  assert_true(fabs(pg->pigment_map->entries[0].value - 1) < EPS);
  assert_colour(zr__pigment_eval(pg, zr_v3(0.3, 0.2, 0.1)), 0.2, 0, 0.6, 0,
                0);
  /* A weight, with or without its comma, still comes first. */
  s = good(f, "sphere { 0, 1 pigment { average pigment_map {"
              " [0.5, bozo] [0.5 scale 2] [function { x }] } } }");
  pg = first_texture(s)->pigment;
  assert_true(fabs(pg->pigment_map->entries[1].value - 0.5) < EPS);
  assert_int_equal(pg->pigment_map->entries[2].u.pigment->pattern.kind,
                   ZR_PAT_FUNCTION);
  /* Without a weight an entry cannot start with a colour: povray reads
     a float there too. */
  bad(f, "sphere { 0, 1 pigment { average pigment_map { [rgb 1] } } }",
      ZR_ESYNTAX, "unexpected 'rgb'", NULL);
  /* Other patterns' entries need their value, as in povray. */
  bad(f, "sphere { 0, 1 pigment { gradient x pigment_map { [bozo]"
         " [1 rgb 0] } } }",
      ZR_ESYNTAX, "only an average's map entries may leave out their value",
      "t.pov:1:36: error: only an average's map entries may leave out "
      "their value\n"
      "    1 | sphere { 0, 1 pigment { gradient x pigment_map { [bozo] "
      "[1 rgb 0] } } }\n"
      "      |                                    "
      "^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~\n");
  bad(f, "sphere { 0, 1 normal { gradient x normal_map { [bumps 0.5]"
         " [1 dents] } } }",
      ZR_ESYNTAX, "only an average's map entries may leave out their value",
      NULL);
  bad(f, "sphere { 0, 1 texture { gradient x texture_map {"
         " [pigment { rgb 1 }] [1 pigment { rgb 0 }] } } }",
      ZR_ESYNTAX, "only an average's map entries may leave out their value",
      NULL);
}

static void test_texture_pigment_pattern_grey(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "sphere { 0, 1 pigment {"
                        " pigment_pattern { rgb <1, 0, 0> }"
                        " color_map { [0 rgb 0] [1 rgb 1] } } }");
  /* POV-Ray's grey of pure red is 0.297. */
  assert_colour(zr__pigment_eval(first_texture(s)->pigment, zr_v3(0, 0, 0)),
                0.297, 0.297, 0.297, 0, 0);
}

static void test_texture_legacy_colour_map(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "sphere { 0, 1 pigment { gradient x color_map {"
                        " [0.0, 0.5 color rgb 0 color rgb <1, 0, 0>]"
                        " [0.5, 1.0 color rgb <0, 0, 1> color rgb 1] } } }");
  const zr_pigment *pg = first_texture(s)->pigment;
  assert_int_equal(pg->colour_map->n, 4);
  assert_colour(zr__pigment_eval(pg, zr_v3(0.25, 0, 0)), 0.5, 0, 0, 0, 0);
  assert_colour(zr__pigment_eval(pg, zr_v3(0.75, 0, 0)), 0.5, 0.5, 1, 0, 0);
}

static void test_texture_layers_and_see_through(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "#declare L = texture { pigment {"
                        " rgbt <1, 1, 1, 0.8> } }"
                        " texture { pigment { rgbt <1, 0, 0, 0.5> } }\n"
                        "sphere { 0, 1 texture { L } texture {"
                        " pigment { rgbf <0, 1, 0, 0.5> } } }");
  const zr_texture *tx = first_texture(s);
  /* Bottom first: clear white, the red half-clear layer, the green
     filter. */
  assert_non_null(tx->over);
  assert_non_null(tx->over->over);
  assert_null(tx->over->over->over);
  assert_colour(tx->pigment->colour, 1, 1, 1, 0, 0.8);
  /* Through all three: 0.8 * 0.5 * (0.5 * green). */
  zr_rgb t = zr__texture_see_through(tx, zr_v3(0, 0, 0));
  assert_true(fabs(t.r) < EPS && fabs(t.g - 0.2) < EPS && fabs(t.b) < EPS);
}

static void test_texture_layered_pigment_changes_top(void **state) {
  fixture *f = *state;
  /* POV-Ray 3.7 changes the top layer (measured), whatever the manual
     says; the declared texture itself stays as it was. */
  zr_scene *s = good(f, "#declare L = texture { pigment { rgb 1 } }"
                        " texture { pigment { rgbt 1 } }\n"
                        "sphere { 0, 1 texture { L pigment { rgb 0.5 } } }\n"
                        "sphere { 0, 1 texture { L } }");
  const zr_texture *a = s->objects[0]->texture;
  const zr_texture *b = s->objects[1]->texture;
  assert_colour(a->pigment->colour, 1, 1, 1, 0, 0);
  assert_colour(a->over->pigment->colour, 0.5, 0.5, 0.5, 0, 0);
  assert_colour(b->over->pigment->colour, 1, 1, 1, 0, 1);
}

/* texture { T } changes nothing of T: every object shares T itself (a
   sphereflake's 7,381 spheres cost 1,450 bytes each with two copies of
   T apiece, 473 without); anything added makes a copy, and T stays. */
static void test_texture_identifier_alone_is_shared(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "#declare T = texture { pigment { rgb 1 } }\n"
                        "sphere { 0, 1 texture { T } }\n"
                        "sphere { 1, 1 texture { T } }\n"
                        "sphere { 2, 1 texture { T pigment { rgb 0.5 } } }\n"
                        "sphere { 3, 1 texture { T } scale 2 }\n"
                        "sphere { 4, 1 texture { T } }");
  const zr_texture *a = s->objects[0]->texture;
  assert_ptr_equal(a, s->objects[1]->texture);
  assert_ptr_equal(a, s->objects[4]->texture);
  assert_ptr_not_equal(a, s->objects[2]->texture);
  assert_ptr_not_equal(a, s->objects[3]->texture);
  assert_colour(a->pigment->colour, 1, 1, 1, 0, 0);
  assert_colour(s->objects[2]->texture->pigment->colour, 0.5, 0.5, 0.5, 0,
                0);
  assert_null(a->pigment->transform);
  assert_non_null(s->objects[3]->texture->pigment->transform);
}

static void test_texture_texture_on_textured_object_layers(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "#declare S = sphere { 0, 1 texture {"
                        " pigment { rgb <1, 0, 0> } } }\n"
                        "object { S texture { pigment { rgbt <0, 0, 1, 0.5> }"
                        " } }");
  const zr_texture *tx = first_texture(s);
  assert_colour(tx->pigment->colour, 1, 0, 0, 0, 0);
  assert_non_null(tx->over);
  assert_colour(tx->over->pigment->colour, 0, 0, 1, 0, 0.5);
}

static void test_texture_texture_map_picks(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "sphere { 0, 1 texture { gradient x texture_map {"
                        " [0.2 pigment { rgb <1, 0, 0> }]"
                        " [0.6 pigment { rgb <0, 0, 1> }] } scale 2 } }");
  const zr_texture *tx = first_texture(s);
  assert_non_null(tx->map);
  /* The first entry stands in where one plain texture is wanted. */
  assert_colour(tx->pigment->colour, 1, 0, 0, 0, 0);
  const zr_texture *b;
  double t;
  /* World x 0.6 is pattern 0.3: a quarter of the way. */
  const zr_texture *a = zr__texture_pick(tx, zr_v3(0.6, 0, 0), &b, &t);
  assert_ptr_equal(a, tx->map->entries[0].u.texture);
  assert_ptr_equal(b, tx->map->entries[1].u.texture);
  assert_true(fabs(t - 0.25) < EPS);
  a = zr__texture_pick(tx, zr_v3(1.5, 0, 0), &b, &t);
  assert_ptr_equal(a, tx->map->entries[1].u.texture);
  assert_null(b);
}

static void test_texture_block_textures_and_material(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "#declare M = material { texture { checker"
                        " texture { pigment { rgb 1 } }"
                        " texture { pigment { rgb 0 } } }"
                        " interior { ior 1.5 } }\n"
                        "sphere { 0, 1 material { M } }");
  const zr_object *o = s->objects[0];
  assert_non_null(o->interior);
  assert_true(fabs(o->interior->ior - 1.5) < EPS);
  const zr_texture *b;
  double t;
  const zr_texture *a =
      zr__texture_pick(o->texture, zr_v3(1.5, 0.5, 0.5), &b, &t);
  assert_null(b);
  assert_colour(a->pigment->colour, 0, 0, 0, 0, 0);
}

static void test_texture_average_texture_map(void **state) {
  fixture *f = *state;
  /* Entries of an average may leave out their weight, which is 1. */
  zr_scene *s = good(f, "sphere { 0, 1 texture { average texture_map {"
                        " [pigment { rgbt <1, 0, 0, 1> }]"
                        " [3 pigment { rgbt <0, 0, 1, 0.2> }] } } }");
  const zr_texture *tx = first_texture(s);
  assert_int_equal(tx->map->n, 2);
  assert_true(fabs(tx->map->entries[0].value - 1) < EPS);
  zr_rgb t = zr__texture_see_through(tx, zr_v3(0, 0, 0));
  /* (1 * 1 + 3 * 0.2) / 4 in every channel. */
  assert_true(fabs(t.r - 0.4) < EPS && fabs(t.g - 0.4) < EPS &&
              fabs(t.b - 0.4) < EPS);
}

static void test_texture_slope_map_hermite(void **state) {
  (void)state;
  /* Heights 0 and 1 with zero slopes make the smoothstep 3t^2 - 2t^3. */
  zr_map_entry e[2];
  memset(e, 0, sizeof e);
  e[0].value = 0;
  e[1].value = 1;
  e[1].u.slope.height = 1;
  zr_map m = {2, e, 0};
  assert_true(fabs(zr__slope_map_eval(&m, 0.25) - 0.15625) < EPS);
  assert_true(fabs(zr__slope_map_eval(&m, 1.0) - 1.0) < EPS);
  /* A slope of 1 at both ends of a 0..1 rise is the straight line. */
  e[0].u.slope.slope = 1;
  e[1].u.slope.slope = 1;
  assert_true(fabs(zr__slope_map_eval(&m, 0.3) - 0.3) < EPS);
}

/* POV-Ray 3.7's normals of a plane wearing bumps 0.5, dents 0.5 and
   wrinkles 0.5 (scale 0.3), read back from its renders by bench/conform/bump_fit.py
   (normal_probe.pov, 128x128, pixels (10,20), (64,64), (100,37),
   (77,110)): the world point and the tilt (nx, ny) / n_z of the normal
   towards the viewer.  The read-back is good to about 1e-4. */
static const struct {
  const char *normal;
  double side, x, y, tx, ty;
} bump_cases[] = {
    {"bumps 0.5", 1, -0.83593750, 0.67968750, 0.33828, -0.03779},
    {"bumps 0.5", 1, 0.00781250, -0.00781250, -0.16571, 0.14483},
    {"bumps 0.5", 1, 0.57031250, 0.41406250, 0.00515, 0.17820},
    {"bumps 0.5", 1, 0.21093750, -0.72656250, -0.00839, 0.04588},
    {"dents 0.5", 1, -0.83593750, 0.67968750, 0.14780, -0.01653},
    {"dents 0.5", 1, 0.00781250, -0.00781250, -0.00644, 0.00559},
    {"dents 0.5", 1, 0.57031250, 0.41406250, 0.00086, 0.02947},
    {"dents 0.5", 1, 0.21093750, -0.72656250, -0.00120, 0.00655},
    {"bumps 0.5", -1, 0.83593750, 0.67968750, 0.03193, -0.03638},
    {"bumps 0.5", -1, -0.00781250, -0.00781250, -0.28944, 0.23396},
    {"bumps 0.5", -1, -0.57031250, 0.41406250, -0.09752, 0.05418},
    {"bumps 0.5", -1, -0.21093750, -0.72656250, 0.07486, -0.14876},
    {"wrinkles 0.5", -1, 0.83593750, 0.67968750, 0.11517, 0.20334},
    {"wrinkles 0.5", -1, -0.00781250, -0.00781250, 0.29310, 0.23823},
    {"wrinkles 0.5", -1, -0.57031250, 0.41406250, 0.12501, 0.14140},
    {"wrinkles 0.5", -1, -0.21093750, -0.72656250, 0.20033, 0.23291},
    {"wrinkles 0.5", 1, -0.83593750, 0.67968750, 0.47277, 0.14626},
    {"wrinkles 0.5", 1, 0.00781250, -0.00781250, 0.54933, 0.50602},
    {"wrinkles 0.5", 1, 0.57031250, 0.41406250, 0.30813, 0.50125},
    {"wrinkles 0.5", 1, 0.21093750, -0.72656250, 0.14172, 0.15519},
};

static void test_texture_noise_normals_match_povray(void **state) {
  fixture *f = *state;
  for (size_t k = 0; k < sizeof bump_cases / sizeof bump_cases[0]; k++) {
    char text[128];
    snprintf(text, sizeof text, "plane { -z, 0 normal { %s scale 0.3 } }",
             bump_cases[k].normal);
    zr_scene *s = good(f, text);
    assert_true(s->n_objects >= 1);
    const zr_normal *nm = s->objects[0]->texture->normal;
    assert_non_null(nm);
    double side = bump_cases[k].side;
    zr_vec3 n = zr__normal_perturb(nm, zr_v3(bump_cases[k].x,
                                             bump_cases[k].y, 0),
                                   zr_v3(0, 0, -side));
    double nz = -side * n.z;
    assert_true(nz > 0);
    assert_true(fabs(n.x / nz - bump_cases[k].tx) < 2e-4);
    assert_true(fabs(n.y / nz - bump_cases[k].ty) < 2e-4);
  }
}

static void test_texture_new_patterns(void **state) {
  (void)state;
  zr_pattern pt;
  zr__pattern_init(&pt, ZR_PAT_CELLS);
  /* One value per unit cube. */
  assert_true(fabs(zr__pattern_eval(&pt, zr_v3(0.1, 0.2, 0.3)) -
                   zr__pattern_eval(&pt, zr_v3(0.9, 0.8, 0.7))) < EPS);
  zr__pattern_init(&pt, ZR_PAT_QUILTED);
  /* POV-Ray 3.7's values (#debug of a quilted pattern function, six
     decimals, bench/conform/quilted_probe.py): 0 in the middle of a
     cube, 0.575962 at its corners, 0.055630 a quarter along an axis. */
  assert_true(fabs(zr__pattern_eval(&pt, zr_v3(0.5, 0.5, 0.5))) < EPS);
  assert_true(fabs(zr__pattern_eval(&pt, zr_v3(1, 1, 1)) - 0.575962) < 1e-6);
  assert_true(fabs(zr__pattern_eval(&pt, zr_v3(0.75, 0.5, 0.5)) - 0.055630) <
              1e-6);
  pt.control0 = 0.3;
  pt.control1 = 0.8;
  assert_true(fabs(zr__pattern_eval(&pt, zr_v3(-0.5, 0.25, 0)) -
                   0.17414873) < 1e-8);
  /* ripples and waves at points of bench/conform/waves_probe.py's
     sample, POV-Ray 3.7's values to 1e-8 (the table keeps 10
     decimals). */
  static const double waves_cases[2][3][4] = {
      {{3.245026313708422, 3.2714671076284434, 0.6379300493792783,
        0.5267584507666885},
       {-1.4277875792067256, -3.5146236785650924, -0.5496800729303359,
        0.6331144673199071},
       {-0.3237411512200121, -3.5925232548779933, -3.5611806034554876,
        0.7518193816293756}},
      {{3.245026313708422, 3.2714671076284434, 0.6379300493792783,
        0.5192858294465001},
       {-1.4277875792067256, -3.5146236785650924, -0.5496800729303359,
        0.3854529294937483},
       {-0.3237411512200121, -3.5925232548779933, -3.5611806034554876,
        0.3759747964058118}}};
  for (int w = 0; w < 2; w++) {
    zr__pattern_init(&pt, w == 0 ? ZR_PAT_RIPPLES : ZR_PAT_WAVES);
    for (int i = 0; i < 3; i++) {
      const double *c = waves_cases[w][i];
      assert_true(fabs(zr__pattern_eval(&pt, zr_v3(c[0], c[1], c[2])) -
                       c[3]) < 1e-8);
    }
  }
  zr__pattern_init(&pt, ZR_PAT_SPIRAL1);
  pt.arms = 2;
  for (int i = 0; i < 20; i++) {
    double v = zr__pattern_eval(&pt, zr_v3(0.3 * i - 3, 0.7, 0.1 * i));
    assert_true(v >= 0 && v <= 1);
  }
}

static void test_texture_normal_forms_parse(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "sphere { 0, 1 normal { gradient x normal_map {"
                        " [0 bumps 0.5] [1 dents 0.3] } } }\n"
                        "sphere { 0, 1 normal { checker normal { bumps }"
                        " normal { quilted 0.4 control0 0 control1 1 } } }\n"
                        "sphere { 0, 1 normal { spiral1 3, 0.5"
                        " slope_map { [0 <0, 1>] [1 <1, 0>] } } }\n"
                        "#default { normal { bump_size 1.5 } }");
  assert_non_null(s->objects[0]->texture->normal->normal_map);
  assert_int_equal(s->objects[1]->texture->normal->normal_map->n, 2);
  assert_int_equal(s->objects[2]->texture->normal->pattern.arms, 3);
  assert_non_null(s->objects[2]->texture->normal->slope_map);
  assert_non_null(s->default_texture->normal);
}

static void test_texture_noise_and_waves_settings(void **state) {
  fixture *f = *state;
  good(f, "global_settings { noise_generator 1 }\n"
          "sphere { 0, 1 pigment { bozo noise_generator 3 } }");
  bad(f, "global_settings { noise_generator 4 }", ZR_ESCENE,
      "noise_generator must be 1, 2 or 3", NULL);
  /* number_of_waves sets the default of the waves made after it. */
  zr_scene *s = good(f, "global_settings { number_of_waves 3 }\n"
                        "sphere { 0, 1 pigment { waves } }");
  assert_int_equal(s->objects[0]->texture->pigment->pattern.waves, 3);
  /* In a pattern povray 3.7 does not parse it ("Cannot parse input"). */
  bad(f, "sphere { 0, 1 pigment { ripples number_of_waves 5 } }",
      ZR_ESYNTAX, "number_of_waves belongs in global_settings, not in a "
      "pattern", NULL);
}

/* ---- image maps ("Filtering and Transmitting Bitmap Areas", "Image
   File Gamma") ---- */

/* A 4 x 1 8-bit palette PNG: palette red, green, blue, white; the pixels
   are indices 0, 1, 2, 3.  Made with Python's zlib. */
static const unsigned char palette_png[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d,
    0x49, 0x48, 0x44, 0x52, 0x00, 0x00, 0x00, 0x04, 0x00, 0x00, 0x00, 0x01,
    0x08, 0x03, 0x00, 0x00, 0x00, 0xce, 0xe2, 0xff, 0xff, 0x00, 0x00, 0x00,
    0x0c, 0x50, 0x4c, 0x54, 0x45, 0xff, 0x00, 0x00, 0x00, 0xff, 0x00, 0x00,
    0x00, 0xff, 0xff, 0xff, 0xff, 0xfb, 0x00, 0x60, 0xf6, 0x00, 0x00, 0x00,
    0x0d, 0x49, 0x44, 0x41, 0x54, 0x78, 0xda, 0x63, 0x60, 0x60, 0x64, 0x62,
    0x06, 0x00, 0x00, 0x0f, 0x00, 0x07, 0x5b, 0xd0, 0x8b, 0x7d, 0x00, 0x00,
    0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};

/* A 1 x 1 8-bit RGB PNG without gAMA or sRGB chunks: codes 128, 64,
   200. */
static const unsigned char rgb_png[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d,
    0x49, 0x48, 0x44, 0x52, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01,
    0x08, 0x02, 0x00, 0x00, 0x00, 0x90, 0x77, 0x53, 0xde, 0x00, 0x00, 0x00,
    0x0c, 0x49, 0x44, 0x41, 0x54, 0x78, 0xda, 0x63, 0x68, 0x70, 0x38, 0x01,
    0x00, 0x02, 0xcc, 0x01, 0x89, 0x1b, 0x22, 0x39, 0x9f, 0x00, 0x00, 0x00,
    0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};

/* The same pixel with a gAMA chunk of 1.0: the file says its codes are
   linear. */
static const unsigned char linear_png[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d,
    0x49, 0x48, 0x44, 0x52, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01,
    0x08, 0x02, 0x00, 0x00, 0x00, 0x90, 0x77, 0x53, 0xde, 0x00, 0x00, 0x00,
    0x04, 0x67, 0x41, 0x4d, 0x41, 0x00, 0x01, 0x86, 0xa0, 0x31, 0xe8, 0x96,
    0x5f, 0x00, 0x00, 0x00, 0x0c, 0x49, 0x44, 0x41, 0x54, 0x78, 0xda, 0x63,
    0x68, 0x70, 0x38, 0x01, 0x00, 0x02, 0xcc, 0x01, 0x89, 0x1b, 0x22, 0x39,
    0x9f, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60,
    0x82};

/* Writes bytes to a fresh file under /tmp and returns its path in buf. */
static const char *write_file(char *buf, size_t size, const char *name,
                              const unsigned char *bytes, size_t n) {
  snprintf(buf, size, "/tmp/zr-texture-%ld-%s", (long)getpid(), name);
  FILE *fp = fopen(buf, "wb");
  assert_non_null(fp);
  assert_int_equal(fwrite(bytes, 1, n, fp), n);
  assert_int_equal(fclose(fp), 0);
  return buf;
}

/* Parses "sphere { 0, 1 pigment { image_map { png PATH MODS } } }". */
static const zr_pigment *image_pigment(fixture *f, const char *path,
                                       const char *mods) {
  char text[1024];
  /* A 3.7 scene: a legacy one works in gamma 2.2 (directive.c), which
     takes image colours there too. */
  snprintf(text, sizeof text,
           "#version 3.7;\n"
           "sphere { 0, 1 pigment { image_map { png \"%s\" %s } } }", path,
           mods);
  const zr_pigment *pg = first_texture(good(f, text))->pigment;
  assert_int_equal(pg->kind, ZR_PIGMENT_IMAGE);
  return pg;
}

/* Pixel k of the 4 x 1 map lies at u = (k + 0.5) / 4. */
static zr_colour palette_pixel(const zr_pigment *pg, int k) {
  return zr__pigment_eval(pg, zr_v3((k + 0.5) / 4, 0.5, 0));
}

static void test_texture_image_map_palette_filter_transmit(void **state) {
  fixture *f = *state;
  char path[256];
  write_file(path, sizeof path, "pal.png", palette_png, sizeof palette_png);
  /* Index forms set one entry each; the rest stay 0. */
  const zr_pigment *pg = image_pigment(
      f, path, "filter 1, 0.5 transmit 2, 0.25 transmit 3, 1");
  assert_int_equal(pg->image->palette_size, 4);
  assert_colour(palette_pixel(pg, 0), 1, 0, 0, 0, 0);
  assert_colour(palette_pixel(pg, 1), 0, 1, 0, 0.5, 0);
  assert_colour(palette_pixel(pg, 2), 0, 0, 1, 0, 0.25);
  assert_colour(palette_pixel(pg, 3), 1, 1, 1, 0, 1);
  /* "all" sets every entry; a later index form overrides one, an
     earlier one is overwritten, as POV-Ray 3.7 renders it.  The entry
     is INDEX + 0.01 rounded towards zero (measured: see
     zr__sdl_image_map_index), so 1.995 is entry 2. */
  pg = image_pigment(f, path, "transmit 0, 0.75 transmit all 0.5 "
                              "filter all 0.125 filter 1.995, 1");
  assert_colour(palette_pixel(pg, 0), 1, 0, 0, 0.125, 0.5);
  assert_colour(palette_pixel(pg, 2), 0, 0, 1, 1, 0.5);
  assert_colour(palette_pixel(pg, 3), 1, 1, 1, 0.125, 0.5);
  unlink(path);
}

/* The pigment's warps and turbulence move the point before the picture
   is read (textures/pigments/warp1.pov and warp2.pov in POV-Ray 3.7). */
static void test_texture_image_map_warped(void **state) {
  fixture *f = *state;
  char path[256], text[1024];
  write_file(path, sizeof path, "pal.png", palette_png, sizeof palette_png);
  /* repeat 0.25*x: every quarter repeats the first, red pixel. */
  snprintf(text, sizeof text, "sphere { 0, 1 pigment { image_map { png "
           "\"%s\" } warp { repeat 0.25*x } } }", path);
  const zr_pigment *pg = first_texture(good(f, text))->pigment;
  for (int k = 0; k < 4; k++)
    assert_colour(palette_pixel(pg, k), 1, 0, 0, 0, 0);
  /* Turbulence: some pixel centre along the row reads another pixel. */
  snprintf(text, sizeof text, "sphere { 0, 1 pigment { image_map { png "
           "\"%s\" } turbulence 0.6 } }", path);
  pg = first_texture(good(f, text))->pigment;
  /* Without turbulence the pixel centres read their own pixel. */
  const zr_colour own[4] = {
      zr_colour5(1, 0, 0, 0, 0), zr_colour5(0, 1, 0, 0, 0),
      zr_colour5(0, 0, 1, 0, 0), zr_colour5(1, 1, 1, 0, 0)};
  int moved = 0;
  for (int k = 0; k < 4; k++)
    for (int j = 0; j < 8; j++) {
      zr_vec3 p = zr_v3((k + 0.5) / 4, (j + 0.5) / 8, 0.37 * j);
      zr_colour a = zr__pigment_eval(pg, p);
      moved += a.r != own[k].r || a.g != own[k].g || a.b != own[k].b;
    }
  assert_true(moved > 0);
  unlink(path);
}

static void test_texture_image_map_bad_palette_index(void **state) {
  fixture *f = *state;
  char pal[256], rgb[256], text[1024];
  write_file(pal, sizeof pal, "pal.png", palette_png, sizeof palette_png);
  write_file(rgb, sizeof rgb, "rgb.png", rgb_png, sizeof rgb_png);
  char message[512];
  snprintf(text, sizeof text, "sphere { 0, 1 pigment { image_map { png "
           "\"%s\" transmit 4, 1 } } }", pal);
  snprintf(message, sizeof message, "transmit palette index 4 is out of "
           "range: '%s' has 4 palette entries", pal);
  bad(f, text, ZR_ESCENE, message, NULL);
  /* POV-Ray 3.7 takes -1.005 as entry 0 and refuses -1.02 (measured
     on a two-entry palette): the index rounds towards zero. */
  snprintf(text, sizeof text, "sphere { 0, 1 pigment { image_map { png "
           "\"%s\" filter -1.02, 1 } } }", pal);
  snprintf(message, sizeof message, "filter palette index -1.02 is out "
           "of range: '%s' has 4 palette entries", pal);
  bad(f, text, ZR_ESCENE, message, NULL);
  const zr_pigment *pg = image_pigment(f, pal, "filter -1.005, 1");
  assert_colour(palette_pixel(pg, 0), 1, 0, 0, 1, 0);
  assert_colour(palette_pixel(pg, 1), 0, 1, 0, 0, 0);
  /* POV-Ray 3.7 refuses the index form on an RGB PNG too (measured:
     "Keyword 'filter' cannot be used with non color-mapped image"). */
  snprintf(text, sizeof text, "sphere { 0, 1 pigment { image_map { png "
           "\"%s\" filter 0, 1 } } }", rgb);
  snprintf(message, sizeof message, "'filter INDEX, AMOUNT' needs a "
           "palette image; '%s' has no palette (use 'filter all AMOUNT')",
           rgb);
  bad(f, text, ZR_ESCENE, message, NULL);
  snprintf(text, sizeof text, "sphere { 0, 1 pigment { image_map { png "
           "\"%s\" transmit 0 } } }", pal);
  bad(f, text, ZR_ESYNTAX,
      "unexpected '}', expected '+', '-', '*', '/', ',' or '.'", NULL);
  unlink(pal);
  unlink(rgb);
}

static void test_texture_image_map_gamma(void **state) {
  fixture *f = *state;
  char rgb[256], pal[256], text[1024];
  write_file(rgb, sizeof rgb, "rgb.png", rgb_png, sizeof rgb_png);
  write_file(pal, sizeof pal, "pal.png", palette_png, sizeof palette_png);
  /* "gamma G": linear = (code / 255) ^ G, whatever the file says.  The
     decoded floats are single precision: 1e-6 relative covers them. */
  const zr_pigment *pg = image_pigment(f, rgb, "gamma 2.2");
  zr_colour c = zr__pigment_eval(pg, zr_v3(0.5, 0.5, 0));
  assert_true(fabs(c.r - pow(128 / 255.0, 2.2)) < 1e-6);
  assert_true(fabs(c.g - pow(64 / 255.0, 2.2)) < 1e-6);
  assert_true(fabs(c.b - pow(200 / 255.0, 2.2)) < 1e-6);
  pg = image_pigment(f, rgb, "gamma 1 once");
  c = zr__pigment_eval(pg, zr_v3(0.5, 0.5, 0));
  assert_true(fabs(c.r - 128 / 255.0) < 1e-6);
  assert_true(fabs(c.b - 200 / 255.0) < 1e-6);
  /* Without it the file's default, sRGB, holds: code 128 is 0.2158605. */
  pg = image_pigment(f, rgb, "");
  c = zr__pigment_eval(pg, zr_v3(0.5, 0.5, 0));
  assert_true(fabs(c.r - 0.2158605) < 1e-6);
  /* "gamma srgb" ("The Gamma Option"): the sRGB transfer function,
     whatever the file says.  This file says linear (gAMA 1.0), which
     povray 3.7 and zRcube both show as code 128 = 0.50196 without the
     keyword and 0.21585 with it (16-bit renders, File_Gamma=1;
     tests/test_image_gamma_povray.sh compares live).  Items may
     follow, as in jarOfBonus.inc's "png F gamma srgb map_type 2 once
     interpolate 2". */
  char lin[256];
  write_file(lin, sizeof lin, "lin.png", linear_png, sizeof linear_png);
  pg = image_pigment(f, lin, "");
  c = zr__pigment_eval(pg, zr_v3(0.5, 0.5, 0));
  assert_true(fabs(c.r - 128 / 255.0) < 1e-6);
  pg = image_pigment(f, lin, "gamma srgb map_type 0 once interpolate 2");
  c = zr__pigment_eval(pg, zr_v3(0.5, 0.5, 0));
  assert_true(fabs(c.r - 0.2158605) < 1e-6);
  assert_true(fabs(c.g - 0.0512695) < 1e-6);
  assert_true(fabs(c.b - 0.5775804) < 1e-6);
  /* bump_map takes it too. */
  snprintf(text, sizeof text, "#version 3.7;\nsphere { 0, 1 normal { "
           "bump_map { png \"%s\" gamma srgb bump_size 2 } } }", lin);
  assert_int_equal(parse(f, text), ZR_OK);
  /* srgb is a keyword there, not a colour: "gamma srgb 0.5" is not. */
  snprintf(text, sizeof text, "sphere { 0, 1 pigment { image_map { png "
           "\"%s\" gamma srgb 0.5 } } }", lin);
  assert_int_not_equal(parse(f, text), ZR_OK);
  unlink(lin);
  /* A palette image keeps its indices under a gamma. */
  pg = image_pigment(f, pal, "gamma 2 transmit 3, 0.5");
  assert_colour(palette_pixel(pg, 3), 1, 1, 1, 0, 0.5);
  snprintf(text, sizeof text, "sphere { 0, 1 pigment { image_map { png "
           "\"%s\" gamma 0 } } }", rgb);
  bad(f, text, ZR_ESCENE, "image_map gamma 0 must be positive", NULL);
  /* gamma must follow the file name ("Image File Gamma"). */
  snprintf(text, sizeof text, "sphere { 0, 1 pigment { image_map { png "
           "\"%s\" once gamma 2.2 } } }", rgb);
  assert_int_equal(parse(f, text), ZR_ESYNTAX);
  unlink(pal);
  unlink(rgb);
}

static void test_texture_bad_maps(void **state) {
  fixture *f = *state;
  bad(f, "sphere { 0, 1 pigment { gradient x pigment_map { } } }",
      ZR_ESYNTAX, "a pigment_map needs an entry", NULL);
  bad(f, "sphere { 0, 1 pigment { checker pigment { rgb 1 }"
         " pigment { rgb 0 } pigment { rgb 0.5 } } }",
      ZR_ESYNTAX, "too many items for this pattern", NULL);
  bad(f, "sphere { 0, 1 normal { bumps slope_map { [0 1] } } }", ZR_ESCENE,
      "a slope_map entry wants <height, slope>", NULL);
}

/* ---- uv_mapping ("UV Mapping") ---- */

/* The (u, v) where the ray from o along d first meets the scene's first
   object, as zr__hit_uv gives them. */
static void first_uv(const zr_scene *s, zr_vec3 o, zr_vec3 d, double *u,
                     double *v) {
  zr_hit h[ZR_MAX_CROSSINGS];
  zr_ray r = {o, d};
  assert_true(zr__intersect(s->objects[0], &r, 0.0, INFINITY, h) >= 1);
  assert_true(zr__hit_uv(&h[0], zr_v3_madd(o, d, h[0].t), u, v));
}

/* The uv values are the manual's definitions evaluated by hand (sphere:
   u the angle about y from +x over a turn, v = 1/2 + asin(y) / pi;
   torus: u = 1/2 - atan2(z, x) / 2 pi, v = 1/2 + atan2(y, r - major) /
   2 pi, which povray 3.7 renders of gradient x and y bear out; mesh2:
   uv_vectors
   blended barycentrically), so 1e-9 covers only rounding. */
static void test_texture_uv_mapping_sphere(void **state) {
  fixture *f = *state;
  /* The rotation turns the sphere, not the uv pattern on it. */
  zr_scene *s = good(f, "sphere { 0, 1 pigment { uv_mapping checker"
                        " rgb 0, rgb 1 scale 0.25 } rotate 90*y }");
  const zr_pigment *pg = first_texture(s)->pigment;
  assert_true(pg->uv_mapping);
  double u, v;
  /* World (0, 0.5, -sqrt(3)/2) is object (sqrt(3)/2, 0.5, 0) after the
     inverse of rotate 90*y: u = 0, v = 1/2 + 1/6. */
  first_uv(s, zr_v3(0, 0.5, -5), zr_v3(0, 0, 1), &u, &v);
  assert_true(fabs(u - 0.0) < EPS);
  assert_true(fabs(v - 2.0 / 3.0) < EPS);
  /* Checker at (0, 2/3, 0) / 0.25 = (0, 2.67, 0): floor sum 2, even. */
  assert_colour(zr__pigment_eval(pg, zr_v3(u, v, 0)), 0, 0, 0, 0, 0);
  /* World (-1, 0, 0) is object (0, 0, -1): a three-quarter turn. */
  first_uv(s, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), &u, &v);
  assert_true(fabs(u - 0.75) < EPS);
  assert_true(fabs(v - 0.5) < EPS);
  /* (3, 2, 0): odd. */
  assert_colour(zr__pigment_eval(pg, zr_v3(u, v, 0)), 1, 1, 1, 0, 0);
}

static void test_texture_uv_mapping_torus_and_object(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "torus { 2, 0.5 uv_mapping texture { pigment {"
                        " checker } } translate 10*x }");
  assert_true(s->objects[0]->uv_mapping);
  double u, v;
  /* The outer equator at +x: u = 1/2, v = 1/2. */
  first_uv(s, zr_v3(20, 0, 0), zr_v3(-1, 0, 0), &u, &v);
  assert_true(fabs(u - 0.5) < EPS);
  assert_true(fabs(v - 0.5) < EPS);
  /* The top of the tube at +z: u = 1/4, v = (pi / 2 + pi) / 2 pi. */
  first_uv(s, zr_v3(10, 5, 2), zr_v3(0, -1, 0), &u, &v);
  assert_true(fabs(u - 0.25) < EPS);
  assert_true(fabs(v - 0.75) < EPS);
}

/* The box map is the manual's UV Boxmap figure (povray 3.7 renders of
   gradient x and y on a box match it); 1e-9 covers rounding. */
static void test_texture_uv_mapping_box(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "box { 0, <1, 2, 4> pigment { uv_mapping checker"
                        " } }");
  double u, v;
  /* Max x at y = 1, z = 1: u = 3/4 - (1/4) / 4, v = 1/3 + (1/2) / 3. */
  first_uv(s, zr_v3(5, 1, 1), zr_v3(-1, 0, 0), &u, &v);
  assert_true(fabs(u - (0.75 - 0.0625)) < EPS);
  assert_true(fabs(v - 0.5) < EPS);
  /* Max y at x = 0.5, z = 3: u = 1/4 + 1/8, v = 1 - (3/4) / 3. */
  first_uv(s, zr_v3(0.5, 5, 3), zr_v3(0, -1, 0), &u, &v);
  assert_true(fabs(u - 0.375) < EPS);
  assert_true(fabs(v - 0.75) < EPS);
}

static void test_texture_uv_mapping_mesh2(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>,"
                        " <0,1,0> } uv_vectors { 3, <0,0>, <2,0>, <0,4> }"
                        " face_indices { 1, <0,1,2> } uv_indices { 1,"
                        " <0,1,2> } texture { uv_mapping pigment {"
                        " checker } } }");
  assert_true(first_texture(s)->uv_mapping);
  double u, v;
  /* (0.25, 0.5) has weights 0.25, 0.25, 0.5 on the three corners. */
  first_uv(s, zr_v3(0.25, 0.5, 5), zr_v3(0, 0, -1), &u, &v);
  assert_true(fabs(u - 0.5) < EPS);
  assert_true(fabs(v - 2.0) < EPS);
  /* Without uv_vectors each triangle has (0,0), (1,0), (1,1). */
  s = good(f, "mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> }"
              " pigment { uv_mapping checker } }");
  first_uv(s, zr_v3(0.25, 0.5, 5), zr_v3(0, 0, -1), &u, &v);
  assert_true(fabs(u - 0.75) < EPS);
  assert_true(fabs(v - 0.5) < EPS);
}

static void test_texture_uv_mapping_without_uv(void **state) {
  fixture *f = *state;
  bad(f, "plane { y, 0 pigment { uv_mapping checker } }", ZR_EUNSUPPORTED,
      "uv_mapping on a plane: zRcube has surface coordinates only for "
      "mesh, mesh2, sphere, box and torus",
      NULL);
  bad(f, "union { sphere { 0, 1 } cylinder { 0, y, 1 } uv_mapping }",
      ZR_EUNSUPPORTED,
      "uv_mapping on a cylinder: zRcube has surface coordinates only for "
      "mesh, mesh2, sphere, box and torus",
      NULL);
}

/* How far a transformation moved a pattern: its translation part. */
static void assert_moved(const zr_transform *t, double x, double y,
                         double z) {
  assert_non_null(t);
  assert_true(fabs(t->m[0][3] - x) < EPS);
  assert_true(fabs(t->m[1][3] - y) < EPS);
  assert_true(fabs(t->m[2][3] - z) < EPS);
}

/* A transformation changes a texture in place once it has copied it
   for this texture block or this object (lib/sdl/build.c,
   zr__sdl_texture_move); the declared textures and objects, and the
   other objects using them, never see it. */
static void test_texture_moved_in_place_stays_private(void **state) {
  fixture *f = *state;
  zr_scene *s = good(
      f, "#declare T = texture { pigment { bozo } normal { bumps } }"
         " texture { pigment { agate } }\n"
         "#declare M = texture { gradient x texture_map { [0 T]"
         " [1 T translate z] } }\n"
         "box { 0, 1 texture { T translate x translate y } translate z }\n"
         "box { 0, 1 texture { T translate 2 * x } translate 2 * y"
         " translate 2 * z }\n"
         "box { 0, 1 texture { M translate x } translate y }\n"
         "box { 0, 1 texture { T } }\n"
         "#declare U = texture { pigment { bozo } finish { ambient 0.2 }"
         " translate x }\n"
         "box { 0, 1 texture { U } translate y translate y }\n"
         "box { 0, 1 texture { U } translate z }\n"
         "box { 0, 1 texture { U } }\n");
  assert_int_equal(s->n_objects, 7);
  const zr_texture *a = s->objects[0]->texture;
  assert_moved(a->pigment->transform, 1, 1, 1);
  assert_moved(a->normal->transform, 1, 1, 1);
  assert_moved(a->over->pigment->transform, 1, 1, 1);
  const zr_texture *b = s->objects[1]->texture;
  assert_moved(b->pigment->transform, 2, 2, 2);
  assert_moved(b->normal->transform, 2, 2, 2);
  assert_moved(b->over->pigment->transform, 2, 2, 2);
  const zr_texture *m = s->objects[2]->texture;
  assert_moved(m->transform, 1, 1, 0);
  const zr_texture *e0 = m->map->entries[0].u.texture;
  const zr_texture *e1 = m->map->entries[1].u.texture;
  assert_moved(e0->pigment->transform, 1, 1, 0);
  assert_moved(e0->over->pigment->transform, 1, 1, 0);
  assert_moved(e1->pigment->transform, 1, 1, 1);
  assert_moved(e1->normal->transform, 1, 1, 1);
  /* T itself. */
  const zr_texture *t = s->objects[3]->texture;
  assert_null(t->pigment->transform);
  assert_null(t->normal->transform);
  assert_null(t->over->pigment->transform);
  assert_moved(s->objects[4]->texture->pigment->transform, 1, 2, 0);
  assert_moved(s->objects[5]->texture->pigment->transform, 1, 0, 1);
  assert_moved(s->objects[6]->texture->pigment->transform, 1, 0, 0);
}

static void test_texture_moved_with_copies_of_objects(void **state) {
  fixture *f = *state;
  zr_scene *s = good(
      f, "#declare B = box { 0, 1 texture { pigment { bozo } translate x }"
         " translate y }\n"
         "object { B translate z translate z }\n"
         "object { B scale 2 }\n"
         "object { B }\n"
         "blob { sphere { 0, 1, 1 texture { pigment { bozo } translate x }"
         " translate y translate y } sphere { 0, 1, 1 texture { pigment {"
         " bozo } translate x } } translate z translate z }\n"
         "union { box { 0, 1 texture { pigment { bozo } translate x }"
         " translate y } sphere { 0, 1 texture { pigment { bozo } } }"
         " translate z translate z }\n"
         "box { 0, 1 texture { uv_mapping pigment { bozo } translate x }"
         " translate y scale 2 }\n");
  assert_int_equal(s->n_objects, 6);
  assert_moved(s->objects[0]->texture->pigment->transform, 1, 1, 2);
  assert_moved(s->objects[1]->texture->pigment->transform, 2, 2, 0);
  assert_moved(s->objects[2]->texture->pigment->transform, 1, 1, 0);
  const zr_blob_component *c = s->objects[3]->u.blob.components;
  assert_moved(c[0].texture->pigment->transform, 1, 2, 2);
  assert_moved(c[1].texture->pigment->transform, 1, 0, 2);
  const zr_object *o = s->objects[4];
  assert_true(zr__is_csg(o->kind) && o->u.csg.n_children == 2);
  assert_moved(o->u.csg.children[0]->texture->pigment->transform, 1, 1, 2);
  assert_moved(o->u.csg.children[1]->texture->pigment->transform, 0, 0, 2);
  /* uv_mapping: the object's transformations leave it on the surface. */
  assert_moved(s->objects[5]->texture->pigment->transform, 1, 0, 0);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_texture_pigment_map_blends),
      cmocka_unit_test(test_texture_block_pigments_and_transform),
      cmocka_unit_test(test_texture_colour_lists_without_commas),
      cmocka_unit_test(test_texture_reflection_without_comma),
      cmocka_unit_test(test_texture_slope_without_braces),
      cmocka_unit_test(test_texture_average_weights),
      cmocka_unit_test(test_texture_average_without_weights),
      cmocka_unit_test(test_texture_pigment_pattern_grey),
      cmocka_unit_test(test_texture_legacy_colour_map),
      cmocka_unit_test(test_texture_layers_and_see_through),
      cmocka_unit_test(test_texture_layered_pigment_changes_top),
      cmocka_unit_test(test_texture_texture_on_textured_object_layers),
      cmocka_unit_test(test_texture_texture_map_picks),
      cmocka_unit_test(test_texture_block_textures_and_material),
      cmocka_unit_test(test_texture_average_texture_map),
      cmocka_unit_test(test_texture_slope_map_hermite),
      cmocka_unit_test(test_texture_noise_normals_match_povray),
      cmocka_unit_test(test_texture_new_patterns),
      cmocka_unit_test(test_texture_normal_forms_parse),
      cmocka_unit_test(test_texture_noise_and_waves_settings),
      cmocka_unit_test(test_texture_bad_maps),
      cmocka_unit_test(test_texture_uv_mapping_sphere),
      cmocka_unit_test(test_texture_uv_mapping_torus_and_object),
      cmocka_unit_test(test_texture_uv_mapping_box),
      cmocka_unit_test(test_texture_uv_mapping_mesh2),
      cmocka_unit_test(test_texture_uv_mapping_without_uv),
      cmocka_unit_test(test_texture_image_map_palette_filter_transmit),
      cmocka_unit_test(test_texture_image_map_warped),
      cmocka_unit_test(test_texture_image_map_bad_palette_index),
      cmocka_unit_test(test_texture_image_map_gamma),
      cmocka_unit_test(test_texture_identifier_alone_is_shared),
      cmocka_unit_test(test_texture_moved_in_place_stays_private),
      cmocka_unit_test(test_texture_moved_with_copies_of_objects),
  };
  return cmocka_run_group_tests(tests, setup, teardown);
}
