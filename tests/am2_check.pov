// am2_check.pov - edges for the antialiasing methods (tests/test_aa_method.sh).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.5, 0> angle 40 }
light_source { <5, 10, -5>, 1 }
plane { y, 0 pigment { checker rgb 1 rgb <0.1, 0.1, 0.4> scale 0.5 } }
sphere { <0, 1, 0>, 1 pigment { rgb <1, 0.3, 0.2> } finish { phong 0.8 reflection 0.3 } }
box { <-2.5, 0, 1>, <-1.5, 2, 1.3> pigment { rgb <0.2, 1, 0.3> } rotate y*20 }
