// caustics_bumps.pov - simulated caustics under a bumpy water surface,
// seen from above (tests/test_caustics.sh compares it with povray's).
#version 3.7;
global_settings { assumed_gamma 1 }
light_source { <0, 50, 0> color rgb 1 }
camera { orthographic sky z location <0, 9, 0> look_at <0, 0, 0>
         up z * 10 right x * 10 }
plane { y, 0 pigment { rgb 0.6 } finish { ambient 0 diffuse 0.7 } }
plane { y, 10 hollow on
        pigment { rgbf <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0 }
        interior { ior 1.1 caustics 1.0 } normal { bumps 0.5 } }
