/*
 * test_parser.c - the scene language front end: grammar/pov.y and
 * lib/sdl (directives, values, building the scene model), through the
 * public zr_scene_parse_file/_string calls.
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
#include <sys/stat.h>
#include <unistd.h>

#include "config.h"
#include "core/context.h"
#include "core/transform.h"
#include "scene/scene.h"
#include "zrcube.h"
#include "parse_fixture.h"
#include "test_util.h"

/* Values written in the scenes are small decimals combined by a few
   operations, and transforms multiply a few 4x4 matrices: 1e-9 leaves
   room for their rounding and catches any real mistake. */
#define EPS 1e-9

static void assert_num(double a, double b) {
  if (fabs(a - b) > EPS)
    fail_msg("%.12g != %.12g", a, b);
}

static void assert_colour(zr_colour c, double r, double g, double b,
                          double fl, double t) {
  assert_num(c.r, r);
  assert_num(c.g, g);
  assert_num(c.b, b);
  assert_num(c.f, fl);
  assert_num(c.t, t);
}

static void assert_rgb(zr_rgb c, double r, double g, double b) {
  assert_num(c.r, r);
  assert_num(c.g, g);
  assert_num(c.b, b);
}

static zr_vec3 to_world(const zr_object *o, zr_vec3 p) {
  return o->transform ? zr__xform_point(o->transform->m, p) : p;
}

/* ---- good input ---- */

static void test_parser_primitives(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f,
      "sphere { <1, 2, 3>, 0.5 }\n"
      "box { <-1, -2, -3>, <1, 2, 3> }\n"
      "plane { <0, 2, 0>, -1 }\n"
      "triangle { <0,0,0>, <1,0,0>, <0,1,0> }\n"
      "cylinder { 0, y*2, 0.25 open }\n"
      "cone { <0,0,0>, 1, <0,3,0>, 0.5 }\n"
      "disc { <0,1,0>, <0,0,3>, 2, 0.5 }\n"
      "disc { 0, y, 1 }\n");
  assert_int_equal(s->n_objects, 8);
  zr_object **o = s->objects;
  assert_int_equal(o[0]->kind, ZR_OBJ_SPHERE);
  assert_vec(o[0]->u.sphere.centre, 1, 2, 3, EPS);
  assert_num(o[0]->u.sphere.radius, 0.5);
  assert_vec(o[1]->u.box.corner1, -1, -2, -3, EPS);
  assert_vec(o[1]->u.box.corner2, 1, 2, 3, EPS);
  /* A x + B y + C z = D |<A,B,C>|: the normal is made unit, D stays. */
  assert_vec(o[2]->u.plane.normal, 0, 1, 0, EPS);
  assert_num(o[2]->u.plane.distance, -1);
  assert_vec(o[3]->u.triangle.p[1], 1, 0, 0, EPS);
  assert_vec(o[3]->u.triangle.p[2], 0, 1, 0, EPS);
  assert_vec(o[4]->u.cylinder.cap, 0, 2, 0, EPS);
  assert_num(o[4]->u.cylinder.radius, 0.25);
  assert_true(o[4]->u.cylinder.open);
  assert_false(o[5]->u.cone.open);
  assert_num(o[5]->u.cone.base_radius, 1);
  assert_vec(o[5]->u.cone.cap, 0, 3, 0, EPS);
  assert_num(o[5]->u.cone.cap_radius, 0.5);
  assert_vec(o[6]->u.disc.normal, 0, 0, 1, EPS);
  assert_num(o[6]->u.disc.radius, 2);
  assert_num(o[6]->u.disc.hole_radius, 0.5);
  assert_num(o[7]->u.disc.hole_radius, 0);
  assert_string_equal(o[6]->where.file, "t.pov");
  assert_int_equal(o[6]->where.line, 7);
  zr_scene_info info;
  zr_scene_get_info(s, &info);
  assert_int_equal(info.primitives, 8);
  assert_int_equal(info.infinite_primitives, 1);
  assert_int_equal(info.has_camera, 0);
}

static void test_parser_optional_commas(void **state) {
  fixture *f = *state;
  /* POV-Ray 3.7 renders these without complaint. */
  zr_scene *s = good(f,
      "light_source { <0, 0, -5> color rgb 1 }\n"
      "sphere { <0, 0, 0> 1 }\n"
      "disc { 0 y 1 0.5 }\n"
      "cone { 0 1 y 0 open }\n");
  assert_int_equal(s->n_lights, 1);
  assert_num(s->objects[0]->u.sphere.radius, 1);
  assert_num(s->objects[1]->u.disc.hole_radius, 0.5);
  assert_true(s->objects[2]->u.cone.open);
}

static void test_parser_expressions(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f,
      "#declare A = 1 + 2 * 3 - -4 / 2;\n"            /* 9 */
      "#declare V = (<1, 2, 3> + 1) * 2;\n"           /* <4, 6, 8> */
      "sphere { V, A }\n"
      "sphere { <V.x, V.y, V.z> / 2, V.y - (A - 1) }\n" /* <2,3,4>, -2 */
      "sphere { x + y * 2 - z, sqrt(16) + pow(2, 3) }\n"
      "sphere { <min(3, 1, 2), max(1, 5), abs(-2)>, sin(pi / 2) }\n"
      "sphere { <floor(1.5), ceil(1.5), int(-1.5)>, mod(7, 4) }\n"
      "sphere { <degrees(pi), radians(180), log(100)>, ln(exp(2)) }\n"
      "sphere { <vlength(<3, 4, 0>), vdot(x, y), atan2(1, 1)>, 1 }\n"
      "sphere { <!0, !2, !!1e-11>, 1 }\n");
  zr_object **o = s->objects;
  assert_vec(o[0]->u.sphere.centre, 4, 6, 8, EPS);
  assert_num(o[0]->u.sphere.radius, 9);
  assert_vec(o[1]->u.sphere.centre, 2, 3, 4, EPS);
  assert_num(o[1]->u.sphere.radius, -2);
  assert_vec(o[2]->u.sphere.centre, 1, 2, -1, EPS);
  assert_num(o[2]->u.sphere.radius, 12);
  assert_vec(o[3]->u.sphere.centre, 1, 5, 2, EPS);
  assert_num(o[3]->u.sphere.radius, 1);
  assert_vec(o[4]->u.sphere.centre, 1, 2, -1, EPS);
  assert_num(o[4]->u.sphere.radius, 3);
  assert_vec(o[5]->u.sphere.centre, 180, M_PI, 2, EPS);
  assert_num(o[5]->u.sphere.radius, 2);
  assert_vec(o[6]->u.sphere.centre, 5, 0, M_PI / 4, EPS);
  assert_vec(o[7]->u.sphere.centre, 1, 0, 0, EPS);
}

static void test_parser_colours(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f,
      "#declare Orange = color red 1 green 0.5;\n"
      "#declare P = <0.1, 0.2, 0.3>;\n"
      "sphere { 0, 1 pigment { rgb <0.1, 0.2, 0.3> } }\n"
      "sphere { 0, 1 pigment { rgb 0.5 } }\n"
      "sphere { 0, 1 pigment { rgbf <0.1, 0.2, 0.3, 0.4> } }\n"
      "sphere { 0, 1 pigment { rgbt <0.1, 0.2, 0.3, 0.4> } }\n"
      "sphere { 0, 1 pigment { color rgbft <0.1, 0.2, 0.3, 0.4, 0.5> } }\n"
      "sphere { 0, 1 pigment { Orange } }\n"
      "sphere { 0, 1 pigment { color Orange blue 0.25 transmit 0.5 } }\n"
      "sphere { 0, 1 pigment { colour P filter 0.3 } }\n"
      "sphere { 0, 1 pigment { color 0.5 } }\n"
      "sphere { 0, 1 pigment { Orange * 0.5 } }\n");
  zr_colour c[10];
  for (int i = 0; i < 10; i++)
    c[i] = s->objects[i]->texture->pigment->colour;
  assert_colour(c[0], 0.1, 0.2, 0.3, 0, 0);
  assert_colour(c[1], 0.5, 0.5, 0.5, 0, 0);
  assert_colour(c[2], 0.1, 0.2, 0.3, 0.4, 0);
  assert_colour(c[3], 0.1, 0.2, 0.3, 0, 0.4);
  assert_colour(c[4], 0.1, 0.2, 0.3, 0.4, 0.5);
  assert_colour(c[5], 1, 0.5, 0, 0, 0);
  assert_colour(c[6], 1, 0.5, 0.25, 0, 0.5);
  assert_colour(c[7], 0.1, 0.2, 0.3, 0.3, 0);
  /* A float where a colour is wanted fills all five components
     (reference manual, "Reflection"). */
  assert_colour(c[8], 0.5, 0.5, 0.5, 0.5, 0.5);
  assert_colour(c[9], 0.5, 0.25, 0, 0, 0);
  /* A pigment alone takes the default finish. */
  assert_num(s->objects[0]->texture->finish->diffuse, 0.6);
}

