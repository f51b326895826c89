/*
 * test_preview.c - zr_scene_preview through the public API: a sphere's
 * corners lie on it and its normals point out of it, a box is its 12
 * triangles on its 8 corners, a mesh its own faces, a plane its patch
 * at its height, a CSG intersection and a clipped_by lose what they do
 * not keep, a mesh face with its own texture takes its colour,
 * an object without surfaces its bounding box's 12 edges, and the
 * camera is the scene's.  Positions are floats: their tolerance, 1e-5
 * of the values here, is float rounding (2^-24 relative) with room.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "zrcube.h"

#define TOL 1e-5

static zr_preview *preview_of(const char *text, int detail) {
  zr_context *ctx = NULL;
  assert_int_equal(zr_context_new(&ctx), ZR_OK);
  zr_scene *scene = NULL;
  assert_int_equal(
      zr_scene_parse_string(ctx, "<test>", text, strlen(text), &scene),
      ZR_OK);
  zr_preview *pv = NULL;
  assert_int_equal(zr_scene_preview(ctx, scene, detail, &pv), ZR_OK);
  assert_non_null(pv);
  /* The preview owns its arrays: it outlives the scene. */
  zr_scene_free(scene);
  zr_context_free(ctx);
  return pv;
}

static double dist3(const float *p, const double c[3]) {
  double dx = p[0] - c[0], dy = p[1] - c[1], dz = p[2] - c[2];
  return sqrt(dx * dx + dy * dy + dz * dz);
}

static void test_preview_sphere(void **state) {
  (void)state;
  zr_preview *pv = preview_of(
      "sphere { <1, 2, 3>, 2 pigment { rgb <1, 0.5, 0> } }\n", 16);
  const float *xyz, *normal, *rgb;
  size_t n = zr_preview_triangles(pv, &xyz, &normal, &rgb);
  /* 16 x 16 cells, two triangles each, less those a pole collapses
     (at most one a cell at each of the two poles). */
  assert_true(n >= 2 * 16 * 16 - 2 * 16 && n <= 2 * 16 * 16);
  const double c[3] = {1, 2, 3};
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY,
                                                           -INFINITY,
                                                           -INFINITY};
  for (size_t v = 0; v < 3 * n; v++) {
    const float *p = &xyz[3 * v], *nv = &normal[3 * v];
    assert_true(fabs(dist3(p, c) - 2.0) < TOL * 4);
    /* The normal is (p - c) / r. */
    for (int k = 0; k < 3; k++) {
      assert_true(fabs(nv[k] - (p[k] - c[k]) / 2.0) < TOL * 4);
      lo[k] = fmin(lo[k], p[k]);
      hi[k] = fmax(hi[k], p[k]);
    }
  }
  /* The grid reaches both poles and goes round: the corners span the
     sphere's box to within a cell's sag (1 - cos(pi / 16) of r). */
  for (int k = 0; k < 3; k++) {
    assert_true(lo[k] < c[k] - 2.0 * cos(M_PI / 16) + TOL);
    assert_true(hi[k] > c[k] + 2.0 * cos(M_PI / 16) - TOL);
  }
  for (size_t t = 0; t < n; t++) {
    assert_true(fabs(rgb[3 * t] - 1.0) < TOL);
    assert_true(fabs(rgb[3 * t + 1] - 0.5) < TOL);
    assert_true(fabs(rgb[3 * t + 2]) < TOL);
  }
  zr_preview_info info;
  zr_preview_get_info(pv, &info);
  assert_int_equal(info.triangles, n);
  assert_int_equal(info.lines, 0);
  assert_int_equal(info.objects_as_triangles, 1);
  assert_int_equal(info.objects_as_boxes, 0);
  assert_int_equal(info.objects_left_out, 0);
  zr_preview_free(pv);

  /* A transform is applied: a unit sphere scaled by 2 and moved. */
  pv = preview_of("sphere { 0, 1 scale 2 translate <5, 0, 0> }\n", 0);
  n = zr_preview_triangles(pv, &xyz, NULL, NULL);
  /* detail 0 is 24. */
  assert_true(n >= 2 * 24 * 24 - 2 * 24 && n <= 2 * 24 * 24);
  const double c2[3] = {5, 0, 0};
  for (size_t v = 0; v < 3 * n; v++)
    assert_true(fabs(dist3(&xyz[3 * v], c2) - 2.0) < TOL * 4);
  zr_preview_free(pv);
}

