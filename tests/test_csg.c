/*
 * test_csg.c - CSG (intersection, difference, merge, nested unions,
 * inverse), quadrics, clipped_by, bounded_by and hollow, from scene text
 * through the parser and the scene's flattening to the tracer's
 * crossings and inside tests (lib/trace/csg.c, obj_quadric.c,
 * lib/sdl/build_object.c).
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
#include "scene/scene.h"
#include "trace/intersect.h"
#include "zrcube.h"
#include "parse_fixture.h"
#include "test_util.h"

/* Crossings here are roots of quadratics or of linear equations with
   small integer coefficients: 1e-12 covers double rounding. */
#define EPS 1e-12

static void test_csg_difference_cuts_with_inverted_normal(void **state) {
  fixture *f = *state;
  const zr_object *o = only(f, "difference { sphere { 0, 1 }\n"
                               "  box { <0, -2, -2>, <2, 2, 2> } }\n");
  assert_int_equal(o->kind, ZR_OBJ_INTERSECTION);
  zr_hit h[2];
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0.0, h), 2);
  assert_near(h[0].t, 4.0, EPS);
  assert_vec(h[0].normal, -1, 0, 0, EPS);
  assert_int_equal(h[0].object->kind, ZR_OBJ_SPHERE);
  /* The cut face: the inverted box's normal points out of the solid. */
  assert_near(h[1].t, 5.0, EPS);
  assert_vec(h[1].normal, 1, 0, 0, EPS);
  assert_int_equal(h[1].object->kind, ZR_OBJ_BOX);
  assert_true(h[1].object->inverse);
  /* Both parts belong to the primitive, whose interior rays enter. */
  assert_ptr_equal(h[0].object->solid, o);
  assert_ptr_equal(h[1].object->solid, o);
  /* The removed half has no surface: a ray through it meets nothing. */
  assert_int_equal(cross(o, zr_v3(0.5, -5, 0), zr_v3(0, 1, 0), 0.0, h), 0);
  assert_true(zr__inside(o, zr_v3(-0.5, 0, 0)));
  assert_false(zr__inside(o, zr_v3(0.5, 0, 0)));
  assert_false(zr__inside(o, zr_v3(-2, 0, 0)));
}

static void test_csg_intersection_is_a_lens(void **state) {
  fixture *f = *state;
  const zr_object *o =
      only(f, "intersection { sphere { 0, 1 } sphere { x, 1 } }\n");
  zr_hit h[2];
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0.0, h), 2);
  assert_near(h[0].t, 5.0, EPS); /* enters the second sphere at x = 0 */
  assert_vec(h[0].normal, -1, 0, 0, EPS);
  assert_near(h[1].t, 6.0, EPS); /* leaves the first at x = 1 */
  assert_vec(h[1].normal, 1, 0, 0, EPS);
  assert_true(zr__inside(o, zr_v3(0.5, 0, 0)));
  assert_false(zr__inside(o, zr_v3(-0.5, 0, 0)));
}

static void test_csg_merge_drops_inner_surfaces(void **state) {
  fixture *f = *state;
  const zr_object *m =
      only(f, "merge { sphere { 0, 1 } sphere { x, 1 } }\n");
  zr_hit h[2];
  assert_int_equal(cross(m, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0.0, h), 2);
  assert_near(h[0].t, 4.0, EPS);
  assert_near(h[1].t, 7.0, EPS);
  /* A union inside an intersection keeps its inner surfaces. */
  const zr_object *u = only(f, "intersection {\n"
                               "  union { sphere { 0, 1 } sphere { x, 1 } }\n"
                               "  box { -10, 10 } }\n");
  assert_int_equal(cross(u, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0.0, h), 2);
  assert_near(h[0].t, 4.0, EPS);
  assert_near(h[1].t, 5.0, EPS);
  /* Crossings beyond the first two are found from a later start. */
  zr_ray r = {zr_v3(-5, 0, 0), zr_v3(1, 0, 0)};
  assert_int_equal(zr__intersect(u, &r, 5.5, INFINITY, h), 2);
  assert_near(h[0].t, 6.0, EPS);
  assert_near(h[1].t, 7.0, EPS);
}

static void test_csg_inverse_follows_de_morgan(void **state) {
  fixture *f = *state;
  const zr_object *o = only(f, "difference { sphere { 0, 1 }\n"
                               "  box { <0, -2, -2>, <2, 2, 2> } inverse }\n");
  /* The inverse of an intersection is a merge of inverted children. */
  assert_int_equal(o->kind, ZR_OBJ_MERGE);
  assert_false(zr__inside(o, zr_v3(-0.5, 0, 0)));
  assert_true(zr__inside(o, zr_v3(0.5, 0, 0)));
  assert_true(zr__inside(o, zr_v3(-5, 0, 0)));
  zr_hit h[2];
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0.0, h), 2);
  assert_near(h[0].t, 4.0, EPS);
  assert_vec(h[0].normal, 1, 0, 0, EPS); /* now pointing into the sphere */
  assert_near(h[1].t, 5.0, EPS);
  assert_vec(h[1].normal, -1, 0, 0, EPS);
  /* Inverted twice is the object again. */
  o = only(f, "difference { sphere { 0, 1 } box { <0, -2, -2>, 2 }\n"
              "  inverse inverse }\n");
  assert_int_equal(o->kind, ZR_OBJ_INTERSECTION);
  assert_true(zr__inside(o, zr_v3(-0.5, 0, 0)));
}