static void test_parser_finish(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f,
      "#declare F = finish { ambient 0.2 diffuse 0.7 brilliance 2\n"
      "  phong 0.5 phong_size 60 specular 0.3 roughness 0.01\n"
      "  metallic reflection 0.25 emission rgb <1, 2, 3> }\n"
      "sphere { 0, 1 finish { F } }\n"
      "sphere { 0, 1 finish { F diffuse 0.1 metallic 0.5\n"
      "  reflection { 0.1, <0.9, 0.8, 0.7> falloff 2 fresnel metallic }\n"
      "  conserve_energy } }\n"
      "sphere { 0, 1 finish { reflection { rgb <0.5, 0.4, 0.3>"
      " metallic 0.5 } ambient <0.1, 0.2, 0.3> } }\n");
  const zr_finish *a = s->objects[0]->texture->finish;
  assert_rgb(a->ambient, 0.2, 0.2, 0.2);
  assert_num(a->diffuse, 0.7);
  assert_num(a->brilliance, 2);
  assert_num(a->phong, 0.5);
  assert_num(a->phong_size, 60);
  assert_num(a->specular, 0.3);
  assert_num(a->roughness, 0.01);
  assert_num(a->metallic, 1);
  assert_rgb(a->reflection, 0.25, 0.25, 0.25);
  assert_rgb(a->reflection_max, 0.25, 0.25, 0.25);
  assert_rgb(a->emission, 1, 2, 3);
  const zr_finish *b = s->objects[1]->texture->finish;
  assert_num(b->diffuse, 0.1);
  assert_num(b->phong, 0.5); /* from F */
  assert_num(b->metallic, 0.5);
  assert_rgb(b->reflection, 0.1, 0.1, 0.1);
  assert_rgb(b->reflection_max, 0.9, 0.8, 0.7);
  assert_num(b->reflection_falloff, 2);
  assert_true(b->reflection_fresnel);
  assert_num(b->reflection_metallic, 1);
  assert_true(b->conserve_energy);
  /* The declared finish did not change. */
  assert_num(a->diffuse, 0.7);
  assert_false(a->reflection_fresnel);
  const zr_finish *c = s->objects[2]->texture->finish;
  assert_rgb(c->reflection, 0.5, 0.4, 0.3);
  assert_rgb(c->reflection_max, 0.5, 0.4, 0.3);
  assert_rgb(c->ambient, 0.1, 0.2, 0.3);
  assert_num(c->reflection_metallic, 0.5);
  assert_num(a->reflection_metallic, 0);
  assert_num(c->diffuse, 0.6); /* POV-Ray's default */
}

static void test_parser_transforms_in_order(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f,
      "sphere { 0, 1 scale 2 translate <1, 0, 0> }\n"
      "sphere { 0, 1 translate <1, 0, 0> scale 2 }\n"
      "sphere { 0, 1 rotate <0, 90, 0> }\n"
      "sphere { 0, 1 scale <1, 2, 3> }\n"
      "box { 0, 1 matrix <1,0,0, 0,1,0, 0,0,1, 1,2,3> }\n"
      "sphere { 0, 1 pigment { rgb 1 } scale 2 translate y }\n"
      "sphere { 0, 1 texture { pigment { rgb 1 } scale 3 } }\n");
  zr_object **o = s->objects;
  assert_vec(to_world(o[0], zr_v3(1, 0, 0)), 3, 0, 0, EPS);
  assert_vec(to_world(o[1], zr_v3(1, 0, 0)), 4, 0, 0, EPS);
  /* rotate y 90 takes +x to -z in POV-Ray's left-handed space. */
  assert_vec(to_world(o[2], zr_v3(1, 0, 0)), 0, 0, -1, EPS);
  assert_vec(to_world(o[3], zr_v3(1, 1, 1)), 1, 2, 3, EPS);
  assert_vec(to_world(o[4], zr_v3(0, 0, 0)), 1, 2, 3, EPS);
  /* The texture moves with the object: its pigment's transform. */
  const zr_transform *pt = o[5]->texture->pigment->transform;
  assert_non_null(pt);
  assert_vec(zr__xform_point(pt->m, zr_v3(1, 0, 0)), 2, 1, 0, EPS);
  pt = o[6]->texture->pigment->transform;
  assert_non_null(pt);
  assert_vec(zr__xform_point(pt->m, zr_v3(1, 0, 0)), 3, 0, 0, EPS);
  assert_null(o[6]->transform);

  /* POV-Ray: "Scale X by 0.0. Changed to 1.0." with a warning. */
  s = good(f, "sphere { 0, 1 scale <0, 2, 0> }");
  assert_int_equal(f->diag.warnings, 1);
  assert_string_equal(f->diag.warning,
                      "t.pov:1:21: warning: scale by 0 in xz changed to 1\n"
                      "    1 | sphere { 0, 1 scale <0, 2, 0> }\n"
                      "      |                     ^~~~~~~~~\n");
  assert_vec(to_world(s->objects[0], zr_v3(1, 1, 1)), 1, 2, 1, EPS);
}

/* normal { facets [coords F | size F] } is read and warned about once
   ("Facets": not rendered), so the scene renders without its facets. */
static void test_parser_facets_warned(void **state) {
  fixture *f = *state;
  good(f, "#declare N = normal { facets coords 0.5 scale 8 }\n"
          "sphere { 0, 1 normal { facets size 0.2 } }\n"
          "sphere { 0, 1 normal { N } }");
  assert_int_equal(f->diag.warnings, 1);
  assert_non_null(strstr(f->diag.warning,
                         "t.pov:1:23: warning: the 'facets' normal pattern "
                         "is not rendered"));
}

static void test_parser_union_pushes_modifiers(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f,
      "union {\n"
      "  sphere { 0, 1 pigment { rgb x } }\n"
      "  union { box { 0, 1 } cylinder { 0, y, 1 } }\n"
      "  translate <0, 5, 0>\n"
      "  pigment { rgb y }\n"
      "  no_shadow\n"
      "}\n");
  assert_int_equal(s->n_objects, 1);
  zr_scene_info info;
  zr_scene_get_info(s, &info);
  assert_int_equal(info.objects, 1);
  assert_int_equal(info.primitives, 3);
  for (size_t i = 0; i < s->n_primitives; i++) {
    const zr_object *p = s->primitives[i];
    assert_vec(to_world(p, zr_v3(0, 0, 0)), 0, 5, 0, EPS);
    assert_true(p->no_shadow);
  }
  /* The sphere keeps its own texture (moved with it); the others
     inherit the union's. */
  assert_colour(s->primitives[0]->texture->pigment->colour, 1, 0, 0, 0, 0);
  assert_non_null(s->primitives[0]->texture->pigment->transform);
  assert_colour(s->primitives[1]->texture->pigment->colour, 0, 1, 0, 0, 0);
  assert_colour(s->primitives[2]->texture->pigment->colour, 0, 1, 0, 0, 0);
}

