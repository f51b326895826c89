/*
 * test_mesh.c - mesh, mesh2 and smooth_triangle: parsing (the fast
 * reader and the grammar giving the same mesh), the inner BVH against a
 * brute-force search, smooth normals, texture lists, inside_vector,
 * shared instances, and the messages for broken lists.
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
#include "core/arena.h"
#include "core/strbuf.h"
#include "scene/scene.h"
#include "trace/bvh.h"
#include "trace/bvh_wide.h"
#include "trace/intersect.h"
#include "trace/obj_mesh.h"
#include "zrcube.h"
#include "parse_fixture.h"
#include "test_util.h"

/* Hits are computed from small whole-number vertices by a few products:
   1e-9 leaves room for rounding and catches any real mistake. */
#define EPS 1e-9

static const struct zr_mesh *only_mesh(const zr_scene *s) {
  assert_int_equal(s->n_primitives, 1);
  assert_int_equal(s->primitives[0]->kind, ZR_OBJ_MESH);
  return s->primitives[0]->u.mesh.data;
}

/* A unit square at z = 1 in two triangles. */
#define SQUARE_MESH2                                                       \
  "mesh2 {\n"                                                              \
  "  vertex_vectors { 4, <0,0,1>, <1,0,1>, <1,1,1>, <0,1,1> }\n"           \
  "  face_indices { 2, <0,1,2>, <0,2,3> }\n"                               \
  "  pigment { rgb 1 }\n"                                                  \
  "}\n"

static void test_mesh_mesh2_hit(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, SQUARE_MESH2);
  const struct zr_mesh *m = only_mesh(s);
  assert_int_equal(m->n_vertices, 4);
  assert_int_equal(m->n_faces, 2);
  zr_ray ray = {zr_v3(0.25, 0.5, 0), zr_v3(0, 0, 2)};
  zr_hit hit;
  assert_true(zr__bvh_nearest(s->bvh, &ray, 0, INFINITY, &hit));
  assert_near(hit.t, 0.5, EPS);
  assert_near(fabs(hit.normal.z), 1.0, EPS);
  zr_ray miss = {zr_v3(1.5, 0.5, 0), zr_v3(0, 0, 1)};
  assert_false(zr__bvh_nearest(s->bvh, &miss, 0, INFINITY, &hit));
}

/* The same vertices written so that the grammar must read some items
   (an identifier, an expression, a directive between items) give the
   same mesh as the plain numbers the fast reader takes. */
static void test_mesh_fast_and_grammar_agree(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "#declare One = 1;\n"
                        "mesh2 {\n"
                        "  vertex_vectors { 2 + 2, <0,0,1>, <One,0,1>,\n"
                        "#if (1)\n"
                        "    <1,1,0.5*2>,\n"
                        "#end\n"
                        "    <0,1,1> }\n"
                        "  face_indices { 2, <0,1,2> <0,2,3> }\n"
                        "}\n");
  const struct zr_mesh *m = only_mesh(s);
  assert_int_equal(m->n_vertices, 4);
  assert_near(m->vertices[1].x, 1, EPS);
  assert_near(m->vertices[2].z, 1, EPS);
  assert_int_equal(m->n_faces, 2);
  zr_ray ray = {zr_v3(0.75, 0.5, 0), zr_v3(0, 0, 1)};
  zr_hit hit;
  assert_true(zr__bvh_nearest(s->bvh, &ray, 0, INFINITY, &hit));
  assert_near(hit.t, 1.0, EPS);
}

/* An n x n grid of vertices at <i, amp sin(i fi) cos(j fj), j>, two
   triangles a cell, as one mesh2. */
static zr_scene *rippled_grid(fixture *f, int n, double amp, double fi,
                              double fj) {
  zr_strbuf b;
  zr__strbuf_init(&b);
  zr__strbuf_printf(&b, "mesh2 { vertex_vectors { %d", n * n);
  for (int j = 0; j < n; j++)
    for (int i = 0; i < n; i++)
      zr__strbuf_printf(&b, ", <%d, %g, %d>", i,
                        amp * sin(i * fi) * cos(j * fj), j);
  zr__strbuf_printf(&b, " } face_indices { %d", 2 * (n - 1) * (n - 1));
  for (int j = 0; j < n - 1; j++)
    for (int i = 0; i < n - 1; i++) {
      int a = j * n + i;
      zr__strbuf_printf(&b, ", <%d,%d,%d>, <%d,%d,%d>", a, a + 1, a + n,
                        a + 1, a + n + 1, a + n);
    }
  zr__strbuf_printf(&b, " } }\n");
  zr_scene *s = good(f, zr__strbuf_cstr(&b));
  zr__strbuf_free(&b);
  return s;
}

