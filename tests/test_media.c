/*
 * test_media.c - participating media (lib/trace/media.c) and the blocks
 * that describe them (lib/sdl/build_media.c), checked against physics:
 * Beer-Lambert transmittance and the emission integral of constant
 * media (closed forms of the volume rendering equation), the integral
 * of each phase function over the sphere, convergence to a finely
 * integrated reference as samples grow; shadows through media, hollow
 * and solid containers, interior_texture, photons blocks, and exact
 * messages for bad input.  tests/test_media_povray.sh compares whole
 * pictures with POV-Ray 3.7's.
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

#define PI 3.14159265358979323846

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

/* The centre pixel of a 20 x 20 render, all three channels. */
static void centre_rgb(fixture *f, const char *text, float rgb[3]) {
  zr_scene *s = good(f, text);
  zr_render_params p;
  zr_render_params_init(&p);
  p.width = 20;
  p.height = 20;
  uint32_t index = 10 * 20 + 10;
  assert_int_equal(zr_render_pixels(s, &p, &index, 1, NULL, rgb, NULL),
                   ZR_OK);
}

/* Beer-Lambert: through d = 2 units of constant absorption a the light
   behind keeps exp(-a d), per channel, whatever the sampling. */
static void test_media_beer_lambert(void **state) {
  fixture *f = *state;
  static const char *const sampling[] = {"", "samples 1, 1",
                                         "method 1 samples 3, 9",
                                         "method 2 samples 7 jitter 0.5",
                                         "intervals 5 samples 4"};
  for (size_t i = 0; i < sizeof sampling / sizeof sampling[0]; i++) {
    char text[1024];
    snprintf(text, sizeof text,
             SCENE_HEAD "box { <-1,-1,-1>, <1,1,1> pigment { rgbt 1 } "
                        "hollow interior { media { absorption <0.1, 0.5, "
                        "2> %s } } }\n",
             sampling[i]);
    float rgb[3];
    centre_rgb(f, text, rgb);
    assert_near(rgb[0], BACK * exp(-0.2), EPS);
    assert_near(rgb[1], BACK * exp(-1.0), EPS);
    assert_near(rgb[2], BACK * exp(-4.0), EPS);
  }
  /* Scattering takes light out of the ray as absorption does, scaled by
     extinction. */
  double v = centre_red(f, SCENE_HEAD
                        "box { <-1,-1,-1>, <1,1,1> pigment { rgbt 1 } "
                        "hollow interior { media { scattering { 1, 0.5 "
                        "extinction 0.5 } absorption 0.25 } } }\n");
  assert_near(v, BACK * exp(-2.0 * (0.25 + 0.25)), EPS);
}

/* A medium that only emits adds e d. */
static void test_media_emission_integral(void **state) {
  fixture *f = *state;
  double v = centre_red(f, SCENE_HEAD
                        "box { <-1,-1,-1>, <1,1,1> pigment { rgbt 1 } "
                        "hollow interior { media { emission 0.1 } } }\n");
  assert_near(v, BACK + 0.2, EPS);
  /* Two media in one container add. */
  v = centre_red(f, SCENE_HEAD
                 "box { <-1,-1,-1>, <1,1,1> pigment { rgbt 1 } hollow "
                 "interior { media { emission 0.1 } media { emission 0.05 "
                 "} } }\n");
  assert_near(v, BACK + 0.3, EPS);
}

/* Emission e with absorption a over d: the solution of dL/ds = e - a L
   is L = B exp(-a d) + e (1 - exp(-a d)) / a, but POV-Ray's method 3
   (default samples 10: 6 cells of h = d / 6) sums each cell's
   emission dimmed only by the cells before it, e h sum_{i<6}
   exp(-a i h) (bench/media_quadrature.py measures it; lib/trace/media.c,
   gather_cell()): brighter than the exact value when a h is large. */
static double povray_cells(double e, double a, double d, int cells) {
  double h = d / cells, sum = 0.0;
  for (int i = 0; i < cells; i++)
    sum += exp(-a * i * h);
  return e * h * sum;
}

