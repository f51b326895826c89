// bounded_box.pov - an object's own bounded_by as POV-Ray 3.7 draws it
// when the bound leaves part of the object out (tests/test_bounded_box.sh,
// lib/trace/prepare.c bound_by_box).  Declare=K=1..8 picks the case.  The
// small sphere far behind is there so that povray uses its bounding slabs
// (alone in its scene, a sphere's bound is ignored by povray).
#version 3.7;
global_settings { assumed_gamma 1 }
#ifndef (K) #declare K = 1; #end
#if (K <= 4)
  camera { location <1.5, 2.5, -4> look_at 0 angle 45 }
#else
  camera { location <0, 0, -6> look_at 0 angle 40 }
#end
light_source { <-5, 5, -10> rgb 1 }
sphere { <-3, -2, 6>, 0.1 pigment { rgb 1 } }
#declare S = sphere { <0.5, 0, 0>, 0.8 }
#switch (K)
#case (1) // a torus: cut along the faces of the bounding sphere's box
  torus { 1, 0.4 pigment { rgb 1 } bounded_by { object { S } } }
#break
#case (2) // a lathe: the same
  lathe { linear_spline 4, <0.2, -1>, <1.2, -0.5>, <1, 1>, <0.2, 1>
    pigment { rgb 1 } bounded_by { object { S } } }
#break
#case (3) // a cylinder whose box (3.97) is smaller than the bound's (4.10): whole
  cylinder { <-1, 0, 0>, <1.5, 0, 0>, 0.63
    pigment { rgb 1 } bounded_by { object { S } } }
#break
#case (4) // radius 0.65, its box 4.23: cut
  cylinder { <-1, 0, 0>, <1.5, 0, 0>, 0.65
    pigment { rgb 1 } bounded_by { object { S } } }
#break
#case (5) // a sphere (box 10.65) under a box of 8.1: cut at x = 0.3
  sphere { 0, 1.1 pigment { rgb 1 }
    bounded_by { box { <0.3, -1.5, -1.5>, <1.2, 1.5, 1.5> } } }
#break
#case (6) // under a box of 32.4, narrower in x all the same: whole
  sphere { 0, 1.1 pigment { rgb 1 }
    bounded_by { box { <0.3, -3, -3>, <1.2, 3, 3> } } }
#break
#case (7) // a superellipsoid: cut along the bounding sphere's box
  superellipsoid { <0.3, 0.3> scale 1.1
    pigment { rgb 1 } bounded_by { object { S } } }
#break
#case (8) // a mesh: cut along the bounding sphere's box
  mesh { triangle { <-1, -1, 0>, <1.5, -1, 0>, <0, 1.2, -1.2> }
         triangle { <-1, -1, 0>, <1, 1.2, 0>, <0, 1.2, -1.2> }
    pigment { rgb 1 } bounded_by { object { S } } }
#break
#end
