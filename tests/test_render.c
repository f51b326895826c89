/*
 * test_render.c - the public rendering calls: POV-Ray's defaults, camera
 * rays, the antialiasing pass, and results that do not depend on how the
 * pixels are split between calls (threads and ranks).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "core/arena.h"
#include "scene/scene.h"
#include "trace/prepare.h"
#include "trace/render.h"
#include "test_util.h"

#define EPS 1e-12

static void test_render_params_defaults(void **state) {
  (void)state;
  zr_render_params p;
  memset(&p, 0xff, sizeof p);
  zr_render_params_init(&p);
  assert_int_equal(p.width, 320);
  assert_int_equal(p.height, 240);
  assert_int_equal(p.antialias, 0);
  assert_near(p.aa_threshold, 0.3, 0);
  assert_int_equal(p.aa_depth, 3);
  assert_int_equal(p.jitter, 0);
  assert_near(p.jitter_amount, 1.0, 0);
}

static void test_render_stats_add(void **state) {
  (void)state;
  zr_render_stats a = {1, 2, 3, 4, 5, 6}, b = {10, 20, 30, 40, 50, 60};
  zr_render_stats_add(&a, &b);
  assert_true(a.camera_rays == 11 && a.supersample_rays == 22 &&
              a.reflected_rays == 33 && a.refracted_rays == 44 &&
              a.shadow_rays == 55 && a.supersampled_pixels == 66);
}

static void test_render_camera_ray_spans_right_and_up(void **state) {
  (void)state;
  zr_camera c;
  zr__camera_init(&c);
  /* The top left corner of the image and the centre of the last pixel of
     a 200 x 100 image: right stays 1.33 whatever the aspect (povray 3.7
     renders a sphere 62 pixels wide and 40 high at 200 x 100). */
  zr_ray r = zr__camera_ray(&c, 200, 100, 0, 0);
  assert_near(r.dir.x, -0.665, EPS);
  assert_near(r.dir.y, 0.5, EPS);
  assert_near(r.dir.z, 1.0, EPS);
  r = zr__camera_ray(&c, 200, 100, 199.5, 99.5);
  assert_near(r.dir.x, 1.33 * (199.5 / 200 - 0.5), EPS);
  assert_near(r.dir.y, 0.5 - 99.5 / 100, EPS);
}

static void test_render_colour_difference_is_gamma_adjusted(void **state) {
  (void)state;
  float a[3] = {0.5f, 0.0f, 1.0f}, b[3] = {0.25f, 2.0f, -1.0f};
  /* Exponent 1: plain sum of differences of values clipped to [0, 1]. */
  assert_near(zr__colour_difference(a, b, 1.0), 0.25 + 1.0 + 1.0, 1e-7);
  /* POV-Ray's antialias gamma 2.5 on linear values: v^(1/2.5). */
  float c[3] = {0.04f, 0.04f, 0.04f}, d[3] = {0, 0, 0};
  assert_near(zr__colour_difference(c, d, 1.0 / 2.5),
              3 * pow(0.04, 0.4), 1e-6);
}

static void test_render_hash_uniform_range_and_spread(void **state) {
  (void)state;
  double sum = 0;
  for (uint32_t i = 0; i < 10000; i++) {
    double u = zr__hash_uniform(i, i % 9, i % 2);
    assert_true(u >= 0.0 && u < 1.0);
    sum += u;
  }
  /* The mean of 10000 uniforms has standard deviation 0.0029. */
  assert_near(sum / 10000, 0.5, 0.015);
  assert_true(zr__hash_uniform(1, 2, 0) == zr__hash_uniform(1, 2, 0));
  assert_true(zr__hash_uniform(1, 2, 0) != zr__hash_uniform(2, 1, 0));
}

