/*
 * test_rad_settings.c - the radiosity settings of a scene (issue 4):
 * global_settings { radiosity { } } read and checked with exact
 * messages, its values reaching zr_radiosity_params, the command line
 * overriding them (bin/options.c), an object's radiosity keywords, and
 * finish { energy P } emitting P in all.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "options.h"
#include "parse_fixture.h"
#include "radiosity/radiosity.h"
#include "scene/scene.h"
#include "zrcube.h"

/* A closed box seen from inside, its own emitter: small and quick. */
#define BOX "box { <-1, -1, -1>, <1, 1, 1> pigment { rgb 1 } "

static void test_rad_settings_block_turns_radiosity_on(void **state) {
  fixture *f = *state;
  zr_scene_info info;
  zr_scene_get_info(good(f, BOX "}"), &info);
  assert_int_equal(info.has_radiosity, 0);
  zr_scene_get_info(good(f, "global_settings { radiosity { } }" BOX "}"),
                    &info);
  assert_int_equal(info.has_radiosity, 1);
  assert_int_equal(f->diag.warnings, 0); /* nothing to ignore */
  /* No zRcube item given: the library's defaults, but for the bounces,
     POV-Ray's recursion_limit (2 when not written); without a block
     every bounce (0). */
  zr_radiosity_params p, d;
  zr_radiosity_params_init(&p, f->scene);
  zr_radiosity_params_init(&d, NULL);
  assert_int_equal(p.bounces, 2);
  assert_int_equal(d.bounces, 0);
  p.bounces = 0;
  assert_memory_equal(&p, &d, sizeof p);
  zr_radiosity_params_init(&p, good(f, BOX "}"));
  assert_int_equal(p.bounces, 0);
  zr_radiosity_params_init(
      &p, good(f, "global_settings { radiosity { recursion_limit 5 } }"
                  BOX "}"));
  assert_int_equal(p.bounces, 5);
}

static void test_rad_settings_reach_the_params(void **state) {
  fixture *f = *state;
  good(f, "global_settings { radiosity {\n"
          "  bf_bound 0.003 minimum_area 0.01 visibility_count 3\n"
          "  max_iterations 50 residual_bound 1e-5 brightness 0.5\n"
          "} }" BOX "}");
  zr_radiosity_params p;
  zr_radiosity_params_init(&p, f->scene);
  assert_true(p.bf_eps == 0.003);
  assert_true(p.area_eps == 0.01);
  assert_int_equal(p.visibility_rays, 3);
  assert_int_equal(p.max_iterations, 50);
  assert_true(p.residual == 1e-5);
  assert_true(p.brightness == 0.5);
  assert_int_equal(f->diag.warnings, 0);
}

/* The command line wins where it speaks, the scene elsewhere. */
static void test_rad_settings_command_line_overrides(void **state) {
  fixture *f = *state;
  good(f, "global_settings { radiosity { bf_bound 0.003 "
          "visibility_count 3 brightness 2 } }" BOX "}");
  zr_render_params rp;
  zr_render_params_init(&rp);
  zr_cli_options o;
  zr__cli_init(&o, &rp);
  char arg0[] = "zrcube", arg1[] = "--bf-eps=0.02", arg2[] = "t.pov";
  char *argv[] = {arg0, arg1, arg2, NULL};
  char err[512] = "";
  assert_int_equal(zr__cli_parse(&o, 3, argv, err, sizeof err), 0);
  zr_radiosity_params p;
  zr__cli_radiosity_params(&o, f->scene, &p);
  assert_true(p.bf_eps == 0.02);      /* the command line's */
  assert_int_equal(p.visibility_rays, 3); /* the scene's */
  assert_true(p.brightness == 2.0);
  assert_true(p.area_eps == 1e-4);    /* neither: the default */
  assert_int_equal(p.one_sided_emission, 2); /* the one default */
  assert_int_equal(p.bounces, 2); /* the scene's recursion_limit */
  zr__cli_free(&o);
  /* --bounces: all (every bounce) or N, over the scene's limit. */
  static const char *const given[] = {"--bounces=all", "--bounces=7"};
  for (int k = 0; k < 2; k++) {
    zr__cli_init(&o, &rp);
    char a1[32];
    snprintf(a1, sizeof a1, "%s", given[k]);
    char *av[] = {arg0, a1, arg2, NULL};
    assert_int_equal(zr__cli_parse(&o, 3, av, err, sizeof err), 0);
    zr__cli_radiosity_params(&o, f->scene, &p);
    assert_int_equal(p.bounces, k == 0 ? 0 : 7);
    assert_int_equal(o.radiosity, 0); /* it chooses no model */
    zr__cli_free(&o);
  }
  zr__cli_init(&o, &rp);
  char bad[] = "--bounces=0";
  char *bv[] = {arg0, bad, arg2, NULL};
  assert_int_not_equal(zr__cli_parse(&o, 3, bv, err, sizeof err), 0);
  assert_string_equal(err, "zrcube: '--bounces=0': --bounces takes all or "
                           "a whole number from 1 to 1000000");
  zr__cli_free(&o);
}

