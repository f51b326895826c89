/*
 * test_camlight.c - camera projections, light source kinds and
 * atmospheric effects: parsed from scene text, then checked against
 * values measured from povray 3.7 renders (16-bit PPM, File_Gamma 1.0,
 * no antialiasing) of the same scenes, and the bad inputs' messages.
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
#include "trace/lights.h"
#include "trace/render.h"
#include "test_util.h"

/* povray's 16-bit output steps by 1.5e-5 and its single precision
   colour arithmetic adds a little more; directions are read back from
   a gradient over [-1, 1], which doubles the step. */
#define POV_TOL 2e-4

/* One measured camera ray: the unit direction povray's camera gives at
   image point (u, v) (a 64 x 48 render of a sphere round the camera
   whose pigment is a gradient along x, y or z). */
typedef struct measured_ray {
  const char *camera;
  double u, v;
  double dir[3];
} measured_ray;

static const measured_ray measured_rays[] = {
    {"fisheye angle 180", 0.1328125, 0.07291667, {0.5221, 0.2155, 0.8250}},
    {"fisheye angle 180", -0.1796875, -0.13541667,
     {-0.6609, -0.3745, 0.6501}},
    {"ultra_wide_angle", -0.4140625, 0.42708333, {-0.5811, 0.4638, 0.6686}},
    {"ultra_wide_angle", 0.2890625, -0.34375, {0.4322, -0.3891, 0.8134}},
    {"panoramic", -0.4140625, 0.42708333, {-0.2858, 0.9563, 0.0595}},
    {"panoramic", 0.2890625, -0.34375, {0.4699, -0.8384, 0.2757}},
    {"cylinder 1", -0.4140625, 0.42708333, {-0.5568, 0.3927, 0.7318}},
    {"cylinder 1", 0.2890625, -0.34375, {0.4148, -0.3250, 0.8498}},
    {"cylinder 2", -0.4140625, 0.42708333, {-0.4824, 0.5445, 0.6861}},
    {"cylinder 2", 0.2890625, -0.34375, {0.3588, -0.4798, 0.8005}},
    {"spherical angle 200, 100", -0.4140625, 0.42708333,
     {-0.7290, 0.6782, 0.0919}},
    {"spherical angle 200, 100", 0.2890625, -0.34375,
     {0.6985, -0.5645, 0.4396}},
};

static void test_camlight_projections_match_povray(void **state) {
  fixture *f = *state;
  for (size_t i = 0; i < sizeof measured_rays / sizeof *measured_rays;
       i++) {
    const measured_ray *m = &measured_rays[i];
    char text[256];
    snprintf(text, sizeof text, "camera { %s }\n", m->camera);
    zr_scene *s = good(f, text);
    zr_ray ray;
    assert_true(zr__camera_project(&s->camera, m->u, m->v, &ray));
    double l = zr_v3_len(ray.dir);
    assert_near(ray.dir.x / l, m->dir[0], POV_TOL);
    assert_near(ray.dir.y / l, m->dir[1], POV_TOL);
    assert_near(ray.dir.z / l, m->dir[2], POV_TOL);
  }
}

static void test_camlight_fisheye_circle_and_cylinder_origins(void **state) {
  fixture *f = *state;
  zr_ray ray;
  /* povray renders black outside the circle of radius 0.5 in
     (u |right|, v |up|) units: (-0.414, 0.427) lies at 0.77. */
  zr_scene *s = good(f, "camera { fisheye angle 180 }\n");
  assert_false(zr__camera_project(&s->camera, -0.4140625, 0.42708333, &ray));
  /* Types 3 and 4 move the origin along up and right (exact). */
  s = good(f, "camera { cylinder 3 location <1,2,3> up 2*y }\n");
  assert_true(zr__camera_project(&s->camera, 0.1, 0.25, &ray));
  assert_near(ray.origin.y, 2.5, 1e-12);
  assert_near(ray.dir.y, 0.0, 1e-12);
  s = good(f, "camera { cylinder 4 location <1,2,3> }\n");
  assert_true(zr__camera_project(&s->camera, 0.25, 0.1, &ray));
  assert_near(ray.origin.x, 1 + 0.25 * 1.33, 1e-12);
  assert_near(ray.dir.x, 0.0, 1e-12);
}

