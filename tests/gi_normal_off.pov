// tests/gi_normal_off.pov - radiosity with normal off (the default) under
// a normal { } that tilts the shading normal past 90 degrees
// (tests/test_gi_normal_off.sh): a plane with granite 0.95 scale 0.05, as
// the corpus' pneumaticBoat.pov sand, lit by a sky, over a black plane.
#version 3.7;
global_settings { assumed_gamma 1.0
  radiosity { pretrace_start 0.08 pretrace_end 0.02 count 100 nearest_count 5
              error_bound 0.5 recursion_limit 1 } }
#default { finish { ambient 0 } }
camera { location <0, 3, -3> look_at <0, 0, 0> }
light_source { <-200, 1000, -500> rgb 1 }
sky_sphere { pigment { rgb <0.6, 0.7, 1> } }
plane { y, 0 pigment { rgb <0.8, 0.7, 0.5> } normal { granite 0.95 scale 0.05 } }
plane { y, -1 pigment { rgb 0 } }
