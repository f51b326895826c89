/*
 * test_api.c - the public API's contracts (issue 14), through the shared
 * library's exported symbols only: zr_render_image with threads (the same
 * bytes as one thread), progress in every phase, cancel (a distinct
 * status, promptly, nothing leaked: the ASan build runs this too), the
 * size member of parameter structs, and the byte offset and span of a
 * diagnostic.
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
#include <time.h>

#include "zrcube.h"

/* A scene with reflection, refraction and antialiasing edges, so that
   rows differ in cost and a thread mix-up would show. */
static const char SCENE[] =
    "camera { location <0, 1, -5> look_at <0, 0.5, 0> }\n"
    "light_source { <4, 6, -5> rgb 1 }\n"
    "plane { y, 0 pigment { checker rgb 1 rgb 0.2 } "
    "finish { reflection 0.3 } }\n"
    "sphere { <-1, 1, 0>, 1 pigment { rgbf <1, 1, 1, 0.9> } "
    "interior { ior 1.5 } }\n"
    "sphere { <1.2, 0.7, 1>, 0.7 pigment { rgb <1, 0.3, 0.2> } "
    "finish { phong 1 } }\n";

static zr_scene *parse(zr_context *ctx, const char *text) {
  zr_scene *scene = NULL;
  assert_int_equal(
      zr_scene_parse_string(ctx, "<test>", text, strlen(text), &scene),
      ZR_OK);
  return scene;
}

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* What a progress callback saw. */
typedef struct seen {
  int calls;
  zr_phase phase;
  uint64_t last_done, last_total;
  int went_back;    /* done fell, or passed total */
  int wrong_phase;
  /* Cancel when done reaches this fraction of total (0: never), or at
     the first call of cancel_phase when cancel_at_first is set. */
  double cancel_fraction;
  int cancel_at_first;
  int cancelled;
  double cancelled_at;
} seen;

static int watch(const zr_progress *p, void *user) {
  seen *s = user;
  if (s->calls > 0 && p->phase == s->phase && p->done < s->last_done)
    s->went_back = 1;
  if (p->total && p->done > p->total)
    s->went_back = 1;
  if (p->phase != s->phase)
    s->wrong_phase = 1;
  s->calls++;
  s->last_done = p->done;
  s->last_total = p->total;
  int stop = s->cancel_at_first ||
             (s->cancel_fraction > 0 && p->total &&
              p->done >= s->cancel_fraction * (double)p->total);
  if (stop && !s->cancelled) {
    s->cancelled = 1;
    s->cancelled_at = now();
  }
  return stop;
}

static void render(const zr_scene *scene, zr_context *ctx, int threads,
                   int antialias, float *rgb, zr_render_stats *stats) {
  zr_render_params p;
  zr_render_params_init(&p);
  p.width = 64;
  p.height = 48;
  p.antialias = antialias;
  p.threads = threads;
  p.context = ctx;
  memset(stats, 0, sizeof *stats);
  assert_int_equal(zr_render_image(scene, &p, rgb, stats), ZR_OK);
}

static void test_api_threads_same_bytes(void **state) {
  (void)state;
  zr_scene *scene = parse(NULL, SCENE);
  size_t n = 64 * 48 * 3;
  float *one = malloc(n * sizeof *one), *four = malloc(n * sizeof *four);
  assert_non_null(one);
  assert_non_null(four);
  for (int aa = 0; aa <= 1; aa++) {
    zr_render_stats s1, s4;
    render(scene, NULL, 1, aa, one, &s1);
    render(scene, NULL, 4, aa, four, &s4);
    assert_memory_equal(one, four, n * sizeof *one);
    assert_memory_equal(&s1, &s4, sizeof s1);
    assert_int_equal(s1.camera_rays, 64 * 48);
    if (aa)
      assert_true(s1.supersampled_pixels > 0);
  }
  free(one);
  free(four);
  zr_scene_free(scene);
}

/* +UA through the API (alpha = 1): 4 floats a pixel, the colour with the
   background clear and the alpha, as povray 3.7 makes them (measured:
   tests/test_alpha_povray.sh): in a scene without #version the
   background is clear and black, transmit 0.5 leaves half the pixel
   clear, filter lets through its grey (0.297 r + 0.589 g + 0.114 b) of
   it, an opaque surface keeps the colour of a render without alpha;
   with #version 3.7 an opaque background colour is opaque. */
