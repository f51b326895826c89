// parametric.pov - parametric surfaces (POV-Ray reference, "Parametric"):
// the manual's sphere (u over half a turn, so it is covered once) in a
// sphere container, and a rippled sheet in a box container, turned.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 0, 0> angle 40 }
light_source { <-5, 10, -10> color rgb 1 }
background { color rgb <0.2, 0.3, 0.4> }
plane { y, -1.2 pigment { checker color rgb 0.9 color rgb 0.3 } }
parametric {
  function { sin(u) * cos(v) }
  function { sin(u) * sin(v) }
  function { cos(u) }
  <0, 0>, <pi, 2 * pi>
  contained_by { sphere { 0, 1.1 } }
  max_gradient 1.5
  accuracy 0.001
  precompute 10 x, y, z
  pigment { color rgb <1, 0.6, 0.2> }
  finish { phong 0.4 }
  translate <-1.3, 0, 0>
}
parametric {
  function { u }
  function { 0.3 * sin(3 * u) * cos(3 * v) }
  function { v }
  <-1, -1>, <1, 1>
  contained_by { box { <-1, -1, -1>, <1, 1, 1> } }
  max_gradient 1.2
  pigment { color rgb <0.3, 0.8, 0.4> }
  rotate <-30, 20, 0>
  translate <1.3, 0, 0>
}
