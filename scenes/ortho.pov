// ortho.pov - an orthographic camera without up or right, which POV-Ray
// sizes like a perspective view at the look_at distance, over a row of
// boxes and a spotlight.
//
// POV-Ray reference, "Orthographic projection".
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { orthographic location <6, 5, -8> look_at <0, 0.5, 0> angle 40 }
light_source { <3, 9, -5>, rgb 1 spotlight point_at 0 radius 20
               falloff 35 }
light_source { <-5, 5, -5>, rgb 0.3 shadowless }

plane { y, 0 pigment { rgb 0.8 } }
#declare I = -2;
#while (I <= 2)
  box { <I - 0.35, 0, -0.35>, <I + 0.35, 0.5 + 0.3 * (I + 2), 0.35>
        pigment { rgb <0.9, 0.5 + 0.1 * I, 0.3> } }
  #declare I = I + 1;
#end