static void test_api_alpha(void **state) {
  (void)state;
  static const char legacy[] =
      "camera { location <0, 0, -4> look_at 0 }\n"
      "light_source { <5, 5, -5> rgb 1 }\n"
      "background { rgb <0.2, 0.4, 0.8> }\n"
      "sphere { 0, 0.5 pigment { rgb <1, 0.5, 0.2> } }\n"
      "disc { <-1, 0, 0>, -z, 0.4 pigment { rgbt <0, 0, 1, 0.5> } "
      "finish { ambient 1 diffuse 0 } }\n"
      "disc { <1, 0, 0>, -z, 0.4 pigment { rgbf <1, 0, 0, 1> } "
      "finish { ambient 0 diffuse 0 } }\n";
  zr_scene *scene = parse(NULL, legacy);
  enum { W = 40, H = 30 };
  float *rgba = malloc(W * H * 4 * sizeof *rgba);
  float *other = malloc(W * H * 4 * sizeof *other);
  float *rgb = malloc(W * H * 3 * sizeof *rgb);
  assert_non_null(rgba);
  assert_non_null(other);
  assert_non_null(rgb);
  zr_render_params p;
  zr_render_params_init(&p);
  assert_int_equal(p.alpha, 0);
  p.width = W;
  p.height = H;
  assert_int_equal(zr_render_image(scene, &p, rgb, NULL), ZR_OK);
  p.alpha = 1;
  assert_int_equal(zr_render_image(scene, &p, rgba, NULL), ZR_OK);
  const float *corner = rgba, *mid = rgba + 4 * (15 * W + 20);
  assert_true(corner[0] == 0 && corner[1] == 0 && corner[2] == 0 &&
              corner[3] == 0);
  assert_true(mid[3] == 1.0f);
  assert_memory_equal(mid, rgb + 3 * (15 * W + 20), 3 * sizeof *mid);
  /* The discs' centres: x = +-1 at z = 0 is pixel 20 +- 7.5. */
  const float *blue = rgba + 4 * (15 * W + 12), *red = rgba + 4 * (15 * W + 27);
  assert_float_equal(blue[3], 0.5, 1e-6);
  assert_float_equal(blue[2], 0.5, 1e-6);
  assert_float_equal(red[3], 1.0 - 0.297, 1e-6);
  assert_float_equal(red[0], 0.0, 1e-6);
  /* The same bytes with threads and antialiasing. */
  p.antialias = 1;
  p.aa_threshold = 0.1;
  assert_int_equal(zr_render_image(scene, &p, rgba, NULL), ZR_OK);
  p.threads = 3;
  assert_int_equal(zr_render_image(scene, &p, other, NULL), ZR_OK);
  assert_memory_equal(rgba, other, W * H * 4 * sizeof *rgba);
  zr_scene_free(scene);
  /* #version 3.7: the background's own colour, opaque. */
  char modern[sizeof legacy + 32];
  snprintf(modern, sizeof modern, "#version 3.7;\n%s", legacy);
  scene = parse(NULL, modern);
  p.antialias = 0;
  p.threads = 1;
  p.alpha = 0;
  assert_int_equal(zr_render_image(scene, &p, rgb, NULL), ZR_OK);
  p.alpha = 1;
  assert_int_equal(zr_render_image(scene, &p, rgba, NULL), ZR_OK);
  assert_float_equal(rgba[3], 1.0, 0);
  assert_memory_equal(rgba, rgb, 3 * sizeof *rgba);
  p.alpha = 2;
  assert_int_equal(zr_render_image(scene, &p, rgba, NULL), ZR_EINVAL);
  zr_scene_free(scene);
  free(rgba);
  free(other);
  free(rgb);
}

/* quality 0 and 1 show each surface's colour unlit (the bottom layer of
   a layered texture), quick_color replaces the pigment up to quality 5
   (measured against povray: tests/test_quality.sh, quick.pov). */