/* A rippled grid of n x n vertices built straight by zr__mesh_build
   with the given threads (no parse): faces, rows and nodes out. */
static struct zr_mesh *grid_built(zr_arena *arena, int n, int threads) {
  struct zr_mesh *m = zr__arena_alloc(arena, sizeof *m);
  assert_non_null(m);
  m->n_vertices = (size_t)n * (size_t)n;
  m->n_faces = 2 * (size_t)(n - 1) * (size_t)(n - 1);
  m->vertices = zr__arena_alloc(arena, m->n_vertices * sizeof *m->vertices);
  m->faces = zr__arena_alloc(arena, m->n_faces * sizeof *m->faces);
  assert_non_null(m->vertices);
  assert_non_null(m->faces);
  for (int j = 0; j < n; j++)
    for (int i = 0; i < n; i++)
      m->vertices[j * n + i] =
          zr_v3(i, sin(i * 0.37) * cos(j * 0.21) + 0.01 * ((i * j) % 7), j);
  size_t f = 0;
  for (int j = 0; j < n - 1; j++)
    for (int i = 0; i < n - 1; i++) {
      uint32_t a = (uint32_t)(j * n + i), w = (uint32_t)n;
      uint32_t t1[3] = {a, a + 1, a + w}, t2[3] = {a + 1, a + w + 1, a + w};
      memcpy(m->faces[f++], t1, sizeof t1);
      memcpy(m->faces[f++], t2, sizeof t2);
    }
  size_t bad = 0;
  assert_int_equal(zr__mesh_build(m, arena, threads, &bad), ZR_OK);
  return m;
}

/* The hierarchy of a large mesh is built by several threads
   (zr_context_set_threads) into the same bytes as by one: the same
   nodes, the faces in the same order, whatever the number. */
static void test_mesh_threads_build_same_tree(void **state) {
  (void)state;
  zr_arena arena;
  zr__arena_init(&arena);
  const int n = 200; /* 79,202 faces: above the threads' minimum */
  const struct zr_mesh *one = grid_built(&arena, n, 1);
  assert_true(one->n_nodes > 1000);
  for (int threads = 2; threads <= 8; threads += threads < 4 ? 1 : 4) {
    const struct zr_mesh *m = grid_built(&arena, n, threads);
    assert_int_equal(m->n_nodes, one->n_nodes);
    /* A mesh node is one wide node (obj_mesh.c). */
    assert_memory_equal(m->nodes, one->nodes,
                        one->n_nodes * sizeof(zr_wide_node));
    assert_memory_equal(m->faces, one->faces,
                        one->n_faces * sizeof *one->faces);
    assert_memory_equal(m->face_row, one->face_row,
                        one->n_faces * sizeof *one->face_row);
  }
  zr__arena_free(&arena);
}

/* A grid of many triangles: the BVH's nearest crossing must be the one
   a test of every face finds. */
