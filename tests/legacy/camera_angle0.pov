// "angle 0" on an orthographic camera: POV-Ray 3.7 sizes the view at
// the look_at distance from direction and right (a 13.3-unit width here).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0,0,-10> angle 0 right x*4/3 look_at 0 }
light_source { <0,10,-10> rgb 1 }
sphere { 0, 1 pigment { rgb 1 } }
plane { z, 2 pigment { checker rgb 0 rgb 1 } }
