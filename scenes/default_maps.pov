// default_maps.pov - the colour maps POV-Ray 3.7 gives radial, marble
// and wood written without one (bench/conform/defmap_probe.sh); gradient
// keeps the grey ramp.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> look_at 0 right x * 4 up y * 3 }
light_source { <0, 0, -100> rgb 1 }
#declare F = finish { ambient 0.4 diffuse 0.6 }
plane { z, 0 clipped_by { box { <-2, -1.5, -1>, <0, 0, 1> } }
  pigment { radial rotate x * -90 translate <-1, -0.75, 0> } finish { F } }
plane { z, 0 clipped_by { box { <0, -1.5, -1>, <2, 0, 1> } }
  pigment { marble scale 0.5 } finish { F } }
plane { z, 0 clipped_by { box { <-2, 0, -1>, <0, 1.5, 1> } }
  pigment { wood scale 0.4 translate <-1, 0.75, 0> } finish { F } }
plane { z, 0 clipped_by { box { <0, 0, -1>, <2, 1.5, 1> } }
  pigment { gradient x } finish { F } }
