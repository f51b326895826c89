// tests/negative_transmit.pov - a pigment with a negative transmit
// (tests/test_negative_transmit.sh): povray 3.7 shows the surface's own
// colour times 1 - t plus t times the scene behind it, t < 0 too.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (T) #declare T = -1; #end
camera { orthographic location <0, 0, -5> look_at 0 right x*4/3 up y }
plane { z, 1 pigment { checker rgb <0.1, 0.4, 0.9> rgb <0.8, 0.3, 0.1>
  scale 0.25 } finish { ambient 1 diffuse 0 } }
box { <-0.5, -0.5, -0.1>, <0.5, 0.5, 0>
  pigment { rgb 0.5 transmit T } finish { ambient 1 diffuse 0 } }