static void test_parser_declare_copies(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f,
      "#declare P = pigment { rgb <1, 0, 0> }\n"
      "#declare T = texture { pigment { P } finish { phong 1 } }\n"
      "#declare O = union { sphere { 0, 1 } sphere { x, 1 } texture { T } }\n"
      "object { O translate y }\n"
      "object { O }\n"
      "sphere { 0, 1 texture { T pigment { P scale 2 } } }\n"
      "sphere { 0, 1 texture { T } }\n"
      "#declare O2 = O;\n"
      "#declare O = sphere { 0, 7 }\n"
      "object { O2 }\n");
  zr_object **o = s->objects;
  /* O2 is the union O was when O2 was declared. */
  assert_int_equal(o[4]->kind, ZR_OBJ_UNION);
  assert_int_equal(o[0]->u.csg.n_children, 2);
  assert_vec(to_world(o[0]->u.csg.children[1], zr_v3(0, 0, 0)), 0, 1, 0, EPS);
  /* The declared union (and so the second copy) did not move. */
  assert_null(o[1]->u.csg.children[1]->transform);
  assert_null(o[1]->texture->pigment->transform);
  assert_ptr_not_equal(o[0]->u.csg.children[0], o[1]->u.csg.children[0]);
  assert_non_null(o[2]->texture->pigment->transform);
  assert_null(o[3]->texture->pigment->transform);
  assert_num(o[3]->texture->finish->phong, 1);
  assert_colour(o[3]->texture->pigment->colour, 1, 0, 0, 0, 0);
  zr_scene_info info;
  zr_scene_get_info(s, &info);
  assert_int_equal(info.primitives, 8);
}

/* Primitives take the texture they inherit in place (lib/scene/scene.c
   flatten): a declared object placed both bare and in a textured union,
   in either order, must still get the default texture bare and the
   union's inside it. */
static void test_parser_inherited_texture_per_use(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f,
      "#declare S = sphere { 0, 1 }\n"
      "object { S }\n"
      "union { object { S } sphere { x, 1 } pigment { rgb z } }\n"
      "object { S translate y }\n"
      "#default { pigment { rgb x } }\n"
      "object { S }\n");
  assert_int_equal(s->n_primitives, 5);
  const zr_texture *bare = s->primitives[0]->texture;
  assert_non_null(bare);
  assert_ptr_equal(s->primitives[3]->texture, bare);
  assert_colour(s->primitives[1]->texture->pigment->colour, 0, 0, 1, 0, 0);
  assert_colour(s->primitives[2]->texture->pigment->colour, 0, 0, 1, 0, 0);
  assert_ptr_not_equal(s->primitives[1]->texture, bare);
  /* #default changes objects made after it only. */
  assert_colour(s->primitives[4]->texture->pigment->colour, 1, 0, 0, 0, 0);
  assert_colour(bare->pigment->colour, 0, 0, 0, 0, 0);
  for (size_t i = 0; i < s->n_primitives; i++)
    assert_non_null(s->primitives[i]->interior);
}

static void test_parser_camera_look_at(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f,
      "camera { location <0, 0, -10> look_at <0, 0, 0> angle 90 }\n");
  zr_camera *c = &s->camera;
  assert_true(c->given);
  assert_vec(c->location, 0, 0, -10, EPS);
  /* 0.5 * |right| / tan(45 degrees) = 0.665 with the default right. */
  assert_vec(c->direction, 0, 0, 0.665, EPS);
  assert_vec(c->right, 1.33, 0, 0, EPS);
  assert_vec(c->up, 0, 1, 0, EPS);

  s = good(f, "camera { location <5, 0, 0> look_at 0 }\n");
  c = &s->camera;
  assert_vec(c->direction, -1, 0, 0, EPS);
  /* Looking down -x with y up is a -90 degree turn about y, which takes
     the right vector +x to +z. */
  assert_vec(c->right, 0, 0, 1.33, EPS);
  assert_vec(c->up, 0, 1, 0, EPS);

  /* The Cornell box's mirrored right vector stays mirrored. */
  s = good(f, "camera { location <0, 1, -3> right <-1, 0, 0> up y\n"
              "  look_at <0, 1, 0> angle 60 }\n");
  c = &s->camera;
  assert_vec(c->right, -1, 0, 0, EPS);
  assert_vec(c->up, 0, 1, 0, EPS);
  assert_vec(c->direction, 0, 0, 0.5 / tan(M_PI / 6), EPS);

  s = good(f, "camera { perspective location 0 direction z * 2\n"
              "  up y right x sky x look_at z translate <1, 2, 3> }\n");
  c = &s->camera;
  assert_vec(c->location, 1, 2, 3, EPS);
  assert_vec(c->direction, 0, 0, 2, EPS);
  /* With sky along +x the camera rolls: up turns to +x. */
  assert_vec(c->up, 1, 0, 0, EPS);
  assert_vec(c->right, 0, -1, 0, EPS);

  s = good(f, "camera { location <0, 0, -1> rotate <0, 90, 0> }\n");
  c = &s->camera;
  assert_vec(c->location, -1, 0, 0, EPS);
  assert_vec(c->direction, 1, 0, 0, EPS);
}

/* Where the camera puts point q on a width x height image: solves
   q - location = s (direction + u right + v up). */
static void project(const zr_camera *c, zr_vec3 q, int width, int height,
                    double *px, double *py) {
  zr_vec3 d = zr_v3_sub(q, c->location);
  zr_vec3 ru = zr_v3_cross(c->right, c->up);
  double det = zr_v3_dot(c->direction, ru);
  double s = zr_v3_dot(d, ru) / det;
  double u = zr_v3_dot(c->direction, zr_v3_cross(d, c->up)) / det / s;
  double v = zr_v3_dot(c->direction, zr_v3_cross(c->right, d)) / det / s;
  *px = (u + 0.5) * width;
  *py = (0.5 - v) * height;
}

static void test_parser_camera_matches_povray(void **state) {
  fixture *f = *state;
  /* Reference: POV-Ray 3.7 rendered each camera at 160x120 with a white
     sphere of radius 0.1 at <1.5, 0.5, 1> on black; (x, y) is the
     centroid of its 10 to 32 lit pixels, which locates the centre to
     within half a pixel.  The cases pin down POV-Ray's order: look_at,
     sky and angle act after every other item, transforms after them. */
  static const struct {
    const char *camera;
    double x, y;
  } cases[] = {
      {"location <3, 4, -7> sky <0.3, 1, 0> look_at <0, 1, 0> angle 50",
       115.5, 56.0},
      {"look_at <0, 1, 0> sky <0.3, 1, 0> location <3, 4, -7> angle 50",
       115.5, 56.0},
      {"location <3, 4, -7> translate <1, 0, 0> look_at <0, 1, 0> angle 50",
       96.12, 63.88},
      {"location <3, 4, -7> look_at <0, 1, 0> rotate <0, 10, 0> angle 50",
       112.3, 64.5},
      {"location <3, 4, -7> angle 50 right x look_at <0, 1, 0>", 115.0,
       65.3},
      {"location <3, 4, -7> angle 50 direction z look_at <0, 1, 0>", 115.12,
       66.88},
      {"location <3, 4, -7> rotate <0, 30, 0> look_at <2, 1, 0>\n"
       "rotate <10, 0, 0> angle 40",
       58.38, 51.91},
      {"location <0, 1, -3> right <-1, 0, 0> up y look_at <0, 1, 0>\n"
       "angle 60",
       28.0, 73.0},
  };
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
    char text[512];
    snprintf(text, sizeof text, "camera { %s }\n", cases[i].camera);
    zr_scene *s = good(f, text);
    double x, y;
    project(&s->camera, zr_v3(1.5, 0.5, 1), 160, 120, &x, &y);
    if (fabs(x - cases[i].x) > 0.5 || fabs(y - cases[i].y) > 0.5)
      fail_msg("case %zu: (%g, %g) but POV-Ray (%g, %g)", i, x, y,
               cases[i].x, cases[i].y);
  }
}