/* A lit sphere before a plane: plenty of edges for antialiasing. */
static zr_scene *edge_scene(void) {
  zr_scene *s = zr__scene_new();
  s->camera.location = zr_v3(0, 1, -5);
  zr_object *o = zr__arena_alloc(&s->arena, sizeof *o);
  o->kind = ZR_OBJ_SPHERE;
  o->u.sphere.radius = 1;
  zr_pigment *p = zr__arena_alloc(&s->arena, sizeof *p);
  zr__pigment_init(p);
  p->colour = zr_colour5(1, 0.5, 0.25, 0, 0);
  zr_finish *f = zr__arena_alloc(&s->arena, sizeof *f);
  zr__finish_init(f);
  f->phong = 0.8;
  zr_texture *t = zr__arena_alloc(&s->arena, sizeof *t);
  t->pigment = p;
  t->finish = f;
  o->texture = t;
  zr__scene_add_object(s, o);
  zr_object *pl = zr__arena_alloc(&s->arena, sizeof *pl);
  pl->kind = ZR_OBJ_PLANE;
  pl->u.plane.normal = zr_v3(0, 1, 0);
  pl->u.plane.distance = -1;
  zr__scene_add_object(s, pl);
  zr_light l = {0};
  l.location = zr_v3(3, 5, -6);
  l.colour = zr_rgb3(1, 1, 1);
  zr__scene_add_light(s, &l);
  s->settings.background = zr_colour5(0.2, 0.3, 0.6, 0, 0);
  assert_int_equal(zr__scene_finish(s, NULL), ZR_OK);
  return s;
}

/*
 * Rendering in interleaved pixel sets, in reverse order, one call per
 * set, gives the very same floats as one zr_render_image() call, with
 * antialiasing and jitter on.
 */
static void test_render_split_invariance_with_jitter(void **state) {
  (void)state;
  zr_scene *s = edge_scene();
  zr_render_params p;
  zr_render_params_init(&p);
  p.width = 48;
  p.height = 36;
  p.antialias = 1;
  p.jitter = 1;
  size_t n = (size_t)p.width * p.height;
  float *whole = malloc(n * 3 * sizeof *whole);
  float *centres = malloc(n * 3 * sizeof *centres);
  float *parts = malloc(n * 3 * sizeof *parts);
  uint32_t *set = malloc(n * sizeof *set);
  zr_render_stats st_whole = {0}, st_parts = {0};
  assert_int_equal(zr_render_image(s, &p, whole, &st_whole), ZR_OK);
  const int sets = 3;
  for (int pass = 0; pass < 2; pass++)
    for (int r = sets - 1; r >= 0; r--) {
      size_t m = 0;
      for (size_t i = n; i-- > 0;)
        if ((int)(i / p.width) % sets == r)
          set[m++] = (uint32_t)i;
      float *out = malloc(m * 3 * sizeof *out);
      assert_int_equal(zr_render_pixels(s, &p, set, m,
                                        pass ? centres : NULL, out,
                                        &st_parts),
                       ZR_OK);
      for (size_t k = 0; k < m; k++)
        memcpy((pass ? parts : centres) + 3 * (size_t)set[k], out + 3 * k,
               3 * sizeof *out);
      free(out);
    }
  assert_memory_equal(whole, parts, n * 3 * sizeof *whole);
  assert_true(st_whole.camera_rays == n && st_parts.camera_rays == n);
  assert_true(st_whole.supersampled_pixels > 0);
  assert_true(st_whole.supersampled_pixels == st_parts.supersampled_pixels);
  assert_true(st_whole.supersample_rays == 9 * st_whole.supersampled_pixels);
  /* Antialiasing changed some pixels and only those it supersampled. */
  size_t changed = 0;
  for (size_t i = 0; i < n; i++)
    changed += memcmp(whole + 3 * i, centres + 3 * i, 3 * sizeof *whole) != 0;
  assert_true(changed > 0 && changed <= st_whole.supersampled_pixels);
  free(whole);
  free(centres);
  free(parts);
  free(set);
  zr_scene_free(s);
}

