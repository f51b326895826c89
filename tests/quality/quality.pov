#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,2,-5> look_at <0,0.5,0> }
light_source { <4,6,-5> rgb 1 area_light 2*x, 2*z, 4, 4 }
plane { y, 0 pigment { checker rgb 1 rgb 0.2 } finish { reflection 0.3 } }
sphere { <-1,0.8,0>, 0.7 pigment { rgbf <1,1,1,0.9> } interior { ior 1.5 } finish { phong 0.8 } }
sphere { <1,0.8,0>, 0.7 pigment { rgb <1,0.3,0.2> } finish { reflection 0.5 } }
