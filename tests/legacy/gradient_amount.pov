// "gradient x 0.6 scallop_wave" in a normal (gliese1337's Flame1.pov):
// POV-Ray 3.7 reads the number after the pattern's vector, without a
// comma, as the bump size.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-10> rgb 1 }
sphere { <-1.1,0,0>, 1 pigment { rgb 1 }
  normal { gradient x 0.6 scallop_wave scale 0.25 } }
sphere { <1.1,0,0>, 1 pigment { rgb 1 }
  normal { gradient <1,1,0> 2 scale 0.3 } }