static void test_csg_transforms_and_textures_reach_children(void **state) {
  fixture *f = *state;
  const zr_object *o = only(
      f, "#declare D = difference {\n"
         "  sphere { 0, 1 pigment { rgb <1, 0, 0> } }\n"
         "  box { <0, -2, -2>, <2, 2, 2> }\n"
         "  pigment { rgb <0, 0, 1> } }\n"
         "object { D translate <10, 0, 0> }\n");
  zr_hit h[2];
  assert_int_equal(cross(o, zr_v3(5, 0, 0), zr_v3(1, 0, 0), 0.0, h), 2);
  assert_near(h[0].t, 4.0, EPS);
  assert_near(h[1].t, 5.0, EPS);
  /* The sphere keeps its red; the box takes the difference's blue. */
  zr_colour red = h[0].object->texture->pigment->colour;
  zr_colour blue = h[1].object->texture->pigment->colour;
  assert_near(red.r, 1, 0);
  assert_near(red.b, 0, 0);
  assert_near(blue.r, 0, 0);
  assert_near(blue.b, 1, 0);
  assert_non_null(h[0].object->interior);
  /* object { } also wraps an object written in place. */
  o = only(f, "object { intersection { sphere { 0, 1 } sphere { x, 1 } }\n"
              "  translate <0, 3, 0> }\n");
  assert_true(zr__inside(o, zr_v3(0.5, 3, 0)));
  /* The copy moved; the declaration did not. */
  zr_scene *s = good(f, "#declare D = difference { sphere { 0, 1 }\n"
                        "  box { <0, -2, -2>, <2, 2, 2> } }\n"
                        "object { D translate <10, 0, 0> }\n"
                        "object { D }\n");
  assert_int_equal(s->n_primitives, 2);
  assert_true(zr__inside(s->primitives[0], zr_v3(9.5, 0, 0)));
  assert_true(zr__inside(s->primitives[1], zr_v3(-0.5, 0, 0)));
  assert_false(zr__inside(s->primitives[1], zr_v3(9.5, 0, 0)));
}

static void test_csg_bounds_of_intersection(void **state) {
  fixture *f = *state;
  /* shapes.inc's way: an infinite quadric made finite by a box. */
  const zr_object *o =
      only(f, "intersection { quadric { <1, 0, 1>, 0, 0, -1 }\n"
              "  box { <-2, -1, -2>, <2, 3, 2> } }\n");
  zr_vec3 lo, hi;
  assert_true(zr__object_bounds(o, &lo, &hi));
  /* Box corners, widened by the bounds code's relative 1e-9 pad. */
  assert_near(lo.y, -1, 1e-8);
  assert_near(hi.y, 3, 1e-8);
  /* A difference's inverted children add no limit. */
  o = only(f, "difference { box { -1, 1 } sphere { 0, 5 } }\n");
  assert_true(zr__object_bounds(o, &lo, &hi));
  assert_near(hi.x, 1, 1e-8);
  /* An inverted difference is unbounded. */
  o = only(f, "difference { box { -1, 1 } sphere { 0, 5 } inverse }\n");
  assert_false(zr__object_bounds(o, &lo, &hi));
}

/* A number in [0, 1) from a linear congruential stream. */
static double rnd(unsigned *seed) {
  *seed = *seed * 1103515245u + 12345u;
  return *seed / 4294967296.0;
}

/* Intersections of planes and quadrics alone (a chess pawn's neck:
   shapes.inc's Hyperboloid_Y between two planes) have a finite box,
   found by narrowing (lib/trace/bounds_csg.c).  Its exact extent is
   known: |x|, |z| <= 0.5 sqrt(1 + (y - 5)^2) for y in [2.5, 5.5], so
   0.5 sqrt(1 + 2.5^2) at y = 2.5; and every crossing of random rays lies
   in the box. */
static void test_csg_bounds_of_planes_and_quadrics(void **state) {
  fixture *f = *state;
  const char *pawn_neck =
      "intersection { plane { y, 5.5 }\n"
      "  quadric { <1, -1, 1>, 0, 0, -1 translate 5*y scale <0.5, 1, 0.5> }\n"
      "  plane { -y, -2.5 } rotate <10, 20, 30> translate <-28, 0, -20> }\n";
  const char *slanted_slab =
      "intersection { quadric { <1, 1, 0>, 0, 0, -1 }\n" /* Cylinder_Z */
      "  plane { z, 1 rotate 30*x } plane { -z, 2 rotate 30*x } }\n";
  const char *cases[] = {pawn_neck, slanted_slab};
  for (int c = 0; c < 2; c++) {
    const zr_object *o = only(f, cases[c]);
    zr_vec3 lo, hi;
    assert_true(zr__object_bounds(o, &lo, &hi));
    if (c == 0) {
      /* Rotation widens the box; it still holds the exact extent. */
      double r = 0.5 * sqrt(1 + 2.5 * 2.5), ext = hi.x - lo.x;
      assert_true(ext >= 2 * r - 1e-6);
      assert_true(ext < 8.0);
    }
    unsigned seed = 7u + (unsigned)c;
    zr_vec3 mid = zr_v3_scale(zr_v3_add(lo, hi), 0.5);
    for (int k = 0; k < 2000; k++) {
      zr_vec3 org = zr_v3_add(mid, zr_v3(40 * rnd(&seed) - 20,
                                         40 * rnd(&seed) - 20,
                                         40 * rnd(&seed) - 20));
      zr_vec3 dir = zr_v3_norm(zr_v3_sub(
          zr_v3_add(mid, zr_v3(4 * rnd(&seed) - 2, 4 * rnd(&seed) - 2,
                               4 * rnd(&seed) - 2)),
          org));
      zr_hit h[2];
      int n = cross(o, org, dir, 0.0, h);
      for (int i = 0; i < n; i++) {
        zr_vec3 p = zr_v3_madd(org, dir, h[i].t);
        assert_true(p.x >= lo.x - 1e-9 && p.x <= hi.x + 1e-9);
        assert_true(p.y >= lo.y - 1e-9 && p.y <= hi.y + 1e-9);
        assert_true(p.z >= lo.z - 1e-9 && p.z <= hi.z + 1e-9);
      }
    }
  }
  /* Disjoint half-spaces: nothing is inside both, a point box. */
  const zr_object *o =
      only(f, "intersection { plane { y, -1 } plane { -y, -1 } }\n");
  zr_vec3 lo, hi;
  assert_true(zr__object_bounds(o, &lo, &hi));
  assert_true(zr_v3_len(zr_v3_sub(hi, lo)) == 0.0);
  /* A slab of two planes alone stays unbounded across it. */
  o = only(f, "intersection { plane { y, 1 } plane { -y, 1 } }\n");
  assert_false(zr__object_bounds(o, &lo, &hi));
}