static void test_api_quick_colours(void **state) {
  (void)state;
  static const char text[] =
      "camera { location <0, 0, -4> look_at 0 }\n"
      "light_source { <5, 5, -5> rgb 1 }\n"
      "sphere { <-1, 0, 0>, 0.6 pigment { gradient x color_map "
      "{ [0 rgb 1] [1 rgb 0] } quick_color rgb <1, 0.2, 0.6> } }\n"
      "sphere { <1, 0, 0>, 0.6 texture { pigment { rgb <0.5, 0.25, 1> } "
      "finish { ambient 0.3 } } texture { pigment { rgbt <0, 1, 0, 0.5> } "
      "} }\n";
  zr_scene *scene = parse(NULL, text);
  enum { W = 40, H = 30 };
  float rgb[W * H * 3];
  zr_render_params p;
  zr_render_params_init(&p);
  p.width = W;
  p.height = H;
  const float *quick = rgb + 3 * (15 * W + 12);
  const float *layered = rgb + 3 * (15 * W + 27);
  for (int q = 0; q <= 1; q++) {
    p.quality = q;
    assert_int_equal(zr_render_image(scene, &p, rgb, NULL), ZR_OK);
    assert_float_equal(quick[0], 1.0, 1e-6);
    assert_float_equal(quick[1], 0.2, 1e-6);
    assert_float_equal(quick[2], 0.6, 1e-6);
    assert_float_equal(layered[0], 0.5, 1e-6);
    assert_float_equal(layered[1], 0.25, 1e-6);
    assert_float_equal(layered[2], 1.0, 1e-6);
  }
  /* Lit from quality 2; the quick colour's hue up to 5, not from 6. */
  p.quality = 5;
  assert_int_equal(zr_render_image(scene, &p, rgb, NULL), ZR_OK);
  assert_true(quick[0] < 1.0f && quick[0] > 0.0f);
  assert_float_equal(quick[1] / quick[0], 0.2, 1e-4);
  p.quality = 6;
  assert_int_equal(zr_render_image(scene, &p, rgb, NULL), ZR_OK);
  assert_true(fabs(quick[1] / quick[0] - 0.2) > 0.1);
  zr_scene_free(scene);
}

static void test_api_render_progress(void **state) {
  (void)state;
  zr_context *ctx = NULL;
  assert_int_equal(zr_context_new(&ctx), ZR_OK);
  zr_scene *scene = parse(ctx, SCENE);
  float *rgb = malloc(64 * 48 * 3 * sizeof *rgb);
  assert_non_null(rgb);
  for (int threads = 1; threads <= 3; threads += 2) {
    seen s = {0};
    s.phase = ZR_PHASE_RENDER;
    zr_context_set_progress(ctx, watch, &s);
    zr_render_stats st;
    render(scene, ctx, threads, 1, rgb, &st);
    /* Two passes of 48 rows: the last call says all are done. */
    assert_int_equal(s.last_total, 96);
    assert_int_equal(s.last_done, 96);
    assert_false(s.went_back);
    assert_false(s.wrong_phase);
    assert_true(s.calls >= 2);
  }
  free(rgb);
  zr_scene_free(scene);
  zr_context_free(ctx);
}

/*
 * Cancel at 30% of a render of 4 threads: ZR_ECANCELLED, within a row
 * of each thread.  The bound, 2 s, is many times a 320-pixel row of
 * this scene (about a millisecond unloaded) and allows for a loaded
 * machine; a render that ran on would take the remaining 70% of a
 * 320 x 960 antialiased image, far longer.
 */
