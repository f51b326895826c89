/*
 * test_media.c - participating media (lib/trace/media.c) and the blocks
 * that describe them (lib/sdl/build_media.c): closed forms of
 * POV-Ray 3.7.0's sampling for constant media, values measured from
 * povray 3.7.0 renders of the same scenes (16-bit PPM, assumed_gamma 1),
 * shadows through media, hollow and solid containers, interior_texture,
 * photons blocks, and exact messages for bad input.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/arena.h"
#include "parse_fixture.h"
#include "scene/df3.h"
#include "scene/scene.h"
#include "trace/media.h"
#include "trace/render.h"
#include "trace/shade.h"
#include "test_util.h"

/* Closed forms evaluated in double precision, compared with a render's
   single precision pixels. */
#define EPS 2e-7
/* povray's 16-bit PPM quantises to 1.5e-5 after its sRGB encoding, and
   its single precision colours add about as much again. */
#define POV_TOL 2e-4

/* A 20 x 20 orthographic view of a box from z = -1 to 1 holding the
   media, in front of a plane of colour BACK (ambient 1) at z = 5.  The
   plane faces away from the camera so that the camera is not inside it
   (a ray inside a solid object sees no media). */
#define SCENE_HEAD                                                        \
  "camera { orthographic location <0,0,-10> look_at 0 right x up y }\n" \
  "plane { -z, -5 pigment { rgb 0.5 } finish { ambient 1 diffuse 0 } }\n"

static const double BACK = 0.5;

/* The centre pixel's red of a 20 x 20 render of the scene. */
static double centre_red(fixture *f, const char *text) {
  zr_scene *s = good(f, text);
  zr_render_params p;
  zr_render_params_init(&p);
  p.width = 20;
  p.height = 20;
  uint32_t index = 10 * 20 + 10;
  float rgb[3];
  assert_int_equal(zr_render_pixels(s, &p, &index, 1, NULL, rgb, NULL),
                   ZR_OK);
  return rgb[0];
}

/* POV-Ray 3.7.0's method 3 with samples 10 (the default): six
   sub-intervals, the j-th dimmed by exp(-j a d / 6). */
static double method3_default(double a, double e, double d, double back) {
  double sum = 0.0;
  for (int j = 0; j < 6; j++)
    sum += exp(-j * a * d / 6.0);
  return back * exp(-a * d) + e * d * sum / 6.0;
}

static void test_media_absorption_is_exponential(void **state) {
  fixture *f = *state;
  double v = centre_red(f, SCENE_HEAD
                        "box { <-1,-1,-1>, <1,1,1> pigment { rgbt 1 } "
                        "hollow interior { media { absorption 0.5 } } }\n");
  /* Constant media: the optical depth is exact, 0.5 * 2. */
  assert_near(v, BACK * exp(-1.0), EPS);
}

static void test_media_emission_integral(void **state) {
  fixture *f = *state;
  /* Emission alone adds e * d. */
  double v = centre_red(f, SCENE_HEAD
                        "box { <-1,-1,-1>, <1,1,1> pigment { rgbt 1 } "
                        "hollow interior { media { emission 0.1 } } }\n");
  assert_near(v, BACK + 0.2, EPS);
  /* With absorption, POV-Ray 3.7.0's sampling (closed form). */
  v = centre_red(f, SCENE_HEAD
                 "box { <-1,-1,-1>, <1,1,1> pigment { rgbt 1 } hollow "
                 "interior { media { absorption 1 emission 0.4 } } }\n");
  assert_near(v, method3_default(1, 0.4, 2, BACK), EPS);
  /* samples 3: two sub-intervals, (1 + exp(-a d / 2)) / 2. */
  v = centre_red(f, SCENE_HEAD
                 "box { <-1,-1,-1>, <1,1,1> pigment { rgbt 1 } hollow "
                 "interior { media { absorption 1 emission 0.4 samples 3 "
                 "} } }\n");
  assert_near(v, BACK * exp(-2.0) + 0.8 * (1 + exp(-1.0)) / 2, EPS);
}

/* Measured: povray 3.7.0, the same box in front of black, emission 0.4
   over d = 2, absorption a; 16-bit PPM decoded from sRGB. */
