// isosurface.pov - isosurfaces (POV-Ray reference, "Isosurface"): a
// sphere cut by its box container, which closes it; an open one, whose
// inside shows; one with a sphere taken out by CSG (all_intersections);
// and a glass octahedron in a sphere container, which rays enter and
// leave.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 0, 0> angle 45 }
light_source { <-5, 10, -10> color rgb 1 }
background { color rgb <0.2, 0.3, 0.4> }
plane { y, -1.2 pigment { checker color rgb 0.9 color rgb 0.3 } }
isosurface {
  function { x*x + y*y + z*z - 1.3 }
  max_gradient 4
  pigment { color rgb <1, 0.6, 0.2> }
  translate <-2.2, 0, 0>
}
isosurface {
  function { x*x + y*y + z*z - 1.3 + 0.2 * sin(6 * x) * sin(6 * z) }
  open
  max_gradient 4.5
  pigment { color rgb <0.3, 0.5, 1> }
  finish { phong 0.5 }
  rotate <0, 30, 0>
  translate <0, 0, 1>
}
difference {
  isosurface {
    function { pow(sqrt(x*x + z*z) - 0.7, 2) + y*y - 0.09 }
    contained_by { box { <-1.1, -0.4, -1.1>, <1.1, 0.4, 1.1> } }
    max_gradient 3
    all_intersections
  }
  sphere { <0.7, 0.3, 0>, 0.35 }
  pigment { color rgb <0.3, 0.9, 0.4> }
  rotate <-30, 0, 0>
  translate <2.2, 0, 0>
}
isosurface {
  function { abs(x) + abs(y) + abs(z) - 0.6 }
  contained_by { sphere { 0, 1 } }
  threshold 0.05
  max_gradient 1.8
  pigment { color rgbf <1, 1, 1, 0.9> }
  interior { ior 1.5 }
  scale <1, 1.4, 1>
  translate <0, 0, -2>
}
