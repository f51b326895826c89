// Old syntax POV-Ray 3.7 renders without a warning: pigment and finish
// identifiers at the start of a texture, "checker Black White" without a comma,
// and "#include "x.inc";" with a semicolon.
#version 3.7;
global_settings { assumed_gamma 1 }
#include "include_semicolon.inc";
#declare Red = rgb <1,0,0>;
#declare Blue = rgb <0,0,1>;
#declare P = pigment { rgb <1,0.5,0> }
#declare F = finish { ambient 0.6 diffuse 0.2 }
camera { location <0,0,-5> look_at 0 }
light_source { <0,10,-10> rgb 1 }
sphere { <-1.2,0,0>, IncR texture { P } }
sphere { <1.2,0,0>, 1 texture { F pigment { rgb <0.2,1,0.2> } } }
plane { z, 2 pigment { checker Red Blue } }
