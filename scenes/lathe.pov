// lathe.pov - lathes (POV-Ray reference, "Lathe"): the manual's thick
// tube (linear_spline), a quadratic bowl, a cubic vase and a bezier
// ring, turned about y and one of them tilted.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -11> look_at <0, 1, 0> angle 50 }
light_source { <-6, 12, -8>, rgb 1 }
light_source { <7, 5, -6>, rgb 0.3 }
background { rgb <0.6, 0.7, 0.85> }

#declare F = finish { ambient 0.1 diffuse 0.75 phong 0.3 }

plane { y, 0 pigment { rgb <0.55, 0.6, 0.5> } finish { F } }
lathe { linear_spline 5, <2, 0>, <3, 0>, <3, 5>, <2, 5>, <2, 0>
  scale 0.3 translate <-3.5, 0, 0>
  pigment { rgb <0.9, 0.3, 0.2> } finish { F } }
lathe { quadratic_spline 6, <0, -0.1>, <0, 0>, <1, 0.2>, <1.3, 1.2>,
  <1.1, 1.3>, <0.9, 1.25>
  translate <-1, 0, 0.5> pigment { rgb <0.2, 0.5, 0.9> } finish { F } }
lathe { cubic_spline 8, <0, -0.5>, <0, 0>, <0.6, 0.1>, <0.9, 0.8>,
  <0.4, 1.6>, <0.6, 2.2>, <0.7, 2.3>, <0.8, 2.5>
  translate <1.3, 0, 0.5> pigment { rgb <0.95, 0.85, 0.2> } finish { F } }
lathe { bezier_spline 8,
  <0.8, 0>, <1.4, 0>, <1.4, 0.6>, <0.8, 0.6>,
  <0.8, 0.6>, <0.6, 0.6>, <0.6, 0>, <0.8, 0>
  sturm rotate x * -50 translate <3.5, 1, -1>
  pigment { rgb <0.3, 0.8, 0.4> } finish { F } }