static void test_media_matches_povray(void **state) {
  fixture *f = *state;
  static const struct {
    double a;
    const char *samples;
    double povray;
  } cases[] = {
      {0.25, "", 0.65615},          {1.0, "", 0.40671},
      {2.0, "", 0.26899},           {0.5, "samples 3", 0.64260},
      {2.0, "samples 5", 0.35549},
  };
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
    char text[1024];
    snprintf(text, sizeof text,
             "camera { orthographic location <0,0,-10> look_at 0 right x "
             "up y }\n"
             "plane { -z, -5 pigment { rgb 0 } finish { ambient 1 } }\n"
             "box { <-1,-1,-1>, <1,1,1> pigment { rgbt 1 } hollow "
             "interior { media { absorption %g emission 0.4 %s } } }\n",
             cases[i].a, cases[i].samples);
    assert_near(centre_red(f, text), cases[i].povray, POV_TOL);
  }
}

static void test_media_needs_hollow_containers(void **state) {
  fixture *f = *state;
  /* A container that is not hollow shows no media... */
  double v = centre_red(f, SCENE_HEAD
                        "box { <-1,-1,-1>, <1,1,1> pigment { rgbt 1 } "
                        "interior { media { absorption 0.5 } } }\n");
  assert_near(v, BACK, EPS);
  /* ...and neither does a hollow one seen from inside a solid object:
     here the camera is inside the plane's half space. */
  v = centre_red(f, "camera { orthographic location <0,0,-10> look_at 0 "
                    "right x up y }\n"
                    "plane { z, 5 pigment { rgb 0.5 } finish { ambient 1 "
                    "diffuse 0 } }\n"
                    "box { <-1,-1,-1>, <1,1,1> pigment { rgbt 1 } hollow "
                    "interior { media { absorption 0.5 } } }\n");
  assert_near(v, BACK, EPS);
}

static void test_media_density_scales(void **state) {
  fixture *f = *state;
  /* A plain density of 0.5 halves the absorption; two densities
     multiply. */
  double v = centre_red(f, SCENE_HEAD
                        "box { <-1,-1,-1>, <1,1,1> pigment { rgbt 1 } "
                        "hollow interior { media { absorption 0.5 "
                        "density { rgb 0.5 } density { rgb 0.5 } } } }\n");
  assert_near(v, BACK * exp(-0.25), EPS);
  /* A density pattern's colour_map: planar is 1 - |y|, and the centre
     pixel's ray runs at y = 0.025 (half a pixel off the axis). */
  v = centre_red(f, SCENE_HEAD
                 "box { <-1,-1,-1>, <1,1,1> pigment { rgbt 1 } hollow "
                 "interior { media { absorption 0.5 density { planar "
                 "color_map { [0 rgb 0] [1 rgb 0.25] } } } } }\n");
  assert_near(v, BACK * exp(-0.25 * 0.975), EPS);
}

static void test_media_atmosphere(void **state) {
  fixture *f = *state;
  /* Atmospheric media fill the path from the camera to the plane (15
     units) when nothing solid holds the camera. */
  double v = centre_red(f, SCENE_HEAD "media { absorption 0.02 }\n");
  assert_near(v, BACK * exp(-0.3), EPS);
  /* A ray that hits nothing crosses them out to povray's 2e10 units:
     even thin haze hides the background, as povray renders it. */
  v = centre_red(f, "camera { location <0,0,-10> look_at 0 }\n"
                    "background { rgb 0.5 }\n"
                    "media { absorption 1e-6 }\n");
  assert_near(v, 0.5 * exp(-2e4), EPS);
  /* Interior media are only sampled up to a surface. */
  v = centre_red(f, "camera { orthographic location <0,0,-10> look_at 0 "
                    "right x up y }\n"
                    "background { rgb 0.5 }\n"
                    "box { -1, 1 pigment { rgbt 1 } hollow interior { "
                    "media { absorption 0.5 } } }\n");
  assert_near(v, 0.5 * exp(-1.0), EPS);
}

