// no_bump_scale in a texture and in a normal, on textures without bumps
// (parsing only; tests/no_bump_scale.pov checks the depth).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-5> look_at 0 }
light_source { <0,10,-10> rgb 1 }
sphere { <-1.1,0,0>, 1 texture { pigment { rgb <1,0.5,0.2> } scale 2 no_bump_scale } }
sphere { <1.1,0,0>, 1 pigment { rgb <0.2,0.5,1> } normal { bumps 0 no_bump_scale } }
