// waves_quilted.pov - the quilted, ripples and waves patterns ("Quilted
// Pattern", "Ripples Pattern", "Waves Pattern") as POV-Ray 3.7 renders
// them: formulas and wave centres measured by
// bench/conform/quilted_probe.py and bench/conform/waves_probe.py.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> look_at 0 right x * 4 up y * 3 }
light_source { <0, 0, -100> rgb 1 }
#declare F = finish { ambient 0.3 diffuse 0.7 }
plane { z, 0 clipped_by { box { <-2, -1.5, -1>, <0, 0, 1> } }
  pigment { quilted control0 1 control1 1
            color_map { [0 rgb <1, 0.2, 0>] [0.6 rgb <0, 0.3, 1>] }
            scale 0.4 } finish { F } }
plane { z, 0 clipped_by { box { <0, -1.5, -1>, <2, 0, 1> } }
  pigment { quilted control0 0 control1 0.5
            color_map { [0 rgb 0] [0.4 rgb <1, 1, 0.5>] }
            scale 0.5 translate 0.1 } finish { F } }
plane { z, 0 clipped_by { box { <-2, 0, -1>, <0, 1.5, 1> } }
  pigment { ripples frequency 0.7 phase 0.2
            color_map { [0 rgb <0, 0.5, 0>] [1 rgb 1] }
            scale 0.3 } finish { F } }
plane { z, 0 clipped_by { box { <0, 0, -1>, <2, 1.5, 1> } }
  pigment { waves color_map { [0.2 rgb <0.5, 0, 0.5>] [0.8 rgb 1] }
            scale 0.2 translate <1, 0.5, 0> } finish { F } }
