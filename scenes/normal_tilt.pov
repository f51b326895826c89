// normal_tilt.pov - how far normal patterns tilt ("Normal", "Slope
// Maps"; bench/conform/normal_probe.sh measures the rule): the tilt does
// not change under a uniform scale of the pattern, follows a non-uniform
// one, and is taken on the viewer's side of a surface.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -10> look_at <0, 0, 0> angle 45 }
light_source { <-10, 10, -10> rgb 1 }
light_source { <10, 0, 10> rgb 0.6 }
#declare F = finish { ambient 0.1 diffuse 0.8 specular 0.4 }
// The same ramp at scale 1 and 0.1: the same slope.
box { <-3.8, 0.2, 0>, <-2.0, 2.4, 1> pigment { rgb 1 } finish { F }
  normal { gradient x, 1 triangle_wave scale 0.6 } }
box { <-1.8, 0.2, 0>, <0, 2.4, 1> pigment { rgb 1 } finish { F }
  normal { gradient x, 1 triangle_wave scale 0.06 } }
// A slope map and a non-uniform scale.
box { <0.2, 0.2, 0>, <2.0, 2.4, 1> pigment { rgb 1 } finish { F }
  normal { gradient y, 2 slope_map { [0 <0, 1>] [0.5 <1, 0>] [1 <0, -1>] }
           scale <1, 0.3, 0.1> } }
// Onion rings on a sphere, leopard on another.
sphere { <3, 1.3, 0.5>, 1 pigment { rgb <1, 0.8, 0.6> } finish { F }
  normal { onion 1.5 sine_wave scale 0.3 } }
sphere { <-2.6, -1.6, 0.5>, 1.2 pigment { rgb <0.6, 0.8, 1> } finish { F }
  normal { leopard 3 scale 0.1 } }
// A plane seen from behind: the tilt stays on the viewer's side.
plane { z, 2 pigment { rgb 0.7 } finish { F }
  normal { gradient <1, 1, 0>, 1.5 triangle_wave scale 0.5 } }
// A disc whose normal is along the gradient (only the part along the
// normal changes the length, then the direction, of the normal).
disc { <0.8, -1.7, 0>, <-0.3, 0.2, -1>, 1.4 pigment { rgb <0.8, 1, 0.7> }
  finish { F } normal { gradient <0.3, -0.2, 1>, 3 triangle_wave scale 0.4 } }