typedef struct thread_part {
  const zr_scene *scene;
  const zr_render_params *params;
  const uint32_t *pixels;
  size_t count;
  const float *centres;
  float *rgb;
  zr_status status;
} thread_part;

static void *render_part(void *arg) {
  thread_part *t = arg;
  t->status = zr_render_pixels(t->scene, t->params, t->pixels, t->count,
                               t->centres, t->rgb, NULL);
  return NULL;
}

/* Four threads rendering interleaved pixels of one scene at once give
   the same floats as one thread: tracing shares no mutable state. */
static void test_render_threads_share_the_scene(void **state) {
  (void)state;
  zr_scene *s = edge_scene();
  zr_render_params p;
  zr_render_params_init(&p);
  p.width = 40;
  p.height = 30;
  p.antialias = 1;
  p.jitter = 1;
  size_t n = (size_t)p.width * p.height;
  float *whole = malloc(n * 3 * sizeof *whole);
  float *centres = malloc(n * 3 * sizeof *centres);
  float *parts = malloc(n * 3 * sizeof *parts);
  uint32_t *order = malloc(n * sizeof *order);
  assert_int_equal(zr_render_image(s, &p, whole, NULL), ZR_OK);
  /* Pixels k, k + 4, k + 8, ... go to thread k; each thread's output is
     contiguous, so the pixel lists are laid out thread by thread. */
  enum { THREADS = 4 };
  size_t per = n / THREADS;
  for (int k = 0; k < THREADS; k++)
    for (size_t i = 0; i < per; i++)
      order[k * per + i] = (uint32_t)(i * THREADS + k);
  for (int pass = 0; pass < 2; pass++) {
    pthread_t th[THREADS];
    thread_part part[THREADS];
    float *out = pass ? parts : centres;
    float *tmp = malloc(n * 3 * sizeof *tmp);
    for (int k = 0; k < THREADS; k++) {
      part[k] = (thread_part){s,           &p, order + k * per, per,
                              pass ? centres : NULL, tmp + 3 * k * per,
                              ZR_OK};
      assert_int_equal(pthread_create(&th[k], NULL, render_part, &part[k]),
                       0);
    }
    for (int k = 0; k < THREADS; k++) {
      pthread_join(th[k], NULL);
      assert_int_equal(part[k].status, ZR_OK);
    }
    for (size_t i = 0; i < n; i++)
      memcpy(out + 3 * (size_t)order[i], tmp + 3 * i, 3 * sizeof *tmp);
    free(tmp);
  }
  assert_memory_equal(whole, parts, n * 3 * sizeof *whole);
  free(whole);
  free(centres);
  free(parts);
  free(order);
  zr_scene_free(s);
}

static void test_render_threshold_controls_supersampling(void **state) {
  (void)state;
  zr_scene *s = edge_scene();
  zr_render_params p;
  zr_render_params_init(&p);
  p.width = 32;
  p.height = 24;
  p.antialias = 1;
  float *rgb = malloc((size_t)p.width * p.height * 3 * sizeof *rgb);
  zr_render_stats a = {0}, b = {0}, c = {0};
  p.aa_threshold = 3.0; /* no two colours differ by more */
  assert_int_equal(zr_render_image(s, &p, rgb, &a), ZR_OK);
  assert_true(a.supersampled_pixels == 0);
  p.aa_threshold = 0.3;
  assert_int_equal(zr_render_image(s, &p, rgb, &b), ZR_OK);
  p.aa_threshold = 0.0; /* any difference at all */
  assert_int_equal(zr_render_image(s, &p, rgb, &c), ZR_OK);
  assert_true(b.supersampled_pixels > 0);
  assert_true(c.supersampled_pixels > b.supersampled_pixels);
  free(rgb);
  zr_scene_free(s);
}

