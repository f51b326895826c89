/*
 * test_meshcam.c - the mesh_camera and omnimax projections and the
 * transform functions the stock mesh camera scenes use
 * (transforms.inc's vtransform), checked against povray 3.7 renders of
 * the same scenes: 16-bit PNG, File_Gamma 1.0, no antialiasing.  A
 * plane coloured by position (red x / 16, green (y + 2) / 8) in front of
 * small meshes tells which face shot each pixel's ray; a sphere of
 * radius 1000 coloured by position tells a ray's direction.
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

#include "parse_fixture.h"
#include "scene/scene.h"
#include "trace/render.h"
#include "test_util.h"

/* povray's 16-bit output steps by 1.5e-5; its single precision colour
   arithmetic adds a little (colours), and directions read back from a
   gradient over [-1, 1] double the step. */
#define POV_TOL 2e-4

static float *render(fixture *f, const char *text, int w, int h) {
  zr_scene *s = good(f, text);
  zr_render_params p;
  zr_render_params_init(&p);
  p.width = w;
  p.height = h;
  float *rgb = calloc((size_t)w * h * 3, sizeof *rgb);
  assert_non_null(rgb);
  assert_int_equal(zr_render_image(s, &p, rgb, NULL), ZR_OK);
  return rgb;
}

/* Faces 0 .. n-1 of a mesh M, face i a small triangle about <i, 0, 0>
   looking along +z (corners at its lower left, upper left, lower
   right), a copy M2 of n2 faces, and the coloured plane at z = 5. */
static void mesh_scene(char *text, size_t size, int n, int n2,
                       const char *camera) {
  snprintf(text, size,
           "#declare M = mesh { #local i = 0; #while (i < %d)\n"
           "  triangle { <i-0.25,-0.25,0>, <i-0.25,0.5,0>, <i+0.5,-0.25,0> }\n"
           "  #local i = i + 1; #end }\n"
           "#declare M2 = mesh { #local i = 0; #while (i < %d)\n"
           "  triangle { <i-0.25,-0.25,0>, <i-0.25,0.5,0>, <i+0.5,-0.25,0> }\n"
           "  #local i = i + 1; #end }\n"
           "background { rgb <0,0,1> }\n"
           "camera { %s }\n"
           "plane { z, 5 pigment { average pigment_map {\n"
           "  [1 function { x/16 } color_map { [0 rgb 0] [1 rgb <2,0,0>] }]\n"
           "  [1 function { (y+2)/8 }\n"
           "     color_map { [0 rgb 0] [1 rgb <0,2,0>] }]\n"
           "} } finish { ambient 1 diffuse 0 } }\n"
           "plane { z, -5 pigment { rgb <0,1,0> } finish { ambient 1 "
           "diffuse 0 } }\n",
           n, n2, camera);
}

/* Expected pixel: the face at <face, y> seen on the plane, or black
   (face < 0: no ray). */
static void check_face(const float *px, int face, double y) {
  if (face < 0) {
    assert_near(px[0] + px[1] + px[2], 0.0, 0.0);
    return;
  }
  assert_near(px[0], face / 16.0, POV_TOL);
  assert_near(px[1], (y + 2) / 8.0, POV_TOL);
  assert_near(px[2], 0.0, POV_TOL);
}

/* Distribution 0: pixel (x, y) takes face x + W max(y - 1, 0), so rows
   0 and 1 are alike; a pixel without a face is black.  Two rays per
   pixel average mesh 0's and mesh 1's faces. */
static void test_meshcam_distribution_0(void **state) {
  fixture *f = *state;
  char text[2048];
  mesh_scene(text, sizeof text, 6, 6, "mesh_camera { 1 0 mesh { M } }");
  float *rgb = render(f, text, 4, 3);
  static const int faces[12] = {0, 1, 2, 3, 0, 1, 2, 3, 4, 5, -1, -1};
  for (int i = 0; i < 12; i++)
    check_face(rgb + 3 * i, faces[i], 0.0);
  free(rgb);
  mesh_scene(text, sizeof text, 6, 6,
             "mesh_camera { 2 0 mesh { M } mesh { M2 translate y } }");
  rgb = render(f, text, 4, 3);
  for (int i = 0; i < 12; i++)
    check_face(rgb + 3 * i, faces[i], 0.5);
  free(rgb);
}

/* Distribution 1 numbers the faces of all meshes in a row; 2 splits the
   image in strips, one a mesh, strip (x + 0.5) n / W, face
   x + (W / n) max(y - 1, 0). */