static void test_preview_box(void **state) {
  (void)state;
  /* Flat faces take detail / 4 cells a side: 1 at detail 4. */
  zr_preview *pv = preview_of("box { <-1, 0, 2>, <3, 1, 4> }\n", 4);
  const float *xyz, *normal;
  size_t n = zr_preview_triangles(pv, &xyz, &normal, NULL);
  assert_int_equal(n, 12);
  const double lo[3] = {-1, 0, 2}, hi[3] = {3, 1, 4};
  int seen = 0;
  for (size_t v = 0; v < 3 * n; v++) {
    int corner = 0;
    for (int k = 0; k < 3; k++) {
      double p = xyz[3 * v + k];
      bool at_lo = fabs(p - lo[k]) < TOL, at_hi = fabs(p - hi[k]) < TOL;
      assert_true(at_lo || at_hi);
      corner |= at_hi << k;
    }
    seen |= 1 << corner;
  }
  assert_int_equal(seen, 0xff);
  /* Every triangle's normals point out of the box along one axis. */
  for (size_t t = 0; t < n; t++) {
    double centroid[3], mid[3];
    for (int k = 0; k < 3; k++) {
      centroid[k] = (xyz[9 * t + k] + xyz[9 * t + 3 + k] +
                     xyz[9 * t + 6 + k]) / 3.0;
      mid[k] = 0.5 * (lo[k] + hi[k]);
    }
    const float *nv = &normal[9 * t];
    double out = 0.0, len = 0.0;
    for (int k = 0; k < 3; k++) {
      out += nv[k] * (centroid[k] - mid[k]);
      len += nv[k] * nv[k];
    }
    assert_true(fabs(len - 1.0) < TOL);
    assert_true(out > 0.0);
  }
  zr_preview_free(pv);

  /* At detail 8, 2 x 2 cells a face. */
  pv = preview_of("box { <-1, 0, 2>, <3, 1, 4> }\n", 8);
  assert_int_equal(zr_preview_triangles(pv, NULL, NULL, NULL), 6 * 2 * 4);
  zr_preview_free(pv);
}

static void test_preview_mesh_and_plane(void **state) {
  (void)state;
  zr_preview *pv = preview_of(
      "mesh { triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }\n"
      "       triangle { <0, 0, 5>, <0, 2, 5>, <3, 0, 5> } }\n"
      "plane { y, -1 }\n",
      4);
  const float *xyz;
  size_t n = zr_preview_triangles(pv, &xyz, NULL, NULL);
  /* The mesh's 2 faces, then the plane's 2 x 4 cells a side. */
  assert_int_equal(n, 2 + 2 * 8 * 8);
  double mesh_sum = 0.0;
  size_t at_plane = 0;
  for (size_t t = 0; t < n; t++) {
    bool flat = true;
    for (int k = 0; k < 3; k++)
      flat = flat && fabs(xyz[9 * t + 3 * k + 1] + 1.0) < TOL;
    if (flat) {
      at_plane++;
      continue;
    }
    for (int k = 0; k < 9; k++)
      mesh_sum += xyz[9 * t + k];
  }
  assert_int_equal(at_plane, 2 * 8 * 8);
  /* The faces' coordinates, as written: 1 + 1 and 5 + 2 + 5 + 3 + 5. */
  assert_true(fabs(mesh_sum - 22.0) < TOL);
  zr_preview_info info;
  zr_preview_get_info(pv, &info);
  assert_int_equal(info.objects_as_triangles, 2);
  zr_preview_free(pv);

  /* A plane with nothing finite to bound it is left out. */
  pv = preview_of("plane { y, 0 }\n", 0);
  zr_preview_get_info(pv, &info);
  assert_int_equal(info.triangles, 0);
  assert_int_equal(info.objects_left_out, 1);
  assert_true(info.lo[0] > info.hi[0]);
  zr_preview_free(pv);
}

