// sor.pov - surfaces of revolution (POV-Ray reference, "Surface of
// Revolution"): the manual's open vase, a closed bottle, and one tilted
// to show its caps.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -9> look_at <0, 1, 0> angle 45 }
light_source { <-6, 12, -8>, rgb 1 }
light_source { <7, 5, -6>, rgb 0.3 }
background { rgb <0.6, 0.7, 0.85> }

#declare F = finish { ambient 0.1 diffuse 0.75 phong 0.3 }

plane { y, 0 pigment { rgb <0.55, 0.6, 0.5> } finish { F } }
sor { 7, <0.000000, 0.000000>, <0.118143, 0.000000>, <0.620253, 0.540084>,
  <0.210970, 0.827004>, <0.194093, 0.962025>, <0.286920, 1.000000>,
  <0.468354, 1.033755>
  open scale 2.5 translate <-2.2, 0, 0>
  pigment { rgb <0.9, 0.3, 0.2> } finish { F } }
sor { 8, <0, -0.2>, <0.6, 0>, <0.7, 0.5>, <0.6, 1.2>, <0.25, 1.6>,
  <0.2, 2.0>, <0.25, 2.2>, <0.3, 2.4>
  translate <0.3, 0, 0.5> pigment { rgb <0.2, 0.5, 0.9> } finish { F } }
sor { 6, <0.3, -0.5>, <0.5, 0>, <0.8, 0.5>, <0.4, 1.0>, <0.6, 1.5>,
  <0.2, 2>
  sturm rotate z * -60 translate <2.2, 0.6, -1>
  pigment { rgb <0.3, 0.8, 0.4> } finish { F } }