/* Which of the listed pixels pass 2 supersamples, given centres. */
static uint64_t supersampled(const zr_scene *s, const zr_render_params *p,
                             const float *centres, uint32_t pixel) {
  zr_render_stats st = {0};
  float rgb[3];
  assert_int_equal(zr_render_pixels(s, p, &pixel, 1, centres, rgb, &st),
                   ZR_OK);
  return st.supersampled_pixels;
}

/*
 * A black-to-white step between columns 31 and 32 lies on a border of
 * povray's 32 x 32 render blocks: column 32 sees its left neighbour
 * differ and is supersampled, column 31 is not (povray has finished its
 * block).  The same step inside a block supersamples both sides.
 */
static void test_render_antialias_pairs_and_block_borders(void **state) {
  (void)state;
  zr_scene *s = edge_scene();
  zr_render_params p;
  zr_render_params_init(&p);
  p.width = 64;
  p.height = 2;
  p.antialias = 1;
  float centres[64 * 2 * 3];
  for (int step = 32; step >= 20; step -= 12) {
    for (int i = 0; i < 64 * 2; i++)
      for (int k = 0; k < 3; k++)
        centres[3 * i + k] = (i % 64) < step ? 0.0f : 1.0f;
    assert_true(supersampled(s, &p, centres, (uint32_t)step) == 1);
    assert_true(supersampled(s, &p, centres, (uint32_t)step - 1) ==
                (step == 32 ? 0 : 1));
    assert_true(supersampled(s, &p, centres, (uint32_t)step + 1) == 0);
    assert_true(supersampled(s, &p, centres, (uint32_t)step - 2) == 0);
  }
  zr_scene_free(s);
}

static void test_render_rejects_bad_arguments(void **state) {
  (void)state;
  zr_scene *s = edge_scene();
  zr_render_params p;
  zr_render_params_init(&p);
  p.width = 4;
  p.height = 4;
  float rgb[3];
  uint32_t bad = 16, good = 15;
  assert_int_equal(zr_render_pixels(s, &p, &bad, 1, NULL, rgb, NULL),
                   ZR_EINVAL);
  assert_int_equal(zr_render_pixels(s, &p, &good, 1, NULL, NULL, NULL),
                   ZR_EINVAL);
  p.width = 0;
  assert_int_equal(zr_render_pixels(s, &p, &good, 1, NULL, rgb, NULL),
                   ZR_EINVAL);
  p.width = 4;
  p.antialias = 1;
  p.aa_depth = 10;
  assert_int_equal(zr_render_image(s, &p, NULL, NULL), ZR_EINVAL);
  assert_int_equal(zr_render_pixels(NULL, &p, &good, 1, NULL, rgb, NULL),
                   ZR_EINVAL);
  zr_scene_free(s);
  /* A scene never finished has no hierarchy to trace. */
  s = zr__scene_new();
  zr_object *o = zr__arena_alloc(&s->arena, sizeof *o);
  o->kind = ZR_OBJ_SPHERE;
  o->u.sphere.radius = 1;
  zr__scene_add_object(s, o);
  s->primitives = NULL;
  s->n_primitives = 1;
  zr_render_params_init(&p);
  assert_int_equal(zr_render_pixels(s, &p, &good, 1, NULL, rgb, NULL),
                   ZR_ESCENE);
  s->n_primitives = 0;
  zr_scene_free(s);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_render_params_defaults),
      cmocka_unit_test(test_render_stats_add),
      cmocka_unit_test(test_render_camera_ray_spans_right_and_up),
      cmocka_unit_test(test_render_colour_difference_is_gamma_adjusted),
      cmocka_unit_test(test_render_hash_uniform_range_and_spread),
      cmocka_unit_test(test_render_split_invariance_with_jitter),
      cmocka_unit_test(test_render_threads_share_the_scene),
      cmocka_unit_test(test_render_threshold_controls_supersampling),
      cmocka_unit_test(test_render_antialias_pairs_and_block_borders),
      cmocka_unit_test(test_render_rejects_bad_arguments),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
