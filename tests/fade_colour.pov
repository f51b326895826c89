// fade_colour.pov - how fade_color colours the fade of a clear interior
// (tests/test_fade_colour.sh).  Eight clear slabs 0.25 to 2 thick,
// fade_distance 2, fade_color <0.35, 0.42, 0.85>, fade_power Power (by Case below);
// View 1: seen through (orthographic) against a white ambient wall;
// View 2: their shadows on a white floor under a light straight above.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
// Case: 1 view, power 1001; 2 shadow, 1001; 3 view, 1000; 4 view, 999;
// 5 shadow, power 2.
#ifndef (Case) #declare Case = 1; #end
#declare View = ((Case = 2 | Case = 5) ? 2 : 1);
#declare Power = (Case = 3 ? 1000 : (Case = 4 ? 999 : (Case = 5 ? 2 : 1001)));
#declare Glass = material {
  texture { pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 } }
  interior { ior 1.5 fade_distance 2 fade_power Power
             fade_color <0.35, 0.42, 0.85> }
}
#if (View = 1)
  camera { orthographic location <0, 0, -10> look_at 0 right 8*x up 6*y }
  plane { z, 10 pigment { rgb 1 } finish { ambient 1 diffuse 0 } }
  #declare K = 0;
  #while (K < 8)
    box { <-4 + K, -3, 0>, <-3 + K, 3, 0.25*(K + 1)> material { Glass } }
    #declare K = K + 1;
  #end
#else
  camera { orthographic location <0, 0.5, 0> look_at 0 right 8*x up 6*z sky z }
  light_source { <0, 100000, 0> rgb 1 }
  plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
  #declare K = 0;
  #while (K < 8)
    box { <-4 + K, 1, -3>, <-3 + K, 1 + 0.25*(K + 1), 3> material { Glass } }
    #declare K = K + 1;
  #end
#end