static void test_preview_csg(void **state) {
  (void)state;
  /* The lower half of a unit sphere: the cells above z = 0 are cut
     (their centres are outside the box), and so is the box outside the
     sphere; what is left lies below z = 0 but for the corners of cells
     whose centre is just below it (a cell's height, pi / 24). */
  zr_preview *pv = preview_of(
      "intersection { sphere { 0, 1 } box { <-2, -2, -2>, <2, 2, 0> } }\n",
      24);
  const float *xyz;
  size_t n = zr_preview_triangles(pv, &xyz, NULL, NULL);
  assert_true(n > 0);
  double zmax = -INFINITY, zmin = INFINITY, rmax = 0.0;
  const double o[3] = {0, 0, 0};
  for (size_t v = 0; v < 3 * n; v++) {
    zmax = fmax(zmax, xyz[3 * v + 2]);
    zmin = fmin(zmin, xyz[3 * v + 2]);
    rmax = fmax(rmax, dist3(&xyz[3 * v], o));
  }
  assert_true(zmax < M_PI / 24 + TOL);
  assert_true(zmin < -1.0 + 1e-2);
  /* The box's faces outside the sphere are gone: the box's z = 0 face
     keeps the cells inside the unit disc (its 6 x 6 cells are 2/3
     wide, so corners reach at most a cell's diagonal past it). */
  assert_true(rmax < 1.0 + sqrt(2.0) * 4.0 / 6.0 + TOL);
  zr_preview_free(pv);
}

static void test_preview_clip_and_face_textures(void **state) {
  (void)state;
  /* clipped_by { plane { y, 0 } } keeps the lower half, as the CSG
     intersection above does. */
  zr_preview *pv = preview_of(
      "sphere { 0, 1 clipped_by { plane { y, 0 } } }\n", 24);
  const float *xyz, *rgb;
  size_t n = zr_preview_triangles(pv, &xyz, NULL, NULL);
  assert_true(n > 0 && n <= 24 * 24 + 24);
  double ymax = -INFINITY;
  for (size_t v = 0; v < 3 * n; v++)
    ymax = fmax(ymax, xyz[3 * v + 1]);
  assert_true(ymax < M_PI / 24 + TOL);
  zr_preview_free(pv);

  /* A mesh's faces with textures of their own are coloured by them:
     the face at z = 0 red, the one at z = 5 green. */
  pv = preview_of(
      "mesh { triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> "
      "texture { pigment { rgb <1, 0, 0> } } }\n"
      "       triangle { <0, 0, 5>, <0, 2, 5>, <3, 0, 5> "
      "texture { pigment { rgb <0, 1, 0> } } } }\n",
      0);
  n = zr_preview_triangles(pv, &xyz, NULL, &rgb);
  assert_int_equal(n, 2);
  for (size_t t = 0; t < n; t++) {
    bool near = fabs(xyz[9 * t + 2]) < TOL;
    assert_true(fabs(rgb[3 * t] - (near ? 1.0 : 0.0)) < TOL);
    assert_true(fabs(rgb[3 * t + 1] - (near ? 0.0 : 1.0)) < TOL);
  }
  zr_preview_free(pv);
}

static void test_preview_boxes_for_the_rest(void **state) {
  (void)state;
  /* A blob has no surface yet: its bounding box's 12 edges. */
  zr_preview *pv = preview_of(
      "blob { threshold 0.5 sphere { <0, 0, 0>, 1, 1 } "
      "pigment { rgb <0, 0, 1> } }\n",
      0);
  zr_preview_info info;
  zr_preview_get_info(pv, &info);
  assert_int_equal(info.triangles, 0);
  assert_int_equal(info.lines, 12);
  assert_int_equal(info.objects_as_boxes, 1);
  const float *xyz, *rgb;
  assert_int_equal(zr_preview_lines(pv, &xyz, &rgb), 12);
  double total = 0.0;
  for (size_t l = 0; l < 12; l++) {
    double len = 0.0;
    int axes = 0;
    for (int k = 0; k < 3; k++) {
      double d = xyz[6 * l + 3 + k] - xyz[6 * l + k];
      len += d * d;
      axes += fabs(d) > TOL;
      /* Both ends on the bounds. */
      assert_true(fabs(xyz[6 * l + k] - info.lo[k]) < TOL ||
                  fabs(xyz[6 * l + k] - info.hi[k]) < TOL);
    }
    assert_int_equal(axes, 1);
    total += sqrt(len);
    assert_true(fabs(rgb[3 * l + 2] - 1.0) < TOL);
  }
  /* 4 edges along each axis. */
  double edges = 0.0;
  for (int k = 0; k < 3; k++)
    edges += 4.0 * (info.hi[k] - info.lo[k]);
  assert_true(fabs(total - edges) < 1e-4);
  zr_preview_free(pv);
}