/* povray: a plane at z = 0 seen by an orthographic camera at -10 z; the
   hit at the left edge of a 64 x 48 image (u = -0.4921875). */
static void test_camlight_orthographic_view_sizes(void **state) {
  fixture *f = *state;
  static const struct {
    const char *camera;
    double x;
  } cases[] = {
      /* right and up given: their own lengths, 4 * u. */
      {"orthographic location -10*z right 4*x up 3*y", -1.9687},
      /* none given: as wide as the perspective view at the default
         look_at point <0,0,1>, 11 units away. */
      {"orthographic location -10*z", -7.2001},
      {"orthographic location -10*z look_at 0 angle 60", -5.6828},
      {"orthographic location -10*z angle 60", -6.2510},
  };
  for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
    char text[256];
    snprintf(text, sizeof text, "camera { %s }\n", cases[i].camera);
    zr_scene *s = good(f, text);
    zr_ray ray;
    assert_true(zr__camera_project(&s->camera, -0.4921875, 0.0, &ray));
    double t = -ray.origin.z / ray.dir.z;
    /* povray's hit positions are read from a 16-bit gradient over 40
       units: 6e-4 per step. */
    assert_near(ray.origin.x + t * ray.dir.x, cases[i].x, 1.5e-3);
  }
}

/* look_at keeps the handedness of right, up and direction; a degenerate
   triple (up along direction, or right in the plane of the other two)
   counts as mirrored, as POV-Ray 3.7 renders it: a camera above a
   gradient x plane with up z and sky z sees x grow to the left with the
   default direction z and with direction x, to the right with
   direction -y (measured). */
static void test_camlight_look_at_handedness(void **state) {
  fixture *f = *state;
  static const struct {
    const char *direction;
    double right_x; /* the sign of right's x after look_at */
  } cases[] = {{"", -1}, {"direction x", -1}, {"direction y", -1},
               {"direction -y", 1}};
  for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
    char text[256];
    snprintf(text, sizeof text,
             "camera { orthographic location <0, 10, 0> %s right 2 * x "
             "up 2 * z sky z look_at 0 }\n",
             cases[i].direction);
    zr_scene *s = good(f, text);
    assert_near(s->camera.right.x, 2 * cases[i].right_x, 1e-12);
    assert_near(s->camera.up.z, 2, 1e-12);
  }
}

/* #declare C = camera { ... } and camera { C ... }: the declared camera
   is the one the same block would have made, a declaration leaves the
   scene's camera alone, and items after the identifier act on it. */
static void test_camlight_camera_identifiers(void **state) {
  fixture *f = *state;
  const char *block = "camera { angle 60 location <2,2.5,-3> "
                      "look_at <0,1,0> }\n";
  zr_scene *s = good(f, block);
  zr_camera direct = s->camera;
  char text[512];
  snprintf(text, sizeof text, "#declare C0 = camera { location -9*z }\n"
           "#declare C1 = %scamera { C1 }\n", block);
  s = good(f, text);
  assert_true(s->camera.given);
  assert_memory_equal(&s->camera.location, &direct.location,
                      sizeof direct.location);
  assert_memory_equal(&s->camera.direction, &direct.direction,
                      sizeof direct.direction);
  assert_memory_equal(&s->camera.right, &direct.right, sizeof direct.right);
  assert_memory_equal(&s->camera.up, &direct.up, sizeof direct.up);
  assert_near(s->camera.h_angle, direct.h_angle, 0.0);
  /* A declaration alone: the default camera. */
  s = good(f, "#declare C = camera { location <5,5,5> }\n");
  assert_false(s->camera.given);
  assert_near(s->camera.location.x, 0.0, 0.0);
  /* A transform after the identifier moves the placed camera. */
  s = good(f, "#declare C = camera { location -3*z look_at 0 }\n"
              "camera { C translate 2*x }\n");
  assert_near(s->camera.location.x, 2.0, 1e-12);
  assert_near(s->camera.location.z, -3.0, 1e-12);
}