static void test_mesh_bvh_matches_brute_force(void **state) {
  fixture *f = *state;
  const int n = 40;
  zr_scene *s = rippled_grid(f, n, 1, 0.7, 0.3);
  const struct zr_mesh *m = only_mesh(s);
  assert_int_equal(m->n_faces, 2 * (n - 1) * (n - 1));
  unsigned seed = 12345;
  for (int k = 0; k < 500; k++) {
    seed = seed * 1103515245u + 12345u;
    double x = (seed >> 8) % 10000 / 10000.0 * (n - 1);
    seed = seed * 1103515245u + 12345u;
    double z = (seed >> 8) % 10000 / 10000.0 * (n - 1);
    zr_ray ray = {zr_v3(x, 5, z), zr_v3(0.1, -1, 0.05)};
    double best = INFINITY;
    for (size_t face = 0; face < m->n_faces; face++) {
      zr_vec3 p0 = m->vertices[m->faces[face][0]];
      zr_vec3 e1 = zr_v3_sub(m->vertices[m->faces[face][1]], p0);
      zr_vec3 e2 = zr_v3_sub(m->vertices[m->faces[face][2]], p0);
      zr_vec3 pv = zr_v3_cross(ray.dir, e2);
      double det = zr_v3_dot(e1, pv);
      zr_vec3 tv = zr_v3_sub(ray.origin, p0);
      double u = zr_v3_dot(tv, pv) / det;
      zr_vec3 qv = zr_v3_cross(tv, e1);
      double v = zr_v3_dot(ray.dir, qv) / det;
      double t = zr_v3_dot(e2, qv) / det;
      if (u >= 0 && v >= 0 && u + v <= 1 && t > 0 && t < best)
        best = t;
    }
    zr_hit hit;
    bool found = zr__bvh_nearest(s->bvh, &ray, 0, INFINITY, &hit);
    assert_int_equal(found, best < INFINITY);
    if (found)
      assert_near(hit.t, best, EPS);
  }
}

/* Every t at which the line crosses a face of m, by a test of each. */
static size_t brute_crossings(const struct zr_mesh *m, const zr_ray *ray,
                              double *ts, size_t cap) {
  size_t n = 0;
  for (size_t face = 0; face < m->n_faces; face++) {
    double t, u, v;
    if (zr__mesh_face_hit(m, face, ray->origin, ray->dir, &t, &u, &v) &&
        n < cap)
      ts[n++] = t;
  }
  return n;
}

/*
 * The four-wide hierarchy against a test of every face, for segments in
 * every direction across a rippled grid (shadow rays' (0, tmax)): the
 * any-hit search (zr__mesh_any_t) finds a crossing exactly when one
 * lies in the interval, and it is one of them; the search for the
 * nearest two (zr__mesh_crossings) finds the two least.
 */
static void test_mesh_any_hit_and_two_nearest(void **state) {
  fixture *f = *state;
  const int n = 24;
  zr_scene *s = rippled_grid(f, n, 2, 0.9, 0.5);
  const zr_object *o = s->primitives[0];
  const struct zr_mesh *m = only_mesh(s);
  unsigned seed = 777;
  int hits = 0, misses = 0;
  for (int k = 0; k < 2000; k++) {
    double r[6];
    for (int i = 0; i < 6; i++) {
      seed = seed * 1103515245u + 12345u;
      r[i] = (seed >> 8) % 10000 / 10000.0;
    }
    /* From a point near the surface towards another: a shadow ray's
       segment, t in (0, 1). */
    zr_vec3 from = zr_v3(r[0] * (n - 1), 4 * r[1] - 2, r[2] * (n - 1));
    zr_vec3 to = zr_v3(r[3] * (n - 1), 4 * r[4] - 1, r[5] * (n - 1));
    zr_ray ray = {from, zr_v3_sub(to, from)};
    double all[4096];
    size_t c = brute_crossings(m, &ray, all, 4096);
    double in[2] = {INFINITY, INFINITY};
    size_t n_in = 0;
    for (size_t i = 0; i < c; i++) {
      if (!(all[i] > 0.0 && all[i] < 1.0))
        continue;
      n_in++;
      if (all[i] < in[0]) {
        in[1] = in[0];
        in[0] = all[i];
      } else if (all[i] < in[1]) {
        in[1] = all[i];
      }
    }
    zr_hit hit;
    int any = zr__mesh_any_t(o, &ray, 0.0, 1.0, &hit);
    assert_int_equal(any, n_in > 0);
    if (any) {
      hits++;
      bool real = false;
      for (size_t i = 0; i < c; i++)
        real = real || all[i] == hit.t;
      assert_true(real);
      assert_true(hit.t > 0.0 && hit.t < 1.0);
    } else {
      misses++;
    }
    zr_mesh_crossing two[2];
    int got = zr__mesh_crossings(m, ray.origin, ray.dir, 0.0, 1.0, two);
    assert_int_equal(got, n_in < 2 ? (int)n_in : 2);
    for (int i = 0; i < got; i++)
      assert_true(two[i].t == in[i]);
  }
  /* The segments must try both answers for the test to mean anything. */
  assert_true(hits > 100 && misses > 100);
}