static void test_parser_lights_background_settings(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f,
      "#version 3.7;\n"
      "global_settings { assumed_gamma 2.2 max_trace_level 10\n"
      "  adc_bailout 0.01 ambient_light rgb <0.5, 0.6, 0.7> }\n"
      "background { color rgb <0.1, 0.2, 0.3> }\n"
      "light_source { <1, 2, 3>, color rgb <1, 0.5, 0.25> }\n"
      "light_source { <0, 0, 0>, 1 shadowless translate <0, 10, 0> }\n");
  assert_int_equal(s->n_lights, 2);
  assert_vec(s->lights[0].location, 1, 2, 3, EPS);
  assert_rgb(s->lights[0].colour, 1, 0.5, 0.25);
  assert_false(s->lights[0].shadowless);
  assert_vec(s->lights[1].location, 0, 10, 0, EPS);
  assert_rgb(s->lights[1].colour, 1, 1, 1);
  assert_true(s->lights[1].shadowless);
  assert_colour(s->settings.background, 0.1, 0.2, 0.3, 0, 0);
  assert_num(s->settings.assumed_gamma, 2.2);
  assert_true(s->settings.assumed_gamma_given);
  assert_int_equal(s->settings.max_trace_level, 10);
  assert_num(s->settings.adc_bailout, 0.01);
  assert_rgb(s->settings.ambient_light, 0.5, 0.6, 0.7);
  assert_num(zr_scene_assumed_gamma(s), 2.2);
  assert_num(s->settings.version, 3.7);
  good(f, "#version 3.5; sphere { 0, 1 interior { ior 1.5 } inverse }\n");
  assert_num(f->scene->objects[0]->interior->ior, 1.5);
  assert_true(f->scene->objects[0]->inverse);
  assert_num(f->scene->settings.version, 3.5);
  good(f, "sphere { 0, 1 }");
  assert_num(f->scene->settings.version, 3.7);
  /* The encoding a scene's picture is written with: a legacy scene
     (no assumed_gamma, no #version 3.7 at its end) imposes file gamma
     2.2 over assumed gamma 2.2 (colours as they are); a 3.7 scene
     leaves the file gamma to the caller (0, sRGB). */
  zr_image_encoding enc;
  good(f, "#version 3.7; sphere { 0, 1 }\n");
  zr_scene_image_encoding(f->scene, ZR_FORMAT_PNG16, &enc);
  assert_int_equal(enc.format, ZR_FORMAT_PNG16);
  assert_num(enc.assumed_gamma, 1.0);
  assert_num(enc.file_gamma, 0.0);
  good(f, "#version 3.5; sphere { 0, 1 }\n");
  zr_scene_image_encoding(f->scene, ZR_FORMAT_AUTO, &enc);
  assert_num(enc.assumed_gamma, 2.2);
  assert_num(enc.file_gamma, 2.2);
  /* POV-Ray takes a #version without ';' and warns ("Possible Parse
     Error"); the same for a float #declare below version 3.5, and from
     3.5 on it refuses the #declare (tests/test_refused.sh). */
  good(f, "#version max(3.1, 3.4)\n#declare A = 2 sphere { 0, A }\n");
  assert_num(f->scene->settings.version, 3.4);
  assert_num(f->scene->objects[0]->u.sphere.radius, 2);
  assert_int_equal(f->diag.warnings, 2);
  assert_string_equal(f->diag.warning,
                      "t.pov:2:14: warning: '#declare' of a float, vector "
                      "or colour should end with ';'\n"
                      "    2 | #declare A = 2 sphere { 0, A }\n"
                      "      |              ^\n");
  bad(f, "#version max(3.1, 3.6);\n#declare A = 2 sphere { 0, A }\n",
      ZR_ESYNTAX, "'#declare' of a float, vector or colour needs ';' at "
      "its end when the language version is 3.5 or later (it is 3.6 "
      "here): add the ';', or set '#version 3.1;'",
      "t.pov:2:14: error: '#declare' of a float, vector or colour needs "
      "';' at its end when the language version is 3.5 or later (it is "
      "3.6 here): add the ';', or set '#version 3.1;'\n"
      "    2 | #declare A = 2 sphere { 0, A }\n"
      "      |              ^\n");
  good(f, "#version 3.5");
  assert_num(f->scene->settings.version, 3.5);
  assert_int_equal(f->diag.warnings, 1);
}

static void test_parser_zfor_replays(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f,
      "#declare zr = 42;\n"
      "#zfor (3)\n"
      "  sphere { <zr, 0, 0>, 1 }\n"
      "  #zfor (1 + 1) sphere { <zr, 1, 0>, 0.5 } #zend\n"
      "  sphere { <zr, 2, 0>, 0.25 }\n"
      "#zend\n"
      "#zfor (0) sphere { 0, 1 } #zend\n"
      "sphere { <zr, 0, 0>, 1 }\n");
  /* 3 * (1 + 2 + 1) spheres and the last one. */
  assert_int_equal(s->n_objects, 13);
  zr_object **o = s->objects;
  assert_vec(o[0]->u.sphere.centre, 0, 0, 0, EPS);
  assert_vec(o[1]->u.sphere.centre, 0, 1, 0, EPS);
  assert_vec(o[2]->u.sphere.centre, 1, 1, 0, EPS);
  /* After the inner loop the outer zr is back. */
  assert_vec(o[3]->u.sphere.centre, 0, 2, 0, EPS);
  assert_vec(o[4]->u.sphere.centre, 1, 0, 0, EPS);
  assert_vec(o[11]->u.sphere.centre, 2, 2, 0, EPS);
  assert_vec(o[12]->u.sphere.centre, 42, 0, 0, EPS);
}

/* ---- files and includes ---- */

static char tmpdir[64];

static void write_file(const char *name, const char *text) {
  char path[256];
  snprintf(path, sizeof path, "%s/%s", tmpdir, name);
  FILE *fp = fopen(path, "w");
  assert_non_null(fp);
  fputs(text, fp);
  fclose(fp);
}

static int make_tmpdir(void **state) {
  snprintf(tmpdir, sizeof tmpdir, "/tmp/zr_parser_XXXXXX");
  assert_non_null(mkdtemp(tmpdir));
  char sub[128];
  snprintf(sub, sizeof sub, "%s/lib", tmpdir);
  assert_int_equal(mkdir(sub, 0700), 0);
  write_file("scene.pov",
             "#include \"shapes.inc\"\n"
             "#include \"libshapes.inc\"\n"
             "object { Ball translate x }\n"
             "object { Cube }\n");
  write_file("shapes.inc",
             "#local R = 2;\n"
             "#declare Ball = sphere { 0, R }\n");
  write_file("lib/libshapes.inc",
             "#declare Cube = box { -1, 1 }\n");
  write_file("uses_local.pov",
             "#include \"shapes.inc\"\n"
             "sphere { 0, R }\n");
  write_file("outer.inc", "// outer\n#include \"inner.inc\"\n");
  write_file("inner.inc", "\n  #include \"nowhere.inc\"\n");
  write_file("nested.pov", "sphere { 0, 1 }\n#include \"outer.inc\"\n");
  write_file("self.inc", "#include \"self.inc\"\n");
  write_file("recursive.pov", "#include \"self.inc\"\n");
  write_file("badinc.inc", "sphere { 0, 1 } /* open\n");
  write_file("lexerror.pov", "#include \"badinc.inc\"\n");
  (void)state;
  return 0;
}

static int remove_tmpdir(void **state) {
  (void)state;
  static const char *const names[] = {
      "scene.pov", "shapes.inc", "lib/libshapes.inc", "uses_local.pov",
      "outer.inc", "inner.inc", "nested.pov", "self.inc", "recursive.pov",
      "badinc.inc", "lexerror.pov", "lib"};
  for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
    char path[256];
    snprintf(path, sizeof path, "%s/%s", tmpdir, names[i]);
    remove(path);
  }
  rmdir(tmpdir);
  return 0;
}