/* Declared lights, and lights inside unions: they follow the object's
   transforms, and every use of a declared union brings its own. */
static void test_camlight_lights_declared_and_in_unions(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "#declare L = light_source { <0, 0, 0> rgb 1 }\n");
  assert_int_equal(s->n_lights, 0);
  s = good(f, "#declare L = light_source { <0, 0, 0> rgb 1 }\n"
              "light_source { L translate x }\n"
              "object { L translate 2*z }\n");
  assert_int_equal(s->n_lights, 2);
  assert_near(s->lights[0].location.x, 1.0, 1e-12);
  assert_near(s->lights[1].location.z, 2.0, 1e-12);
  s = good(f, "#declare U = union { light_source { <1, 0, 0> rgb 1 }\n"
              "  sphere { 0, 1 } }\n"
              "object { U translate y }\n"
              "object { U rotate 90*z }\n");
  assert_int_equal(s->n_lights, 2);
  assert_int_equal(s->n_objects, 2);
  assert_near(s->lights[0].location.x, 1.0, 1e-12);
  assert_near(s->lights[0].location.y, 1.0, 1e-12);
  assert_near(s->lights[1].location.x, 0.0, 1e-12);
  assert_near(s->lights[1].location.y, 1.0, 1e-12);
  /* The declaration itself is unchanged by the uses. */
  s = good(f, "#declare U = union { light_source { <1, 0, 0> rgb 1 }\n"
              "  sphere { 0, 1 } }\n"
              "object { U scale 3 }\nobject { U }\n");
  assert_near(s->lights[0].location.x, 3.0, 1e-12);
  assert_near(s->lights[1].location.x, 1.0, 1e-12);
}

/* Factors measured under a light 10 units above a white plane (diffuse
   1, ambient 0): brightness / cos(incidence). */
static void test_camlight_spot_cylinder_fade_factors(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "light_source { <0,10,0> 1 spotlight point_at 0 "
                        "radius 10 falloff 30 }\n"
                        "light_source { <0,10,0> 1 spotlight point_at 0 "
                        "radius 10 falloff 30 tightness 10 }\n"
                        "light_source { <0,10,0> 1 cylinder point_at 0 "
                        "radius 2 falloff 6 tightness 3 }\n"
                        "light_source { <0,10,0> 1 fade_distance 5 "
                        "fade_power 2 }\n"
                        "light_source { <0,10,0> 1 fade_distance 5 "
                        "fade_power 1 }\n");
  assert_int_equal(s->n_lights, 5);
  /* The plane points at x = 3.1840 and 4.7761 (17.66 and 25.53 degrees
     off the axis) and 1.5920 (9.05 degrees). */
  assert_near(zr__light_cone(&s->lights[0], zr_v3(3.1840, 0, 0)), 0.82193,
              POV_TOL);
  assert_near(zr__light_cone(&s->lights[0], zr_v3(4.7761, 0, 0)), 0.22348,
              POV_TOL);
  assert_near(zr__light_cone(&s->lights[0], zr_v3(7, 0, 0)), 0.0, 0.0);
  assert_near(zr__light_cone(&s->lights[1], zr_v3(1.5920, 0, 0)), 0.88237,
              POV_TOL);
  assert_near(zr__light_cone(&s->lights[2], zr_v3(1.5920, 0, 0)), 0.39652,
              POV_TOL);
  assert_near(zr__light_cone(&s->lights[2], zr_v3(3.1840, 0, 0)), 0.08156,
              POV_TOL);
  assert_near(zr__light_fade(&s->lights[3], 10), 0.4, POV_TOL);
  assert_near(zr__light_fade(&s->lights[4], 10), 2.0 / 3.0, POV_TOL);
  /* A cylinder light arrives along its axis (povray lights the plane
     under it at normal incidence). */
  zr_vec3 l;
  zr_rgb c;
  assert_true(zr__light_arrive(&s->lights[2], zr_v3(1, 0, 0), &l, &c));
  assert_near(l.y, 1.0, 1e-12);
  /* The light that arrives carries both factors (zr__light_arrive_way
     asks for each only where the light has a cone or fades). */
  assert_near(c.r, zr__light_cone(&s->lights[2], zr_v3(1, 0, 0)), 1e-15);
  assert_near(c.r, pow(1.0 - 1.0 / 6.0, 3.0), 1e-12);
  assert_true(zr__light_arrive(&s->lights[0], zr_v3(3.1840, 0, 0), &l, &c));
  assert_near(c.g, 0.82193, POV_TOL);
  assert_true(zr__light_arrive(&s->lights[3], zr_v3(0, 0, 0), &l, &c));
  assert_near(c.b, 0.4, 1e-12);
  assert_false(zr__light_arrive(&s->lights[0], zr_v3(7, 0, 0), &l, &c));
}

