// exit_fresnel.pov - Fresnel reflection where a ray goes out of a glass
// (tests/test_exit_fresnel.sh).  A glass ball (ior 1.5, reflection
// { 0, 1 fresnel }) before a white wall behind the camera: its picture
// is the wall reflected at the front face, plus, where the ball reflects
// inside at the back face, the wall seen again through the front.
#version 3.7;
#ifndef (Case) #declare Case = 1; #end
global_settings { assumed_gamma 1.0 max_trace_level 15 }
camera { location <0, 0, -4> look_at <0, 0, 0> angle 35 }
plane { z, -10 pigment { rgb 1 } finish { ambient 1 diffuse 0 } }
#declare Black = texture { pigment { rgb 0 } finish { ambient 0 diffuse 0 } }
#declare Clear = texture { pigment { rgbt 1 } finish { ambient 0 diffuse 0 } }
#declare Rmin = 0;
#declare Ball = sphere { 0, 1 }
#switch (Case)
#case (1) /* nothing around: the inside reflection shows */
#break
#case (2) /* a black solid plane behind, the camera and ball inside it */
  plane { z, 3 texture { Black } }
#break
#case (3) /* the same surface facing away: nothing around */
  plane { -z, -3 texture { Black } }
#break
#case (4) /* a black box behind: met by the light through, not around */
  box { <-20, -20, 3>, <20, 20, 4> texture { Black } }
#break
#case (5) /* a clear hollow sphere around the camera */
  sphere { 0, 5 hollow texture { Clear } }
#break
#case (6) /* a clear sphere around the ball, not the camera, ior 1.2 */
  sphere { 0, 3 texture { Clear } interior { ior 1.2 } }
#break
#case (7) /* as 5 with reflection { 0.1, 1 fresnel }: 0.1 is left */
  sphere { 0, 5 hollow texture { Clear } }
  #declare Rmin = 0.1;
#break
#case (8) /* as 7 with nothing around */
  #declare Rmin = 0.1;
#break
#case (9) /* a right prism inside the sphere of 5: total internal
             reflection at its slope as anywhere */
  sphere { 0, 5 hollow texture { Clear } }
  plane { x, -4 pigment { rgb <0, 1, 0> } finish { ambient 1 diffuse 0 } }
  #declare Ball = intersection { box { -1, 1 } plane { <1, 0, 1>, 0 } }
#break
#end
object { Ball
  pigment { rgbf 1 }
  finish { ambient 0 diffuse 0 reflection { Rmin, 1 fresnel } }
  interior { ior 1.5 } }
