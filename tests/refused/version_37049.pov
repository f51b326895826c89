// ... and 3.7049 is 3.70, which POV-Ray 3.7 reads.
#version 3.7049;
global_settings { assumed_gamma 1 }
sphere { 0, 1 pigment { rgb 1 } }
camera { location <0, 0, -5> look_at 0 }
light_source { <0, 10, -10> rgb 1 }
