// Does a clear box without photons { refraction } let photons through to
// a target lens inside it?  Caustic on the floor (no media).
#version 3.7;
global_settings { assumed_gamma 1 photons { spacing 0.01 } }
camera { location <0, 10, 0> look_at <0, 0, 0> right x*4/3 angle 30 }
light_source { <0, 20, 0>, rgb 1 photons { refraction on reflection on } }
plane { y, 0 pigment { rgb 0.3 } finish { ambient 0 diffuse 1 } }
box { <-2, 0.01, -2>, <2, 3, 2> hollow pigment { rgbf 1 } finish { ambient 0 diffuse 0 }
  #ifdef (BOXTARGET) photons { target } #end }
sphere { <-0.8, 1.5, 0>, 0.5 pigment { rgbf 1 } finish { ambient 0 diffuse 0 }
  interior { ior 1.5 } photons { target refraction on reflection off collect off } }
