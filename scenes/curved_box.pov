// golden: skip (a benchmark scene: bench/gi_error.sh "curved")
// curved_box.pov - a closed box lit by one point light, holding curved
// diffuse surfaces: two spheres, a cylinder and a torus (issue 11's
// target "a box with curved surfaces reaches a relative error of 0.10
// in at most 5x the time POV-Ray's cheapest useful setting takes").
// Coloured walls bleed onto the curved objects, which shade the floor.
#version 3.7;
global_settings { assumed_gamma 1.0 radiosity { } }
camera { location <0, 1, -3.4> look_at <0, 1, 0> angle 52 }
light_source { <0, 1.9, 0> rgb 1 }
#declare White = texture { pigment { rgb 0.75 } finish { diffuse 1 } }
box { <-1, 0, -3.5>, <1, 2, 1> hollow texture { White } }
box { <-1.05, -0.01, -3.5>, <-1, 2.01, 1>
      pigment { rgb <0.75, 0.1, 0.1> } finish { diffuse 1 } }
box { <1, -0.01, -3.5>, <1.05, 2.01, 1>
      pigment { rgb <0.1, 0.6, 0.15> } finish { diffuse 1 } }
sphere { <-0.45, 0.4, 0.2>, 0.4 texture { White } }
sphere { <0.5, 0.25, -0.5>, 0.25 pigment { rgb <0.2, 0.3, 0.8> }
         finish { diffuse 1 } }
cylinder { <0.45, 0, 0.5>, <0.45, 0.9, 0.5>, 0.25 texture { White } }
torus { 0.3, 0.08 rotate x * 90 translate <-0.3, 1.3, 0.6>
        pigment { rgb <0.9, 0.8, 0.3> } finish { diffuse 1 } }