static void test_mesh_smooth_normals(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "smooth_triangle { <0,0,0>, <0,0,-1>, <1,0,0>, "
                        "<1,0,-1>, <0,1,0>, <0,1,-1> }\n");
  zr_ray ray = {zr_v3(0.5, 0.25, -1), zr_v3(0, 0, 1)};
  zr_hit hit;
  assert_true(zr__bvh_nearest(s->bvh, &ray, 0, INFINITY, &hit));
  assert_near(hit.t, 1, EPS);
  /* Barycentric weights 0.25, 0.5, 0.25 of the corner normals. */
  zr_vec3 want = zr_v3_norm(zr_v3(0.5, 0.25, -1));
  assert_near(hit.normal.x, want.x, EPS);
  assert_near(hit.normal.y, want.y, EPS);
  assert_near(hit.normal.z, want.z, EPS);
  /* mesh { smooth_triangle } gives the same normal. */
  s = good(f, "mesh { triangle { <5,5,5>, <6,5,5>, <5,6,5> }\n"
              "  smooth_triangle { <0,0,0>, <0,0,-1>, <1,0,0>, "
              "<1,0,-1>, <0,1,0>, <0,1,-1> } }\n");
  assert_true(zr__bvh_nearest(s->bvh, &ray, 0, INFINITY, &hit));
  assert_near(hit.normal.x, want.x, EPS);
  assert_near(hit.normal.y, want.y, EPS);
}

static void test_mesh_texture_list(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "mesh2 {\n"
                        "  vertex_vectors { 4, <0,0,1>, <1,0,1>, <1,1,1>, "
                        "<0,1,1> }\n"
                        "  texture_list { 2, texture { pigment { rgb "
                        "<1,0,0> } } texture { pigment { rgb <0,0,1> } } }\n"
                        "  face_indices { 2, <0,1,2>, 1, <0,2,3>, 0 }\n"
                        "  pigment { rgb <0,1,0> }\n"
                        "}\n");
  zr_hit hit;
  zr_ray right = {zr_v3(0.75, 0.25, 0), zr_v3(0, 0, 1)};
  assert_true(zr__bvh_nearest(s->bvh, &right, 0, INFINITY, &hit));
  assert_near(hit.object->texture->pigment->colour.b, 1, EPS);
  zr_ray left = {zr_v3(0.25, 0.75, 0), zr_v3(0, 0, 1)};
  assert_true(zr__bvh_nearest(s->bvh, &left, 0, INFINITY, &hit));
  assert_near(hit.object->texture->pigment->colour.r, 1, EPS);
  /* mesh { } triangles with and without their own texture. */
  s = good(f, "mesh { triangle { <0,0,1>, <1,0,1>, <1,1,1> texture { "
              "pigment { rgb <1,0,0> } } }\n"
              "  triangle { <0,0,1>, <1,1,1>, <0,1,1> }\n"
              "  pigment { rgb <0,1,0> } }\n");
  assert_true(zr__bvh_nearest(s->bvh, &right, 0, INFINITY, &hit));
  assert_near(hit.object->texture->pigment->colour.r, 1, EPS);
  assert_true(zr__bvh_nearest(s->bvh, &left, 0, INFINITY, &hit));
  assert_near(hit.object->texture->pigment->colour.g, 1, EPS);
}

/* A tetrahedron: closed, so inside_vector makes it a solid. */
#define TETRA                                                              \
  "  vertex_vectors { 4, <0,0,0>, <1,0,0>, <0,1,0>, <0,0,1> }\n"          \
  "  face_indices { 4, <0,2,1>, <0,1,3>, <0,3,2>, <1,2,3> }\n"