/* Planes whose faces all lie across the axes (shapes2.inc's
   Dodecahedron, stock textures/pigments/dodec2.pov) are bounded by the
   box of their polyhedron's vertices (lib/trace/bounds_csg.c): here
   exactly +-1 in y (its two caps) and the circumradius 1.2584 at most
   across; every crossing of random rays lies in the box.  Five planes
   round an axis (a pentagonal prism) stay unbounded, and so does a
   polyhedron cut off on one side only. */
static void test_csg_bounds_of_plane_polyhedra(void **state) {
  fixture *f = *state;
  const char *dodecahedron =
      "intersection {\n"
      "  #for (I, 0, 4)\n"
      "    plane { -z, 1 rotate <-26.56505117708, -72*I, 0> }\n"
      "    plane { -z, 1 rotate <26.56505117708, -36 - 72*I, 0> }\n"
      "  #end\n"
      "  plane { y, 1 } plane { -y, 1 }\n"
      "  translate y*1.8 rotate x*72 rotate z*144 }\n";
  const zr_object *o = only(f, dodecahedron);
  zr_vec3 lo, hi;
  assert_true(zr__object_bounds(o, &lo, &hi));
  zr_vec3 mid = zr_v3_scale(zr_v3_add(lo, hi), 0.5);
  zr_vec3 size = zr_v3_sub(hi, lo);
  /* Turned about two axes, the box is at most the circumsphere's. */
  assert_true(size.x <= 2 * 1.2585 && size.y <= 2 * 1.2585 &&
              size.z <= 2 * 1.2585);
  /* The centre sits where it was moved to: y 1.8, turned 72 about x
     (y cos 72, y sin 72), then 144 about z. */
  double c72 = cos(72 * M_PI / 180), s72 = sin(72 * M_PI / 180);
  double c144 = cos(144 * M_PI / 180), s144 = sin(144 * M_PI / 180);
  zr_vec3 centre = zr_v3(-1.8 * c72 * s144, 1.8 * c72 * c144, 1.8 * s72);
  assert_near(mid.x, centre.x, 0.2);
  assert_near(mid.y, centre.y, 0.2);
  assert_near(mid.z, centre.z, 0.2);
  unsigned seed = 99u;
  int crossings = 0;
  for (int k = 0; k < 3000; k++) {
    zr_vec3 org = zr_v3_add(centre, zr_v3(20 * rnd(&seed) - 10,
                                          20 * rnd(&seed) - 10,
                                          20 * rnd(&seed) - 10));
    zr_vec3 at = zr_v3_add(centre, zr_v3(3 * rnd(&seed) - 1.5,
                                         3 * rnd(&seed) - 1.5,
                                         3 * rnd(&seed) - 1.5));
    zr_hit h[2];
    int n = cross(o, org, zr_v3_sub(at, org), 0.0, h);
    for (int i = 0; i < n; i++) {
      zr_vec3 p = zr_v3_madd(org, zr_v3_sub(at, org), h[i].t);
      assert_true(p.x >= lo.x && p.x <= hi.x);
      assert_true(p.y >= lo.y && p.y <= hi.y);
      assert_true(p.z >= lo.z && p.z <= hi.z);
    }
    crossings += n;
    /* Points inside lie in the box. */
    if (zr__inside(o, at))
      assert_true(at.x >= lo.x && at.x <= hi.x && at.y >= lo.y &&
                  at.y <= hi.y && at.z >= lo.z && at.z <= hi.z);
  }
  assert_true(crossings > 1000);
  const char *open[] = {
      "intersection { #for (I, 0, 4) plane { -z, 1 rotate y*72*I } #end\n"
      "  rotate <10, 20, 30> }\n",
      "intersection { #for (I, 0, 4)\n"
      "  plane { -z, 1 rotate <-26.56505117708, -72*I, 0> } #end\n"
      "  plane { -y, 1 } rotate <10, 20, 30> }\n",
  };
  for (int c = 0; c < 2; c++) {
    o = only(f, open[c]);
    assert_false(zr__object_bounds(o, &lo, &hi));
  }
}

/* A part the tracer cannot box (a quartic torus, advanced/pawns.pov)
   takes its union's bounded_by box in the hierarchy, moved with the
   union; a part it can box keeps its own, however loose the bound. */
static void test_csg_bounded_by_boxes_unboundable_parts(void **state) {
  fixture *f = *state;
  const char *torus = /* (x^2+y^2+z^2+R^2-r^2)^2 - 4R^2(x^2+z^2), R 8 r 1.5 */
      "quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, -132.5, 0, 0, 0, 0, 0, 0, 0,\n"
      "  0, 0, 0, 1, 0, 0, 2, 0, 123.5, 0, 0, 0, 0, 1, 0, -132.5, 0,\n"
      "  3813.0625> }\n";
  char text[512];
  snprintf(text, sizeof text,
           "union { %s bounded_by { box { <-10, -2, -10>, <10, 2, 10> } }\n"
           "  translate 5*x }\n", torus);
  const zr_object *o = only(f, text);
  assert_int_equal(o->kind, ZR_OBJ_POLY);
  zr_vec3 lo, hi;
  assert_true(zr__primitive_bounds(o, &lo, &hi));
  assert_near(lo.x, -5, 1e-6);
  assert_near(hi.x, 15, 1e-6);
  assert_near(hi.y, 2, 1e-6);
  /* Inside tests (a CSG child's box) never take the bound. */
  assert_false(zr__object_bounds(o, &lo, &hi));
  /* Without the bound it has none. */
  o = only(f, torus);
  assert_false(zr__primitive_bounds(o, &lo, &hi));
  /* A bounded intersection cut out of a box (shapes.inc's Supercone in
     logo.inc's bevel): the inverted part's inside is all outside its
     bound, so its CSG box must not be the bound's. */
  o = only(f, "difference { box { -4, 4 }\n"
              "  intersection { sphere { 0, 1 } sphere { 0.5, 1 }\n"
              "    bounded_by { sphere { 0, 1 } } } }\n");
  assert_true(zr__inside(o, zr_v3(3, 3, 3)));
  assert_false(zr__inside(o, zr_v3(0.2, 0, 0)));
  /* A sphere keeps its own box under a loose bound. */
  o = only(f, "union { sphere { 0, 1 } bounded_by { sphere { 0, 100 } } }\n");
  assert_true(zr__primitive_bounds(o, &lo, &hi));
  assert_near(hi.x, 1, 1e-6);
}

