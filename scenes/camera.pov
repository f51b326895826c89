// camera.pov - the perspective camera's vectors.
//
// location, look_at, a narrow angle, an explicit direction/up/right set
// and a tilted sky (POV-Ray reference, "Camera"): the horizon tilts by
// the sky's angle, and angle 35 magnifies compared to the default 67.4.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  perspective
  location <3, 4, -7>
  direction <0, 0, 1>
  up <0, 1, 0>
  right <4/3, 0, 0>
  sky <0.25, 1, 0>
  angle 35
  look_at <0, 0.7, 0>
}
light_source { <-5, 10, -5>, rgb 1 }
background { rgb <0.4, 0.5, 0.7> }
plane { y, 0 pigment { rgb <0.8, 0.75, 0.6> } }

// A small "compass": red along +x, green up +y, blue along +z.
sphere { <0, 0.5, 0>, 0.5 pigment { rgb 0.9 } }
cylinder { <0, 0.5, 0>, <1.6, 0.5, 0>, 0.1 pigment { rgb <0.9, 0.1, 0.1> } }
cylinder { <0, 0.5, 0>, <0, 2.1, 0>, 0.1 pigment { rgb <0.1, 0.8, 0.1> } }
cylinder { <0, 0.5, 0>, <0, 0.5, 1.6>, 0.1 pigment { rgb <0.1, 0.2, 0.9> } }
box { <-2.5, 0, 1.5>, <-1.5, 1, 2.5> pigment { rgb <0.9, 0.6, 0.1> } }
