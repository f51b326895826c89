// no_bump_scale in a texture and in a normal (here on textures without
// bumps, so only the parsing and the warning are checked).
// expect: 'no_bump_scale' is ignored
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-5> look_at 0 }
light_source { <0,10,-10> rgb 1 }
sphere { <-1.1,0,0>, 1 texture { pigment { rgb <1,0.5,0.2> } scale 2 no_bump_scale } }
sphere { <1.1,0,0>, 1 pigment { rgb <0.2,0.5,1> } normal { bumps 0 no_bump_scale } }
