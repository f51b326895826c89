// legacy_gamma.pov - a #version 3.6 scene without assumed_gamma works in
// the display's gamma (2.2), as POV-Ray 3.7 renders legacy scenes
// ("assumed_gamma": undefined for legacy scenes; incdemo/woods/ash.pov).
#version 3.6;
camera { location <0, 6, -3> look_at <0.5, 0.5, 0> }
light_source { <4, 6, -5> rgb 1 }
plane { y, 0 pigment { rgb 0.6 } }
sphere { <2, 0.7, 1>, 0.7 pigment { gradient y color_map { [0 rgb 0.1] [1 rgb 0.9] } scale 2 } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.8, 0.5, 0.3> } finish { phong 0.5 } }