static void test_csg_quadric_cylinder_and_paraboloid(void **state) {
  fixture *f = *state;
  /* x^2 + z^2 - 1: shapes.inc's Cylinder_Y. */
  const zr_object *o = only(f, "quadric { <1, 0, 1>, <0, 0, 0>,\n"
                               "  <0, 0, 0>, -1 }\n");
  assert_int_equal(o->kind, ZR_OBJ_QUADRIC);
  zr_vec3 lo, hi;
  assert_false(zr__object_bounds(o, &lo, &hi));
  zr_hit h[2];
  assert_int_equal(cross(o, zr_v3(-5, 7, 0), zr_v3(1, 0, 0), 0.0, h), 2);
  assert_near(h[0].t, 4.0, EPS);
  assert_vec(h[0].normal, -1, 0, 0, EPS);
  assert_near(h[1].t, 6.0, EPS);
  assert_vec(h[1].normal, 1, 0, 0, EPS);
  /* Along the axis it is never crossed. */
  assert_int_equal(cross(o, zr_v3(0, -5, 0), zr_v3(0, 1, 0), 0.0, h), 0);
  assert_true(zr__inside(o, zr_v3(0.5, 100, 0)));
  assert_false(zr__inside(o, zr_v3(1.5, 0, 0)));
  /* y = x^2 + z^2: along the axis the equation is linear. */
  o = only(f, "quadric { <1, 0, 1>, <0, 0, 0>, <0, -1, 0>, 0 }\n");
  assert_int_equal(cross(o, zr_v3(0, 5, 0), zr_v3(0, -1, 0), 0.0, h), 1);
  assert_near(h[0].t, 5.0, EPS);
  assert_vec(h[0].normal, 0, -1, 0, EPS);
  assert_true(zr__inside(o, zr_v3(0, 1, 0)));
  /* Transformed: the unit cylinder scaled by 2 about its axis. */
  o = only(f, "quadric { <1, 0, 1>, 0, 0, -1 scale 2 }\n");
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0.0, h), 2);
  assert_near(h[0].t, 3.0, EPS);
  assert_near(h[1].t, 7.0, EPS);
}

/* How many of the scene's primitives hold p. */
static int holders(const zr_scene *s, zr_vec3 p) {
  int n = 0;
  for (size_t i = 0; i < s->n_primitives; i++)
    n += zr__inside(s->primitives[i], p);
  return n;
}

/* The second and later transformations of an object change the
   transforms its first one made in place (lib/sdl/build.c,
   compose_object); a copy that shares a transform, the declared object
   and a bound its clip was copied from never see it. */
static void test_csg_transforms_in_place_stay_private(void **state) {
  fixture *f = *state;
  zr_scene *s = good(
      f, "#declare U = union { sphere { 0, 0.5 translate x }\n"
         "  box { -0.5, 0.5 } }\n"
         "object { U translate y translate y }\n"
         "#declare V = object { U translate 3 * z }\n"
         "object { V translate z translate z }\n"
         "object { V }\n"
         "object { U }\n");
  assert_int_equal(s->n_primitives, 8);
  assert_int_equal(holders(s, zr_v3(1, 2, 0)), 1);
  assert_int_equal(holders(s, zr_v3(0, 2, 0)), 1);
  assert_int_equal(holders(s, zr_v3(1, 0, 5)), 1);
  assert_int_equal(holders(s, zr_v3(0, 0, 5)), 1);
  assert_int_equal(holders(s, zr_v3(1, 0, 3)), 1);
  assert_int_equal(holders(s, zr_v3(0, 0, 3)), 1);
  assert_int_equal(holders(s, zr_v3(1, 0, 0)), 1);
  assert_int_equal(holders(s, zr_v3(0, 0, 0)), 1);
  /* clipped_by { bounded_by } copies the bound, which shares its
     transform with the clip until each gets its own. */
  const zr_object *o =
      only(f, "sphere { 0, 1 bounded_by { box { -0.5, 0.5 } }\n"
              "  translate 3 * x clipped_by { bounded_by }\n"
              "  translate 3 * x translate 3 * x }\n");
  assert_true(zr__inside(o, zr_v3(9.25, 0, 0)));
  assert_false(zr__inside(o, zr_v3(9.75, 0, 0)));
}

