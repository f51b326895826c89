// tests/gi_bounce.pov - a closed room lit only by an emitting panel, to
// measure what the radiosity block's recursion_limit does
// (tests/test_gi_bounce.sh, bench/gi_bounce.sh).  Rec: recursion_limit
// (0 leaves it out: POV-Ray's default, 2).  Hi 1: povray's reference
// settings (count 1600, error_bound 0.1), 0: the settings the test
// renders with.
#version 3.7;
#ifndef (Rec) #declare Rec = 2; #end
#ifndef (Hi) #declare Hi = 0; #end
global_settings { assumed_gamma 1.0
  radiosity {
    #if (Hi) count 1600 error_bound 0.1 nearest_count 20 pretrace_end 0.01
    #else count 200 error_bound 0.3 nearest_count 10 pretrace_end 0.02 #end
    #if (Rec > 0) recursion_limit Rec #end
  } }
camera { location <0, 1.6, -1.95> look_at <0, 1.2, 1> angle 100 }
background { rgb 0 }
#declare W = finish { diffuse 0.75 ambient 0 emission 0 }
// the room, white walls, a red one on the left
box { <-2, 0, -2>, <2, 3, 2> hollow pigment { rgb 1 } finish { W } }
box { <-1.99, 0.01, -1.99>, <-1.98, 2.99, 1.99> pigment { rgb <1, 0.2, 0.2> }
      finish { W } }
// a lamp hanging in the room: a thin box whose faces all emit
box { <-0.5, 2.4, -0.5>, <0.5, 2.45, 0.5> pigment { rgb 1 }
      finish { diffuse 0 ambient 0 emission 4 } }
// a block on the floor
box { <0.3, 0, 0.2>, <1.1, 0.8, 1.0> pigment { rgb 1 } finish { W } }
