/*
 * test_shaft.c - the area light shafts of lib/trace/shaft.c.  A shaft's
 * plan must give every shadow ray's answer: when it says nothing can
 * be met, the shadow walk (zr__shadow_transmission) finds each ray to
 * any point of the light's grid (jitter included) unblocked; when it
 * lists objects, a ray is blocked exactly when it crosses one of them.
 * Checked from seeded random points of a Cornell-like room (nine 4 x 4
 * jittered lights tiling a ceiling panel, blocks of triangles, a box,
 * a sphere, a plane, a glass ball and a no_shadow panel), against grid
 * points and random points of each light's rectangle.  Then a render of
 * the room with the shafts and without must be the same bytes, and the
 * plans must say "nothing" and "these" often enough that the test
 * would notice shafts that never answer.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "parse_fixture.h"
#include "scene/scene.h"
#include "trace/lights.h"
#include "trace/render.h"
#include "trace/shade.h"
#include "trace/shaft.h"

/* The room: walls of triangles, a ceiling in the lights' plane (the
   lights hang in it, as radiosity/cornell.pov's do), blocks, and
   shapes of the kinds the shafts handle (box, sphere, plane) and one
   they must hand back (a glass ball: not opaque). */
static const char room[] =
    "camera { location <27.8, 27.3, -80> look_at <27.8, 27.3, 0>\n"
    "         angle 39.5 }\n"
    "#declare L = light_source { <27.8, 54.88, 27.95> rgb <1, 0.67, 0.21>\n"
    "  area_light 13/3*x, 10.5/3*z, 4, 4 jitter adaptive 0\n"
    "  spotlight radius -90 falloff 90 tightness 1\n"
    "  point_at <27.8, 0, 27.95> fade_power 2 fade_distance 4 }\n"
    "#for (i, 0, 2) #for (j, 0, 2)\n"
    "  light_source { L translate <(i - 1) * 13/3, 0, (j - 1) * 10.5/3> }\n"
    "#end #end\n"
    /* A light of its own plane, full grid (3 x 3: its mean is 9 * 1/9),
       circular; and an orient light, which no shaft covers. */
    "light_source { <50, 40, 10> rgb 0.3 area_light 4*x, 4*y, 3, 3\n"
    "  circular jitter }\n"
    "light_source { <5, 45, 40> rgb 0.2 area_light 3*x, 3*z, 3, 3\n"
    "  orient circular adaptive 1 }\n"
    "box { <21.3, 54.87, 22.7>, <34.3, 54.88, 33.2> no_shadow\n"
    "  pigment { rgb 1 } finish { ambient 0.78 diffuse 0 } }\n"
    "union {\n"
    "  triangle { <55.28, 0, 0>, <0, 0, 0>, <0, 0, 55.92> }\n"
    "  triangle { <55.28, 0, 0>, <0, 0, 55.92>, <54.96, 0, 55.92> }\n"
    "  triangle { <55.6, 54.88, 0>, <55.6, 54.88, 55.92>,\n"
    "             <0, 54.88, 55.92> }\n"
    "  triangle { <55.6, 54.88, 0>, <0, 54.88, 55.92>, <0, 54.88, 0> }\n"
    "  triangle { <0, 54.88, 55.92>, <55.6, 54.88, 55.92>,\n"
    "             <54.96, 0, 55.92> }\n"
    "  triangle { <0, 54.88, 55.92>, <54.96, 0, 55.92>, <0, 0, 55.92> }\n"
    "  triangle { <0, 54.88, 0>, <0, 54.88, 55.92>, <0, 0, 55.92> }\n"
    "  triangle { <0, 54.88, 0>, <0, 0, 55.92>, <0, 0, 0> }\n"
    "  pigment { rgb 0.8 } finish { diffuse 0.75 ambient 0 } }\n"
    "union {\n"
    "  triangle { <13, 16.5, 6.5>, <8.2, 16.5, 22.5>, <24, 16.5, 27.2> }\n"
    "  triangle { <13, 16.5, 6.5>, <24, 16.5, 27.2>, <29, 16.5, 11.4> }\n"
    "  triangle { <29, 0, 11.4>, <29, 16.5, 11.4>, <24, 16.5, 27.2> }\n"
    "  triangle { <29, 0, 11.4>, <24, 16.5, 27.2>, <24, 0, 27.2> }\n"
    "  triangle { <13, 0, 6.5>, <13, 16.5, 6.5>, <29, 16.5, 11.4> }\n"
    "  triangle { <13, 0, 6.5>, <29, 16.5, 11.4>, <29, 0, 11.4> }\n"
    "  pigment { rgb 0.9 } finish { diffuse 0.75 ambient 0 } }\n"
    "box { <38, 0, 30>, <46, 30, 40> pigment { rgb 0.7 } }\n"
    "sphere { <14, 40, 36>, 4 pigment { rgb 0.5 } }\n"
    "sphere { <40, 44, 14>, 3 pigment { rgb 1 filter 0.6 } }\n"
    "plane { x, 60 pigment { rgb 0.4 } }\n";

