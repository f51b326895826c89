/*
 * test_embree.c - the Embree backend for meshes (lib/trace/embree.c)
 * against the built-in hierarchy: the same scene parsed twice, once
 * with zr_context_set_accel(ZR_ACCEL_BUILTIN) and once with
 * ZR_ACCEL_EMBREE, and the same rays asked of both meshes.
 *
 * The backend only names candidate triangles and our double-precision
 * test decides, so a ray that finds the same face finds it at the same
 * t, bit for bit.  Where the two disagree the ray must pass within
 * single precision of an edge: both answers then lie at the same t
 * within 1e-6 relative (a neighbour across the edge), or one backend
 * misses a grazing ray; such rays are rare (at most 1 in 1000 of the
 * random rays here, bench/embree.sh found 2 to 13 in 512^2 camera
 * rays).  In a build without Embree only the status of
 * zr_context_set_accel is checked.
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

#include "config.h"
#include "core/strbuf.h"
#include "scene/scene.h"
#include "trace/embree.h"
#include "trace/obj_mesh.h"
#include "zrcube.h"

static void test_embree_set_accel(void **state) {
  (void)state;
  zr_context *ctx;
  assert_int_equal(zr_context_new(&ctx), ZR_OK);
  assert_int_equal(zr_context_set_accel(ctx, ZR_ACCEL_BUILTIN), ZR_OK);
  assert_int_equal(zr_context_set_accel(ctx, ZR_ACCEL_DEFAULT), ZR_OK);
#ifdef ZR_HAVE_EMBREE
  assert_int_equal(zr_context_set_accel(ctx, ZR_ACCEL_EMBREE), ZR_OK);
#else
  assert_int_equal(zr_context_set_accel(ctx, ZR_ACCEL_EMBREE),
                   ZR_EUNSUPPORTED);
#endif
  assert_int_equal(zr_context_set_accel(ctx, (zr_accel)7), ZR_EINVAL);
  zr_context_free(ctx);
}

#ifdef ZR_HAVE_EMBREE

static double next_uniform(uint64_t *seed) {
  *seed = *seed * 6364136223846793005ULL + 1442695040888963407ULL;
  return (double)(*seed >> 11) * (1.0 / 9007199254740992.0);
}

static double range(uint64_t *seed, double lo, double hi) {
  return lo + (hi - lo) * next_uniform(seed);
}

/* A closed-form terrain of (N-1)^2 quads, two flat triangles each, and
   a smooth bowl, in one mesh2 each, written as a scene. */
enum { N = 48 };

static double height(int i, int j) {
  return 0.6 * sin(0.37 * i) * cos(0.29 * j) + 0.05 * ((i * 7 + j * 3) % 5);
}

static char *terrain_scene(void) {
  zr_strbuf b;
  zr__strbuf_init(&b);
  zr__strbuf_puts(&b, "mesh2 { vertex_vectors { ");
  zr__strbuf_printf(&b, "%d", N * N);
  for (int j = 0; j < N; j++)
    for (int i = 0; i < N; i++)
      zr__strbuf_printf(&b, ", <%d, %.17g, %d>", i - N / 2, height(i, j),
                        j - N / 2);
  zr__strbuf_printf(&b, " }\n face_indices { %d", 2 * (N - 1) * (N - 1));
  for (int j = 0; j + 1 < N; j++)
    for (int i = 0; i + 1 < N; i++) {
      int a = j * N + i, c = a + N;
      zr__strbuf_printf(&b, ", <%d,%d,%d>, <%d,%d,%d>", a, a + 1, c + 1, a,
                        c + 1, c);
    }
  zr__strbuf_puts(&b, " }\n pigment { rgb 1 } }\n");
  assert_false(b.failed);
  return zr__strbuf_take(&b);
}