static void test_mesh_inside_vector(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "mesh2 {\n" TETRA "  inside_vector <1, 2, 3>\n}\n");
  const zr_object *o = s->primitives[0];
  assert_true(zr__has_inside(o));
  assert_true(zr__inside(o, zr_v3(0.1, 0.1, 0.1)));
  assert_false(zr__inside(o, zr_v3(0.5, 0.5, 0.5)));
  assert_false(zr__inside(o, zr_v3(-0.1, 0.1, 0.1)));
  s = good(f, "mesh2 {\n" TETRA "}\n");
  o = s->primitives[0];
  assert_false(zr__has_inside(o));
  assert_false(zr__inside(o, zr_v3(0.1, 0.1, 0.1)));
}

/* object { M translate } copies refer to the same triangles. */
static void test_mesh_instances_share(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "#declare M = " SQUARE_MESH2
                        "object { M }\n"
                        "object { M translate <5, 0, 0> }\n"
                        "object { M translate <0, 0, 3> }\n");
  assert_int_equal(s->n_primitives, 3);
  for (int i = 1; i < 3; i++)
    assert_ptr_equal(s->primitives[i]->u.mesh.data,
                     s->primitives[0]->u.mesh.data);
  zr_ray ray = {zr_v3(5.25, 0.5, -1), zr_v3(0, 0, 1)};
  zr_hit hit;
  assert_true(zr__bvh_nearest(s->bvh, &ray, 0, INFINITY, &hit));
  assert_near(hit.t, 2, EPS);
  zr_ray behind = {zr_v3(0.25, 0.5, 2), zr_v3(0, 0, 1)};
  assert_true(zr__bvh_nearest(s->bvh, &behind, 0, INFINITY, &hit));
  assert_near(hit.t, 2, EPS);
}

/* A smooth, textured n x n grid (normal_vectors, a texture_list of
   two, alternating faces) with the given object modifiers. */
static zr_scene *smooth_textured_grid(fixture *f, int n, const char *mods) {
  zr_strbuf b;
  zr__strbuf_init(&b);
  zr__strbuf_printf(&b, "mesh2 { vertex_vectors { %d", n * n);
  for (int j = 0; j < n; j++)
    for (int i = 0; i < n; i++)
      zr__strbuf_printf(&b, ", <%d, %g, %d>", i, sin(0.7 * i) * cos(0.4 * j),
                        j);
  zr__strbuf_printf(&b, " } normal_vectors { %d", n * n);
  for (int j = 0; j < n; j++)
    for (int i = 0; i < n; i++)
      zr__strbuf_printf(&b, ", <%g, 1, %g>", -0.7 * cos(0.7 * i) * cos(0.4 * j),
                        0.4 * sin(0.7 * i) * sin(0.4 * j));
  zr__strbuf_printf(&b, " } texture_list { 2, texture { pigment { rgb "
                        "<1,0,0> } } texture { pigment { rgb <0,0,1> } } }");
  int faces = 2 * (n - 1) * (n - 1);
  zr__strbuf_printf(&b, " face_indices { %d", faces);
  for (int j = 0; j < n - 1; j++)
    for (int i = 0; i < n - 1; i++) {
      int a = j * n + i;
      zr__strbuf_printf(&b, ", <%d,%d,%d>, %d, <%d,%d,%d>, %d", a, a + 1,
                        a + n, (i + j) % 2, a + 1, a + n + 1, a + n,
                        (i + j + 1) % 2);
    }
  zr__strbuf_printf(&b, " } normal_indices { %d", faces);
  for (int j = 0; j < n - 1; j++)
    for (int i = 0; i < n - 1; i++) {
      int a = j * n + i;
      zr__strbuf_printf(&b, ", <%d,%d,%d>, <%d,%d,%d>", a, a + 1, a + n,
                        a + 1, a + n + 1, a + n);
    }
  zr__strbuf_printf(&b, " } %s }\n", mods);
  zr_scene *s = good(f, zr__strbuf_cstr(&b));
  zr__strbuf_free(&b);
  return s;
}

/*
 * The search for the nearest surface makes a mesh's normal from the face
 * its own walk found (bvh.c, zr__mesh_world_normal) instead of
 * searching the mesh again: hit for hit it must give what zr__intersect
 * gives the mesh alone, the same t, object (texture), u, v and normal
 * to the bit, through a transform, inverse and smooth normals.
 */
