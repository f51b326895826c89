// csg_inside.pov - CSG with the shapes whose inside reaches beyond their
// box (tests/test_csg_inside.sh): a disc's inside is its plane's
// half-space, a height field's everything below it over its unit square.
// Declare=K=1..5 picks the case.
#version 3.7;
global_settings { assumed_gamma 1 }
light_source { <-5, 5, -10> rgb 1 }
#ifndef (K) #declare K = 1; #end
#if (K <= 2)
  camera { location <0, 2, -5> look_at 0 angle 40 }
#elseif (K <= 4)
  camera { location <0.5, 0.3, -2.5> look_at <0.5, 0.2, 0.5> angle 50 }
#else
  camera { orthographic location <0.5, 0, -5> look_at <0.5, 0, 0>
           right 4*x up 3*y }
#end
#declare F = function { 0.5 + 0.1*x }
#switch (K)
#case (1) // the cap of a sphere above a disc, seen from above
  intersection { sphere { -0.5*y, 1 } disc { 0, -y, 1.5 } pigment { rgb 1 } }
#break
#case (2) // the same with a disc smaller than the sphere's cut
  intersection { sphere { -0.5*y, 1 } disc { 0, -y, 0.3 } pigment { rgb 1 } }
#break
#case (3) // a box cut by a height field: its sides up to the field
  intersection { height_field { function 8, 8 { F(x, y, z) } }
                 box { <0.1, -0.5, 0.1>, <0.9, 2, 0.9> } pigment { rgb 1 } }
#break
#case (4) // the box less the field: only what is above the field
  difference { box { <0.1, -0.5, 0.1>, <0.9, 2, 0.9> }
               height_field { function 8, 8 { F(x, y, z) } } pigment { rgb 1 } }
#break
#case (5) // the field's inside reaches far below y = 0, over x and z in [0, 1]
  intersection { height_field { function 8, 8 { F(x, y, z) } water_level 0.2 }
                 box { <-0.5, -1.4, 0.1>, <1.5, 1.4, 0.9> } pigment { rgb 1 } }
#break
#end