static void test_media_emitting_absorbing(void **state) {
  fixture *f = *state;
  static const double as[] = {0.25, 1.0, 2.0};
  for (size_t i = 0; i < sizeof as / sizeof as[0]; i++) {
    char text[1024];
    snprintf(text, sizeof text,
             SCENE_HEAD "box { <-1,-1,-1>, <1,1,1> pigment { rgbt 1 } "
                        "hollow interior { media { absorption %g emission "
                        "0.4 } } }\n",
             as[i]);
    double a = as[i], d = 2.0;
    assert_near(centre_red(f, text),
                BACK * exp(-a * d) + povray_cells(0.4, a, d, 6), EPS);
  }
}

/* Simpson's rule for 2 pi times the integral of the phase function over
   mu = cos in [-1, 1]: the integral over the sphere. */
static double sphere_integral(const zr_medium *m) {
  const int n = 200000; /* even; the error is far below 1e-9 here */
  double h = 2.0 / n, sum = 0.0;
  for (int i = 0; i <= n; i++) {
    double w = i == 0 || i == n ? 1.0 : i % 2 ? 4.0 : 2.0;
    sum += w * zr__media_phase(m, -1.0 + i * h);
  }
  return 2.0 * PI * sum * h / 3.0;
}

static void test_media_phase_integrals(void **state) {
  (void)state;
  zr_medium m = {0};
  /* Isotropic and Henyey-Greenstein integrate to 4 pi: their mean over
     the sphere is 1. */
  m.scattering_type = ZR_SCATTER_ISOTROPIC;
  assert_near(sphere_integral(&m), 4.0 * PI, 1e-9);
  static const double gs[] = {-0.7, 0.0, 0.3, 0.8};
  m.scattering_type = ZR_SCATTER_HENYEY_GREENSTEIN;
  for (size_t i = 0; i < sizeof gs / sizeof gs[0]; i++) {
    m.eccentricity = gs[i];
    assert_near(sphere_integral(&m), 4.0 * PI, 1e-6);
  }
  /* Positive eccentricity scatters forward: most when the light shines
     along the ray toward the viewer (cos 1). */
  m.eccentricity = 0.5;
  assert_true(zr__media_phase(&m, 1.0) > zr__media_phase(&m, -1.0));
  /* The other three keep the scale measured from POV-Ray (lib/trace/
     media.c): 4 pi times that scale over the 4 pi one, whose derivation
     is there (3/4, 1/2, 33/83). */
  m.scattering_type = ZR_SCATTER_RAYLEIGH;
  assert_near(sphere_integral(&m), 4.0 * PI * 0.79936 / 0.75, 1e-9);
  m.scattering_type = ZR_SCATTER_MIE_HAZY;
  assert_near(sphere_integral(&m), 4.0 * PI * 0.57666 / 0.5, 1e-9);
  m.scattering_type = ZR_SCATTER_MIE_MURKY;
  assert_near(sphere_integral(&m), 4.0 * PI * 0.49571 / (33.0 / 83.0),
              1e-8);
  /* Mie scatters forward too, Rayleigh evenly forward and back. */
  assert_true(zr__media_phase(&m, 1.0) > 50.0 * zr__media_phase(&m, -1.0));
  m.scattering_type = ZR_SCATTER_RAYLEIGH;
  assert_near(zr__media_phase(&m, 0.6), zr__media_phase(&m, -0.6), 1e-15);
}

/* The density of `spherical` with colour_map 0 -> 1 at a point. */
static double ball(double x, double y, double z) {
  double r = sqrt(x * x + y * y + z * z);
  return r < 1.0 ? 1.0 - r : 0.0;
}

/* Emission 0.9 and absorption 1 scaled by that density (not e / a =
   BACK, which any quadrature would get right), on the centre
   pixel's ray (x 0.025, y -0.025, from z = -1 to 1, then the plane of
   colour BACK): a midpoint rule with a million steps. */
static double ball_reference(void) {
  const int n = 1000000;
  double h = 2.0 / n, depth = 0.0, light = 0.0;
  for (int i = 0; i < n; i++) {
    double rho = ball(0.025, -0.025, -1.0 + (i + 0.5) * h);
    /* The step's light, dimmed by the depth before it and by half the
       step's own (the midpoint of its exact exp integral). */
    light += 0.9 * rho * h * exp(-(depth + 0.5 * rho * h));
    depth += rho * h;
  }
  return BACK * exp(-depth) + light;
}

