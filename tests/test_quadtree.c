/*
 * test_quadtree.c - the radiosity quadtrees (lib/radiosity/quadtree.c):
 * corner vertices shared between cells (no duplicates), the leaf that
 * holds a (u,v), and smoothing that leaves no crack where a small leaf
 * meets a large one (T-vertices).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "radiosity/radiosity.h"
#include "zrcube.h"

typedef struct fixture {
  zr_context *ctx;
  zr_scene *scene;
  zr_radiosity *rad;
} fixture;

static int setup(void **state) {
  static fixture f;
  memset(&f, 0, sizeof f);
  const char *text = "box { <0,0,0>, <2,1,1> }\n";
  if (zr_context_new(&f.ctx) != ZR_OK ||
      zr_scene_parse_string(f.ctx, "<string>", text, strlen(text),
                            &f.scene) != ZR_OK ||
      zr__rad_create(f.ctx, f.scene, NULL, &f.rad) != ZR_OK)
    return -1;
  *state = &f;
  return 0;
}

static int teardown(void **state) {
  fixture *f = *state;
  zr_radiosity_free(f->rad);
  zr_scene_free(f->scene);
  zr_context_free(f->ctx);
  return 0;
}

/* Six faces with four corners each; splitting a root adds five
   vertices (four edge midpoints and the centre), splitting one of its
   children five more: corners already there are shared, not copied. */
static void test_quadtree_shared_vertices(void **state) {
  fixture *f = *state;
  zr_radiosity *rad = f->rad;
  assert_int_equal(rad->n_surfs, 6);
  assert_int_equal(rad->n_verts, 24);
  int32_t root = rad->surfs[0].root;
  assert_true(zr__rad_subdivide(rad, root));
  assert_int_equal(rad->n_verts, 29);
  int32_t c0 = rad->nodes[root].child;
  assert_true(zr__rad_subdivide(rad, c0));
  assert_int_equal(rad->n_verts, 34);
  /* Neighbouring children share the corners of their common edge. */
  const zr__rad_node *a = &rad->nodes[c0], *b = &rad->nodes[c0 + 1];
  assert_int_equal(a->vert[1], b->vert[0]);
  assert_int_equal(a->vert[2], b->vert[3]);
  /* Child areas add up to the parent's (planar face: exact quadrature,
     1e-12 relative for rounding). */
  double sum = 0.0;
  for (int k = 0; k < 4; k++)
    sum += rad->nodes[c0 + k].area;
  assert_true(fabs(sum - rad->nodes[root].area) < 1e-12);
}

static void test_quadtree_leaf_at(void **state) {
  fixture *f = *state;
  zr_radiosity *rad = f->rad;
  int32_t root = rad->surfs[0].root;
  int32_t c0 = rad->nodes[root].child;
  assert_true(c0 >= 0); /* split by the test before */
  int32_t gc = rad->nodes[c0].child;
  assert_int_equal(zr__rad_leaf_at(rad, 0, 0.1, 0.1), gc);
  assert_int_equal(zr__rad_leaf_at(rad, 0, 0.4, 0.1), gc + 1);
  assert_int_equal(zr__rad_leaf_at(rad, 0, 0.9, 0.9), c0 + 2);
  assert_int_equal(zr__rad_leaf_at(rad, 0, 0.1, 0.9), c0 + 3);
  assert_int_equal(zr__rad_leaf_at(rad, 1, 0.5, 0.5), rad->surfs[1].root);
}

/* Leaves get uneven values; after smoothing, the interpolation along the
   edge u = 1/2 between the small leaves of child 0 and the large child 1
   agrees from both sides (1e-12: the same linear interpolation). */
static void test_quadtree_smoothing_has_no_cracks(void **state) {
  fixture *f = *state;
  zr_radiosity *rad = f->rad;
  for (size_t n = 0; n < rad->n_nodes; n++)
    for (int c = 0; c < 3; c++)
      rad->nodes[n].b[0][c] = rad->nodes[n].b[1][c] =
          1.0 + (double)(n * 7 % 5) + c;
  zr__rad_smooth(rad);
  int32_t root = rad->surfs[0].root;
  int32_t big = rad->nodes[root].child + 1;
  for (int i = 0; i <= 20; i++) {
    double v = 0.5 * i / 20.0;
    int32_t small = zr__rad_leaf_at(rad, 0, 0.4999, v < 0.5 ? v : 0.4999);
    double x[3], y[3];
    zr__rad_interpolate(rad, small, 0, 0.5, v, x);
    zr__rad_interpolate(rad, big, 0, 0.5, v, y);
    for (int c = 0; c < 3; c++)
      assert_true(fabs(x[c] - y[c]) < 1e-12);
  }
}

/* A constant solution stays exactly constant through smoothing. */
static void test_quadtree_constant_is_kept(void **state) {
  fixture *f = *state;
  zr_radiosity *rad = f->rad;
  for (size_t n = 0; n < rad->n_nodes; n++)
    for (int s = 0; s < 2; s++)
      for (int c = 0; c < 3; c++)
        rad->nodes[n].b[s][c] = 0.25;
  zr__rad_smooth(rad);
  for (int i = 0; i < 10; i++) {
    double u = 0.05 + 0.1 * i, v = 0.95 - 0.09 * i, out[3];
    zr__rad_interpolate(rad, zr__rad_leaf_at(rad, 0, u, v), 1, u, v, out);
    assert_true(fabs(out[0] - 0.25) < 1e-15);
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_quadtree_shared_vertices),
      cmocka_unit_test(test_quadtree_leaf_at),
      cmocka_unit_test(test_quadtree_smoothing_has_no_cracks),
      cmocka_unit_test(test_quadtree_constant_is_kept),
  };
  return cmocka_run_group_tests(tests, setup, teardown);
}