/* The scene's one mesh, parsed with the given backend. */
static zr_scene *parse_with(zr_context *ctx, zr_accel accel,
                            const char *text) {
  assert_int_equal(zr_context_set_accel(ctx, accel), ZR_OK);
  zr_scene *s = NULL;
  assert_int_equal(
      zr_scene_parse_string(ctx, "<terrain>", text, strlen(text), &s),
      ZR_OK);
  assert_int_equal(s->n_primitives, 1);
  assert_int_equal(s->primitives[0]->kind, ZR_OBJ_MESH);
  return s;
}

typedef struct pair {
  zr_context *ctx;
  zr_scene *builtin, *embree;
  const struct zr_mesh *a, *b; /* builtin's mesh, Embree's */
} pair;

static int setup_pair(void **state) {
  static pair p;
  char *text = terrain_scene();
  assert_int_equal(zr_context_new(&p.ctx), ZR_OK);
  p.builtin = parse_with(p.ctx, ZR_ACCEL_BUILTIN, text);
  p.embree = parse_with(p.ctx, ZR_ACCEL_EMBREE, text);
  free(text);
  p.a = p.builtin->primitives[0]->u.mesh.data;
  p.b = p.embree->primitives[0]->u.mesh.data;
  assert_null(p.a->accel);
  assert_non_null(p.b->accel);
  *state = &p;
  return 0;
}

static int teardown_pair(void **state) {
  pair *p = *state;
  zr_scene_free(p->builtin);
  zr_scene_free(p->embree);
  zr_context_free(p->ctx);
  return 0;
}

/* Rays from above the terrain towards it, from beside it (grazing) and
   from under it up through it. */
static void random_ray(uint64_t *seed, zr_vec3 *org, zr_vec3 *dir) {
  double e = N / 2.0;
  *org = zr_v3(range(seed, -e, e), range(seed, -3, 8), range(seed, -e, e));
  zr_vec3 to = zr_v3(range(seed, -e, e), range(seed, -1, 1),
                     range(seed, -e, e));
  *dir = zr_v3_sub(to, *org);
}

static bool near_t(double a, double b) {
  return fabs(a - b) <= 1e-6 * fmax(1.0, fabs(a));
}

enum { RAYS = 20000 };

/* The nearest crossing: the same face at the same t and normal, or
   (rarely) a tie across an edge or a grazing miss. */
static void test_embree_nearest_matches(void **state) {
  pair *p = *state;
  uint64_t seed = 12345;
  int differ = 0, hits = 0;
  for (int r = 0; r < RAYS; r++) {
    zr_vec3 org, dir;
    random_ray(&seed, &org, &dir);
    double tmin = r % 3 ? 1e-6 : range(&seed, 0, 0.5);
    zr_mesh_crossing ca, cb;
    int na = zr__mesh_nearest(p->a, org, dir, tmin, INFINITY, &ca);
    int nb = zr__mesh_nearest(p->b, org, dir, tmin, INFINITY, &cb);
    hits += na;
    if (na == nb && (!na || ca.face == cb.face)) {
      if (na) {
        assert_true(ca.t == cb.t);
        assert_true(ca.u == cb.u && ca.v == cb.v);
        assert_true(ca.normal.x == cb.normal.x &&
                    ca.normal.y == cb.normal.y &&
                    ca.normal.z == cb.normal.z);
      }
      continue;
    }
    differ++;
    if (na && nb)
      assert_true(near_t(ca.t, cb.t));
  }
  /* The rays must mostly hit for the comparison to mean anything. */
  assert_true(hits > RAYS / 2);
  print_message("nearest: %d of %d rays (%d hits) differ\n", differ, RAYS,
                hits);
  if (differ > RAYS / 1000)
    fail_msg("%d of %d rays found another nearest crossing", differ, RAYS);
}

/* The nearest two (shadow rays, CSG): the same faces in the same order,
   or ties and grazing rays as above. */