static void test_meshcam_distributions_1_and_2(void **state) {
  fixture *f = *state;
  char text[2048];
  mesh_scene(text, sizeof text, 6, 6,
             "mesh_camera { 1 1 mesh { M } mesh { M2 translate y } }");
  float *rgb = render(f, text, 4, 3);
  static const int faces[12] = {0, 1, 2, 3, 0, 1, 2, 3, 4, 5, 0, 1};
  for (int i = 0; i < 12; i++)
    check_face(rgb + 3 * i, faces[i], i >= 10 ? 1.0 : 0.0);
  free(rgb);
  mesh_scene(text, sizeof text, 30, 30,
             "mesh_camera { 1 2 mesh { M } mesh { M2 translate y } "
             "mesh { M translate 2*y } }");
  rgb = render(f, text, 4, 5);
  static const int strip[4] = {0, 1, 1, 2};
  for (int y = 0; y < 5; y++)
    for (int x = 0; x < 4; x++)
      check_face(rgb + 3 * (4 * y + x), x + (y > 0 ? y - 1 : 0),
                 strip[x]);
  free(rgb);
}

/* location z moves the origin along the face's normal, direction z < 0
   turns the ray round, and max_distance stops it (the background). */
static void test_meshcam_location_direction_max_distance(void **state) {
  fixture *f = *state;
  char text[2048];
  static const struct {
    const char *camera;
    double wall; /* a white wall at this z (0: none) */
    double rgb[3];
  } cases[] = {
      {"mesh_camera { 1 0 mesh { M } } location <0,0,-1>", -0.5, {1, 1, 1}},
      {"mesh_camera { 1 0 mesh { M } } location <0,0,1> direction -z", 0.5,
       {1, 1, 1}},
      {"mesh_camera { 1 0 mesh { M } } direction <0,0,-1>", 0, {0, 1, 0}},
      {"mesh_camera { 1 0 mesh { M } } location <0,0,-1> direction -z",
       -0.5, {0, 1, 0}},
      {"mesh_camera { 1 0 mesh { M } } translate -6*z", 0, {0, 1, 0}},
      {"mesh_camera { 1 0 3 mesh { M } }", 0, {0, 0, 1}},
      {"mesh_camera { 1 0 6 mesh { M } }", 0, {0, 0.25, 0}},
  };
  for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
    mesh_scene(text, sizeof text, 4, 4, cases[i].camera);
    if (cases[i].wall != 0) {
      char wall[128];
      snprintf(wall, sizeof wall, "plane { z, %g pigment { rgb 1 } "
               "finish { ambient 1 diffuse 0 } }\n", cases[i].wall);
      strcat(text, wall);
    }
    float *rgb = render(f, text, 1, 1);
    for (int k = 0; k < 3; k++)
      assert_near(rgb[k], cases[i].rgb[k], POV_TOL);
    free(rgb);
  }
}

/* Distribution 3: sample (sx, sy) maps to u = min(sx - 0.5, W - 1.5) / W
   and v = 1 - max(sy - 0.5, 0.5) / H, the ray leaving the point of the
   face whose uv holds it.  Two faces cover uv [0,1]^2 as the square
   [0,4]^2 of the x-y plane, so the plane (red x/4, green y/4) shows
   (u, v). */
static void test_meshcam_distribution_3(void **state) {
  fixture *f = *state;
  const char *text =
      "#declare M = mesh {\n"
      "  triangle { <0,0,0>, <0,4,0>, <4,0,0> uv_vectors <0,0>, <0,1>, "
      "<1,0> }\n"
      "  triangle { <4,4,0>, <4,0,0>, <0,4,0> uv_vectors <1,1>, <1,0>, "
      "<0,1> } }\n"
      "camera { mesh_camera { 1 3 mesh { M } } }\n"
      "plane { z, 5 pigment { average pigment_map {\n"
      "  [1 function { x/4 } color_map { [0 rgb 0] [1 rgb <2,0,0>] }]\n"
      "  [1 function { y/4 } color_map { [0 rgb 0] [1 rgb <0,2,0>] }]\n"
      "} } finish { ambient 1 diffuse 0 } }\n";
  float *rgb = render(f, text, 16, 8);
  for (int y = 0; y < 8; y++)
    for (int x = 0; x < 16; x++) {
      const float *px = rgb + 3 * (16 * y + x);
      /* povray: x for every column but the last (14.5), y for every row
         but the first (0.5). */
      assert_near(px[0], (x < 15 ? x : 14.5) / 16.0, POV_TOL);
      assert_near(px[1], 1.0 - (y > 0 ? y : 0.5) / 8.0, POV_TOL);
    }
  free(rgb);
}