static zr_status parse_file(fixture *f, const char *name) {
  char path[256];
  snprintf(path, sizeof path, "%s/%s", tmpdir, name);
  zr_scene_free(f->scene);
  f->scene = NULL;
  memset(&f->diag, 0, sizeof f->diag);
  return zr_scene_parse_file(f->ctx, path, &f->scene);
}

static void test_parser_include_paths(void **state) {
  fixture *f = *state;
  /* libshapes.inc is only in lib/: not found until the path is added. */
  assert_int_equal(parse_file(f, "scene.pov"), ZR_ENOTFOUND);
  char expected[512];
  snprintf(expected, sizeof expected,
           "cannot find include file 'libshapes.inc'");
  assert_string_equal(f->diag.message, expected);
  char lib[128];
  snprintf(lib, sizeof lib, "%s/lib", tmpdir);
  assert_int_equal(zr_context_add_include_path(f->ctx, lib), ZR_OK);
  assert_int_equal(parse_file(f, "scene.pov"), ZR_OK);
  zr_scene *s = f->scene;
  assert_int_equal(s->n_objects, 2);
  assert_num(s->objects[0]->u.sphere.radius, 2);
  assert_vec(to_world(s->objects[0], zr_v3(0, 0, 0)), 1, 0, 0, EPS);
  assert_int_equal(s->objects[1]->kind, ZR_OBJ_BOX);
  /* POV-Ray's own include directory is searched last: consts.inc is
     found there, and its directives run (e = exp(1), o = <0,0,0>). */
  assert_int_equal(parse(f, "#include \"consts.inc\"\n"
                            "sphere { o, e }\n"),
                   ZR_OK);
  assert_num(f->scene->objects[0]->u.sphere.radius, exp(1));
}

static void test_parser_local_stays_in_its_file(void **state) {
  fixture *f = *state;
  assert_int_equal(parse_file(f, "uses_local.pov"), ZR_EUNDEFINED);
  assert_string_equal(f->diag.message, "undefined identifier 'R'");
}

/* Serves one scene from memory, as an MPI rank would. */
static zr_status memory_reader(const char *path, char **bytes, size_t *size,
                               void *user) {
  (void)user;
  const char *text = strcmp(path, "mem.pov") == 0
                         ? "#include \"m.inc\"\nobject { M }\n"
                         : strcmp(path, "m.inc") == 0
                               ? "#declare M = sphere { 0, 3 }\n"
                               : NULL;
  if (!text)
    return ZR_ENOTFOUND;
  *size = strlen(text);
  *bytes = strdup(text);
  return *bytes ? ZR_OK : ZR_ENOMEM;
}

static void test_parser_custom_reader(void **state) {
  fixture *f = *state;
  zr_context_set_reader(f->ctx, memory_reader, NULL);
  assert_int_equal(zr_scene_parse_file(f->ctx, "mem.pov", &f->scene),
                   ZR_OK);
  assert_num(f->scene->objects[0]->u.sphere.radius, 3);
}

/* ---- bad input ---- */

/* Splits the list of an "expected A, B or C" message into its names:
   quoted tokens ('}', ',') and bare words (number, identifier).  Fails
   the test on a list that is not of that form; returns the count. */
static int expected_names(const char *list, char names[][40], int max) {
  int n = 0;
  bool last = false;
  const char *p = list;
  for (;;) {
    const char *end;
    if (*p == '\'') {
      /* A quoted token may be a quote or comma itself: its closing
         quote is the one followed by a separator or the end. */
      end = p + 2;
      while (*end && !(end[0] == '\'' &&
                       (end[1] == '\0' || end[1] == ',' || end[1] == ' ')))
        end++;
      if (*end != '\'')
        fail_msg("unclosed quote in the expected list '%s'", list);
      end++;
    } else {
      end = p;
      while (*end >= 'a' && *end <= 'z')
        end++;
      if (end == p)
        fail_msg("no name at '%s' in the expected list '%s'", p, list);
    }
    if (n == max || end - p >= 40)
      fail_msg("expected list too long: '%s'", list);
    snprintf(names[n], sizeof names[n], "%.*s", (int)(end - p), p);
    n++;
    /* Names are separated by ", ", the last two by " or ". */
    if (*end == '\0') {
      if (n >= 2 && !last)
        fail_msg("no ' or ' before the last name in '%s'", list);
      return n;
    }
    if (last)
      fail_msg("a name after the ' or ' one in '%s'", list);
    if (strncmp(end, ", ", 2) == 0) {
      p = end + 2;
    } else if (strncmp(end, " or ", 4) == 0) {
      p = end + 4;
      last = true;
    } else {
      fail_msg("bad separator at '%s' in the expected list '%s'", end,
               list);
    }
  }
}

static bool named(char names[][40], int n, const char *name) {
  for (int k = 0; k < n; k++)
    if (strcmp(names[k], name) == 0)
      return true;
  return false;
}

/*
 * Parses the one-line text, which must fail with one syntax error at
 * column of line 1 on the token what (as quoted in the message):
 * "unexpected WHAT, expected LIST", a well-formed list naming no token
 * twice, every name of must and none of must_not; the full text is
 * "t.pov:1:COLUMN: error: MESSAGE", the line quoted and a caret (with a
 * tilde for each further character of the token) under the column.
 * Which other tokens are listed, and in what order, is the grammar's
 * business: adding an object modifier must not break this test.  A
 * list longer than MAX_EXPECTED in grammar/pov.y is left out of the
 * message; if that happens here, raise MAX_EXPECTED (a message that
 * says only "unexpected ','" helps nobody).
 */
static void syntax_error(fixture *f, const char *text, int column,
                         const char *what, const char *const *must,
                         const char *const *must_not) {
  assert_int_equal(parse(f, text), ZR_ESYNTAX);
  assert_int_equal(f->diag.errors, 1);
  assert_int_equal(f->diag.status, ZR_ESYNTAX);
  char head[128];
  snprintf(head, sizeof head, "unexpected %s, expected ", what);
  const char *msg = f->diag.message;
  if (strncmp(msg, head, strlen(head)) != 0)
    fail_msg("'%s' does not begin with '%s'", msg, head);
  char names[64][40];
  int n = expected_names(msg + strlen(head), names, 64);
  for (int i = 0; i < n; i++)
    for (int k = i + 1; k < n; k++)
      if (strcmp(names[i], names[k]) == 0)
        fail_msg("%s is listed twice in '%s'", names[i], msg);
  for (; must && *must; must++)
    if (!named(names, n, *must))
      fail_msg("%s is not listed in '%s'", *must, msg);
  for (; must_not && *must_not; must_not++)
    if (named(names, n, *must_not))
      fail_msg("%s cannot come here, yet '%s' lists it", *must_not, msg);
  /* The token's width: a quoted token's characters, else one. */
  size_t width = what[0] == '\'' ? strlen(what) - 2 : 1;
  size_t line_len = strcspn(text, "\n");
  char full[4096], caret[256];
  assert_true(column >= 1 && (size_t)column - 1 + width < sizeof caret);
  memset(caret, ' ', (size_t)column - 1);
  caret[column - 1] = '^';
  memset(caret + column, '~', width - 1);
  caret[column - 1 + width] = '\0';
  snprintf(full, sizeof full,
           "t.pov:1:%d: error: %s\n    1 | %.*s\n      | %s\n", column, msg,
           (int)line_len, text, caret);
  assert_string_equal(f->diag.text, full);
}

