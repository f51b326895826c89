// camera_sky.pov - a mirrored camera (right -x) whose look_at lies along
// the sky vector: POV-Ray 3.7 takes up from the right vector as given,
// then mirrors right, so +x shows on the right and -z at the top.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 10, 0> look_at 0 right -x * 4 / 3 }
light_source { <0, 100, 0> rgb 1 }
light_source { <0, -100, 0> rgb 1 }
light_source { <0, 0, -100> rgb 1 }
box { <1, -0.1, -0.5>, <3, 0.1, 0.5> pigment { rgb <1, 0, 0> } }
box { <-0.5, -0.1, 1>, <0.5, 0.1, 3> pigment { rgb <0, 1, 0> } }
box { <-3, -0.1, -0.3>, <-1, 0.1, 0.3> pigment { rgb <0, 0, 1> } }
sphere { <0, 0, -2>, 0.5 pigment { rgb <1, 1, 0> } }
sphere { <0, 2, 0>, 0.5 pigment { rgb <1, 0, 1> } }