/* Renders the scene text at w x h and returns the floats (caller
   frees). */
static float *render(fixture *f, const char *text, int w, int h,
                     int threads_split) {
  zr_scene *s = good(f, text);
  zr_render_params p;
  zr_render_params_init(&p);
  p.width = w;
  p.height = h;
  float *rgb = calloc((size_t)w * h * 3, sizeof *rgb);
  assert_non_null(rgb);
  if (!threads_split) {
    assert_int_equal(zr_render_image(s, &p, rgb, NULL), ZR_OK);
    return rgb;
  }
  /* Odd pixels in one call, even ones in another, as two threads or
     ranks would share them. */
  size_t n = (size_t)w * h;
  uint32_t *pix = malloc(n * sizeof *pix);
  float *part = malloc(n * 3 * sizeof *part);
  assert_true(pix && part);
  for (int parity = 0; parity < 2; parity++) {
    size_t k = 0;
    for (size_t i = parity; i < n; i += 2)
      pix[k++] = (uint32_t)i;
    assert_int_equal(
        zr_render_pixels(s, &p, pix, k, NULL, part, NULL), ZR_OK);
    for (size_t j = 0; j < k; j++)
      memcpy(rgb + 3 * pix[j], part + 3 * j, 3 * sizeof *rgb);
  }
  free(pix);
  free(part);
  return rgb;
}

/* A 1 x 1 view of a black or coloured wall at distance 1 through fog:
   povray gives these pixels (fog rgb <1,0.5,0>, distance 1, wall
   rgb <0.2,0.6,1>, the camera outside the hollow wall). */
static void test_camlight_fog_filter_and_transmit(void **state) {
  fixture *f = *state;
  static const struct {
    const char *fog;
    double rgb[3];
  } cases[] = {
      {"rgb <1,0.5,0>", {0.7057, 0.5368, 0.3679}},
      {"rgbt <1,0.5,0,0.5>", {0.6000, 0.5500, 0.5000}},
      {"rgbf <1,0.5,0,0.5>", {0.7057, 0.4816, 0.1839}},
      {"rgbft <1,0.5,0,0.3,0.2>", {0.7057, 0.5037, 0.2575}},
      /* A colour expression (lights/circular.pov writes "Wheat*.5"),
         and an item's value that goes on ("distance 1 - 0"). */
      {"<2,1,0>*0.5", {0.7057, 0.5368, 0.3679}},
      {"<1,0.5,0> distance 1 - 0", {0.7057, 0.5368, 0.3679}},
  };
  for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
    char text[512];
    snprintf(text, sizeof text,
             "camera { location 0 direction z right 0.001*x up 0.001*y }\n"
             "fog { distance 1 %s }\n"
             "plane { z, 1 hollow pigment { rgb <0.2,0.6,1> } "
             "finish { ambient 1 diffuse 0 } }\n",
             cases[i].fog);
    float *rgb = render(f, text, 1, 1, 0);
    for (int k = 0; k < 3; k++)
      assert_near(rgb[k], cases[i].rgb[k], POV_TOL);
    free(rgb);
  }
}