static void test_parser_syntax_error(void **state) {
  fixture *f = *state;
  /* After a sphere's radius: its modifiers, the operators that could
     continue the radius, or the closing brace; not another value. */
  static const char *const modifiers[] = {
      "'translate'", "'rotate'", "'scale'", "'pigment'", "'texture'",
      "'finish'", "'no_shadow'", "'+'", "'*'", "'}'", NULL};
  static const char *const not_after_radius[] = {
      "','", "'sphere'", "'{'", "number", "'shadowless'", NULL};
  syntax_error(f, "sphere { <0, 0, 0>, 1, 2 }\n", 22, "','", modifiers,
               not_after_radius);
  syntax_error(f, "box { 0, 1 shadowless }", 12, "'shadowless'",
               modifiers, not_after_radius);
  /* Inside a call: another argument, the closing parenthesis or an
     operator (a list that names the comma token itself). */
  static const char *const in_call[] = {"','", "')'", "'+'", "'<='", NULL};
  static const char *const not_in_call[] = {"';'", "'}'", "'{'", NULL};
  syntax_error(f, "#declare A = max(1;", 19, "';'", in_call, not_in_call);
  /* Here the list is short and fixed by the language. */
  static const char *const identifier[] = {"identifier", NULL};
  syntax_error(f, "#declare 3 = 1;", 10, "number", identifier, NULL);
  assert_string_equal(f->diag.message,
                      "unexpected number, expected identifier");
  /* As in POV-Ray, "-1" after a vector subtracts: the radius is missing
     and too many tokens could start it to list them. */
  bad(f, "sphere { <0, 0, 0> -1 }", ZR_ESYNTAX, "unexpected '}'", NULL);
  /* Every statement and object keyword could follow: too many to list
     (more than MAX_EXPECTED in grammar/pov.y). */
  bad(f, "sphere { 0, 1 }\n}\n", ZR_ESYNTAX, "unexpected '}'", NULL);
}

static void test_parser_type_errors(void **state) {
  fixture *f = *state;
  bad(f, "sphere { 0, <1, 2, 3> }", ZR_ESYNTAX,
      "expected a float, got a vector",
      "t.pov:1:13: error: expected a float, got a vector\n"
      "    1 | sphere { 0, <1, 2, 3> }\n"
      "      |             ^~~~~~~~~\n");
  bad(f, "sphere { 0, 1 open }", ZR_ESYNTAX,
      "'open' is for cylinders and cones, not for a sphere", NULL);
  bad(f, "#declare A = 1;\nsphere { 0, A.y }", ZR_ESYNTAX,
      "a float has no component '.y'", NULL);
  /* 1/0 is +inf with a warning (tests/legacy/divzero.pov); a radius
     must still be finite. */
  bad(f, "sphere { 0, 1 / 0 }", ZR_ESCENE,
      "this value is not a finite number (inf): an overflow (such as "
      "1e400) or a division such as inf/inf upstream?", NULL);
  bad(f, "box { 0, 1 matrix <1, 2, 3> }", ZR_ESYNTAX,
      "a matrix has 12 values, not 3", NULL);
}

static void test_parser_undefined_identifier(void **state) {
  fixture *f = *state;
  bad(f, "#declare Ok = 1;\nsphere { Ok, Foo }\n", ZR_EUNDEFINED,
      "undefined identifier 'Foo'",
      "t.pov:2:14: error: undefined identifier 'Foo'\n"
      "    2 | sphere { Ok, Foo }\n"
      "      |              ^~~\n");
}

static void test_parser_unsupported_keyword(void **state) {
  fixture *f = *state;
  bad(f, "sphere { 0, 1 }\n  iff { }\n", ZR_EUNSUPPORTED,
      "'iff' is not supported yet",
      "t.pov:2:3: error: 'iff' is not supported yet\n"
      "    2 |   iff { }\n"
      "      |   ^~~\n");
}

static void test_parser_missing_include_chain(void **state) {
  fixture *f = *state;
  assert_int_equal(parse_file(f, "nested.pov"), ZR_ENOTFOUND);
  char expected[1024];
  snprintf(expected, sizeof expected,
           "%s/inner.inc:2:12: error: cannot find include file "
           "'nowhere.inc'\n"
           "in file included from %s/outer.inc:2:1\n"
           "in file included from %s/nested.pov:2:1\n"
           "    2 |   #include \"nowhere.inc\"\n"
           "      |            ^~~~~~~~~~~~~\n",
           tmpdir, tmpdir, tmpdir);
  assert_string_equal(f->diag.text, expected);
  assert_null(f->scene);
}

static void test_parser_missing_file(void **state) {
  fixture *f = *state;
  assert_int_equal(parse_file(f, "no-such-scene.pov"), ZR_ENOTFOUND);
  char expected[512];
  snprintf(expected, sizeof expected,
           "cannot open scene file '%s/no-such-scene.pov': file not found",
           tmpdir);
  assert_string_equal(f->diag.message, expected);
  assert_null(f->scene);
}

static void test_parser_unterminated(void **state) {
  fixture *f = *state;
  bad(f, "sphere { 0, 1 }\n/* a /* b */\nbox { 0, 1 }\n", ZR_ESYNTAX,
      "unterminated comment",
      "t.pov:2:1: error: unterminated comment\n"
      "    2 | /* a /* b */\n"
      "      | ^~\n");
  bad(f, "#include \"x.inc\n", ZR_ESYNTAX, "unterminated string",
      "t.pov:1:10: error: unterminated string\n"
      "    1 | #include \"x.inc\n"
      "      |          ^\n");
  /* A stray character is an error where the scene reaches it, after
     the errors before it, and none in a skipped #if branch or an unused
     macro (POV-Ray 3.7, measured: tests/refused/bad_char_*.pov). */
  bad(f, "sphere { 0, 1 }\nsphere { 0, 1 } @ box { 0, 1 }\n", ZR_ESYNTAX,
      "unexpected character '@'",
      "t.pov:2:17: error: unexpected character '@'\n"
      "    2 | sphere { 0, 1 } @ box { 0, 1 }\n"
      "      |                 ^\n");
  bad(f, "sphere { 0, Nope }\n@\n", ZR_EUNDEFINED,
      "undefined identifier 'Nope'", NULL);
  good(f, "#if (0) #declare A = 5 % 2; #end\n"
          "#macro M() #declare B = 5 % 2; #end\nsphere { 0, 1 }\n");
  /* A lexical error in an included file shows the chain. */
  assert_int_equal(parse_file(f, "lexerror.pov"), ZR_ESYNTAX);
  char expected[512];
  snprintf(expected, sizeof expected,
           "%s/badinc.inc:1:17: error: unterminated comment\n"
           "in file included from %s/lexerror.pov:1:1\n"
           "    1 | sphere { 0, 1 } /* open\n"
           "      |                 ^~\n",
           tmpdir, tmpdir);
  assert_string_equal(f->diag.text, expected);
}

static void test_parser_zfor_errors(void **state) {
  fixture *f = *state;
  bad(f, "sphere { 0, 1 }\n#zfor (2) sphere { 0, 1 }\n", ZR_ESYNTAX,
      "'#zfor' without a matching '#zend'",
      "t.pov:2:1: error: '#zfor' without a matching '#zend'\n"
      "    2 | #zfor (2) sphere { 0, 1 }\n"
      "      | ^~~~~\n");
  bad(f, "#zend\n", ZR_ESYNTAX, "'#zend' without a matching '#zfor'", NULL);
  bad(f, "#zfor (2 sphere { 0, 1 } #zend", ZR_ESYNTAX,
      "unexpected 'sphere', expected '<=', '>=', '!=', '?', '|', '&', '<', "
      "'>', '=', '+', '-', '*', '/', ')' or '.'",
      NULL);
  bad(f, "#zfor (-1) #zend", ZR_ESCENE,
      "the count of '#zfor' is negative (-1)", NULL);
  bad(f, "#zfor (1e300) #zend", ZR_ELIMIT,
      "the count of '#zfor' is more than 100000000 (1e+300)", NULL);
}

static void test_parser_include_recursion_limit(void **state) {
  fixture *f = *state;
  assert_int_equal(parse_file(f, "recursive.pov"), ZR_ELIMIT);
  assert_string_equal(f->diag.message,
                      "#include nested more than 64 levels deep "
                      "(does a file include itself?)");
  assert_non_null(strstr(f->diag.text,
                         "(and 58 more levels of inclusion or macro "
                         "calls)\n"));
}