/* With smooth, distribution 3 shoots along the blend of the corners'
   unit normals.  Where the rays reach a sphere of radius 1000 round the
   mesh, divided by 1000, in a 4 x 4 render (povray's values). */
static void test_meshcam_distribution_3_smooth(void **state) {
  fixture *f = *state;
  const char *text =
      "#declare N0 = <1,0,1>; #declare N1 = <0,1,1>; #declare N2 = z;\n"
      "#declare M = mesh {\n"
      "  smooth_triangle { <0,0,0>, N0, <0,4,0>, N1, <4,0,0>, N2\n"
      "    uv_vectors <0,0>, <0,1>, <1,0> }\n"
      "  smooth_triangle { <4,4,0>, N2, <4,0,0>, N1, <0,4,0>, N0\n"
      "    uv_vectors <1,1>, <1,0>, <0,1> } }\n"
      "camera { mesh_camera { 1 3 mesh { M } smooth } }\n";
  zr_scene *s = good(f, text);
  static const struct {
    int x, y;
    double at[3];
  } cases[] = {
      {0, 3, {0.588, 0.197, 0.784}},
      {1, 3, {0.405, 0.203, 0.892}},
      {3, 0, {0.297, 0.102, 0.949}},
      {2, 2, {0.002, 0.384, 0.923}},
      {0, 0, {0.093, 0.658, 0.748}},
  };
  for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
    zr_ray ray;
    assert_true(zr__camera_mesh_ray(&s->camera, 4, 4, cases[i].x + 0.5,
                                    cases[i].y + 0.5, 0, &ray));
    zr_vec3 d = zr_v3_norm(ray.dir);
    double b = zr_v3_dot(ray.origin, d);
    double c = zr_v3_dot(ray.origin, ray.origin) - 1e6;
    double t = -b + sqrt(b * b - c);
    zr_vec3 hit = zr_v3_scale(zr_v3_madd(ray.origin, d, t), 1e-3);
    /* povray's values are printed to 1e-3. */
    assert_vec(hit, cases[i].at[0], cases[i].at[1], cases[i].at[2],
               1.5e-3);
  }
}

/* The directions of povray's omnimax camera (64 x 48 renders), and
   where it shoots no ray: beyond the 90 degree circle, and more than 45
   degrees below the direction. */
static void test_meshcam_omnimax_matches_povray(void **state) {
  fixture *f = *state;
  static const struct {
    const char *camera;
    double u, v;
    double dir[3]; /* zero: no ray */
  } cases[] = {
      {"omnimax", 0.1328125, 0.28125, {0.3286, 0.7870, 0.5222}},
      {"omnimax", -0.3359375, -0.13541667, {-0.8374, 0.0118, 0.5464}},
      {"omnimax", 0.2890625, -0.34375, {0.7264, -0.3816, 0.5716}},
      {"omnimax", 0.0078125, -0.48958333, {0.0206, -0.6904, 0.7232}},
      {"omnimax", 0.0078125, 0.44791667, {0.0174, 0.9838, 0.1780}},
      {"omnimax", -0.4609375, -0.48958333, {0, 0, 0}},
      {"omnimax", 0.4921875, 0.07291667, {0, 0, 0}},
      {"omnimax right x", 0.1328125, 0.28125, {0.3288, 0.6964, 0.6378}},
      {"omnimax right x", -0.3359375, -0.13541667,
       {-0.7988, -0.3220, 0.5082}},
      {"omnimax right x", 0.4921875, 0.07291667, {0.9892, 0.1466, 0.0088}},
      {"omnimax right x", 0.2890625, -0.34375, {0, 0, 0}},
      {"omnimax right x", -0.1796875, -0.42708333, {0, 0, 0}},
  };
  for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
    char text[128];
    snprintf(text, sizeof text, "camera { %s }\n", cases[i].camera);
    zr_scene *s = good(f, text);
    zr_ray ray;
    bool shot = zr__camera_project(&s->camera, cases[i].u, cases[i].v, &ray);
    if (cases[i].dir[2] == 0) {
      assert_false(shot);
      continue;
    }
    assert_true(shot);
    zr_vec3 d = zr_v3_norm(ray.dir);
    assert_vec(d, cases[i].dir[0], cases[i].dir[1], cases[i].dir[2],
               POV_TOL);
  }
}

/* function { transform { ... } } gives the point transformed, and
   F(x,y,z).y one component; povray 3.7 prints the same. */
