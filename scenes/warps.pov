// warps.pov - pattern warps (POV-Ray reference, "Warp"): the manual's
// toroidal, spherical and cylindrical mapping examples, and a floor
// whose checker is repeated with flip and offset, then drawn into a
// black hole.  Every warp rule is measured in bench/warp_probe.sh.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -7> look_at <0, 0, 0> angle 50 }
light_source { <-5, 10, -10> rgb 1 }
background { rgb 0.2 }
torus { 1, 0.5
  pigment { hexagon scale 0.1
    warp { toroidal orientation y dist_exp 1 major_radius 1 } }
  translate <-2.2, 0, 0> }
sphere { 0, 1
  pigment { hexagon scale <0.5 / pi, 0.25 / pi, 1> * 0.1
    warp { spherical orientation y dist_exp 1 } } }
cylinder { -y, y, 1
  pigment { hexagon scale <0.5 / pi, 1, 1> * 0.1
    warp { cylindrical orientation y dist_exp 1 } }
  translate <2.2, 0, 0> }
plane { y, -1.01
  pigment { checker rgb 1 rgb 0.3
    warp { repeat 2 * x flip <1, 0, 1> offset <0, 0, 0.3> }
    warp { black_hole <0.5, 0, 1>, 1 strength 1.5 } } }
