// srgb, srgbf, srgbt, srgbft colours, under assumed_gamma 1 and 2.2.
#version 3.7;
#ifndef (Gamma) #declare Gamma = 1; #end
global_settings { assumed_gamma Gamma }
camera { orthographic location <0,0,-10> right x*8 up y*6 look_at 0 }
light_source { <0,0,-10> rgb 1 }
box { <-4,0,0>, <-2,3,1> pigment { srgb 0.5 } finish { ambient 1 diffuse 0 } }
box { <-2,0,0>, <0,3,1> pigment { srgb <0.2,0.6,0.9> } finish { ambient 1 diffuse 0 } }
box { <0,0,0>, <2,3,1> pigment { color srgbf <0.8,0.3,0.1,0.5> } finish { ambient 1 diffuse 0 } }
box { <2,0,0>, <4,3,1> pigment { color srgbt <0.1,0.3,0.8,0.5> } finish { ambient 1 diffuse 0 } }
box { <-4,-3,0>, <0,0,1> pigment { color srgbft <0.03,0.5,0.7,0.2,0.3> } finish { ambient 1 diffuse 0 } }
box { <0,-3,0>, <4,0,1> pigment { color srgb 0.02 } finish { ambient 1 diffuse 0 } }
plane { z, 3 pigment { rgb <0.2,0.8,0.3> } finish { ambient 1 diffuse 0 } }
