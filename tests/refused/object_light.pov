// "object { light_source { ... } }" (gnu0000's POV1/OLD/TSTS-A.POV, which
// POV-Ray 3.7 reads up to a POV-Ray 1 texture at line 19): a light.
#version 3.7;
global_settings { assumed_gamma 1 }
object { light_source { <0, 10, -10> color rgb 1 } }
object { light_source { <0, 0, 0> color rgb <0, 0, 1> } translate <-10, 0, -5> }
sphere { 0, 1 pigment { rgb 1 } }
camera { location <0, 0, -5> look_at 0 }
