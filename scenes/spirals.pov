// spirals.pov - spiral1 and spiral2 ("Spiral1 Pattern", "Spiral2
// Pattern") as POV-Ray 3.7 renders them: values probed by
// bench/conform/spiral_probe.pov.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> look_at 0 right x * 4 up y * 3 }
light_source { <0, 0, -100> rgb 1 }
#declare F = finish { ambient 0.3 diffuse 0.7 }
plane { z, 0 clipped_by { box { <-2, -1.5, -1>, <0, 0, 1> } }
  pigment { spiral1 1 color_map { [0 rgb <1, 0.2, 0>] [1 rgb <0, 0.3, 1>] }
            translate <-1, -0.75, 0> } finish { F } }
plane { z, 0 clipped_by { box { <0, -1.5, -1>, <2, 0, 1> } }
  pigment { spiral1 3 sine_wave color_map { [0 rgb 0] [1 rgb <1, 1, 0.5>] }
            translate <1, -0.75, 0> } finish { F } }
plane { z, 0 clipped_by { box { <-2, 0, -1>, <0, 1.5, 1> } }
  pigment { spiral2 2 color_map { [0 rgb <0, 0.5, 0>] [1 rgb 1] }
            translate <-1, 0.75, 0> } finish { F } }
plane { z, 0 clipped_by { box { <0, 0, -1>, <2, 1.5, 1> } }
  pigment { spiral2 5 ramp_wave color_map { [0 rgb <0.5, 0, 0.5>] [1 rgb 1] }
            translate <1, 0.75, 0> } finish { F } }
