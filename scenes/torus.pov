// torus.pov - tori (POV-Ray reference, "Torus"): one lying, one standing
// and seen nearly edge on, one thin ring whose rays graze it, and a
// shadow through the hole.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -9> look_at <0, 1, 0> angle 50 }
light_source { <-6, 10, -8>, rgb 1 }
light_source { <7, 5, -6>, rgb 0.3 }
background { rgb <0.6, 0.7, 0.85> }

#declare F = finish { ambient 0.08 diffuse 0.75 phong 0.4 phong_size 40 }

plane { y, 0 pigment { rgb <0.55, 0.6, 0.5> } finish { F } }
torus { 1.2, 0.4 translate <-2.2, 0.4, 0>
        pigment { rgb <0.9, 0.3, 0.2> } finish { F } }
torus { 1, 0.3 sturm rotate <90, 20, 0> translate <1.3, 1.3, 0.5>
        pigment { rgb <0.2, 0.5, 0.9> } finish { F } }
torus { 0.9, 0.05 rotate x * 80 translate <3.2, 1.2, -1.5>
        pigment { rgb <0.95, 0.85, 0.2> } finish { F } }
torus { 0.6, 0.25 scale <1, 2, 1> translate <-0.3, 0.5, -2.5>
        pigment { rgb <0.3, 0.8, 0.4> } finish { F } }
