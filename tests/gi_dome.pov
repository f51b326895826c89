// tests/gi_dome.pov - a box on a floor under an emitting sky dome, a
// common way to light a radiosity scene (tests/test_gi_room.sh): the
// dome's emission must reach the inside, as povray's does.
#version 3.7;
global_settings { assumed_gamma 1.0 radiosity { count 100 error_bound 0.5 } }
camera { location <0, 2, -5> look_at <0, 0.5, 0> }
sphere { 0, 50 hollow pigment { rgb <0.6, 0.7, 1> }
         finish { diffuse 0 ambient 0 emission 1 } }
plane { y, 0 pigment { rgb 0.8 } finish { diffuse 0.8 ambient 0 } }
box { -0.5, 0.5 translate y * 0.5 pigment { rgb <1, 0.6, 0.4> }
      finish { diffuse 0.8 ambient 0 } }