/*
 * "sphere { <x, y, z>, r texture { T } }" on one line is one token for
 * the grammar, T_SPHERE_TEXTURED (lib/sdl/directive.c, sphere_textured),
 * whose action makes the calls the slow path's actions make.  Random
 * scenes mixing that line with its near misses (a newline inside, a
 * modifier after the texture, a pigment, float, macro, deprecated or
 * undefined identifier, a sphere where none may stand (in a camera),
 * #declare and #version waiting for their end, unions, CSG) are parsed
 * with the fused token and without it (ctx->sdl_tokens_apart); both
 * must give the same status, messages (text, place and caret),
 * primitives (centres, radii, which share a texture) and image bytes.
 */
typedef struct parsed_view {
  zr_status status;
  captured diag;
  size_t n;
  double sphere[600][4];
  int kind[600];
  int shares[600]; /* the first primitive with the same texture */
  float rgb[16 * 16 * 3];
} parsed_view;

static void view_of(fixture *f, const char *text, int apart,
                    parsed_view *v) {
  memset(v, 0, sizeof *v);
  f->ctx->sdl_tokens_apart = apart;
  v->status = parse(f, text);
  f->ctx->sdl_tokens_apart = 0;
  v->diag = f->diag;
  if (v->status != ZR_OK)
    return;
  const zr_scene *sc = f->scene;
  v->n = sc->n_primitives < 600 ? sc->n_primitives : 600;
  for (size_t i = 0; i < v->n; i++) {
    const zr_object *o = sc->primitives[i];
    v->kind[i] = (int)o->kind;
    if (o->kind == ZR_OBJ_SPHERE) {
      v->sphere[i][0] = o->u.sphere.centre.x;
      v->sphere[i][1] = o->u.sphere.centre.y;
      v->sphere[i][2] = o->u.sphere.centre.z;
      v->sphere[i][3] = o->u.sphere.radius;
    }
    v->shares[i] = (int)i;
    for (size_t j = 0; j < i; j++)
      if (sc->primitives[j]->texture == o->texture) {
        v->shares[i] = (int)j;
        break;
      }
  }
  zr_render_params rp;
  zr_render_params_init(&rp);
  rp.width = 16;
  rp.height = 16;
  assert_int_equal(zr_render_image(sc, &rp, v->rgb, NULL), ZR_OK);
}

static unsigned fused_rand(unsigned *seed) {
  *seed = *seed * 1103515245u + 12345u;
  return (*seed >> 16) & 0x7fff;
}

/* One line of a random scene (kinds 0-19; the errors are 20-24). */
static void fused_line(char *out, size_t size, int kind, unsigned *seed) {
  double x = (int)(fused_rand(seed) % 200) / 50.0 - 2.0;
  double y = (int)(fused_rand(seed) % 200) / 80.0;
  double z = (int)(fused_rand(seed) % 200) / 50.0 + 1.0;
  double r = (int)(fused_rand(seed) % 50 + 1) / 100.0;
  /* T2 has no finish (the block's copy takes the default's, so it is
     kept), T3 a pattern (the copy takes its first entry's parts). */
  static const char *const textures[] = {"T1", "T2", "T3"};
  const char *tex = textures[fused_rand(seed) % 3];
  switch (kind) {
  case 0: case 1: case 2: case 3:
    snprintf(out, size, "sphere { <%g, %g, %g>, %g texture { %s } }\n", x,
             y, z, r, tex);
    break;
  case 4:
    snprintf(out, size, "  sphere{<%g,%g,%g>,%g texture{%s}}  sphere { "
             "<%g, %g, %g>, %g texture { %s } }\n", x, y, z, r, tex, z, x,
             y, r, tex);
    break;
  case 5:
    snprintf(out, size, "sphere { <%g, %g, %g>, %g texture { %s }\n}\n",
             x, y, z, r, tex);
    break;
  case 6:
    snprintf(out, size, "sphere { <%g, %g, %g>, %g texture {\n %s } }\n",
             x, y, z, r, tex);
    break;
  case 7:
    snprintf(out, size, "sphere { <%g, %g, %g>, %g texture { %s } scale "
             "1.5 }\n", x, y, z, r, tex);
    break;
  case 8:
    snprintf(out, size, "sphere { <%g, %g, %g>, %g texture { P1 } }\n", x,
             y, z, r);
    break;
  case 9:
    snprintf(out, size, "sphere { <%g, %g, %g>, %g texture { M() } }\n", x,
             y, z, r);
    break;
  case 10:
    snprintf(out, size, "sphere { <%g, %g, %g>, -%g texture { %s } }\n", x,
             y, z, r, tex);
    break;
  case 11:
    snprintf(out, size, "union { sphere { <%g, %g, %g>, %g texture { %s } "
             "} sphere { <%g, %g, %g>, %g texture { T2 } } }\n", x, y, z, r,
             tex, y, z, x, r);
    break;
  case 12:
    snprintf(out, size, "#declare S = sphere { <%g, %g, %g>, %g texture { "
             "%s } }\nobject { S translate x }\n", x, y, z, r, tex);
    break;
  case 13:
    snprintf(out, size, "sphere { <%g, %g, %g>, %g texture { D } }\n", x, y,
             z, r);
    break;
  case 14:
    snprintf(out, size, "sphere { <%g, %g, %g>, %g texture { %s } } // "
             "sphere\n", x, y, z, r, tex);
    break;
  case 15:
    snprintf(out, size, "#local L = texture { %s finish { phong 1 } }\n"
             "sphere { <%g, %g, %g>, %g texture { L } }\n", tex, x, y, z, r);
    break;
  case 16:
    snprintf(out, size, "#version 3.7\nsphere { <%g, %g, %g>, %g texture { "
             "%s } }\n", x, y, z, r, tex);
    break;
  case 17:
    snprintf(out, size, "object { sphere { <%g, %g, %g>, %g texture { %s } "
             "} rotate 10*y }\n", x, y, z, r, tex);
    break;
  case 18:
    snprintf(out, size, "difference { sphere { <%g, %g, %g>, %g texture { "
             "%s } } box { <%g, %g, %g>, <%g, %g, %g> } }\n", x, y, z, r,
             tex, x, y, z, x + 1, y + 1, z + 1);
    break;
  case 19:
    snprintf(out, size, "light_group { sphere { <%g, %g, %g>, %g texture { "
             "%s } } light_source { <1, 5, -2>, 1 } }\n", x, y, z, r, tex);
    break;
  case 20:
    snprintf(out, size, "camera { sphere { <%g, %g, %g>, %g texture { %s "
             "} } }\n", x, y, z, r, tex);
    break;
  case 21:
    snprintf(out, size, "sphere { <%g, %g, %g>, %g texture { U } }\n", x, y,
             z, r);
    break;
  case 22:
    snprintf(out, size, "sphere { <%g, %g, %g>, %g texture { F } }\n", x, y,
             z, r);
    break;
  case 23:
    snprintf(out, size, "union { sphere { <%g, %g, %g>, %g texture { %s } "
             "} 5 }\n", x, y, z, r, tex);
    break;
  default:
    snprintf(out, size, "#declare %s = sphere { <%g, %g, %g>, %g texture { "
             "%s } }\n", tex, x, y, z, r, tex);
    break;
  }
}

static void assert_views_same(const parsed_view *a, const parsed_view *b,
                              const char *text) {
  if (a->status != b->status || a->diag.errors != b->diag.errors ||
      a->diag.warnings != b->diag.warnings ||
      strcmp(a->diag.text, b->diag.text) != 0 ||
      strcmp(a->diag.warning, b->diag.warning) != 0)
    fail_msg("messages differ:\n%s\n--- fused: %d, %d errors, %d "
             "warnings\n%s\n%s\n--- apart: %d, %d errors, %d warnings\n"
             "%s\n%s", text, a->status, a->diag.errors, a->diag.warnings,
             a->diag.text, a->diag.warning, b->status, b->diag.errors,
             b->diag.warnings, b->diag.text, b->diag.warning);
  assert_int_equal(a->n, b->n);
  for (size_t i = 0; i < a->n; i++) {
    assert_int_equal(a->kind[i], b->kind[i]);
    assert_int_equal(a->shares[i], b->shares[i]);
    assert_memory_equal(a->sphere[i], b->sphere[i], sizeof a->sphere[i]);
  }
  if (memcmp(a->rgb, b->rgb, sizeof a->rgb) != 0)
    fail_msg("images differ:\n%s", text);
}

