// flat_box.pov - boxes of zero thickness along one axis are hit on their
// face, as POV-Ray 3.7 renders them (camera/Orthographic_scene.pov's
// screen, screen.inc).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <1, 2, -5> look_at <0, 0.5, 0> }
light_source { <-5, 8, -10> rgb 1 }
box { <-2, 0, 0>, <-0.2, 2, 0> pigment { checker rgb <1, 0.3, 0.2> rgb 1 scale 0.5 } }
box { <0.2, 0, -1>, <2, 0, 1> pigment { rgb <0.3, 0.6, 1> } }
box { <0, 0.5, -0.5>, <0, 1.5, 0.5> pigment { rgb <0.2, 0.9, 0.3> } rotate y * 30 translate x }
plane { y, -0.01 pigment { rgb 0.6 } }