/* POV-Ray's items are read for the irradiance cache (lib/gi) without a
   warning; subsurface, which zRcube lacks, is named in one. */
static void test_rad_settings_pov_items_warn(void **state) {
  fixture *f = *state;
  good(f, "global_settings { radiosity {\n"
          "  pretrace_start 0.08 pretrace_end 0.04 count 35, 1000\n"
          "  nearest_count 5, 3 error_bound 1.8 recursion_limit 2\n"
          "  low_error_factor 0.5 gray_threshold 0 minimum_reuse 0.015\n"
          "  maximum_reuse 0.2 adc_bailout 0.01 always_sample off\n"
          "  max_sample -1 media on normal off subsurface off\n"
          "} }" BOX "}");
  assert_int_equal(f->diag.warnings, 1);
  assert_non_null(strstr(f->diag.warning,
                         "t.pov:7:1: warning: radiosity: subsurface "
                         "ignored: zRcube has no subsurface light "
                         "transport"));
  good(f, "global_settings { radiosity { recursion_limit 3 } }" BOX "}");
  assert_int_equal(f->diag.warnings, 0);
  good(f, "global_settings { radiosity { save_file \"a.rad\" } }" BOX "}");
  assert_int_equal(f->diag.warnings, 0);
}

static void test_rad_settings_bad_values(void **state) {
  fixture *f = *state;
  static const struct {
    const char *item, *message;
  } cases[] = {
      {"bf_bound 0", "radiosity: bf_bound must be a number > 0 (a "
                     "fraction of the scene's emitted power)"},
      {"minimum_area 1", "radiosity: minimum_area must be between 0 and 1 "
                         "(a fraction of the scene's surface area)"},
      {"visibility_count 2.5",
       "radiosity: visibility_count must be a whole number from 1 to 16"},
      {"visibility_count 17",
       "radiosity: visibility_count must be a whole number from 1 to 16"},
      {"max_iterations 0", "radiosity: max_iterations must be a whole "
                           "number from 1 to 100000000"},
      {"residual_bound -1", "radiosity: residual_bound must be a number > "
                            "0 (a fraction of the scene's emitted power)"},
      {"brightness -0.5", "radiosity: brightness must be a number >= 0"},
      {"brightness 1, 2", "radiosity: brightness takes one value"},
      {"count }", "radiosity: count needs a value"},
      {"count 0", "radiosity: count must be a whole number from 1 to "
                  "1000000"},
      {"recursion_limit 1.5", "radiosity: recursion_limit must be a whole "
                              "number from 1 to 20"},
  };
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
    char text[256];
    snprintf(text, sizeof text,
             "global_settings { radiosity { %s %s" BOX "}", cases[i].item,
             strchr(cases[i].item, '}') ? "}" : "} }");
    bad(f, text, strstr(cases[i].message, "takes one") ||
                         strstr(cases[i].message, "needs a")
                     ? ZR_ESYNTAX
                     : ZR_ESCENE,
        cases[i].message, NULL);
  }
  bad(f, BOX "finish { energy -1 } }", ZR_ESCENE,
      "energy must be a power >= 0 in every channel", NULL);
  bad(f, BOX "radiosity { importance 0 } }", ZR_ESCENE,
      "importance must be greater than 0 and at most 1", NULL);
}

/* An object's radiosity { importance } and no_radiosity: one warning
   each per parse, no effect. */
static void test_rad_settings_object_keywords_warn_once(void **state) {
  fixture *f = *state;
  good(f, BOX "radiosity { importance 0.5 } }\n"
              "sphere { 0, 1 radiosity { importance 1 } no_radiosity }\n"
              "sphere { 0, 2 no_radiosity }");
  assert_int_equal(f->diag.warnings, 2);
  assert_non_null(strstr(f->diag.warning,
                         "t.pov:2:42: warning: no_radiosity is ignored "
                         "(warned once): in zRcube's radiosity every "
                         "surface takes part"));
}

/* finish { energy P }: the object emits P in all, whatever its size
   (the closed box's inner and outer sides with two-sided emission),
   per channel, and whichever sides it leaves (one_sided_emission 2, the
   default: shared by openness; a triangle 0.01 under a plate sends
   almost all of it from its open side).  Emitted power is summed in
   doubles over six faces: 1e-12 relative. */
