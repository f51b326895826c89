// quick.pov - +Q0..2 and quick_color (tests/test_quality.sh): a patterned
// pigment with a quick_color, one without, a solid colour, a transparent
// sphere with emission, and a layered texture whose layers have quick
// colours (one with transmit), over a checkered plane and a background.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -7> look_at <0, 0.6, 0> }
light_source { <4, 6, -5> rgb 1 }
background { rgb <0.1, 0.2, 0.3> }
plane { y, 0 pigment { checker rgb 1 rgb <0.2, 0.3, 0.9> } }
sphere { <-2.4, 0.8, 0>, 0.7
  pigment { gradient x color_map { [0 rgb <1, 1, 0>] [1 rgb <0, 1, 1>] }
    quick_color rgb <1, 0.2, 0.6> }
  finish { phong 0.8 } }
sphere { <-0.8, 0.8, 0>, 0.7 pigment { rgb <0.9, 0.4, 0.1> }
  finish { ambient 0.2 diffuse 0.7 } }
sphere { <0.8, 0.8, 0>, 0.7
  pigment { bozo color_map { [0 rgb <0, 1, 0>] [1 rgb <1, 0, 0>] } }
  finish { reflection 0.3 } }
sphere { <2.4, 0.8, 0>, 0.7
  texture { pigment { rgb <0, 0, 1> quick_color rgb <1, 1, 0> } }
  texture { pigment { gradient x color_map { [0 rgbt <1, 0, 0, 0.5>]
    [1 rgbt <1, 1, 1, 1>] } quick_color rgbt <0, 1, 0, 0.5> } } }
sphere { <0, 0.5, -1.5>, 0.4 pigment { rgbf <0.2, 0.9, 0.3, 0.6> }
  finish { emission 0.5 } interior { ior 1.3 } }
