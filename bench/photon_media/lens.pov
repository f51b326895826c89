// Probe: a spotlight through a glass sphere (photon target) into a
// hollow scattering box: the focused beam behind it is media photons.
#version 3.7;
#ifndef (FACTOR) #declare FACTOR = 1; #end
#ifndef (COUNT) #declare COUNT = 20000; #end
global_settings { assumed_gamma 1 max_trace_level 5
  photons { count COUNT media 100, FACTOR } }
camera { location <0, 10, 0> look_at <0, 0, 0> right x*4/3 angle 40 }
light_source { <-20, 0.5, 0>, rgb 1
  spotlight radius 2 falloff 2.5 point_at <0, 0.5, 0>
  photons { refraction on reflection on } }
box { <-100, -1, -100>, <100, 0, 100> pigment { rgb 0.2 } finish { ambient 0 diffuse 1 } }
box { <-3, 0.01, -2>, <3, 1.2, 2> hollow
  pigment { rgbf 1 } finish { ambient 0 diffuse 0 }
  interior { media { scattering { 1, rgb 0.5 extinction 0 } method 3 intervals 1 samples 4 } }
}
sphere { <-1.5, 0.5, 0>, 0.45
  pigment { rgbf 1 } finish { ambient 0 diffuse 0 }
  interior { ior 1.5 }
  photons { target refraction on reflection off collect off }
}