static void test_preview_camera(void **state) {
  (void)state;
  zr_preview *pv = preview_of(
      "camera { location <1, 2, 3> direction <0, 0, 2> up <0, 1, 0> "
      "right <1.5, 0, 0> }\nsphere { 0, 1 }\n",
      0);
  zr_preview_camera cam;
  zr_preview_get_camera(pv, &cam);
  const double want[4][3] = {{1, 2, 3}, {0, 0, 2}, {0, 1, 0}, {1.5, 0, 0}};
  const double *got[4] = {cam.location, cam.direction, cam.up, cam.right};
  for (int i = 0; i < 4; i++)
    for (int k = 0; k < 3; k++)
      assert_true(fabs(got[i][k] - want[i][k]) < 1e-12);
  assert_int_equal(cam.perspective, 1);
  assert_int_equal(cam.given, 1);
  zr_preview_free(pv);

  /* look_at turns the vectors: direction points at the target. */
  pv = preview_of("camera { orthographic location <0, 0, -5> "
                  "look_at <3, 0, -1> }\nsphere { 0, 1 }\n", 0);
  zr_preview_get_camera(pv, &cam);
  double len = sqrt(cam.direction[0] * cam.direction[0] +
                    cam.direction[1] * cam.direction[1] +
                    cam.direction[2] * cam.direction[2]);
  assert_true(len > 0.0);
  assert_true(fabs(cam.direction[0] / len - 0.6) < 1e-9);
  assert_true(fabs(cam.direction[2] / len - 0.8) < 1e-9);
  assert_int_equal(cam.perspective, 0);
  zr_preview_free(pv);

  /* No camera block: POV-Ray's default, said so. */
  pv = preview_of("sphere { 0, 1 }\n", 0);
  zr_preview_get_camera(pv, &cam);
  assert_int_equal(cam.given, 0);
  assert_true(fabs(cam.direction[2] - 1.0) < 1e-12);
  zr_preview_free(pv);
}

static void test_preview_bad_detail(void **state) {
  (void)state;
  zr_context *ctx = NULL;
  assert_int_equal(zr_context_new(&ctx), ZR_OK);
  zr_scene *scene = NULL;
  const char *text = "sphere { 0, 1 }\n";
  assert_int_equal(
      zr_scene_parse_string(ctx, "<test>", text, strlen(text), &scene),
      ZR_OK);
  zr_preview *pv = (zr_preview *)&pv;
  assert_int_equal(zr_scene_preview(ctx, scene, -1, &pv), ZR_EINVAL);
  assert_null(pv);
  assert_int_equal(zr_scene_preview(ctx, scene, 257, &pv), ZR_EINVAL);
  assert_non_null(strstr(zr_context_last_error(ctx), "detail 257"));
  assert_int_equal(zr_scene_preview(ctx, scene, 256, &pv), ZR_OK);
  zr_preview_free(pv);
  zr_preview_free(NULL);
  zr_scene_free(scene);
  zr_context_free(ctx);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_preview_sphere),
      cmocka_unit_test(test_preview_box),
      cmocka_unit_test(test_preview_mesh_and_plane),
      cmocka_unit_test(test_preview_csg),
      cmocka_unit_test(test_preview_clip_and_face_textures),
      cmocka_unit_test(test_preview_boxes_for_the_rest),
      cmocka_unit_test(test_preview_camera),
      cmocka_unit_test(test_preview_bad_detail),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
