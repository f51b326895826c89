// bicubic.pov - bicubic patches (POV-Ray reference, "Bicubic Patch"):
// the manual's example as type 0 and type 1, one with a flatness that
// stops the splitting early, and a saddle patch rotated and scaled.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 6, -12> look_at <0, 1, 0> angle 50 }
light_source { <-6, 12, -8>, rgb 1 }
light_source { <7, 5, -6>, rgb 0.3 }
background { rgb <0.6, 0.7, 0.85> }

#declare F = finish { ambient 0.1 diffuse 0.75 phong 0.4 }
#declare Manual = bicubic_patch {
  type 0 flatness 0.01 u_steps 4 v_steps 4
  <0, 0, 2>, <1, 0, 0>, <2, 0, 0>, <3, 0, -2>,
  <0, 1, 0>, <1, 1, 0>, <2, 1, 0>, <3, 1, 0>,
  <0, 2, 0>, <1, 2, 0>, <2, 2, 0>, <3, 2, 0>,
  <0, 3, 2>, <1, 3, 0>, <2, 3, 0>, <3, 3, -2>
}

plane { y, 0 pigment { rgb <0.55, 0.6, 0.5> } finish { F } }
object { Manual scale 0.8 translate <-4.2, 0.2, 0.5>
  pigment { rgb <0.9, 0.3, 0.2> } finish { F } }
bicubic_patch { type 1 u_steps 3 v_steps 3
  <0, 0, 2> <1, 0, 0> <2, 0, 0> <3, 0, -2>
  <0, 1, 0> <1, 1, 0> <2, 1, 0> <3, 1, 0>
  <0, 2, 0> <1, 2, 0> <2, 2, 0> <3, 2, 0>
  <0, 3, 2> <1, 3, 0> <2, 3, 0> <3, 3, -2>
  scale 0.8 rotate y * -30 translate <-0.8, 0.2, 0>
  pigment { rgb <0.2, 0.5, 0.9> } finish { F } }
bicubic_patch { type 1 flatness 0.1 u_steps 4 v_steps 2
  uv_vectors <0, 0>, <1, 0>, <1, 1>, <0, 1>
  <0, 0, 0>, <1, 1, 0>, <2, 1, 0>, <3, 0, 0>,
  <0, 1, 1>, <1, 0, 1>, <2, 0, 1>, <3, 1, 1>,
  <0, 1, 2>, <1, 0, 2>, <2, 0, 2>, <3, 1, 2>,
  <0, 0, 3>, <1, 1, 3>, <2, 1, 3>, <3, 0, 3>
  scale <0.8, 1.2, 0.8> rotate x * -60 translate <2.2, 0.5, -1>
  pigment { checker rgb <0.3, 0.8, 0.4>, rgb 1 scale 0.5 } finish { F } }