/* Horizontal rays through a ground fog (offset 0.5, alt 1, distance 5)
   to a black wall 5 units away: povray's fog share at three heights,
   which fit a density of 1 / (1 + x^2), not the manual's
   1 / (1 + x)^2. */
static void test_camlight_ground_fog_density(void **state) {
  fixture *f = *state;
  float *rgb = render(f,
                      "camera { orthographic location <0,2,0> direction z "
                      "right 0.01*x up 4*y }\n"
                      "fog { fog_type 2 distance 5 fog_offset 0.5 "
                      "fog_alt 1 rgb 1 }\n"
                      "plane { z, 5 hollow pigment { rgb 0 } "
                      "finish { ambient 0 diffuse 0 } }\n",
                      1, 40, 0);
  /* Rows 0, 24 and 39: heights 3.95, 1.55 and 0.05. */
  assert_near(rgb[0], 0.0746, POV_TOL);
  assert_near(rgb[3 * 24], 0.3785, POV_TOL);
  assert_near(rgb[3 * 39], 0.6321, POV_TOL);
  free(rgb);
}

/* The arc of a white rainbow (angle 20, arc 120, falloff 60) seen
   through a 90 degree camera at 101 x 101: povray's values at 0, 40, 50
   and 60 degrees round the arc. */
static void test_camlight_rainbow_arc(void **state) {
  fixture *f = *state;
  float *rgb = render(f,
                      "camera { location 0 direction z right x up y "
                      "angle 90 }\n"
                      "rainbow { angle 20 width 10 direction z "
                      "arc_angle 120 falloff_angle 60 up y "
                      "color_map { [0 rgb 1] [1 rgb 1] } }\n",
                      101, 101, 0);
  static const struct {
    int phi;
    double value;
  } cases[] = {{0, 1.0}, {40, 0.7136}, {50, 0.2864}, {60, 0.0}};
  double r = tan(20 * M_PI / 180) * 0.5;
  for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
    double a = cases[i].phi * M_PI / 180;
    int x = (int)((r * sin(a) + 0.5) * 101);
    int y = (int)((0.5 - r * cos(a)) * 101);
    assert_near(rgb[3 * (y * 101 + x)], cases[i].value, POV_TOL);
  }
  free(rgb);
}

static const char *sky_scene =
    "camera { location <0,1,-4> look_at 0 }\n"
    "sky_sphere { pigment { gradient y color_map { [0.5 rgb 1] "
    "[1 rgb <0,0,1>] } scale 2 translate -1 }\n"
    "  pigment { gradient x color_map { [0.5 rgbt 1] "
    "[0.7 rgbf <1,0,0,0.5>] } scale 0.2 }\n"
    "  emission rgb <0.8,0.8,1> rotate 20*x }\n";

/* A two-layer sky_sphere: povray's values at two pixels of a 64 x 48
   render. */
