// ovus.pov - ovus objects (POV-Ray reference, "Ovus"): eggs with the
// small end up and down, tilted; one cut open by CSG; and one whose top
// radius is twice its bottom one or more, which is a sphere (POV-Ray and
// zRcube both warn).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -7> look_at <0, 0.8, 0> angle 45 }
light_source { <-5, 10, -10> color rgb 1 }
background { color rgb <0.2, 0.3, 0.4> }
plane { y, -1 pigment { checker color rgb 0.9 color rgb 0.3 } }
ovus { 1, 0.5 pigment { color rgb <1, 0.8, 0.5> } finish { phong 0.5 } translate <-2.3, 0, 0> }
ovus { 0.6, 1 pigment { color rgb <0.5, 0.8, 1> } rotate <0, 0, 30> translate <0, 0.4, 1> }
difference {
  ovus { 0.9, 0.9 }
  box { <0, -2, -2>, <2, 2, 0> }
  pigment { color rgb <0.4, 1, 0.5> }
  rotate 40 * y
  translate <2.2, 0, 0>
}
ovus { 0.3, 0.7 pigment { color rgb <1, 0.4, 0.4> } translate <0, -0.7, -1.6> }
