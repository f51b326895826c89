// POV-Ray 3.0's "refraction 1 ior 1.5" in a finish: POV-Ray 3.7 renders
// it as interior { ior 1.5 }, with warnings.
// expect: Index of refraction value should be specified in 'interior{...}' statement.
// expect: Refraction value unnecessary to turn on refraction.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-5> look_at 0 }
light_source { <0,10,-10> rgb 1 }
#declare T = texture { pigment { rgbf <1,1,0.8,0.9> } finish { ior 1.33 } }
sphere { <-1.1,0,0>, 1 pigment { rgbf <1,1,1,0.9> } finish { refraction 1 ior 1.5 } }
sphere { <1.1,0,0>, 1 texture { T } }
plane { z, 2 pigment { checker rgb <1,0,0> rgb <0,0,1> } }