static void test_media_shadows(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "light_source { <0, 10, 0> 1 }\n"
                        "sphere { <0, 5, 0>, 1 pigment { rgbt 1 } hollow "
                        "interior { media { absorption 0.25 scattering { "
                        "1, 0.5 extinction 0.5 } } } }\n");
  zr_render_stats stats = {0};
  zr_tracer tr = {.scene = s, .stats = &stats};
  /* From the origin to the light the ray crosses 2 units of media whose
     extinction is 0.25 + 0.5 * 0.5. */
  zr_rgb c = zr__shadow_transmission(&tr, zr_v3(0, 10, 0), zr_v3(0, 0, 0));
  assert_near(c.r, exp(-2.0 * 0.5), EPS);
  /* A shadow ray that starts inside the container. */
  c = zr__shadow_transmission(&tr, zr_v3(0, 10, 0), zr_v3(0, 5, 0));
  assert_near(c.g, exp(-0.5), EPS);
}

static void test_media_scattering_lights_the_media(void **state) {
  fixture *f = *state;
  /* An isotropic scatterer lit by a white light: with no absorption
     and extinction 0 the light just adds, s * d, as emission would. */
  double v = centre_red(f, SCENE_HEAD
                        "light_source { <0, 0, 0> 1 }\n"
                        "box { <-1,-1,-1>, <1,1,1> pigment { rgbt 1 } "
                        "hollow no_shadow interior { media { scattering { "
                        "1, 0.1 extinction 0 } } } }\n");
  assert_near(v, BACK + 0.2, EPS);
  /* media_interaction off: the light does not scatter. */
  v = centre_red(f, SCENE_HEAD
                 "light_source { <0, 0, 0> 1 media_interaction off }\n"
                 "box { <-1,-1,-1>, <1,1,1> pigment { rgbt 1 } hollow "
                 "no_shadow interior { media { scattering { 1, 0.1 "
                 "extinction 0 } } } }\n");
  assert_near(v, BACK, EPS);
}

static void test_media_deterministic_jitter(void **state) {
  fixture *f = *state;
  const char *text = SCENE_HEAD
      "box { <-1,-1,-1>, <1,1,1> pigment { rgbt 1 } hollow interior { "
      "media { emission 0.3 absorption 0.7 method 1 samples 4, 20 "
      "density { bozo } } } }\n";
  double a = centre_red(f, text), b = centre_red(f, text);
  assert_true(a == b);
  assert_true(a > 0.0 && a < 1.0);
}

static void test_media_interior_texture(void **state) {
  fixture *f = *state;
  /* Seen from inside, the far side of a clear sphere wears its
     interior_texture: a red plain ambient surface. */
  double v = centre_red(
      f, SCENE_HEAD
      "sphere { 0, 2 pigment { rgbt 1 } "
      "interior_texture { pigment { rgb <0.25, 0, 0> } finish { ambient 1 "
      "diffuse 0 } } }\n");
  assert_near(v, 0.25, EPS);
}

static void test_media_photons_blocks(void **state) {
  fixture *f = *state;
  /* Objects' and lights' photons blocks alone are read quietly. */
  good(f, "light_source { 0, 1 photons { refraction on reflection off "
          "area_light } }\n"
          "sphere { 0, 1 photons { target 0.5 refraction on reflection on "
          "collect off pass_through } }\n");
  assert_int_equal(f->diag.warnings, 0);
  good(f, "global_settings {\n  photons { spacing 0.02 gather 20, 100 "
          "media 100, 2 radius 0.1, 1, 0.2 autostop 0 jitter 0.4 "
          "max_trace_level 5 adc_bailout 0.01 expand_thresholds 0.2, 40 "
          "save_file \"a.ph\" }\n}\n");
  assert_int_equal(f->diag.warnings, 1);
  assert_non_null(strstr(f->diag.warning,
                         "t.pov:2:3: warning: 'photons' is not simulated: "
                         "zRcube renders without photon mapping, so there "
                         "are no caustics"));
}

static void test_media_identifiers_and_transforms(void **state) {
  fixture *f = *state;
  /* A declared media, copied and changed; the original stays. */
  double v = centre_red(f, SCENE_HEAD
                        "#declare M = media { absorption 0.5 }\n"
                        "box { <-1,-1,-1>, <1,1,1> pigment { rgbt 1 } "
                        "hollow interior { media { M } media { M "
                        "absorption 0.25 } } }\n");
  assert_near(v, BACK * exp(-1.5), EPS);
  /* An object's transform moves its media's density: the planar
     density (1 - |y| near y = 0) of a box made at y = -10 and moved up
     by 10 is 0 on the centre ray, which runs near y = 0 + 10 - 10. */
  v = centre_red(f, SCENE_HEAD
                 "box { <-1,-11,-1>, <1,-9,1> pigment { rgbt 1 } hollow "
                 "interior { media { absorption 0.5 density { planar } } } "
                 "translate 10 * y }\n");
  assert_near(v, BACK, EPS);
}