static void test_camlight_sky_sphere_layers(void **state) {
  fixture *f = *state;
  float *rgb = render(f, sky_scene, 64, 48, 0);
  static const struct {
    int pixel;
    double rgb[3];
  } cases[] = {{5 * 64 + 10, {0.4643, 0.4643, 1.0}},
               /* povray 3.7.0.10 (+FN16, File_Gamma=1.0): the filter of
                  rgbf <1,0,0,0.5> passes what is below untinted. */
               {40 * 64 + 50, {0.8, 0.4, 0.5}},
               {20 * 64 + 33, {0.6593, 0.6593, 1.0}}};
  for (size_t i = 0; i < sizeof cases / sizeof *cases; i++)
    for (int k = 0; k < 3; k++)
      assert_near(rgb[3 * cases[i].pixel + k], cases[i].rgb[k], POV_TOL);
  free(rgb);
  zr_scene *s = good(f, sky_scene);
  assert_non_null(s->settings.sky_sphere);
  assert_int_equal(s->settings.sky_sphere->n_pigments, 2);
  assert_near(s->settings.sky_sphere->emission.b, 1.0, 0.0);
  /* A declared sky_sphere, used with a transform of its own (skies.inc
     declares them). */
  s = good(f, "#declare S = sky_sphere { pigment { rgb 0.5 } }\n"
              "sky_sphere { S rotate 10*x }\n");
  assert_non_null(s->settings.sky_sphere);
  assert_int_equal(s->settings.sky_sphere->n_pigments, 1);
  assert_non_null(s->settings.sky_sphere->transform);
}

/* Area light jitter and focal blur use per-pixel hashes: splitting the
   pixels between calls changes nothing, to the bit. */
static void test_camlight_soft_effects_independent_of_split(void **state) {
  fixture *f = *state;
  const char *text =
      "camera { location <0,3,-6> look_at 0 aperture 0.4 blur_samples 8 "
      "focal_point <0,0,0> }\n"
      "light_source { <3,8,-3> 1 area_light 2*x, 2*z, 4, 4 jitter "
      "adaptive 1 circular orient }\n"
      "plane { y, 0 pigment { rgb 1 } }\n"
      "sphere { <0,1,0>, 1 pigment { rgb <1,0.5,0.2> } }\n";
  float *a = render(f, text, 24, 18, 0);
  float *b = render(f, text, 24, 18, 1);
  assert_memory_equal(a, b, 24 * 18 * 3 * sizeof *a);
  free(a);
  free(b);
}

/* A clear slab of depth 2 with a faded interior in front of a white
   background: povray's pixels. */
static void test_camlight_interior_fade(void **state) {
  fixture *f = *state;
  static const struct {
    const char *interior;
    double rgb[3];
  } cases[] = {
      {"fade_distance 1 fade_power 2", {0.2, 0.2, 0.2}},
      {"fade_distance 2 fade_power 2 fade_color <1,0.5,0>",
       {1.0, 0.75, 0.5}},
      {"fade_distance 2 fade_power 1001", {0.3679, 0.3679, 0.3679}},
  };
  for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
    char text[512];
    snprintf(text, sizeof text,
             "camera { location <0,0,-5> direction z right 0.001*x "
             "up 0.001*y }\n"
             "background { rgb 1 }\n"
             "box { <-1,-1,0>, <1,1,2> pigment { rgbt 1 } finish { "
             "ambient 0 diffuse 0 } interior { ior 1 %s } }\n",
             cases[i].interior);
    float *rgb = render(f, text, 1, 1, 0);
    for (int k = 0; k < 3; k++)
      assert_near(rgb[k], cases[i].rgb[k], POV_TOL);
    free(rgb);
  }
}

/* looks_like: the object moves to the light and casts no shadow. */
static void test_camlight_looks_like(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "light_source { <3,4,-3> 1 looks_like { sphere { "
                        "0, 0.3 } } translate y }\n");
  assert_int_equal(s->n_objects, 1);
  const zr_object *o = s->objects[0];
  assert_true(o->no_shadow);
  zr_vec3 lo, hi;
  assert_true(zr__object_bounds(o, &lo, &hi));
  assert_near(0.5 * (lo.y + hi.y), 5.0, 1e-9);
  assert_near(s->lights[0].location.y, 5.0, 1e-12);
}

