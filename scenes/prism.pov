// prism.pov - prisms (POV-Ray reference, "Prism"): the manual's frame in
// each spline type (linear, quadratic, cubic), a bezier star, a conic
// pyramid and an open prism seen from above.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 9, -12> look_at <0, 0.5, 0> angle 55 }
light_source { <-6, 12, -8>, rgb 1 }
light_source { <7, 5, -6>, rgb 0.3 }
background { rgb <0.6, 0.7, 0.85> }

#declare F = finish { ambient 0.1 diffuse 0.75 phong 0.3 }

plane { y, 0 pigment { rgb <0.55, 0.6, 0.5> } finish { F } }
prism { linear_spline 0, 1, 10,
  <0,0>, <6,0>, <6,8>, <0,8>, <0,0>, <1,1>, <5,1>, <5,7>, <1,7>, <1,1>
  scale 0.3 translate <-5, 0, 0.5>
  pigment { rgb <0.9, 0.3, 0.2> } finish { F } }
prism { quadratic_spline 0, 1, 12,
  <1,-1>, <0,0>, <6,0>, <6,8>, <0,8>, <0,0>,
  <2,0>, <1,1>, <5,1>, <5,7>, <1,7>, <1,1>
  scale 0.3 translate <-2.5, 0, 0.5>
  pigment { rgb <0.2, 0.5, 0.9> } finish { F } }
prism { cubic_spline 0, 1, 14,
  <1,-1>, <0,0>, <6,0>, <6,8>, <0,8>, <0,0>, <-1,1>,
  <2,0>, <1,1>, <5,1>, <5,7>, <1,7>, <1,1>, <0,2>
  scale 0.3 translate <0, 0, 0.5>
  pigment { rgb <0.95, 0.85, 0.2> } finish { F } }
prism { bezier_spline -0.5, 0.8, 16,
  <1, 0>, <0.3, 0.3>, <0.3, 0.3>, <0, 1>,
  <0, 1>, <-0.3, 0.3>, <-0.3, 0.3>, <-1, 0>,
  <-1, 0>, <-0.3, -0.3>, <-0.3, -0.3>, <0, -1>,
  <0, -1>, <0.3, -0.3>, <0.3, -0.3>, <1, 0>
  sturm scale 1.2 translate <3.5, 0.5, 1>
  pigment { rgb <0.3, 0.8, 0.4> } finish { F } }
prism { conic_sweep linear_spline 0, 1, 5,
  <1, 1>, <-1, 1>, <-1, -1>, <1, -1>, <1, 1>
  rotate x * 180 translate y scale <1.2, 2, 1.2> translate <-2.5, 0, -3>
  pigment { rgb <0.8, 0.4, 0.8> } finish { F } }
prism { 0, 1.2, 4, <-1, -0.6>, <1, -0.6>, <0, 1>, <-1, -0.6> open
  translate <1.5, 0, -3.5> pigment { rgb <0.9, 0.9, 0.9> } finish { F } }