static double uniform(uint64_t *seed) {
  *seed = *seed * 6364136223846793005ULL + 1442695040888963407ULL;
  return (double)(*seed >> 11) * (1.0 / 9007199254740992.0);
}

/* A point of the light's rectangle, grown by half a cell for jitter:
   anywhere a grid point may be. */
static zr_vec3 rectangle_point(const zr_light *l, uint64_t *seed) {
  double g1 = l->size1 > 1 ? 0.5 / (l->size1 - 1) : 0.0;
  double g2 = l->size2 > 1 ? 0.5 / (l->size2 - 1) : 0.0;
  double a = (uniform(seed) - 0.5) * (1.0 + 2.0 * g1);
  double b = (uniform(seed) - 0.5) * (1.0 + 2.0 * g2);
  return zr_v3_madd(zr_v3_madd(l->location, l->axis1, a), l->axis2, b);
}

typedef struct tally {
  long clear, listed, unknown, rays;
} tally;

/* The plan from p to light l, checked against the walk toward every
   grid point (as seen from p) and some random points. */
static void check_point(const zr_tracer *tr, const zr_light *l, zr_vec3 p,
                        uint64_t *seed, tally *t) {
  zr_shaft_plan plan;
  zr__shaft_plan(tr, l, p, true, &plan);
  if (plan.n < 0) {
    t->unknown++;
    return;
  }
  if (plan.n == 0)
    t->clear++;
  else
    t->listed++;
  zr_vec3 targets[16 + 8];
  int n = 0;
  for (int j = 0; j < l->size2 && n < 16; j++)
    for (int i = 0; i < l->size1 && n < 16; i++)
      targets[n++] = zr__area_light_point(l, p, i, j);
  while (n < 24)
    targets[n++] = rectangle_point(l, seed);
  for (int k = 0; k < n; k++) {
    zr_rgb v = zr__shadow_transmission(tr, l, targets[k], p);
    t->rays++;
    if (plan.n == 0) {
      assert_true(v.r == 1.0 && v.g == 1.0 && v.b == 1.0);
    } else {
      bool blocked = zr__shaft_blocks(tr, &plan, p, targets[k]);
      assert_true(v.r == 0.0 || v.r == 1.0);
      assert_int_equal(blocked, v.r == 0.0);
    }
  }
}

static void test_shaft_plans_give_the_walks_answers(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, room);
  assert_non_null(s->shafts);
  zr_render_stats stats;
  memset(&stats, 0, sizeof stats);
  zr_shadow_cache cache;
  memset(&cache, 0, sizeof cache);
  zr_tracer tr = {.scene = s, .stats = &stats, .shadow_cache = &cache};
  uint64_t seed = 11;
  tally t = {0};
  for (int k = 0; k < 3000; k++) {
    /* Inside the room, on its floor (a surface offset up, as shading
       leaves it), or on a block's top. */
    zr_vec3 p = zr_v3(0.5 + 55 * uniform(&seed), 54 * uniform(&seed),
                      0.5 + 55 * uniform(&seed));
    if (k % 3 == 1)
      p.y = 1e-6;
    else if (k % 3 == 2)
      p = zr_v3(14 + 10 * uniform(&seed), 16.5 + 1e-6,
                10 + 10 * uniform(&seed));
    for (size_t i = 0; i < s->n_lights; i++)
      check_point(&tr, &s->lights[i], p, &seed, &t);
  }
  /* The shafts answer most of the time, both ways. */
  assert_true(t.clear > 3000);
  assert_true(t.listed > 3000);
  assert_true(t.unknown > 0);
  /* The orient light never has a plan. */
  zr_shaft_plan plan;
  zr__shaft_plan(&tr, &s->lights[10], zr_v3(20, 1e-6, 20), true, &plan);
  assert_int_equal(plan.n, -1);
}

/* A render's pixels, with antialiasing (supersamples meet the lights
   from many points). */
static void render(const zr_scene *s, float *rgb, int w, int h) {
  zr_render_params p;
  zr_render_params_init(&p);
  p.width = w;
  p.height = h;
  p.antialias = 1;
  p.aa_threshold = 0.05;
  p.aa_depth = 3;
  assert_int_equal(zr_render_image(s, &p, rgb, NULL), ZR_OK);
}

static void test_shaft_same_bytes_without(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, room);
  enum { W = 48, H = 36 };
  static float with[W * H * 3], without[W * H * 3];
  render(s, with, W, H);
  struct zr_light_shafts *kept = s->shafts;
  s->shafts = NULL;
  render(s, without, W, H);
  s->shafts = kept;
  assert_memory_equal(with, without, sizeof with);
  /* Not a black picture: the lights reach the room. */
  double sum = 0.0;
  for (size_t i = 0; i < W * H * 3; i++)
    sum += with[i];
  assert_true(sum > 0.05 * W * H * 3);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test_setup_teardown(
          test_shaft_plans_give_the_walks_answers, setup, teardown),
      cmocka_unit_test_setup_teardown(test_shaft_same_bytes_without, setup,
                                      teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
