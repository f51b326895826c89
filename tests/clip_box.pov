// clip_box.pov - a clip whose inside reaches beyond its box (a height
// field, a disc) bounds the object by its box, as POV-Ray 3.7 draws it
// (tests/test_clip_box.sh, lib/trace/prepare.c clip_by_box).
// Declare=K=1..4 picks the case.  The small sphere far behind is there so
// that povray uses its bounding slabs.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 5, -7> look_at <0, -0.5, 0> angle 50 }
light_source { <-5, 5, -10> rgb 1 }
sphere { <-3, -2, 6>, 0.1 pigment { rgb 1 } }
#ifndef (K) #declare K = 1; #end
#declare H = height_field { function 16, 16 { 0.3 + 0.4*x }
  translate <-0.5, 0, -0.5> scale <6, 2, 6> }
#switch (K)
#case (1) // an infinite cylinder clipped by a height field (as hfclip.pov)
  quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -1
    clipped_by { object { H } } pigment { rgb 1 } }
#break
#case (2) // a finite cylinder (box 2 x 6 x 2, larger than the field's): whole
  cylinder { <0, -3, 0>, <0, 3, 0>, 1
    clipped_by { object { H } } pigment { rgb 1 } }
#break
#case (3) // a sphere clipped by a disc: seen through the disc's box only
  sphere { <0, -0.5, 0>, 1.5
    clipped_by { disc { <0, 0, 0>, y, 1 } } pigment { rgb 1 } }
#break
#case (4) // the infinite cylinder clipped by a disc
  quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -1
    clipped_by { disc { <0, 0, 0>, y, 2 } } pigment { rgb 1 } }
#break
#end