/* A red sphere seen head on in front of a white wall lit from behind
   the camera, and a mirror that shows it: no_image hides it from the
   camera but not from the mirror or the light (its shadow stays);
   no_reflection hides it in the mirror only. */
static void test_camlight_no_image_no_reflection(void **state) {
  fixture *f = *state;
  static const char *scene =
      "camera { location <0, 0, -5> look_at 0 angle 10 }\n"
      "light_source { <0, 0, -20> rgb 1 }\n"
      "sphere { 0, 0.1 pigment { rgb <1, 0, 0> } finish { ambient 1 "
      "diffuse 0 } %s }\n"
      "plane { z, 1 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n";
  static const char *mirror =
      "camera { location <0, 0, -5> look_at <0, 0, 10> angle 10 }\n"
      "sphere { <0, 0, -10>, 1 pigment { rgb <1, 0, 0> } finish { "
      "ambient 1 diffuse 0 } %s }\n"
      "plane { z, 1 pigment { rgb 0 } finish { ambient 0 diffuse 0 "
      "reflection 1 } }\n";
  char text[1024];
  const char *mods[] = {"", "no_image", "no_reflection"};
  /* Direct view: red, the wall in its shadow (black), red. */
  const double direct_r[] = {1, 0, 1};
  /* In the mirror (the camera is inside no sphere): red, red, black. */
  const double mirrored_r[] = {1, 1, 0};
  for (int i = 0; i < 3; i++) {
    snprintf(text, sizeof text, scene, mods[i]);
    float *rgb = render(f, text, 1, 1, 0);
    assert_near(rgb[0], direct_r[i], 1e-6);
    assert_near(rgb[1], 0.0, 1e-6);
    free(rgb);
    snprintf(text, sizeof text, mirror, mods[i]);
    rgb = render(f, text, 1, 1, 0);
    assert_near(rgb[0], mirrored_r[i], 1e-6);
    free(rgb);
  }
}

/*
 * A light 10 above a white floor projected through a sphere halfway
 * down, seen from above (24 x 24 pixels of 0.25 units): a plate under
 * the sphere shadows, a plate over it, a ball inside it and a copy of
 * the sphere do not.  The pixels are povray 3.7's (16-bit PNG,
 * File_Gamma 1.0), cos(angle) = 10 / sqrt(100 + r^2) where lit.
 */
static void test_camlight_projected_through(void **state) {
  fixture *f = *state;
  static const char *scene =
      "camera { orthographic location <0,20,0> right 6*x up 6*z "
      "direction -y look_at 0 sky z }\n"
      "#declare White = texture { pigment { rgb 1 } finish { ambient 0 "
      "diffuse 1 } }\n"
      "plane { y, 0 texture { White } }\n"
      "#declare PT = sphere { <0,5,0>, 1 }\n"
      "box { <0,7.5,-3>, <3,7.6,3> texture { White } no_image }\n"
      "box { <-3,2,0.5>, <-0.5,2.1,3> texture { White } no_image }\n"
      "sphere { <0,5,0>, 0.3 texture { White } no_image }\n"
      "object { PT texture { White } no_image }\n"
      "light_source { <0,10,0> rgb 1 projected_through { %s } %s }\n";
  static const struct {
    int i, j;
    double lit, moved;
  } pixels[] = {
      {14, 14, 0.99611, 0.99426}, /* under the upper plate */
      {7, 7, 0.0, 0.0},           /* in the lower plate's shadow */
      {21, 11, 0.0, 0.99611},     /* off the spot, then in it */
      {12, 12, 0.99985, 0.0},     /* through the ball and the copy; moved,
                                     the copy is under the sphere */
      {2, 12, 0.0, 0.0},
  };
  char text[2048];
  for (int moved = 0; moved < 2; moved++) {
    snprintf(text, sizeof text, scene, moved ? "PT" : "object { PT }",
             moved ? "translate <1.5, 0, 0>" : "");
    float *rgb = render(f, text, 24, 24, 0);
    for (size_t k = 0; k < sizeof pixels / sizeof pixels[0]; k++) {
      const float *px = rgb + 3 * (pixels[k].j * 24 + pixels[k].i);
      assert_near(px[0], moved ? pixels[k].moved : pixels[k].lit, POV_TOL);
    }
    free(rgb);
  }
  /* The object is the light's alone. */
  assert_int_equal(f->scene->n_objects, 5);
  /* Each copy of a declared light moves its own object. */
  zr_scene *s = good(f, "#declare L = light_source { <0,10,0> 1 "
                        "projected_through { sphere { <0,5,0>, 1 } } }\n"
                        "light_source { L translate 2*x }\n"
                        "light_source { L }\n");
  assert_int_equal(s->n_lights, 2);
  zr_vec3 lo, hi;
  assert_true(zr__object_bounds(s->lights[0].projected_through, &lo, &hi));
  assert_near(0.5 * (lo.x + hi.x), 2.0, 1e-9);
  assert_true(zr__object_bounds(s->lights[1].projected_through, &lo, &hi));
  assert_near(0.5 * (lo.x + hi.x), 0.0, 1e-9);
  bad(f, "light_source { 0, 1 projected_through { 5 } }\n", ZR_ESYNTAX,
      "unexpected number", NULL);
}