static void test_parser_textured_spheres_same(void **state) {
  fixture *f = *state;
  static const char header[] =
      "camera { location <0, 1, -4> look_at <0, 1, 2> }\n"
      "light_source { <-5, 8, -6>, 1 }\n"
      "#declare T1 = texture { pigment { rgb <0.9, 0.8, 0.6> } finish { "
      "ambient 0.1 diffuse 0.7 reflection 0.3 } }\n"
      "#declare T2 = texture { pigment { rgb <0.2, 0.4, 0.9> } }\n"
      "#declare T3 = texture { checker texture { T1 } texture { T2 } "
      "scale 0.3 }\n"
      "#declare P1 = pigment { rgb <1, 0, 0> }\n"
      "#declare F = 3;\n"
      "#declare deprecated D = texture { T1 }\n"
      "#macro M() T1 #end\n";
  parsed_view *fused = malloc(sizeof *fused);
  parsed_view *apart = malloc(sizeof *apart);
  char *text = malloc(64 * 1024);
  assert_non_null(fused);
  assert_non_null(apart);
  assert_non_null(text);
  unsigned seed = 13;
  int made = 0, errors = 0;
  for (int scene = 0; scene < 300; scene++) {
    size_t len = (size_t)snprintf(text, 64 * 1024, "%s", header);
    int lines = 1 + (int)(fused_rand(&seed) % 12);
    for (int l = 0; l < lines; l++) {
      /* Mostly lines that fuse; an error line now and then, last. */
      int kind = (int)(fused_rand(&seed) % 20);
      if (l == lines - 1 && fused_rand(&seed) % 4 == 0)
        kind = 20 + (int)(fused_rand(&seed) % 5);
      fused_line(text + len, 64 * 1024 - len, kind, &seed);
      len += strlen(text + len);
    }
    view_of(f, text, 0, fused);
    view_of(f, text, 1, apart);
    assert_views_same(fused, apart, text);
    made += fused->status == ZR_OK;
    errors += fused->status != ZR_OK;
  }
  /* Both kinds of outcome were compared. */
  assert_true(made > 150);
  assert_true(errors > 20);
  /* A file longer than the progress report's period (4096 tokens), with
     every sphere fused. */
  size_t len = (size_t)snprintf(text, 64 * 1024, "%s", header);
  for (int i = 0; i < 1000 && len < 60 * 1024; i++) {
    fused_line(text + len, 64 * 1024 - len, 0, &seed);
    len += strlen(text + len);
  }
  view_of(f, text, 0, fused);
  view_of(f, text, 1, apart);
  assert_int_equal(fused->status, ZR_OK);
  assert_views_same(fused, apart, text);
  free(text);
  free(fused);
  free(apart);
}

static void test_parser_string_name_in_messages(void **state) {
  fixture *f = *state;
  zr_scene *scene = NULL;
  const char *text = "sphere { 0, 1 } Bogus";
  assert_int_equal(zr_scene_parse_string(f->ctx, "inline scene", text,
                                         strlen(text), &scene),
                   ZR_EUNDEFINED);
  assert_null(scene);
  assert_string_equal(zr_context_last_error(f->ctx),
                      "inline scene:1:17: error: undefined identifier "
                      "'Bogus'\n"
                      "    1 | sphere { 0, 1 } Bogus\n"
                      "      |                 ^~~~~\n");
}

/* The clock identifiers come from zr_context_set_parse_options, a still
   image reads 0 for all of them, Declare= floats are declared before the
   scene; a caller's older, smaller struct keeps the defaults for the
   fields it lacks (the size rule). */
static void test_parser_clock_and_declare(void **state) {
  fixture *f = *state;
  zr_scene *scene = NULL;
  const char *still =
      "#if (clock != 0 | clock_delta != 0 | clock_on != 0 | "
      "frame_number != 0 | initial_frame != 0 | final_frame != 0 | "
      "initial_clock != 0 | final_clock != 0 | version != 3.7)\n"
      "  #error \"still\"\n#end\nsphere { 0, 1 }";
  assert_int_equal(zr_scene_parse_string(f->ctx, "still", still,
                                         strlen(still), &scene), ZR_OK);
  zr_scene_free(scene);
  zr_parse_options o;
  zr_parse_options_init(&o);
  o.clock = 0.25;
  o.clock_delta = 0.125;
  o.clock_on = 1;
  o.frame_number = 3;
  o.initial_frame = 1;
  o.final_frame = 9;
  o.initial_clock = 0;
  o.final_clock = 1;
  o.version = 3.5;
  assert_int_equal(zr_context_set_parse_options(f->ctx, &o), ZR_OK);
  assert_int_equal(zr_context_declare(f->ctx, "Rad", 2), ZR_OK);
  assert_int_equal(zr_context_declare(f->ctx, "Rad", 4), ZR_OK);
  const char *frame =
      "#if (clock != 0.25 | clock_delta != 0.125 | clock_on != 1 | "
      "frame_number != 3 | initial_frame != 1 | final_frame != 9 | "
      "final_clock != 1 | version != 3.5 | Rad != 4)\n"
      "  #error \"frame\"\n#end\nsphere { 0, 1 }";
  assert_int_equal(zr_scene_parse_string(f->ctx, "frame", frame,
                                         strlen(frame), &scene), ZR_OK);
  zr_scene_free(scene);
  /* A caller that knew only the fields up to clock. */
  zr_parse_options_init(&o);
  o.size = offsetof(zr_parse_options, clock_delta);
  o.clock = 0.5;
  o.clock_on = 1; /* beyond size: not read */
  assert_int_equal(zr_context_set_parse_options(f->ctx, &o), ZR_OK);
  const char *old =
      "#if (clock != 0.5 | clock_on != 0 | version != 3.7)\n"
      "  #error \"old\"\n#end\nsphere { 0, 1 }";
  assert_int_equal(zr_scene_parse_string(f->ctx, "old", old, strlen(old),
                                         &scene), ZR_OK);
  zr_scene_free(scene);
  o.size = 1;
  assert_int_equal(zr_context_set_parse_options(f->ctx, &o), ZR_EINVAL);
  assert_int_equal(zr_context_declare(f->ctx, "2x", 1), ZR_EINVAL);
  assert_int_equal(zr_context_declare(f->ctx, "x", NAN), ZR_EINVAL);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test_setup_teardown(test_parser_facets_warned, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_parser_primitives, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_parser_clock_and_declare, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_parser_optional_commas, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_parser_expressions, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_parser_colours, setup, teardown),
      cmocka_unit_test_setup_teardown(test_parser_finish, setup, teardown),
      cmocka_unit_test_setup_teardown(test_parser_transforms_in_order, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_parser_union_pushes_modifiers,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_parser_inherited_texture_per_use,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_parser_declare_copies, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_parser_camera_look_at, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_parser_camera_matches_povray,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_parser_lights_background_settings,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_parser_zfor_replays, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_parser_include_paths, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_parser_local_stays_in_its_file,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_parser_custom_reader, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_parser_syntax_error, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_parser_type_errors, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_parser_undefined_identifier,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_parser_unsupported_keyword, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_parser_missing_include_chain,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_parser_missing_file, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_parser_unterminated, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_parser_zfor_errors, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_parser_include_recursion_limit,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_parser_string_name_in_messages,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_parser_textured_spheres_same,
                                      setup, teardown),
  };
  return cmocka_run_group_tests(tests, make_tmpdir, remove_tmpdir);
}
