// fade_shadow.pov - light through a clear object whose interior fades it
// ("Attenuation": fade_distance, fade_power, fade_colour) is faded in
// its shadow too, as POV-Ray 3.7 renders (interior/atten2.pov).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 5, -6> look_at <0, 0.5, 0> }
light_source { <0, 10, -1> rgb 1 }
plane { y, 0 pigment { rgb 0.9 } }
box { <-2.5, 1, -1>, <-0.5, 2, 1> pigment { rgbt 1 }
  interior { fade_distance 0.5 fade_power 2 } }
sphere { <1.5, 1.5, 0>, 0.9 pigment { rgbt 1 }
  interior { fade_distance 0.8 fade_power 2 fade_colour <0.2, 0.5, 1> } }