static void test_camlight_bad_input(void **state) {
  fixture *f = *state;
  /* Dispersion is rendered (lib/trace/dispersion.c): no warning, and
     a dispersion_samples below 2 is refused where it was written, as
     povray 3.7 refuses it. */
  good(f, "sphere { 0, 1 interior { ior 1.5 dispersion 1.02 } }\n");
  assert_int_equal(f->diag.warnings, 0);
  bad(f, "sphere { 0, 1 interior { ior 1.5 dispersion_samples 1 } }\n",
      ZR_ESCENE, "dispersion_samples must be between 2 and 1000000",
      NULL);
  bad(f, "camera { cylinder 5 }\n", ZR_ESCENE,
      "a cylinder camera's type must be 1, 2, 3 or 4, not 5", NULL);
  bad(f, "camera { perspective angle 200 }\n", ZR_ESCENE,
      "a perspective camera's angle must be between 0 and 180 degrees, "
      "not 200",
      NULL);
  bad(f, "fog { fog_type 3 }\n", ZR_ESCENE,
      "fog_type must be 1 (constant) or 2 (ground fog), not 3", NULL);
  bad(f, "rainbow { direction z angle 42 width 5 }\n", ZR_ESCENE,
      "a rainbow needs a color_map", NULL);
  bad(f, "sky_sphere { }\n", ZR_ESCENE, "a sky_sphere needs a pigment",
      NULL);
  bad(f, "light_source { 0 1 area_light x, z, 0, 2 }\n", ZR_ESCENE,
      "an area light has 1 to 1024 lights a side, not 0", NULL);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test_setup_teardown(test_camlight_projections_match_povray,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(
          test_camlight_fisheye_circle_and_cylinder_origins, setup,
          teardown),
      cmocka_unit_test_setup_teardown(test_camlight_look_at_handedness,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_camlight_orthographic_view_sizes,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(
          test_camlight_spot_cylinder_fade_factors, setup, teardown),
      cmocka_unit_test_setup_teardown(test_camlight_fog_filter_and_transmit,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_camlight_ground_fog_density,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_camlight_rainbow_arc, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_camlight_sky_sphere_layers,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(
          test_camlight_soft_effects_independent_of_split, setup, teardown),
      cmocka_unit_test_setup_teardown(test_camlight_interior_fade, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_camlight_looks_like, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_camlight_projected_through,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_camlight_camera_identifiers,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(
          test_camlight_lights_declared_and_in_unions, setup, teardown),
      cmocka_unit_test_setup_teardown(test_camlight_no_image_no_reflection,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_camlight_bad_input, setup,
                                      teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
