// media_curvature.pov - method 3 halving (tests/test_media_curvature.sh):
// Case 1: a sphere whose density falls linearly from its centre
//   (spherical, density colours), absorption 8 emission 5 samples 30
//   (the cloud of corpus p2_100386336); Case 2: a slab whose density
//   rises linearly along the ray (no cell halved in povray); Case 3: a
//   slab whose density rises as z^2 (cells halved).
#version 3.7;
global_settings { assumed_gamma 1 }
#ifndef (Case) #declare Case = 1; #end
#if (Case = 1)
camera { location <0, 0, -6> look_at 0 angle 40 }
background { rgb <0.2, 0.3, 0.5> }
sphere { 0, 2 hollow no_shadow texture { pigment { rgbt 1 } }
  interior { media { absorption 8 emission 5 method 3 samples 30, 30
    intervals 1 density { spherical density_map { [0.2575 rgb 0]
      [0.2575 rgb 0] [1 rgb <0.75, 0.25, 0>] } } } } }
#else
camera { orthographic location <0, 0, -50> look_at 0 right 4 * x up 3 * y }
background { rgb 0 }
box { <-1, -1, 0>, <1, 1, 1> hollow pigment { rgbt 1 }
  interior { media { emission <1, 0.5, 0.25> absorption 5 method 3 samples 3
    #if (Case = 2) density { function { z } }
    #else density { function { z * z } } #end } } }
#end
