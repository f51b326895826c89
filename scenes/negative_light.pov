// negative_light.pov - a light of negative colour takes light away
// where it reaches ("Light Source": any colour, negative ones too), as
// advanced/crater/crater_dat.pov and advanced/abyss.pov use it.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -6> look_at <0, 0, 0> }
light_source { <2, 10, -5> rgb 1 }
light_source { <0, 3, 0> rgb -0.6 spotlight point_at <0, 0, 0> radius 15 falloff 25 }
light_source { <-3, 2, -2> rgb <0, -0.3, -0.3> }
plane { y, 0 pigment { checker rgb 1 rgb 0.7 } }
sphere { <1.5, 0.8, 0>, 0.8 pigment { rgb <1, 0.8, 0.4> } finish { phong 0.6 } }