static void test_api_render_cancel(void **state) {
  (void)state;
  zr_context *ctx = NULL;
  assert_int_equal(zr_context_new(&ctx), ZR_OK);
  zr_scene *scene = parse(ctx, SCENE);
  zr_render_params p;
  zr_render_params_init(&p);
  p.width = 320;
  p.height = 960;
  p.antialias = 1;
  p.threads = 4;
  p.context = ctx;
  float *rgb = malloc((size_t)p.width * p.height * 3 * sizeof *rgb);
  assert_non_null(rgb);
  seen s = {0};
  s.phase = ZR_PHASE_RENDER;
  s.cancel_fraction = 0.3;
  zr_context_set_progress(ctx, watch, &s);
  double start = now();
  assert_int_equal(zr_render_image(scene, &p, rgb, NULL), ZR_ECANCELLED);
  double end = now();
  assert_true(s.cancelled);
  assert_true(end - s.cancelled_at < 2.0);
  /* It stopped near where it was told: no more than a row per thread
     was reported after the cancel. */
  assert_true(s.last_done <= (uint64_t)(0.3 * 2 * p.height) + 1 + 4);
  (void)start;
  /* zr_context_cancel: the next call stops at once; withdrawn, it runs. */
  zr_context_set_progress(ctx, NULL, NULL);
  zr_context_cancel(ctx, 1);
  assert_int_equal(zr_render_image(scene, &p, rgb, NULL), ZR_ECANCELLED);
  zr_context_cancel(ctx, 0);
  p.width = 32;
  p.height = 24;
  assert_int_equal(zr_render_image(scene, &p, rgb, NULL), ZR_OK);
  free(rgb);
  zr_scene_free(scene);
  zr_context_free(ctx);
}

/* What diagnostics said, for the cancel and offset tests. */
typedef struct heard {
  int errors;
  zr_status status;
  char message[256];
  size_t offset, length;
  int line, column;
} heard;

static void listen(const zr_diag *d, void *user) {
  heard *h = user;
  if (d->level != ZR_DIAG_ERROR)
    return;
  h->errors++;
  h->status = d->status;
  snprintf(h->message, sizeof h->message, "%s", d->message);
  h->offset = d->offset;
  h->length = d->length;
  h->line = d->line;
  h->column = d->column;
}

static void test_api_parse_progress_and_cancel(void **state) {
  (void)state;
  const char *loop = "#declare I = 0;\n"
                     "#while (I < 100000)\n"
                     "  #declare I = I + 1;\n"
                     "#end\n"
                     "sphere { 0, 1 pigment { rgb 1 } }\n";
  zr_context *ctx = NULL;
  assert_int_equal(zr_context_new(&ctx), ZR_OK);
  heard h = {0};
  zr_context_set_diag(ctx, listen, &h);
  seen s = {0};
  s.phase = ZR_PHASE_PARSE;
  zr_context_set_progress(ctx, watch, &s);
  zr_scene *scene = parse(ctx, loop);
  /* About 1.1 million tokens: a call per 4096. */
  assert_true(s.calls > 100);
  assert_int_equal(s.last_total, 0);
  assert_false(s.went_back);
  assert_false(s.wrong_phase);
  zr_scene_free(scene);
  /* Cancelled at the first report: ZR_ECANCELLED, no scene, one error
     that says so. */
  seen c = {0};
  c.phase = ZR_PHASE_PARSE;
  c.cancel_at_first = 1;
  zr_context_set_progress(ctx, watch, &c);
  scene = NULL;
  assert_int_equal(
      zr_scene_parse_string(ctx, "<loop>", loop, strlen(loop), &scene),
      ZR_ECANCELLED);
  assert_null(scene);
  assert_int_equal(c.calls, 1);
  assert_int_equal(h.errors, 1);
  assert_int_equal(h.status, ZR_ECANCELLED);
  assert_string_equal(h.message, "the parse was cancelled");
  assert_string_equal(zr_status_str(ZR_ECANCELLED),
                      "cancelled by the caller");
  zr_context_free(ctx);
}

#define ROOM                                                             \
  "global_settings { radiosity { } }\n"                                  \
  "camera { location <0, 1, -2.5> look_at <0, 1, 0> }\n"                 \
  "box { <-1, 0, -1>, <1, 2, 1> pigment { rgb 0.7 } }\n"                 \
  "box { <-0.3, 1.95, -0.3>, <0.3, 1.99, 0.3> pigment { rgb 1 } "        \
  "finish { emission 5 } }\n"