static void test_meshcam_transform_functions(void **state) {
  fixture *f = *state;
  /* vtransform as transforms.inc declares it. */
  good(f, "#macro vtransform(vec, trans)\n"
          "  #local fn = function { transform { trans } }\n"
          "  #local result = (fn(vec.x, vec.y, vec.z));\n"
          "  result\n"
          "#end\n"
          "#declare F = function { transform { rotate z*90 "
          "translate <1,2,3> } }\n"
          "#declare V = F(1,0,0);\n"
          "#debug vstr(3, V, \",\", 0, 4)\n"
          "#debug \" \"\n"
          "#declare G = function { F(x,y,z).y * 10 }\n"
          "#debug str(G(1,0,0), 0, 4)\n"
          "#declare T = transform { translate x }\n"
          "#declare H = function { transform { T inverse } }\n"
          "#debug concat(\" \", vstr(3, H(0,0,0), \",\", 0, 4))\n"
          "#declare W = vtransform(x, transform { scale 2 rotate y*90 });\n"
          "#debug concat(\" \", vstr(3, W, \",\", 0, 4))\n");
  assert_string_equal(f->diag.debug, "1.0000,3.0000,3.0000 30.0000 "
                                     "-1.0000,0.0000,0.0000 "
                                     "0.0000,0.0000,-2.0000");
}

static void test_meshcam_bad_input(void **state) {
  fixture *f = *state;
  const char *m = "#declare M = mesh { triangle { 0, x, y } }\n";
  char text[512];
#define BAD(camera, status, message)                                       \
  do {                                                                     \
    snprintf(text, sizeof text, "%scamera { %s }\n", m, camera);           \
    bad(f, text, status, message, NULL);                                   \
  } while (0)
  BAD("mesh_camera { 1 0 }", ZR_ESCENE,
      "a mesh_camera needs at least one mesh or mesh2");
  BAD("mesh_camera { 1 7 mesh { M } }", ZR_ESCENE,
      "a mesh_camera's distribution type is 0, 1, 2 or 3, not 7");
  BAD("mesh_camera { 0 0 mesh { M } }", ZR_ESCENE,
      "a mesh_camera shoots at least 1 ray per pixel, not 0");
  BAD("mesh_camera { 2 0 mesh { M } }", ZR_ESCENE,
      "distribution type 0 needs as many meshes as rays per pixel "
      "(2 rays, 1 meshes)");
  BAD("mesh_camera { 2 2 mesh { M } mesh { M } }", ZR_ESCENE,
      "distribution type 2 shoots 1 ray per pixel, not 2");
  BAD("mesh_camera { 1 0 mesh { M } smooth }", ZR_ESCENE,
      "'smooth' only works with distribution type 3");
  BAD("mesh_camera { 1 3 mesh { M } }", ZR_ESCENE,
      "distribution type 3 needs a first mesh with uv_vectors");
  BAD("mesh_camera { 1 0 sphere { 0, 1 } }", ZR_ESCENE,
      "a mesh_camera takes mesh or mesh2 objects only");
#undef BAD
  bad(f, "#declare S = sphere { 0, 1 }\nmesh { S }\n", ZR_ESCENE,
      "only a mesh or mesh2 identifier can start a mesh { } block", NULL);
  /* The full text: location and caret. */
  snprintf(text, sizeof text, "%scamera { mesh_camera { 1 7 mesh { M } } }\n",
           m);
  bad(f, text, ZR_ESCENE,
      "a mesh_camera's distribution type is 0, 1, 2 or 3, not 7",
      "t.pov:2:26: error: a mesh_camera's distribution type is 0, 1, 2 or "
      "3, not 7\n"
      "    2 | camera { mesh_camera { 1 7 mesh { M } } }\n"
      "      |                          ^\n");
  /* Distribution 1 renders one ray per pixel, as povray 3.7 does. */
  snprintf(text, sizeof text, "%scamera { mesh_camera { 2 1 mesh { M } } }\n",
           m);
  good(f, text);
  assert_int_equal(f->diag.warnings, 1);
  assert_non_null(strstr(f->diag.warning, "distribution type 1 shoots 1 "
                                          "ray per pixel, as povray 3.7 "
                                          "renders it, not 2"));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test_setup_teardown(test_meshcam_distribution_0, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_meshcam_distributions_1_and_2,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(
          test_meshcam_location_direction_max_distance, setup, teardown),
      cmocka_unit_test_setup_teardown(test_meshcam_distribution_3, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_meshcam_distribution_3_smooth,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_meshcam_omnimax_matches_povray,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_meshcam_transform_functions,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_meshcam_bad_input, setup,
                                      teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
