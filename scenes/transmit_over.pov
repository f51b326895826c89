// transmit_over.pov - transmit above 1 ("Color Expressions": any
// value): the surface's own colour then counts negatively, a contrast
// trick of advanced/bwstripe.pov, here a sphere round the camera.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 0.5, 0> }
sphere { <0, 2, -6>, 0.01 hollow
  pigment { rgb 0.4 transmit 2.5 } finish { ambient 1 diffuse 0 } }
light_source { <3, 8, -4> rgb 1 }
plane { y, 0 pigment { gradient x color_map { [0 rgb 0.3] [1 rgb 0.6] } } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.5, 0.4, 0.3> } }
