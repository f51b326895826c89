/*
 * test_lightgroup.c - light_group (lib/sdl/build_object.c, the light
 * test in lib/trace/lights.h) and blob components with textures of
 * their own (lib/sdl/build_shape.c, the blend in lib/trace/shade.c),
 * rendered and read back.  The expected colours are those POV-Ray 3.7
 * renders for the same scenes (measured side by side): a group's
 * lights light its objects only, global lights reach a group's objects
 * only with global_lights on (off by default), every object casts
 * shadows for every light, nested groups take their parents' lights,
 * and overlapping blob components blend their textures' lit colours by
 * their fields at the point.
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

#include "scene/scene.h"
#include "zrcube.h"
#include "parse_fixture.h"
#include "test_util.h"

/* Odd: the middle pixel's centre is x = 0; a pixel is 8 / 81 wide. */
enum { W = 81, H = 21 };

/* Renders the scene (W x H, no antialiasing) and returns the linear
   colour at pixel (x, y) in rgb. */
static void pixel(fixture *f, const char *text, int x, int y,
                  float rgb[3]) {
  zr_scene *s = good(f, text);
  zr_render_params rp;
  zr_render_params_init(&rp);
  rp.width = W;
  rp.height = H;
  float *img = malloc((size_t)W * H * 3 * sizeof *img);
  assert_non_null(img);
  assert_int_equal(zr_render_image(s, &rp, img, NULL), ZR_OK);
  memcpy(rgb, img + 3 * ((size_t)y * W + (size_t)x), 3 * sizeof *rgb);
  free(img);
}

static void assert_rgb(const float c[3], double r, double g, double b,
                       double tol) {
  if (!(fabs(c[0] - r) <= tol && fabs(c[1] - g) <= tol &&
        fabs(c[2] - b) <= tol))
    fail_msg("colour <%g, %g, %g> is not <%g, %g, %g> (tolerance %g)",
             c[0], c[1], c[2], r, g, b, tol);
}

/* An orthographic view of x in [-4, 4], y in [-1, 1]; pixel column
   of x. */
#define VIEW                                                              \
  "global_settings { ambient_light 0 }\n"                                 \
  "camera { orthographic location <0, 0, -10> look_at 0 right 8 * x "     \
  "up 2 * y }\n"
#define WHITE "pigment { rgb 1 } finish { ambient 0 diffuse 1 }"
static int column(double x) { return (int)((x + 4) / 8 * W); }

/* Lights straight from the camera's side: a surface facing the camera
   gets diffuse 1 * colour * cos 0. */
static void test_lightgroup_who_is_lit(void **state) {
  fixture *f = *state;
  char text[2048];
  const char *groups[] = {"", "global_lights off", "global_lights on",
                          "global_lights"};
  for (int k = 0; k < 4; k++) {
    snprintf(text, sizeof text,
             VIEW "light_source { <0, 0, -1000> rgb <0, 1, 0> }\n"
                  "light_group {\n"
                  "  light_source { <0, 0, -1000> rgb <1, 0, 0> }\n"
                  "  sphere { <-3, 0, 0>, 0.9 " WHITE " }\n"
                  "  %s\n}\n"
                  "sphere { <0, 0, 0>, 0.9 " WHITE " }\n",
             groups[k]);
    float c[3];
    bool global = k >= 2;
    /* The group's sphere: its own light, the global one if asked. */
    pixel(f, text, column(-3), H / 2, c);
    assert_rgb(c, 1, global ? 1 : 0, 0, 0.02);
    /* The sphere outside: the global light only. */
    pixel(f, text, column(0), H / 2, c);
    assert_rgb(c, 0, 1, 0, 0.02);
  }
}

/* Every object casts shadows for a group's light: one outside the
   group, and one in another group. */