static void test_csg_clipped_by_keeps_the_inside_part(void **state) {
  fixture *f = *state;
  const zr_object *o =
      only(f, "sphere { 0, 1 clipped_by { plane { x, 0 } }\n"
              "  translate <0, 0, 0> }\n");
  zr_hit h[2];
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0.0, h), 1);
  assert_near(h[0].t, 4.0, EPS);
  /* Nothing of the plane itself remains: the open half shell shows
     its inside. */
  assert_int_equal(cross(o, zr_v3(5, 0, 0), zr_v3(-1, 0, 0), 0.0, h), 1);
  assert_near(h[0].t, 6.0, EPS);
  /* The clip follows later transforms. */
  o = only(f, "sphere { 0, 1 clipped_by { plane { x, 0 } }\n"
              "  translate <3, 0, 0> }\n");
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0.0, h), 1);
  assert_near(h[0].t, 7.0, EPS);
  /* clipped_by { bounded_by } clips by the bound. */
  o = only(f, "sphere { 0, 1 bounded_by { plane { x, 0 } }\n"
              "  clipped_by { bounded_by } }\n");
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0.0, h), 1);
  /* A bound alone changes nothing. */
  o = only(f, "sphere { 0, 1 bounded_by { plane { x, 0 } } }\n");
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0.0, h), 2);
  /* A clipped CSG object. */
  o = only(f, "merge { sphere { 0, 1 } sphere { x, 1 }\n"
              "  clipped_by { plane { -x, -0.5 } } }\n");
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0.0, h), 1);
  assert_near(h[0].t, 7.0, EPS);
}

static void test_csg_hollow_is_stored(void **state) {
  fixture *f = *state;
  assert_true(only(f, "sphere { 0, 1 hollow }\n")->hollow);
  assert_true(only(f, "sphere { 0, 1 hollow on }\n")->hollow);
  assert_false(only(f, "sphere { 0, 1 hollow off }\n")->hollow);
  assert_false(only(f, "sphere { 0, 1 }\n")->hollow);
}

static void test_csg_quartic_torus(void **state) {
  fixture *f = *state;
  /* (x^2 + y^2 + z^2 + 3)^2 - 16 (x^2 + z^2): the torus of radii 2 and
     1 about y, its 35 coefficients in the manual's order (x^4, x^3 y,
     x^3 z, x^3, x^2 y^2, ...). */
  const char *torus = "quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, -10,\n"
                      "  0, 0, 0, 0, 0, 0, 0, 0, 0, 0,\n"
                      "  1, 0, 0, 2, 0, 6, 0, 0, 0, 0,\n"
                      "  1, 0, -10, 0, 9> sturm }\n";
  const zr_object *o = only(f, torus);
  assert_int_equal(o->kind, ZR_OBJ_POLY);
  assert_int_equal(o->u.poly.order, 4);
  zr_hit h[2];
  /* Roots of a quartic refined by Newton's method: 1e-9 allows for the
     conditioning of the expanded coefficients. */
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0.0, h), 2);
  assert_near(h[0].t, 2.0, 1e-9);
  assert_near(h[1].t, 4.0, 1e-9);
  assert_near(h[0].normal.x, -1, 1e-9);
  assert_near(h[1].normal.x, 1, 1e-9);
  zr_ray r = {zr_v3(-5, 0, 0), zr_v3(1, 0, 0)};
  assert_int_equal(zr__intersect(o, &r, 4.5, INFINITY, h), 2);
  assert_near(h[0].t, 6.0, 1e-9);
  assert_near(h[1].t, 8.0, 1e-9);
  /* Through the hole along the axis: no crossing. */
  assert_int_equal(cross(o, zr_v3(0, -5, 0), zr_v3(0, 1, 0), 0.0, h), 0);
  assert_true(zr__inside(o, zr_v3(2, 0.5, 0)));
  assert_false(zr__inside(o, zr_v3(0, 0, 0)));
  /* poly { 2, ... } is a quadric: the unit sphere. */
  o = only(f, "poly { 2, <1, 0, 0, 0, 1, 0, 0, 1, 0, -1> }\n");
  assert_int_equal(cross(o, zr_v3(-5, 0, 0), zr_v3(1, 0, 0), 0.0, h), 2);
  assert_near(h[0].t, 4.0, 1e-9);
  assert_near(h[1].t, 6.0, 1e-9);
}

static void test_csg_bad_poly(void **state) {
  fixture *f = *state;
  bad(f, "cubic { <1, 2, 3> }\n", ZR_ESYNTAX,
      "a poly of order 3 has 20 coefficients, not 3", NULL);
  bad(f, "poly { 9, <1> }\n", ZR_EUNSUPPORTED,
      "a poly's order must be a whole number from 2 to 8, not 9", NULL);
  bad(f, "poly { 2, <1, 0, 0, 0, 1, 0, 0, 1, 0, -1, 5> }\n", ZR_ESYNTAX,
      "a poly of order 2 has 10 coefficients, not more", NULL);
}

static void test_csg_bad_quadric(void **state) {
  fixture *f = *state;
  bad(f, "quadric { <1, 0, 1>, 0, 0, <1, 2, 3> }\n", ZR_ESYNTAX,
      "expected a float, got a vector", NULL);
}

/* Each test gets a fresh fixture. */
#define TEST(fn) cmocka_unit_test_setup_teardown(fn, setup, teardown)

/* A copy of a CSG tree without the children's boxes (lib/trace/
   prepare.c); leaves are shared.  Freed by unboxed_free(). */
static zr_object *unboxed(const zr_object *o) {
  if (!zr__is_csg(o->kind))
    return (zr_object *)o;
  zr_object *c = malloc(sizeof *c);
  assert_non_null(c);
  *c = *o;
  c->u.csg.boxes = NULL;
  c->u.csg.tree = NULL;
  c->u.csg.whole = NULL;
  c->u.csg.children = malloc(o->u.csg.n_children * sizeof *c->u.csg.children);
  assert_non_null(c->u.csg.children);
  for (size_t i = 0; i < o->u.csg.n_children; i++)
    c->u.csg.children[i] = unboxed(o->u.csg.children[i]);
  return c;
}

static void unboxed_free(zr_object *c) {
  if (!zr__is_csg(c->kind))
    return;
  for (size_t i = 0; i < c->u.csg.n_children; i++)
    unboxed_free(c->u.csg.children[i]);
  free(c->u.csg.children);
  free(c);
}

/* o and its copy without boxes (plain) give ray r the same crossings
   (distance for distance, object for object), and with nearest the same
   nearest crossing when only that is wanted; the count of crossings. */
