// tests/gi_pattern.pov - a hall around a sunlit courtyard, in shadow
// under its roof and lit through four doorways (tests/test_gi_pattern.sh):
// the directions of the irradiance cache's sample rays.  Count is
// declared by the test (50, the case measured; 600 converges).
#version 3.7;
#ifndef (Count) #declare Count = 50; #end
global_settings { assumed_gamma 1.0
  radiosity { pretrace_start 0.08 pretrace_end 0.02 count Count
              error_bound 0.5 recursion_limit 1 } }
#default { finish { ambient 0 diffuse 0.6 } }
camera { location <7.5, 1.3, 6.5> right x * 4 / 3 look_at <0, 1.3, 0> angle 45 }
light_source { <-5000, 14000, 15000> rgb <1, 0.9, 0.78> * 2.3 }
sky_sphere { pigment { gradient y color_map { [0 rgb 1] [0.3 rgb <0.5, 0.6, 1>] } } }
plane { y, 0 pigment { rgb <0.9, 0.65, 0.3> } }
union {
  difference {
    box { <-10, -0.1, -10>, <10, 4, 10> }
    box { <-9, 0.3, -9>, <9, 3.5, 9> }
    box { <-4, 0.1, -4>, <4, 5, 4> }
    box { <-2, 0.3, -11>, <2, 2.3, 11> }
    box { <-11, 0.3, -2>, <11, 2.3, 2> }
  }
  #for (I, 0, 3)
    #for (K, 0, 3)
      cylinder { <4.4, 0.2, 4.4 - K * 8.8 / 3>, <4.4, 3.6, 4.4 - K * 8.8 / 3>, 0.2
                 rotate y * 90 * I }
    #end
  #end
  pigment { rgb 0.8 }
}
