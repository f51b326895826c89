// tests/gi_fog.pov - the irradiance cache's sample rays and fog
// (tests/test_gi_fog.sh): a white floor seen from 0.1 above, lit only by
// a green sky through a red fog; Fog 1 is a constant fog of distance 1,
// Fog 2 a ground fog (fog_type 2) as radiosity_36.pov's.
#version 3.7;
#ifndef (Fog) #declare Fog = 1; #end
global_settings { assumed_gamma 1.0
  radiosity { count 100 error_bound 0.5 recursion_limit 1 } }
camera { location <0, 0.1, 0> look_at <0, 0, 0.001> }
sky_sphere { pigment { rgb <0, 1, 0> } }
#if (Fog = 1)
  fog { distance 1 color rgb <1, 0, 0> }
#else
  fog { fog_type 2 fog_alt 1.3 fog_offset 0 distance 8 color rgb <1, 0, 0> }
#end
plane { y, 0 pigment { rgb 1 } finish { diffuse 1 ambient 0 } }
