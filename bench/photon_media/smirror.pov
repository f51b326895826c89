// Surface photons only: does a mirror without a photons block reflect
// the photons a target lens refracted?  Caustic on the wall at x=2?
#version 3.7;
global_settings { assumed_gamma 1 photons { spacing 0.01 } }
camera { location <0, 1, -8> look_at <0, 1, 0> right x*4/3 angle 40 }
light_source { <0, 20, 0>, rgb 1 photons { refraction on reflection on } }
plane { y, 0 pigment { rgb 0.3 } finish { ambient 0 diffuse 1 } }
plane { -x, -2 pigment { rgb 0.3 } finish { ambient 0 diffuse 1 } }
sphere { <0, 3, 0>, 0.5 pigment { rgbf 1 } finish { ambient 0 diffuse 0 }
  interior { ior 1.5 } photons { target refraction on reflection off collect off } }
box { <-0.6, -0.01, -0.6>, <0.6, 0.01, 0.6> rotate z*22.5 translate <0, 1.2, 0>
  pigment { rgb 1 } finish { ambient 0 diffuse 0 reflection 1 } }