static double ball_render(fixture *f, const char *sampling) {
  char text[1024];
  snprintf(text, sizeof text,
           SCENE_HEAD "box { <-1,-1,-1>, <1,1,1> pigment { rgbt 1 } hollow "
                      "interior { media { absorption 1 emission 0.9 %s "
                      "density { spherical color_map { [0 rgb 0] [1 rgb 1] "
                      "} } } } }\n",
           sampling);
  return centre_red(f, text);
}

/* As samples grow the error against the reference falls. */
static void test_media_converges(void **state) {
  fixture *f = *state;
  double truth = ball_reference();
  /* Even spacing (method 2, no jitter): the error falls.  Not as 1/n^2:
     the stretch from an end to its nearest sample takes that sample's
     value, an error of order 1/n. */
  double last = INFINITY;
  static const int ns[] = {2, 4, 8, 16, 32};
  for (size_t i = 0; i < sizeof ns / sizeof ns[0]; i++) {
    char s[64];
    snprintf(s, sizeof s, "method 2 samples %d, %d", ns[i], ns[i]);
    double err = fabs(ball_render(f, s) - truth);
    assert_true(err < last);
    last = err;
  }
  assert_true(last < 1e-4);
  /* Method 3: more samples get closer (a threshold of 100 halves
     nothing here).  Its samples reach n / (n + 1) of the interval, n =
     min samples / 2 + 1, as POV-Ray's do (media.c, reach()), so the
     error is of order 1 / n, and the adaptive halving, which refines
     only that reach, does not remove it. */
  double e3 = fabs(ball_render(f, "method 3 samples 5 aa_threshold 100") -
                   truth);
  double e30 = fabs(ball_render(f, "method 3 samples 30 aa_threshold 100") -
                    truth);
  double e300 = fabs(
      ball_render(f, "method 3 samples 300 aa_threshold 100") - truth);
  double ea = fabs(ball_render(f, "method 3 samples 5 aa_level 4 "
                                  "aa_threshold 0.01") - truth);
  fprintf(stderr, "method 3 errors: samples 5 %.3g, 30 %.3g, 300 %.3g; "
          "5 adaptive %.3g\n", e3, e30, e300, ea);
  assert_true(e30 < e3);
  assert_true(e300 < e30);
  assert_true(ea < 1.5 * e3);
  assert_true(e300 < 0.1 * e3);
  /* Random samples (method 1): many are close, on average. */
  double e1 = fabs(ball_render(f, "method 1 samples 400, 400") - truth);
  assert_true(e1 < 1e-4);
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
  /* The product stops at a density that is zero in every channel
     (media.c's density_at()): the same light whichever side the zero
     is on, and a zero in one channel only still takes the next
     density in the others. */
  float rgb[3];
  centre_rgb(f, SCENE_HEAD
             "box { <-1,-1,-1>, <1,1,1> pigment { rgbt 1 } hollow "
             "interior { media { absorption 0.5 density { rgb 0 } "
             "density { planar color_map { [0 rgb 0.2] [1 rgb 1] } } "
             "} } }\n", rgb);
  assert_near(rgb[1], BACK, EPS);
  centre_rgb(f, SCENE_HEAD
             "box { <-1,-1,-1>, <1,1,1> pigment { rgbt 1 } hollow "
             "interior { media { absorption 0.5 density { planar "
             "color_map { [0 rgb 0.2] [1 rgb 1] } } density { rgb 0 } "
             "} } }\n", rgb);
  assert_near(rgb[1], BACK, EPS);
  centre_rgb(f, SCENE_HEAD
             "box { <-1,-1,-1>, <1,1,1> pigment { rgbt 1 } hollow "
             "interior { media { absorption 0.5 density { rgb <0, 1, 1> } "
             "density { rgb 0.5 } } } }\n", rgb);
  assert_near(rgb[0], BACK, EPS);
  assert_near(rgb[1], BACK * exp(-0.5), EPS);
}