static int same_crossings(const zr_object *o, const zr_object *plain,
                          const zr_ray *r, bool nearest) {
  zr_hit a[ZR_MAX_CROSSINGS], b[ZR_MAX_CROSSINGS];
  int na = zr__intersect(o, r, 0.0, INFINITY, a);
  int nb = zr__intersect(plain, r, 0.0, INFINITY, b);
  assert_int_equal(na, nb);
  for (int i = 0; i < na; i++) {
    assert_true(a[i].t == b[i].t);
    assert_ptr_equal(a[i].object, b[i].object);
  }
  if (nearest) {
    int n1 = zr__intersect_first(o, r, 0.0, INFINITY, true, a);
    assert_int_equal(n1 > 0, nb > 0);
    if (n1 > 0) {
      assert_true(a[0].t == b[0].t);
      assert_ptr_equal(a[0].object, b[0].object);
    }
  }
  return na;
}

/* The children's boxes only skip work: a difference of unions of many
   parts (the corpus' spacecraft cells) gives the same crossings and
   inside tests with and without them, for rays and points all over. */
static void test_csg_child_boxes_skip_work_only(void **state) {
  fixture *f = *state;
  const zr_object *o = only(
      f, "#declare R = union {\n"
         "  #for (I, 0, 23)\n"
         "    sphere { <1.2, 0, 0>, 0.3 rotate z*I*15 rotate y*I*40 }\n"
         "    cylinder { 0, <1.2, 0, 0>, 0.05 rotate z*I*15 rotate y*I*40 }\n"
         "  #end\n"
         "}\n"
         "difference {\n"
         "  union { sphere { 0, 1 } object { R } }\n"
         "  union { sphere { 0, 0.8 } box { <-2, -0.1, -2>, <2, 0.1, 2> }\n"
         "          torus { 1.2, 0.1 } }\n"
         "  plane { y, -1.3 }\n"
         "}\n");
  assert_int_equal(o->kind, ZR_OBJ_INTERSECTION);
  assert_non_null(o->u.csg.boxes);
  zr_object *plain = unboxed(o);
  /* The box kept for the whole part (prepare.c, for the shadow shafts'
     box asked for each point) is the one narrowed from the children
     afresh, to the bit, and so are its parts'. */
  assert_non_null(o->u.csg.whole);
  for (size_t i = 0; i <= o->u.csg.n_children; i++) {
    const zr_object *a = i ? o->u.csg.children[i - 1] : o;
    const zr_object *b = i ? plain->u.csg.children[i - 1] : plain;
    zr_vec3 lo_a, hi_a, lo_b, hi_b;
    memset(&lo_a, 0, sizeof lo_a);
    lo_b = hi_a = hi_b = lo_a;
    bool in_a = zr__object_bounds(a, &lo_a, &hi_a);
    assert_true(in_a == zr__object_bounds(b, &lo_b, &hi_b));
    assert_true(!zr__is_csg(a->kind) || a->u.csg.whole);
    if (in_a) {
      assert_memory_equal(&lo_a, &lo_b, sizeof lo_a);
      assert_memory_equal(&hi_a, &hi_b, sizeof hi_a);
    }
  }
  unsigned seed = 12345u;
#define RND() rnd(&seed)
  int crossings = 0;
  for (int k = 0; k < 4000; k++) {
    double ox = 6 * RND() - 3, oy = 6 * RND() - 3, oz = 6 * RND() - 3;
    zr_vec3 org = zr_v3(ox, oy, oz);
    /* Towards a point near the object, so most rays meet it. */
    double ax = 3 * RND() - 1.5, ay = 3 * RND() - 1.5, az = 3 * RND() - 1.5;
    zr_vec3 at = zr_v3(ax, ay, az);
    zr_vec3 dir = zr_v3_sub(at, org);
    zr_hit a[ZR_MAX_CROSSINGS], b[ZR_MAX_CROSSINGS];
    int na = cross(o, org, dir, 0.0, a), nb = cross(plain, org, dir, 0.0, b);
    assert_int_equal(na, nb);
    for (int i = 0; i < na; i++) {
      assert_true(a[i].t == b[i].t);
      assert_ptr_equal(a[i].object, b[i].object);
    }
    crossings += na;
    assert_true(zr__inside(o, org) == zr__inside(plain, org));
  }
#undef RND
  assert_true(crossings > 1000);
  unboxed_free(plain);
}

/* The tree over many children (lib/trace/csg.c) and the nearest-only
   query only skip work too: a merge of a union of 120 small hollow
   spheres (advanced/grenadine's bubbles) with two larger solids gives
   the same nearest two crossings, the same nearest one when only that
   is wanted, and the same inside tests as the plain copy; and the tree
   is there to be tested. */
static void test_csg_child_tree_skips_work_only(void **state) {
  fixture *f = *state;
  const zr_object *o = only(
      f, "#declare S = seed(7);\n"
         "#declare B = union {\n"
         "  #for (I, 0, 119)\n"
         "    difference { sphere { 0, 0.1 } sphere { 0, 0.09 }\n"
         "      scale rand(S) + 0.2 translate <rand(S), 0.6, 0>\n"
         "      rotate y*360*rand(S) }\n"
         "  #end\n"
         "}\n"
         "merge {\n"
         "  sphere { -0.8*y, 0.95 }\n"
         "  cylinder { -0.8*y, 0.6*y, 0.95 }\n"
         "  intersection { object { B } cylinder { 0.5*y, 0.85*y, 0.95 } }\n"
         "}\n");
  assert_int_equal(o->kind, ZR_OBJ_MERGE);
  const zr_object *inter = o->u.csg.children[2];
  assert_int_equal(inter->kind, ZR_OBJ_INTERSECTION);
  assert_non_null(inter->u.csg.children[0]->u.csg.tree);
  zr_object *plain = unboxed(o);
  unsigned seed = 777u;
#define RND() rnd(&seed)
  int crossings = 0, inside = 0;
  for (int k = 0; k < 4000; k++) {
    zr_vec3 org = zr_v3(4 * RND() - 2, 4 * RND() - 1, 4 * RND() - 2);
    zr_vec3 at = zr_v3(2 * RND() - 1, 0.5 + 0.4 * RND(), 2 * RND() - 1);
    zr_ray r = {org, zr_v3_sub(at, org)};
    crossings += same_crossings(o, plain, &r, true);
    bool in = zr__inside(o, at);
    assert_true(in == zr__inside(plain, at));
    assert_true(zr__inside(inter, at) ==
                zr__inside(plain->u.csg.children[2], at));
    inside += in;
  }
#undef RND
  assert_true(crossings > 1000);
  assert_true(inside > 100 && inside < 3900);
  unboxed_free(plain);
}

