// julia.pov - julia fractals (POV-Ray reference, "Julia Fractal"):
// quaternion sqr and cube, and a hypercomplex sqr, the last sliced off
// the default hyperplane, transformed and with a low precision.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -9> look_at <0, 0.8, 0> angle 50 }
light_source { <-6, 12, -8>, rgb 1 }
light_source { <7, 5, -6>, rgb 0.3 }
background { rgb <0.6, 0.7, 0.85> }

#declare F = finish { ambient 0.1 diffuse 0.75 phong 0.4 }

plane { y, -0.5 pigment { rgb <0.55, 0.6, 0.5> } finish { F } }
julia_fractal { <-0.083, 0.0, -0.83, -0.025>
  quaternion sqr max_iteration 8 precision 15
  translate <-2.6, 1, 0> pigment { rgb <0.9, 0.3, 0.2> } finish { F } }
julia_fractal { <-0.083, 0.0, -0.83, -0.025>
  max_iteration 8 precision 15 quaternion cube
  scale 1.2 rotate y * 30 translate <0, 1, 0>
  pigment { rgb <0.2, 0.5, 0.9> } finish { F } }
julia_fractal { <-0.745, 0, 0.113, 0.05>
  hypercomplex sqr max_iteration 9 precision 20
  slice <0, 0, 0.2, 1>, 0.1
  scale <0.8, 1.2, 0.8> rotate <0, -30, 20> translate <2.6, 1, 0>
  pigment { rgb <0.3, 0.8, 0.4> } finish { F } }
