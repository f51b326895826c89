// "angle 0" on a perspective camera: POV-Ray 3.7 ignores it.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-10> angle 0 right x*4/3 look_at 0 }
light_source { <0,10,-10> rgb 1 }
sphere { 0, 1 pigment { rgb 1 } }
plane { z, 2 pigment { checker rgb 0 rgb 1 } }
