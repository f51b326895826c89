// bounded_poly.pov - bounded_by on a poly, cubic or quartic: POV-Ray
// traces the shape only for rays that meet the bounding object itself;
// a plane's own bound it ignores (tests/test_bounded_poly.sh).  Declare=K=1..5 picks the case.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -5> look_at 0 angle 40 }
light_source { <-5, 5, -10> rgb 1 }
#ifndef (K) #declare K = 1; #end
#if (K >= 4)
  camera { location <0, 2, -5> look_at 0 angle 40 }
#end
#switch (K)
#case (1) // x^2 + y^2 + z^2 = 1, bounded by a sphere of radius 0.5
  poly { 2, <1, 0, 0, 0, 1, 0, 0, 1, 0, -1>
    pigment { rgb 1 } bounded_by { sphere { 0, 0.5 } } }
#break
#case (2) // a torus (radii 1 and 0.4), bounded by a sphere over its right side
  quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, -2.32, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
             1, 0, 0, 2, 0, 1.68, 0, 0, 0, 0, 1, 0, -2.32, 0, 0.7056>
    pigment { rgb 1 } bounded_by { sphere { <0.5, 0, 0>, 0.8 } }
    rotate -90*x }
#break
#case (3) // the same in a union that has the bound
  union {
    quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, -2.32, 0, 0, 0, 0, 0, 0, 0, 0, 0,
               0, 1, 0, 0, 2, 0, 1.68, 0, 0, 0, 0, 1, 0, -2.32, 0, 0.7056> }
    sphere { <0.9, 0, 0.5>, 0.2 }
    pigment { rgb 1 } bounded_by { sphere { <0.5, 0, 0>, 0.8 } }
    rotate -90*x }
#break
#case (4) // a plane's own bound: POV-Ray ignores it
  plane { y, 0 pigment { checker rgb 1 rgb 0.5 } bounded_by { box { -1, 1 } } }
#break
#case (5) // a union's bound limits a plane in it
  union { plane { y, 0 } sphere { <0, 0.5, 0>, 0.5 }
          pigment { checker rgb 1 rgb 0.5 } bounded_by { box { -1, 1 } } }
#break
#end