static void test_media_atmosphere(void **state) {
  fixture *f = *state;
  /* Atmospheric media fill the path from the camera to the plane (15
     units) when nothing solid holds the camera. */
  double v = centre_red(f, SCENE_HEAD "media { absorption 0.02 }\n");
  assert_near(v, BACK * exp(-0.3), EPS);
  /* A ray that hits nothing crosses them out to 2e10 units (measured
     from povray by bench/media_sky.sh): even thin haze hides the
     background. */
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
  zr_rgb c = zr__shadow_transmission(&tr, NULL, zr_v3(0, 10, 0), zr_v3(0, 0, 0));
  assert_near(c.r, exp(-2.0 * 0.5), EPS);
  /* A shadow ray that starts inside the container. */
  c = zr__shadow_transmission(&tr, NULL, zr_v3(0, 10, 0), zr_v3(0, 5, 0));
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

/* A 20 x 20 render of the scene, all pixels. */
static void render_all(fixture *f, const char *text, float *rgb) {
  zr_scene *s = good(f, text);
  zr_render_params p;
  zr_render_params_init(&p);
  p.width = 20;
  p.height = 20;
  uint32_t index[400];
  for (uint32_t i = 0; i < 400; i++)
    index[i] = i;
  assert_int_equal(zr_render_pixels(s, &p, index, 400, NULL, rgb, NULL),
                   ZR_OK);
}

/* A media sample asks only the point lights and the beams of its piece
   of the ray when there are at most 64 lights (lib/trace/media.c,
   sample_at), and every light otherwise: 65 more lights that light no
   media take the second path, which must give the same bytes. */
static void test_media_beams_path_matches_all_lights(void **state) {
  fixture *f = *state;
  const char *lights =
      "light_source { <0, 3, 0> rgb <1, 0.5, 0.2> spotlight point_at 0\n"
      "  radius 10 falloff 15 }\n"
      "light_source { <-2, 0, -2> 0.7 }\n"
      "light_source { <3, 0, 0> rgb <0.2, 1, 0.5> spotlight\n"
      "  point_at <0, 0.3, 0> radius 5 falloff 8 }\n"
      "light_source { <0, -3, 0> 1 cylinder point_at 0 radius 0.3\n"
      "  falloff 0.5 }\n"
      "box { <-1,-1,-1>, <1,1,1> pigment { rgbt 1 } hollow no_shadow\n"
      "  interior { media { scattering { 1, 0.1 extinction 0 }\n"
      "  method 3 intervals 2 } } }\n";
  char few[2048], many[2048];
  snprintf(few, sizeof few, "%s%s", SCENE_HEAD, lights);
  snprintf(many, sizeof many, "%s%s#for (i, 1, 65)\n"
           "  light_source { <i, 9, -9> 0.1 media_interaction off }\n"
           "#end\n", SCENE_HEAD, lights);
  float a[3 * 400], b[3 * 400];
  render_all(f, few, a);
  render_all(f, many, b);
  double lit = 0.0;
  for (int i = 0; i < 3 * 400; i++) {
    assert_true(a[i] == b[i]);
    lit = fmax(lit, a[i] - BACK);
  }
  assert_true(lit > 0.05); /* the media are lit */
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
  /* Objects' and lights' photons blocks are read; what is not
     simulated (a light's area_light) is named in a warning. */
  good(f, "light_source { 0, 1 photons { refraction on reflection off "
          "area_light } }\n"
          "sphere { 0, 1 photons { target 0.5 refraction on reflection on "
          "collect off pass_through } }\n");
  assert_int_equal(f->diag.warnings, 1);
  assert_non_null(strstr(f->diag.warning, "area_light"));
  /* Every global item is read; photon map files are named
     (lib/trace/photons.c simulates the rest, media photons too). */
  good(f, "global_settings {\n  photons { spacing 0.02 gather 20, 100 "
          "media 100, 2 radius 0.1, 1, 0.2 autostop 0 jitter 0.4 "
          "max_trace_level 5 adc_bailout 0.01 expand_thresholds 0.2, 40 "
          "save_file \"a.ph\" }\n}\n");
  assert_int_equal(f->diag.warnings, 1);
  assert_non_null(strstr(f->diag.warning, "photon maps are not saved"));
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
      cmocka_unit_test_setup_teardown(test_media_beer_lambert,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_media_emission_integral, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_media_emitting_absorbing, setup,
                                      teardown),
      cmocka_unit_test(test_media_phase_integrals),
      cmocka_unit_test_setup_teardown(test_media_converges, setup, teardown),
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
      cmocka_unit_test_setup_teardown(
          test_media_beams_path_matches_all_lights, setup, teardown),
      cmocka_unit_test_setup_teardown(test_media_bad_input, setup,
                                      teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