static void test_lightgroup_shadows(void **state) {
  fixture *f = *state;
  const char *blockers[] = {
      "",
      "box { <1.5, 3, -4>, <3.5, 3.2, 4> " WHITE " }",
      "light_group { box { <1.5, 3, -4>, <3.5, 3.2, 4> " WHITE " } }",
  };
  for (int k = 0; k < 3; k++) {
    char text[2048];
    snprintf(text, sizeof text,
             VIEW "light_group {\n"
                  "  light_source { <0, 100, -100> rgb <0, 0, 1> }\n"
                  "  sphere { <2.5, 0, 0>, 0.9 " WHITE " }\n"
                  "}\n%s\n",
             blockers[k]);
    float c[3];
    pixel(f, text, column(2.5), H / 4, c); /* the upper half */
    if (k == 0)
      assert_true(c[2] > 0.5 && c[0] == 0 && c[1] == 0);
    else
      assert_rgb(c, 0, 0, 0, 0);
  }
}

/* The manual's nested group: an inner group's objects take the outer
   group's lights too, the outer's objects not the inner's. */
static void test_lightgroup_nested(void **state) {
  fixture *f = *state;
  const char *text =
      VIEW "#declare L1 = light_group {\n"
           "  light_source { <0, 0, -1000> rgb <1, 0, 0> }\n"
           "  sphere { <-3, 0, 0>, 0.9 " WHITE " }\n"
           "}\n"
           "light_group {\n"
           "  light_source { <0, 0, -1000> rgb <0, 0, 1> }\n"
           "  light_group { L1 }\n"
           "  sphere { <0, 0, 0>, 0.9 " WHITE " }\n"
           "  translate 0.001 * x\n"
           "}\n";
  float c[3];
  pixel(f, text, column(-3), H / 2, c);
  assert_rgb(c, 1, 0, 1, 0.02);
  pixel(f, text, column(0), H / 2, c);
  assert_rgb(c, 0, 0, 1, 0.02);
  /* The declared group stays a group of its own where used alone. */
  const char *alone = VIEW "#declare L1 = light_group {\n"
                           "  light_source { <0, 0, -1000> rgb <1, 0, 0> }\n"
                           "  sphere { <-3, 0, 0>, 0.9 " WHITE " }\n"
                           "}\n"
                           "object { L1 }\n"
                           "light_source { <0, 0, -1000> rgb <0, 1, 0> }\n";
  pixel(f, alone, column(-3), H / 2, c);
  assert_rgb(c, 1, 0, 0, 0.02);
}

static void test_lightgroup_bad_input(void **state) {
  fixture *f = *state;
  bad(f, "light_group { sphere { 0, 1 } pigment { rgb 1 } }\n",
      ZR_ESYNTAX, "unexpected 'pigment'", NULL);
  bad(f, "light_group { sphere { 0, 1 } global_lights <1, 2> }\n",
      ZR_ESYNTAX, "expected a float, got a 2-D vector", NULL);
}

/* Two components with pigments of their own, strengths s1 and s2, at
   x = -0.6 and 0.6: at x = 0 their fields are in the ratio s1 : s2
   (the same distance from both), and so are their colours; away from
   the overlap each shows its own.  ambient 1 and no light: the colour
   is the pigment's. */
