// A light_source identifier alone as a statement: POV-Ray 3.7 adds the
// light, as it renders an object identifier alone (measured: without
// the light the key light's side of the sphere is black).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -5> look_at 0 }
#declare Key = light_source { <-5, 6, -8> rgb <1, 0.9, 0.8> }
#declare Fill = light_source { <6, 2, -3> rgb 0.3 spotlight
                               point_at 0 radius 10 falloff 20 }
Key
Fill
sphere { 0, 1 pigment { rgb 1 } }
plane { y, -1 pigment { checker rgb 0.2 rgb 0.8 } }