static void test_mesh_nearest_normal_as_intersect(void **state) {
  fixture *f = *state;
  const char *mods[3] = {"", "scale <1, 2, 0.5> rotate <10, 20, 30> "
                             "translate <1, 2, 3>",
                         "rotate <-20, 5, 0> scale 3 inverse"};
  for (int m = 0; m < 3; m++) {
    zr_scene *s = smooth_textured_grid(f, 12, mods[m]);
    assert_int_equal(s->n_primitives, 1);
    const zr_object *o = s->primitives[0];
    unsigned seed = 4242;
    int found = 0;
    for (int k = 0; k < 400; k++) {
      double r[5];
      for (int i = 0; i < 5; i++) {
        seed = seed * 1103515245u + 12345u;
        r[i] = (seed >> 8) % 10000 / 10000.0;
      }
      /* From above the grid to below it, in the grid's own space. */
      zr_vec3 from = zr_v3(11 * r[0], 4, 11 * r[1]);
      zr_vec3 to = zr_v3(11 * r[2], -1 + r[4], 11 * r[3]);
      if (o->transform) {
        from = zr__xform_point(o->transform->m, from);
        to = zr__xform_point(o->transform->m, to);
      }
      zr_ray ray = {from, zr_v3_sub(to, from)};
      zr_hit hit, want[ZR_MAX_CROSSINGS];
      bool got = zr__bvh_nearest(s->bvh, &ray, 0.0, INFINITY, &hit);
      int n = zr__intersect(o, &ray, 0.0, INFINITY, want);
      assert_int_equal(got, n > 0);
      if (!got)
        continue;
      found++;
      assert_true(hit.t == want[0].t);
      assert_ptr_equal(hit.object, want[0].object);
      assert_true(hit.u == want[0].u && hit.v == want[0].v);
      assert_memory_equal(&hit.normal, &want[0].normal, sizeof hit.normal);
    }
    assert_true(found > 200);
  }
}

static void test_mesh_bad_lists(void **state) {
  fixture *f = *state;
  bad(f, "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0> }\n"
         "  face_indices { 1, <0,1,2> } }\n",
      ZR_ESCENE, "vertex_vectors: 2 items given, 3 announced", NULL);
  bad(f, "mesh2 { vertex_vectors { 1, <0,0,0>, <1,0,0> } }\n", ZR_ESCENE,
      "vertex_vectors: more items than the 1 announced", NULL);
  bad(f, "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }\n"
         "  face_indices { 1, <0,1,3> } }\n",
      ZR_ESCENE,
      "mesh2 face 0 refers to a vertex, normal, uv or texture that is not "
      "in its lists",
      NULL);
  bad(f, "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }\n"
         "  face_indices { 1, <0,-1,2> } }\n",
      ZR_ESCENE, "face_indices: -1 is not an index", NULL);
  bad(f, "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }\n"
         "  texture_list { 1, texture { pigment { rgb 1 } } }\n"
         "  face_indices { 1, <0,1,2>, 0, 0 } }\n",
      ZR_ESCENE, "face_indices: a face has 1 or 3 texture indices, not 2",
      NULL);
  bad(f, "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } }\n",
      ZR_ESYNTAX, "a mesh2 needs vertex_vectors and face_indices", NULL);
  bad(f, "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }\n"
         "  vertex_vectors { 0 } }\n",
      ZR_ESYNTAX, "mesh2 has two vertex_vectors", NULL);
  bad(f, "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }\n"
         "  face_indices { 1, <0,1,2> } inside_vector 0 }\n",
      ZR_ESCENE, "the inside_vector is zero", NULL);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test_setup_teardown(test_mesh_mesh2_hit, setup, teardown),
      cmocka_unit_test_setup_teardown(test_mesh_fast_and_grammar_agree,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_mesh_bvh_matches_brute_force,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_mesh_any_hit_and_two_nearest,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_mesh_smooth_normals, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_mesh_texture_list, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_mesh_inside_vector, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_mesh_instances_share, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_mesh_bad_lists, setup, teardown),
      cmocka_unit_test(test_mesh_threads_build_same_tree),
      cmocka_unit_test_setup_teardown(test_mesh_nearest_normal_as_intersect,
                                      setup, teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