static void test_blob_component_textures(void **state) {
  fixture *f = *state;
  const double strength[2][2] = {{1, 1}, {1, 2}};
  for (int k = 0; k < 2; k++) {
    char text[2048];
    snprintf(text, sizeof text,
             "global_settings { ambient_light 1 }\n"
             "camera { orthographic location <0, 0, -10> look_at 0 "
             "right 8 * x up 2 * y }\n"
             "blob { threshold 0.3\n"
             "  sphere { <-0.6, 0, 0>, 1.5, %g pigment { rgb <1, 0, 0> }\n"
             "    finish { ambient 1 diffuse 0 } }\n"
             "  sphere { <0.6, 0, 0>, 1.5, %g\n"
             "    texture { pigment { rgb <0, 0, 1> }\n"
             "              finish { ambient 1 diffuse 0 } } }\n"
             "  sphere { <0, 0, 5>, 0.5, 1 }\n" /* no texture, out of sight */
             "  pigment { rgb <0, 1, 0> }\n"
             "}\n",
             strength[k][0], strength[k][1]);
    float c[3];
    double s1 = strength[k][0], s2 = strength[k][1];
    pixel(f, text, W / 2, H / 2, c); /* x = 0 */
    assert_near(c[0] / (c[0] + c[2]), s1 / (s1 + s2), 1e-5);
    assert_near(c[0] + c[2], 1.0, 1e-6);
    assert_near(c[1], 0.0, 0.0);
    pixel(f, text, column(-1.6), H / 2, c); /* the left one's alone */
    assert_rgb(c, 1, 0, 0, 1e-6);
    pixel(f, text, column(1.6), H / 2, c);
    assert_rgb(c, 0, 0, 1, 1e-6);
  }
  /* A component without a texture takes the blob's. */
  float c[3];
  pixel(f,
        "global_settings { ambient_light 1 }\n"
        "camera { orthographic location <0, 0, -10> look_at 0 "
        "right 8 * x up 2 * y }\n"
        "blob { threshold 0.3\n"
        "  sphere { <-2, 0, 0>, 1.5, 1 pigment { rgb <1, 0, 0> } }\n"
        "  sphere { <2, 0, 0>, 1.5, 1 }\n"
        "  pigment { rgb <0, 1, 0> } finish { ambient 1 diffuse 0 }\n"
        "  translate 0.001 * y\n"
        "}\n",
        column(2), H / 2, c);
  assert_rgb(c, 0, 1, 0, 1e-6);
  bad(f, "blob { sphere { 0, 1, 1 no_shadow } }\n", ZR_ESYNTAX,
      "a blob component takes a texture, pigment, normal, finish and "
      "transformations only",
      NULL);
}

/* A component's texture moves with the component's transformations
   written after it and with the blob's, as an object's does. */
static void test_blob_component_texture_moves(void **state) {
  fixture *f = *state;
  const char *fmt =
      "global_settings { ambient_light 1 }\n"
      "camera { orthographic location <0, 0, -10> look_at 0 "
      "right 8 * x up 2 * y }\n"
      "blob { threshold 0.1\n"
      "  sphere { 0, 1.5, 1 pigment { gradient x color_map { [0 rgb 0] "
      "[1 rgb 1] } } finish { ambient 1 diffuse 0 } %s }\n"
      "  %s\n"
      "}\n";
  char text[2048];
  float a[3], b[3];
  /* Moved two pixels (16 / 81) after its pigment: the colour two pixels
     right of x = 0.1 is that of x = 0.1 unmoved. */
  snprintf(text, sizeof text, fmt, "", "");
  pixel(f, text, W / 2 + 1, H / 2, a);
  assert_near(a[0], 8.0 / 81, 1e-5); /* gradient x: x itself */
  snprintf(text, sizeof text, fmt, "translate 16 / 81 * x", "");
  pixel(f, text, W / 2 + 3, H / 2, b);
  assert_near(a[0], b[0], 1e-5);
  snprintf(text, sizeof text, fmt, "", "translate 16 / 81 * x");
  pixel(f, text, W / 2 + 3, H / 2, b);
  assert_near(a[0], b[0], 1e-5);
  /* Moved before its pigment: the pigment does not move. */
  snprintf(text, sizeof text,
           "global_settings { ambient_light 1 }\n"
           "camera { orthographic location <0, 0, -10> look_at 0 "
           "right 8 * x up 2 * y }\n"
           "blob { threshold 0.1\n"
           "  sphere { 0, 1.5, 1 translate 16 / 81 * x pigment { gradient x "
           "color_map { [0 rgb 0] [1 rgb 1] } } finish { ambient 1 "
           "diffuse 0 } }\n"
           "}\n");
  pixel(f, text, W / 2 + 1, H / 2, b);
  assert_near(a[0], b[0], 1e-5);
}

#define TEST(fn) cmocka_unit_test_setup_teardown(fn, setup, teardown)

int main(void) {
  const struct CMUnitTest tests[] = {
      TEST(test_lightgroup_who_is_lit),
      TEST(test_lightgroup_shadows),
      TEST(test_lightgroup_nested),
      TEST(test_lightgroup_bad_input),
      TEST(test_blob_component_textures),
      TEST(test_blob_component_texture_moves),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