static void test_api_radiosity_progress_and_cancel(void **state) {
  (void)state;
  zr_context *ctx = NULL;
  assert_int_equal(zr_context_new(&ctx), ZR_OK);
  heard h = {0};
  zr_context_set_diag(ctx, listen, &h);
  zr_scene *scene = parse(ctx, ROOM);
  zr_radiosity_params rp;
  zr_radiosity_params_init(&rp, scene);
  rp.bf_eps = 1e-2;
  rp.refine_rounds = 2;
  seen s = {0};
  s.phase = ZR_PHASE_RADIOSITY;
  zr_context_set_progress(ctx, watch, &s);
  zr_radiosity *rad = NULL;
  assert_int_equal(zr_radiosity_solve(ctx, scene, &rp, &rad), ZR_OK);
  assert_non_null(rad);
  assert_true(s.calls >= 2);
  assert_int_equal(s.last_total, 3);
  assert_false(s.went_back);
  assert_false(s.wrong_phase);
  zr_radiosity_free(rad);
  /* Cancelled after its first round. */
  seen c = {0};
  c.phase = ZR_PHASE_RADIOSITY;
  c.cancel_fraction = 1e-9; /* at the first call whose done is > 0 */
  zr_context_set_progress(ctx, watch, &c);
  rad = NULL;
  assert_int_equal(zr_radiosity_solve(ctx, scene, &rp, &rad),
                   ZR_ECANCELLED);
  assert_null(rad);
  assert_int_equal(h.status, ZR_ECANCELLED);
  assert_string_equal(h.message, "radiosity: the solve was cancelled");
  /* And a struct that zr_radiosity_params_init() did not make. */
  zr_context_set_progress(ctx, NULL, NULL);
  rp.size = 0;
  assert_int_equal(zr_radiosity_solve(ctx, scene, &rp, &rad), ZR_EINVAL);
  zr_scene_free(scene);
  zr_context_free(ctx);
}

static void test_api_pretrace_progress_and_cancel(void **state) {
  (void)state;
  zr_context *ctx = NULL;
  assert_int_equal(zr_context_new(&ctx), ZR_OK);
  zr_scene *scene = parse(ctx, ROOM);
  zr_render_params p;
  zr_render_params_init(&p);
  p.width = 40;
  p.height = 30;
  p.context = ctx;
  seen s = {0};
  s.phase = ZR_PHASE_PRETRACE;
  zr_context_set_progress(ctx, watch, &s);
  zr_gi_cache *cache = NULL;
  assert_int_equal(zr_gi_cache_new(ctx, scene, NULL, &cache), ZR_OK);
  assert_int_equal(zr_gi_cache_pretrace(cache, &p), ZR_OK);
  assert_true(s.calls >= 2);
  assert_true(s.last_total > 40 * 30);
  assert_int_equal(s.last_done, s.last_total);
  assert_false(s.went_back);
  zr_gi_cache_free(cache);
  seen c = {0};
  c.phase = ZR_PHASE_PRETRACE;
  c.cancel_at_first = 1;
  zr_context_set_progress(ctx, watch, &c);
  assert_int_equal(zr_gi_cache_new(ctx, scene, NULL, &cache), ZR_OK);
  assert_int_equal(zr_gi_cache_pretrace(cache, &p), ZR_ECANCELLED);
  assert_int_equal(c.calls, 1);
  zr_gi_cache_free(cache);
  zr_scene_free(scene);
  zr_context_free(ctx);
}

/* The size member: 0 is refused, members past the library's struct
   must be zero, a smaller (older) struct is not accepted below the
   first release's size. */
static void test_api_params_size(void **state) {
  (void)state;
  zr_scene *scene = parse(NULL, SCENE);
  float rgb[8 * 6 * 3];
  zr_render_params p;
  zr_render_params_init(&p);
  assert_int_equal(p.size, sizeof p);
  assert_int_equal(p.threads, 1);
  assert_null(p.context);
  p.width = 8;
  p.height = 6;
  assert_int_equal(zr_render_image(scene, &p, rgb, NULL), ZR_OK);
  p.size = 0;
  assert_int_equal(zr_render_image(scene, &p, rgb, NULL), ZR_EINVAL);
  uint32_t px = 0;
  assert_int_equal(zr_render_pixels(scene, &p, &px, 1, NULL, rgb, NULL),
                   ZR_EINVAL);
  /* A newer caller's struct: larger, its extra members zero. */
  struct {
    zr_render_params p;
    int future;
  } newer;
  memset(&newer, 0, sizeof newer);
  zr_render_params_init(&newer.p);
  newer.p.size = sizeof newer;
  newer.p.width = 8;
  newer.p.height = 6;
  assert_int_equal(zr_render_image(scene, &newer.p, rgb, NULL), ZR_OK);
  newer.future = 1;
  assert_int_equal(zr_render_image(scene, &newer.p, rgb, NULL), ZR_EINVAL);
  p.size = sizeof p;
  p.threads = -1;
  assert_int_equal(zr_render_image(scene, &p, rgb, NULL), ZR_EINVAL);
  zr_gi_params gp;
  zr_gi_params_init(&gp, scene);
  assert_int_equal(gp.size, sizeof gp);
  gp.size = 0;
  zr_gi_cache *cache = NULL;
  assert_int_equal(zr_gi_cache_new(NULL, scene, &gp, &cache), ZR_EINVAL);
  assert_null(cache);
  zr_radiosity_params rp;
  zr_radiosity_params_init(&rp, NULL);
  assert_int_equal(rp.size, sizeof rp);
  assert_int_equal(rp.criterion, ZR_RAD_CRITERION_BF);
  assert_int_equal(rp.lookup, ZR_RAD_LOOKUP_GATHER);
  assert_int_equal(rp.shooting, ZR_RAD_GATHERING);
  zr_scene_free(scene);
}