/* An intersection asks each child only where the ray is in the other
   children's boxes (lib/trace/csg.c, narrow_children): the corpus'
   complexity.pov tile - a tall cylinder minus another, cut by a box,
   turned and moved, and a torus cut by a box - gives the same crossings,
   to the bit, as the copy without boxes, for rays from all over, rays
   along the box's faces and rays that start on them. */
static void test_csg_narrowed_children_skip_work_only(void **state) {
  fixture *f = *state;
  zr_scene *s = good(
      f, "#declare Q = union {\n"
         "  intersection {\n"
         "    difference { cylinder { <0, -500.1, 0>, <0, 3.1, 0>, 0.54 }\n"
         "                 cylinder { <0, -500.2, 0>, <0, 3.2, 0>, 0.46 } }\n"
         "    box { 0, <1, 3, 1> } }\n"
         "  intersection { torus { 0.5, 0.04 } box { 0, <1, 3, 1> }\n"
         "                 translate y*3 } }\n"
         "object { Q rotate y*90 translate z*1 }\n"
         "object { Q rotate y*180 translate <1, 0, 1> }\n");
  assert_int_equal(s->n_primitives, 4);
  unsigned seed = 4242u;
#define RND() rnd(&seed)
  int crossings = 0;
  for (size_t p = 0; p < s->n_primitives; p++) {
    const zr_object *o = s->primitives[p];
    assert_int_equal(o->kind, ZR_OBJ_INTERSECTION);
    assert_non_null(o->u.csg.boxes);
    zr_object *plain = unboxed(o);
    for (int k = 0; k < 6000; k++) {
      zr_vec3 org = zr_v3(4 * RND() - 1.5, 8 * RND() - 2, 4 * RND() - 1.5);
      zr_vec3 at = zr_v3(1.2 * RND() - 0.1, 3.2 * RND() - 0.1,
                         1.2 * RND() - 0.1);
      if (k % 3 == 1) /* from a face of the tile's box */
        org = zr_v3(k % 2 ? 0.0 : 1.0, 3 * RND(), RND());
      zr_vec3 dir = zr_v3_sub(at, org);
      if (k % 5 == 2) /* along a face: one direction component 0 */
        dir.y = 0.0;
      if (k % 7 == 3)
        dir.x = 0.0;
      zr_ray r = {org, dir};
      same_crossings(o, plain, &r, false);
      /* A shadow ray's interval, ending short of the far side. */
      zr_hit a[ZR_MAX_CROSSINGS], b[ZR_MAX_CROSSINGS];
      int na = zr__intersect_t(o, &r, 0.0, 0.9, a);
      int nb = zr__intersect_t(plain, &r, 0.0, 0.9, b);
      assert_int_equal(na, nb);
      for (int i = 0; i < na; i++)
        assert_true(a[i].t == b[i].t);
      crossings += na;
    }
    unboxed_free(plain);
  }
#undef RND
  assert_true(crossings > 1000);
}
/* A slab minus letters made as chars.inc makes them (the corpus'
   BAMSSLB2): differences with a plane, intersections with an inverted
   cylinder, unions of rotated boxes, bounded_by; and a merge with an
   inverted intersection of ten spheres in it, whose inverse is a merge
   of ten inverted spheres, enough for a tree of children (csg.c). */
static const char *const cut_out_letters =
    "#declare P = union {\n"
    "  difference { cylinder { 0*z, z, 1.5 } cylinder { -z, 2*z, 0.5 }\n"
    "    plane { x, 0 } bounded_by { box { <0, -1.5, 0>, <1.5, 1.5, 1> } }\n"
    "    translate <0.5, 3.5, 0> }\n"
    "  box { <-1.001, 4, 0>, <0.501, 5, 1> }\n"
    "  box { <-2, 0, 0>, <-1, 5, 1> } }\n"
    "#declare A = intersection { box { <-2, 0, -0.1>, <2, 5, 1.1> }\n"
    "  union { box { <-0.5, -6, 0>, <0.5, 0, 1> rotate z*16.699 }\n"
    "    box { <-0.5, -6, 0>, <0.5, 0, 1> rotate -z*16.699 }\n"
    "    box { <-1, -4, 0>, <1, -3, 1> } translate y*5 } }\n"
    "#declare S = intersection { cylinder { 0*z, z, 1.5 }\n"
    "  cylinder { -z, 2*z, 0.5 inverse }\n"
    "  box { <0, 0, -0.1>, <1.5, 1.5, 1.1> } translate <0.5, 3.5, 0> }\n"
    "#declare Balls = intersection {\n"
    "  #for (I, 0, 9) sphere { <I*0.3, 2.5, 0.5>, 1.2 } #end }\n"
    "#declare W = union { object { P } object { A translate 5*x }\n"
    "  object { S translate 10*x } object { Balls translate 12*x } }\n"
    "merge {\n"
    "  difference { box { <-2, -2, 0.1>, <22, 10, 3> }\n"
    "    object { W scale <1, 1.6, 1> }\n"
    "    object { W scale <1, 1.6, 1> translate <0.0001, 0.0001, 0.0001> }\n"
    "    rotate <30, -5, 0> }\n"
    "  sphere { <30, 0, 0>, 1 }\n"
    "  difference { sphere { <30, 0, 0>, 3 } object { Balls } }\n"
    "}\n";

