// height_field.pov - height fields (POV-Ray reference, "Height Field"):
// POV-Ray's plasma3.png (a palette image: heights are its indices),
// smooth; and one made from a function, cut by its water_level and
// turned.  plasma3.png is found in POV-Ray's include directory.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2.2, -3> look_at <0, 0.2, 0> angle 45 }
light_source { <-5, 10, -6> color rgb 1 }
background { color rgb <0.2, 0.3, 0.4> }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.4 scale 0.25 } }
height_field {
  png "plasma3.png" smooth
  pigment { gradient y color_map { [0 rgb <0.2, 0.4, 1>] [1 rgb <1, 0.9, 0.6>] } }
  translate <-0.5, 0, -0.5> scale <1.6, 0.5, 1.6> translate <-0.9, 0, 0>
}
height_field {
  function 40, 40 { 0.5 + 0.4 * sin(x * 9) * cos(y * 7) }
  water_level 0.3
  pigment { color rgb <0.9, 0.5, 0.3> }
  translate <-0.5, 0, -0.5> scale <1.4, 0.6, 1.4> rotate 20 * y
  translate <0.9, 0, 0.2>
}