/* zr_diag.offset and .length: the byte offset of line:column and the
   token's bytes. */
static void test_api_diag_offset(void **state) {
  (void)state;
  const char *text = "sphere { 0, 1 }\n"
                     "// a comment\n"
                     "box { 0, 1 } wibble\n";
  zr_context *ctx = NULL;
  assert_int_equal(zr_context_new(&ctx), ZR_OK);
  heard h = {0};
  zr_context_set_diag(ctx, listen, &h);
  zr_scene *scene = NULL;
  assert_int_not_equal(
      zr_scene_parse_string(ctx, "<t>", text, strlen(text), &scene), ZR_OK);
  assert_int_equal(h.errors, 1);
  assert_int_equal(h.line, 3);
  assert_int_equal(h.column, 14);
  const char *at = strstr(text, "wibble");
  assert_int_equal(h.offset, (size_t)(at - text));
  assert_int_equal(h.length, 6);
  zr_context_free(ctx);
}

/* zr_render_image says why it refuses through params.context, and
   that it was cancelled. */
static void test_api_render_diagnostics(void **state) {
  (void)state;
  zr_context *ctx = NULL;
  assert_int_equal(zr_context_new(&ctx), ZR_OK);
  heard h = {0};
  zr_context_set_diag(ctx, listen, &h);
  zr_scene *scene = parse(ctx, SCENE);
  float rgb[3];
  zr_render_params p;
  zr_render_params_init(&p);
  p.context = ctx;
  p.width = 0;
  assert_int_equal(zr_render_image(scene, &p, rgb, NULL), ZR_EINVAL);
  assert_int_equal(h.errors, 1);
  assert_string_equal(h.message, "render: the image size must be at least "
                                 "1 x 1 and at most 2^32 pixels");
  p.width = p.height = 1;
  zr_context_cancel(ctx, 1);
  assert_int_equal(zr_render_image(scene, &p, rgb, NULL), ZR_ECANCELLED);
  zr_context_cancel(ctx, 0);
  p.threads = 2;
  seen s = {0};
  s.phase = ZR_PHASE_RENDER;
  s.cancel_at_first = 1;
  zr_context_set_progress(ctx, watch, &s);
  assert_int_equal(zr_render_image(scene, &p, rgb, NULL), ZR_ECANCELLED);
  assert_int_equal(h.status, ZR_ECANCELLED);
  assert_string_equal(h.message, "render: cancelled");
  zr_scene_free(scene);
  zr_context_free(ctx);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_api_threads_same_bytes),
      cmocka_unit_test(test_api_render_progress),
      cmocka_unit_test(test_api_render_cancel),
      cmocka_unit_test(test_api_parse_progress_and_cancel),
      cmocka_unit_test(test_api_radiosity_progress_and_cancel),
      cmocka_unit_test(test_api_pretrace_progress_and_cancel),
      cmocka_unit_test(test_api_params_size),
      cmocka_unit_test(test_api_diag_offset),
      cmocka_unit_test(test_api_render_diagnostics),
      cmocka_unit_test(test_api_alpha),
      cmocka_unit_test(test_api_quick_colours),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