static void test_rad_settings_energy_is_total_power(void **state) {
  fixture *f = *state;
  static const char *const scenes[] = {
      "box { 0, <1, 2, 3> pigment { rgb 1 } finish { diffuse 0.5 "
      "energy <12, 6, 3> } }",
      "box { 0, <10, 20, 30> pigment { rgb 1 } finish { diffuse 0.5 "
      "energy <12, 6, 3> } }",
      "triangle { <0, 0, 0>, <1, 0, 0>, <0, 0, 1> pigment { rgb 1 } "
      "finish { diffuse 0 energy <12, 6, 3> } }\n"
      "box { <-1, 0.01, -1>, <2, 0.02, 2> pigment { rgb 1 } }",
  };
  for (int one_sided = 0; one_sided < 3; one_sided++)
    for (int i = 0; i < 3; i++) {
      good(f, scenes[i]);
      zr_radiosity_params p;
      zr_radiosity_params_init(&p, f->scene);
      p.one_sided_emission = one_sided;
      p.refine_rounds = 0;
      zr_radiosity *rad = NULL;
      assert_int_equal(zr_radiosity_solve(f->ctx, f->scene, &p, &rad),
                       ZR_OK);
      zr_radiosity_stats st;
      zr_radiosity_get_stats(rad, &st);
      /* The mean of the channels, (12 + 6 + 3) / 3. */
      assert_true(fabs(st.emitted_power - 7.0) <= 7.0 * 1e-12);
      /* The triangle's front faces down (+y x ... = -y), its back the
         plate 0.01 above: open sides give the front 7 / 0.5 = 14 per
         unit area (mean of channels) within 5%, two sides at full half
         that. */
      if (i == 2) {
        zr_rgb below;
        assert_true(zr__radiosity_radiance(rad, f->scene->primitives[0],
                                           zr_v3(0.2, 0, 0.2),
                                           zr_v3(0, 1, 0), &below));
        double m = M_PI * (below.r + below.g + below.b) / 3.0;
        double want = one_sided == 0 ? 7.0 : 14.0;
        assert_true(fabs(m / want - 1.0) < 0.05);
      }
      zr_radiosity_free(rad);
    }
}

/* brightness scales the reflected light where a ray reads it, not the
   emission: in a furnace (emission e, reflectance rho) the radiance is
   (e + brightness (B - e)) / pi.  1e-12: the same solution read twice. */
static void test_rad_settings_brightness_scales_reflection(void **state) {
  fixture *f = *state;
  const char *text = BOX "finish { diffuse 0.5 emission 0.2 } }";
  zr_rgb l[2];
  double scale[2] = {1.0, 0.25};
  for (int k = 0; k < 2; k++) {
    good(f, text);
    zr_radiosity_params p;
    zr_radiosity_params_init(&p, f->scene);
    p.bf_eps = 1e-2;
    p.area_eps = 1e-2;
    p.brightness = scale[k];
    /* The box is seen from inside, its back: both sides emit. */
    p.one_sided_emission = 0;
    zr_radiosity *rad = NULL;
    assert_int_equal(zr_radiosity_solve(f->ctx, f->scene, &p, &rad), ZR_OK);
    const zr_scene *s = f->scene;
    assert_true(zr__radiosity_radiance(rad, s->primitives[0],
                                       zr_v3(0.2, 0.1, 1), zr_v3(0, 0, 1),
                                       &l[k]));
    zr_radiosity_free(rad);
  }
  double e = 0.2; /* emission * pigment, as radiance */
  assert_true(l[0].r > 0.3); /* about 0.4 */
  assert_true(fabs(l[1].r - (e + 0.25 * (l[0].r - e))) <= 1e-12);
}

/* Bounded bounces (POV-Ray's recursion_limit N): in a closed box of
   emission e and reflectance rho, seen from inside (every form factor
   sums to 1), light that bounced at most N times is
   e (1 + rho + ... + rho^N); every bounce, e / (1 - rho).  The final
   gather (lookup 0, which gathers once more from the solved B) is
   checked against the series within 1% (measured: N = 1, 2 exact, 3
   and 4 0.6% and 0.7% below, every bounce 0.8% below: the closure of
   the solver's factors).  The smoothed elements (lookup 1) read B
   itself, so the solve takes one sweep more: N = 1 is e (1 + rho)
   exactly (the first bounce of a uniform emission is uniform; measured
   0.30000), and more bounces give more light, below every bounce's
   (the smoothed value at this point near an edge is 6% below
   e / (1 - rho), so the series is no oracle for it beyond N = 1). */
