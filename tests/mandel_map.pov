// mandel_map.pov - the colour map POV-Ray 3.7 gives mandel written
// without one (tests/test_mandel_map.sh; lib/scene/texture.c mandel_map):
// the set and its surroundings seen flat, emitting their pigment.
// Declare=K=1: 1000 iterations over the whole set; K=2: 30 iterations.
#version 3.7;
global_settings { assumed_gamma 1 }
#ifndef (K) #declare K = 1; #end
camera { orthographic location <-0.8, 0, -5> look_at <-0.8, 0, 0>
         right 3.2*x up 2.4*y }
plane { z, 0
  pigment { #if (K = 1) mandel 1000 #else mandel 30 #end }
  finish { ambient 1 diffuse 0 } }
