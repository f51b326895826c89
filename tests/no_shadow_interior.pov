// tests/no_shadow_interior.pov - a no_shadow object's interior casts no
// shadow (tests/test_no_shadow_interior.sh): povray 3.7 lets the light
// through the absorbing media (K = 1) or the fade_distance filter
// (K = 2) of a no_shadow sphere; without no_shadow (NS = 0) they shadow
// the plane below.  C = 10 K + NS.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (C) #declare C = 11; #end
#declare K = div(C, 10);
#declare NS = mod(C, 10);
camera { location <0, 3, -6> look_at <0, -0.3, 0> angle 40 }
light_source { <0, 10, 0> rgb 1 }
plane { y, -1 pigment { rgb 1 } }
sphere { 0, 1
  #if (K = 1)
    hollow pigment { rgbt 1 } interior { media { absorption 3 } }
  #else
    pigment { rgbf <1, 0.5, 0.5, 1> }
    interior { fade_distance 0.3 fade_power 2 fade_colour <0.2, 0.2, 1> }
  #end
  #if (NS) no_shadow #end
}