static void test_rad_settings_bounces_follow_the_limit(void **state) {
  fixture *f = *state;
  const double e = 0.2, rho = 0.5;
  for (int lookup = 0; lookup < 2; lookup++) {
    double l_n[5];
    for (int n = 0; n <= 4; n++) {
      good(f, BOX "finish { diffuse 0.5 emission 0.2 } }");
      zr_radiosity_params p;
      zr_radiosity_params_init(&p, f->scene);
      p.bf_eps = 1e-2;
      p.area_eps = 1e-2;
      p.one_sided_emission = 0;
      p.lookup = (zr_rad_lookup)lookup;
      p.bounces = n;
      zr_radiosity *rad = NULL;
      assert_int_equal(zr_radiosity_solve(f->ctx, f->scene, &p, &rad),
                       ZR_OK);
      zr_rgb l;
      assert_true(zr__radiosity_radiance(rad, f->scene->primitives[0],
                                         zr_v3(0.2, 0.1, 1),
                                         zr_v3(0, 0, 1), &l));
      zr_radiosity_free(rad);
      l_n[n] = l.r;
      double series = n == 0 ? e / (1.0 - rho)
                             : e * (1.0 - pow(rho, n + 1)) / (1.0 - rho);
      double tol = lookup == 0 ? 0.01 : n == 1 ? 0.001 : -1.0;
      if (tol > 0.0 && !(fabs(l.r / series - 1.0) < tol))
        fail_msg("lookup %d, bounces %d: radiance %.5f, want %.5f", lookup,
                 n, l.r, series);
    }
    for (int n = 2; n <= 4; n++)
      if (!(l_n[n] > l_n[n - 1] && l_n[n] < l_n[0]))
        fail_msg("lookup %d: bounces %d give %.5f, %d %.5f, all %.5f",
                 lookup, n, l_n[n], n - 1, l_n[n - 1], l_n[0]);
  }
  /* Shooting carries every bounce: with bounces it gathers instead. */
  good(f, BOX "finish { diffuse 0.5 emission 0.2 } }");
  zr_radiosity_params p;
  zr_radiosity_params_init(&p, f->scene);
  p.bf_eps = 1e-2;
  p.area_eps = 1e-2;
  p.one_sided_emission = 0;
  p.shooting = ZR_RAD_SHOOTING;
  p.bounces = 1;
  zr_radiosity *rad = NULL;
  assert_int_equal(zr_radiosity_solve(f->ctx, f->scene, &p, &rad), ZR_OK);
  zr_rgb l;
  assert_true(zr__radiosity_radiance(rad, f->scene->primitives[0],
                                     zr_v3(0.2, 0.1, 1), zr_v3(0, 0, 1),
                                     &l));
  zr_radiosity_free(rad);
  assert_true(fabs(l.r / (e * (1.0 + rho)) - 1.0) < 0.01);
  p.bounces = -1;
  assert_int_equal(zr_radiosity_solve(f->ctx, f->scene, &p, &rad),
                   ZR_EINVAL);
  assert_string_equal(f->diag.message,
                      "radiosity: bounces must be >= 0 (0: every bounce)");
}

/* Settings that would give NaN never reach the solver: the library's
   own check names them. */
static void test_rad_settings_nan_params_refused(void **state) {
  fixture *f = *state;
  good(f, BOX "finish { emission 1 } }");
  zr_radiosity_params p;
  zr_radiosity_params_init(&p, f->scene);
  p.brightness = NAN;
  zr_radiosity *rad = NULL;
  assert_int_equal(zr_radiosity_solve(f->ctx, f->scene, &p, &rad),
                   ZR_EINVAL);
  assert_null(rad);
  assert_string_equal(f->diag.message,
                      "radiosity: brightness must be a finite number >= 0");
  zr_radiosity_params_init(&p, f->scene);
  p.bf_eps = NAN;
  assert_int_equal(zr_radiosity_solve(f->ctx, f->scene, &p, &rad),
                   ZR_EINVAL);
  assert_string_equal(f->diag.message,
                      "radiosity: bf_eps must be a finite number >= 0");
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test_setup_teardown(
          test_rad_settings_block_turns_radiosity_on, setup, teardown),
      cmocka_unit_test_setup_teardown(test_rad_settings_reach_the_params,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(
          test_rad_settings_command_line_overrides, setup, teardown),
      cmocka_unit_test_setup_teardown(test_rad_settings_pov_items_warn,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_rad_settings_bad_values, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(
          test_rad_settings_object_keywords_warn_once, setup, teardown),
      cmocka_unit_test_setup_teardown(
          test_rad_settings_energy_is_total_power, setup, teardown),
      cmocka_unit_test_setup_teardown(
          test_rad_settings_brightness_scales_reflection, setup, teardown),
      cmocka_unit_test_setup_teardown(
          test_rad_settings_bounces_follow_the_limit, setup, teardown),
      cmocka_unit_test_setup_teardown(test_rad_settings_nan_params_refused,
                                      setup, teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
