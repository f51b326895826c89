// gtk_scene.pov - tests/test_gtk.sh's scene: a red sphere right of
// the view's centre, a green box left of it and a blue floor below,
// seen from <0, 0, -10> with POV-Ray's default angle, so that where each
// lands in the picture follows from the camera alone (the test says
// how).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at <0, 0, 0> }
light_source { <-10, 20, -20> rgb 1 }
sphere { <2, 0, 0>, 1 pigment { rgb <1, 0, 0> } }
box { <-3, -1, -1>, <-1, 1, 1> pigment { rgb <0, 1, 0> } }
plane { y, -2 pigment { rgb <0, 0, 1> } }