static void test_embree_crossings_match(void **state) {
  pair *p = *state;
  uint64_t seed = 777;
  int differ = 0, twos = 0;
  for (int r = 0; r < RAYS; r++) {
    zr_vec3 org, dir;
    random_ray(&seed, &org, &dir);
    zr_mesh_crossing ca[2], cb[2];
    int na = zr__mesh_crossings(p->a, org, dir, 1e-6, INFINITY, ca);
    int nb = zr__mesh_crossings(p->b, org, dir, 1e-6, INFINITY, cb);
    twos += na == 2;
    bool same = na == nb;
    for (int i = 0; same && i < na; i++)
      same = ca[i].face == cb[i].face && ca[i].t == cb[i].t;
    if (same)
      continue;
    differ++;
    for (int i = 0; i < na && i < nb; i++)
      assert_true(near_t(ca[i].t, cb[i].t));
  }
  assert_true(twos > RAYS / 20);
  print_message("nearest two: %d of %d rays differ\n", differ, RAYS);
  if (differ > RAYS / 1000)
    fail_msg("%d of %d rays found other crossings", differ, RAYS);
}

/* The rays handed back to the hierarchy (a candidate near an edge) must
   be rare, or the backend would cost more than it saves: under 1%. */
static void test_embree_few_handed_back(void **state) {
  pair *p = *state;
  uint64_t seed = 4242;
  int back = 0;
  for (int r = 0; r < RAYS; r++) {
    zr_vec3 org, dir;
    random_ray(&seed, &org, &dir);
    zr_mesh_raw_hit h, two[2];
    back += zr__embree_nearest(p->b, org, dir, 1e-6, INFINITY, &h) < 0;
    back += zr__embree_crossings(p->b, org, dir, 1e-6, INFINITY, two) < 0;
  }
  print_message("handed back: %d of %d queries\n", back, 2 * RAYS);
  assert_true(back < 2 * RAYS / 100);
}

/* A short interval around a crossing (how the tracer asks for the
   winner's normal, lib/trace/bvh.c) finds it again despite Embree's
   single precision; a negative tmin is the built-in search's. */
static void test_embree_narrow_interval(void **state) {
  pair *p = *state;
  uint64_t seed = 99;
  int found = 0, asked = 0;
  for (int r = 0; r < 2000; r++) {
    zr_vec3 org, dir;
    random_ray(&seed, &org, &dir);
    zr_mesh_crossing c, d[2];
    if (!zr__mesh_nearest(p->a, org, dir, 1e-6, INFINITY, &c))
      continue;
    asked++;
    double margin = 1e-9 * fmax(1.0, c.t);
    int n = zr__mesh_crossings(p->b, org, dir, c.t - margin, c.t + margin,
                               d);
    found += n >= 1 && d[0].t == c.t;
    zr_mesh_crossing ea[2], eb[2];
    int na = zr__mesh_crossings(p->a, org, dir, -1.0, INFINITY, ea);
    int nb = zr__mesh_crossings(p->b, org, dir, -1.0, INFINITY, eb);
    assert_int_equal(na, nb);
    for (int i = 0; i < na; i++)
      assert_true(ea[i].t == eb[i].t && ea[i].face == eb[i].face);
  }
  assert_true(asked > 1000);
  if (found < asked - asked / 500)
    fail_msg("%d of %d crossings found again", found, asked);
}

#endif /* ZR_HAVE_EMBREE */

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_embree_set_accel),
  };
  int failed = cmocka_run_group_tests(tests, NULL, NULL);
#ifdef ZR_HAVE_EMBREE
  const struct CMUnitTest pair_tests[] = {
      cmocka_unit_test(test_embree_nearest_matches),
      cmocka_unit_test(test_embree_crossings_match),
      cmocka_unit_test(test_embree_narrow_interval),
      cmocka_unit_test(test_embree_few_handed_back),
  };
  failed += cmocka_run_group_tests(pair_tests, setup_pair, teardown_pair);
#endif
  return failed;
}