static void test_media_df3_voxels(void **state) {
  (void)state;
  /* A 2 x 1 x 1 file of 16-bit voxels: 0 and 65535. */
  static const unsigned char file[] = {0, 2, 0, 1, 0, 1, 0, 0, 255, 255};
  zr_arena arena;
  zr__arena_init(&arena);
  zr_density_file d = {0};
  assert_int_equal(zr__df3_decode(file, sizeof file, &arena, &d), ZR_OK);
  assert_int_equal(d.nx, 2);
  /* Nearest voxel: [0, 0.5) is the first, [0.5, 1) the second; 0
     outside the unit cube. */
  assert_near(zr__df3_value(&d, zr_v3(0.25, 0.5, 0.5)), 0.0, 0.0);
  assert_near(zr__df3_value(&d, zr_v3(0.75, 0.5, 0.5)), 1.0, 0.0);
  assert_near(zr__df3_value(&d, zr_v3(1.25, 0.5, 0.5)), 0.0, 0.0);
  /* Trilinear from the voxel holding the point to the next, wrapping
     round at the far face as POV-Ray does. */
  d.interpolate = 1;
  assert_near(zr__df3_value(&d, zr_v3(0.25, 0.5, 0.5)), 0.5, 1e-12);
  assert_near(zr__df3_value(&d, zr_v3(0.75, 0.5, 0.5)), 0.5, 1e-12);
  /* A length that does not fit the sizes. */
  assert_int_equal(zr__df3_decode(file, sizeof file - 1, &arena, &d),
                   ZR_EFORMAT);
  zr__arena_free(&arena);
}

static void test_media_bad_input(void **state) {
  fixture *f = *state;
  bad(f, "media { method 4 }\n", ZR_ESCENE,
      "media method must be from 1 to 3, not 4",
      "t.pov:1:16: error: media method must be from 1 to 3, not 4\n"
      "    1 | media { method 4 }\n"
      "      |                ^\n");
  bad(f, "media { intervals 0 }\n", ZR_ESCENE,
      "media intervals must be at least 1, not 0", NULL);
  bad(f, "media { samples 5, 2 }\n", ZR_ESCENE,
      "the most media samples (2) must not be fewer than the least (5)",
      NULL);
  bad(f, "media { aa_threshold 0 }\n", ZR_ESCENE,
      "aa_threshold must be above 0, not 0", NULL);
  bad(f, "media { density { density_file df3 \"none.df3\" } }\n",
      ZR_ENOTFOUND, "density_file 'none.df3' not found", NULL);
  bad(f, "media { confidence 1 }\n", ZR_ESCENE,
      "media confidence must be at least 0 and below 1, not 1", NULL);
  bad(f, "media { scattering { 1, 0.5 eccentricity 0.3 } }\n", ZR_ESCENE,
      "eccentricity is only for scattering type 5 (Henyey-Greenstein)",
      NULL);
  good(f, "media { scattering { 7, 0.5 } }\n");
  assert_int_equal(f->diag.warnings, 1);
  assert_non_null(strstr(f->diag.warning, "unknown scattering type 7: "
                                          "isotropic scattering (1) is "
                                          "used"));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test_setup_teardown(test_media_absorption_is_exponential,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_media_emission_integral, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_media_matches_povray, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_media_needs_hollow_containers,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_media_density_scales, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_media_atmosphere, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_media_shadows, setup, teardown),
      cmocka_unit_test_setup_teardown(test_media_scattering_lights_the_media,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_media_deterministic_jitter,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_media_interior_texture, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_media_photons_blocks, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_media_identifiers_and_transforms,
                                      setup, teardown),
      cmocka_unit_test(test_media_df3_voxels),
      cmocka_unit_test_setup_teardown(test_media_bad_input, setup,
                                      teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
