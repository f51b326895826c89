// exit_fade.pov - what fades where a ray leaves a clear interior of
// fade_distance 1 and fade_power 1001 (exponential), tests/
// test_exit_fade.sh.  An orthographic camera along +z; behind the glass
// an emitting white wall, behind the camera a background of
// rgb <0.2, 0.4, 0.6>.  Declare=K picks the case:
//   1, 2 a slab 1 thick with reflection 0.5, max_trace_level 4 and 5: a
//        ray reflected inside comes back out towards the background;
//   3    a wedge (its back face turned 10 degrees), max_trace_level 4:
//        the stretches before and after the reflection differ;
//   4    the wedge with transmit 0.5 and emission 1: the back face's own
//        light seen from inside;
//   5    a cube of glass turned 20 and 30 degrees (perspective), whose
//        rays meet faces from inside beyond the critical angle.
#version 3.7;
#ifndef (K) #declare K = 1; #end
global_settings { assumed_gamma 1 max_trace_level (K = 2 ? 5 : 4) }
#if (K = 5)
  camera { location <0, 1.2, -3> look_at 0 angle 40 }
  background { rgb 1 }
  plane { z, 2 pigment { checker rgb <1, 1, 0>, rgb <0.2, 0, 0.4> scale 0.25 }
          finish { ambient 1 diffuse 0 } }
#else
  camera { orthographic location <0, 0, -5> look_at 0 right 0.2*x up 0.15*y }
  background { rgb <0.2, 0.4, 0.6> }
  plane { z, 3 pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 1 } }
#end
#declare Fade = interior { ior 1.5 fade_distance 1 fade_power 1001 }
#declare Glass = material {
  texture { pigment { rgbf 1 } finish { ambient 0 diffuse 0 reflection 0.5 } }
  interior { Fade } }
#switch (K)
#range (1, 2)
  box { <-3, -3, -0.5>, <3, 3, 0.5> material { Glass } }
#break
#case (3)
  intersection { box { <-3, -3, -0.5>, <3, 3, 5> } plane { z, 0.5 rotate -10*y }
                 material { Glass } }
#break
#case (4)
  intersection { box { <-3, -3, -0.5>, <3, 3, 5> } plane { z, 0.5 rotate -10*y }
    pigment { rgbt <1, 1, 1, 0.5> } finish { ambient 0 diffuse 0 emission 1 }
    interior { Fade } }
#break
#case (5)
  box { -0.5, 0.5 rotate <20, 30, 0> material { Glass } }
#break
#end
