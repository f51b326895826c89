// tests/gi_room.pov - a closed room lit only by an emitting ceiling panel
// (tests/test_gi_room.sh): what fog and media do to the light carried
// between its surfaces.  Case 0: nothing in the air; 1: a black fog of
// distance 3; 2: an absorbing atmospheric medium, radiosity media off;
// 3: the same medium with media on.
#version 3.7;
#ifndef (Air) #declare Air = 0; #end
global_settings { assumed_gamma 1.0
  radiosity { count 200 error_bound 0.3 recursion_limit 3 pretrace_end 0.02
              nearest_count 10 media (Air = 3) } }
camera { location <0, 1.5, -1.9> look_at <0, 1, 0> angle 90 }
background { rgb 0 }
#if (Air = 1) fog { distance 3 color rgb 0 } #end
#if (Air >= 2) media { absorption 0.3 } #end
#declare W = finish { diffuse 0.75 ambient 0 emission 0 }
box { <-2, 0, -2>, <2, 3, 2> hollow pigment { rgb 1 } finish { W } }
box { <-1.99, 0.01, -1.99>, <-1.98, 2.99, 1.99> pigment { rgb <1, 0.1, 0.1> } finish { W } }
box { <1.98, 0.01, -1.99>, <1.99, 2.99, 1.99> pigment { rgb <0.1, 1, 0.1> } finish { W } }
box { <-0.5, 2.98, -0.5>, <0.5, 2.99, 0.5> pigment { rgb 1 }
      finish { diffuse 0 ambient 0 emission 6 } }
box { <-0.5, 0, -0.3>, <0.3, 0.8, 0.5> pigment { rgb 1 } finish { W } }