/* The boxes of the children of o that hold what lies outside them,
   counted into *n: each holds its child's surface (every crossing of
   random rays with the child alone, all of them, lies in it), and the
   child holds every random point outside it. */
static void check_outside_boxes(const zr_object *o, unsigned *seed,
                                int *n) {
  if (!zr__is_csg(o->kind))
    return;
  assert_non_null(o->u.csg.boxes);
  for (size_t i = 0; i < o->u.csg.n_children; i++) {
    const zr_object *c = o->u.csg.children[i];
    check_outside_boxes(c, seed, n);
    const struct zr_csg_box *b = &o->u.csg.boxes[i];
    if (!b->holds_outside)
      continue;
    assert_true(b->bounded);
    (*n)++;
    zr_vec3 mid = zr_v3_scale(zr_v3_add(b->lo, b->hi), 0.5);
    zr_vec3 half = zr_v3_scale(zr_v3_sub(b->hi, b->lo), 0.5);
    double reach = 2.0 * zr_v3_len(half) + 1.0;
    for (int k = 0; k < 300; k++) {
      zr_vec3 at = zr_v3(mid.x + half.x * (2 * rnd(seed) - 1),
                         mid.y + half.y * (2 * rnd(seed) - 1),
                         mid.z + half.z * (2 * rnd(seed) - 1));
      zr_vec3 org = zr_v3_add(at, zr_v3(reach * (2 * rnd(seed) - 1),
                                        reach * (2 * rnd(seed) - 1),
                                        reach * (2 * rnd(seed) - 1)));
      zr_ray r = {org, zr_v3_sub(at, org)};
      double from = 0.0;
      zr_hit h[ZR_MAX_CROSSINGS];
      for (int m; (m = zr__intersect(c, &r, from, INFINITY, h)) > 0;) {
        for (int j = 0; j < m; j++) {
          zr_vec3 p = zr_v3_madd(org, r.dir, h[j].t);
          assert_true(p.x >= b->lo.x && p.x <= b->hi.x);
          assert_true(p.y >= b->lo.y && p.y <= b->hi.y);
          assert_true(p.z >= b->lo.z && p.z <= b->hi.z);
        }
        from = h[m - 1].t;
      }
      /* A point outside the box: the ray's origin, mostly. */
      if (org.x < b->lo.x || org.x > b->hi.x || org.y < b->lo.y ||
          org.y > b->hi.y || org.z < b->lo.z || org.z > b->hi.z)
        assert_true(zr__inside(c, org));
    }
  }
}

/* The parts a difference cuts out have boxes that bound their surface
   (outside which they hold every point), and these only skip work: the
   same crossings, nearest ones and inside tests as without the boxes. */
static void test_csg_cut_out_boxes_skip_work_only(void **state) {
  fixture *f = *state;
  const zr_object *o = only(f, cut_out_letters);
  assert_int_equal(o->kind, ZR_OBJ_MERGE);
  unsigned seed = 4242u;
  int n_outside = 0;
  check_outside_boxes(o, &seed, &n_outside);
  /* The letters, their parts and the ten spheres, twice over. */
  assert_true(n_outside >= 30);
  /* The merge of ten inverted spheres has its tree, every child in its
     list of point queries. */
  const zr_object *balls = o->u.csg.children[2]->u.csg.children[1];
  assert_int_equal(balls->kind, ZR_OBJ_MERGE);
  assert_non_null(balls->u.csg.tree);
  zr_object *plain = unboxed(o);
  int crossings = 0, inside = 0;
  for (int k = 0; k < 6000; k++) {
    zr_vec3 org = zr_v3(40 * rnd(&seed) - 10, 30 * rnd(&seed) - 10,
                        30 * rnd(&seed) - 20);
    zr_vec3 at = k % 3 == 2 ? zr_v3(30 + 6 * rnd(&seed) - 3,
                                    6 * rnd(&seed) - 3, 6 * rnd(&seed) - 3)
                            : zr_v3(24 * rnd(&seed) - 2,
                                    12 * rnd(&seed) - 2,
                                    3 * rnd(&seed));
    zr_ray r = {org, zr_v3_sub(at, org)};
    crossings += same_crossings(o, plain, &r, true);
    bool in = zr__inside(o, at);
    assert_true(in == zr__inside(plain, at));
    assert_true(zr__inside(balls, at) ==
                zr__inside(plain->u.csg.children[2]->u.csg.children[1], at));
    inside += in;
  }
  assert_true(crossings > 2000);
  assert_true(inside > 300 && inside < 5700);
  unboxed_free(plain);
}
int main(void) {
  const struct CMUnitTest tests[] = {
      TEST(test_csg_difference_cuts_with_inverted_normal),
      TEST(test_csg_child_boxes_skip_work_only),
      TEST(test_csg_child_tree_skips_work_only),
      TEST(test_csg_narrowed_children_skip_work_only),
      TEST(test_csg_cut_out_boxes_skip_work_only),
      TEST(test_csg_intersection_is_a_lens),
      TEST(test_csg_merge_drops_inner_surfaces),
      TEST(test_csg_inverse_follows_de_morgan),
      TEST(test_csg_transforms_and_textures_reach_children),
      TEST(test_csg_transforms_in_place_stay_private),
      TEST(test_csg_bounds_of_intersection),
      TEST(test_csg_bounds_of_planes_and_quadrics),
      TEST(test_csg_bounds_of_plane_polyhedra),
      TEST(test_csg_bounded_by_boxes_unboundable_parts),
      TEST(test_csg_quadric_cylinder_and_paraboloid),
      TEST(test_csg_clipped_by_keeps_the_inside_part),
      TEST(test_csg_hollow_is_stored),
      TEST(test_csg_quartic_torus),
      TEST(test_csg_bad_poly),
      TEST(test_csg_bad_quadric),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
