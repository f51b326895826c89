// hf_glass.pov - an upside-down smooth height field of glass, as the
// board of stock advanced/glasschess.pov: rays reflected or refracted at
// its steps (walls one sample wide, whose smooth normal is nearly
// vertical) leave the surface where they met it (lib/trace/shade.c
// ray_start; tests/test_hf_glass.sh).  Declare=K=1..2 picks the case.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 15 }
camera { location <5.5, 1, -7> look_at <0, 1, 0> angle 60 }
light_source { <500, 50, -5> rgb 1 }
sky_sphere { pigment { gradient y
  color_map { [0 rgb <0.8, 0.5, 0.5>] [1 rgb <0.3, 0.3, 1>] } } }
#ifndef (K) #declare K = 1; #end
#switch (K)
#case (1) // clear: filter 1, refraction only
  #declare T = texture { pigment { rgbf <0.98, 1, 0.98, 1> }
                         finish { ambient 0 diffuse 0 } }
#break
#case (2) // a mirror: reflection only
  #declare T = texture { pigment { rgb 0 }
                         finish { ambient 0 diffuse 0 reflection 1 } }
#break
#end
height_field {
  function 256, 256 { pigment { checker color rgb 1 color rgb 0 scale 1/4 } }
  smooth
  translate <-0.5, 0, -0.5>
  scale <12, -0.5, 12>
  texture { T }
  interior { ior 1.2 }
}
box { <-6, -0.2, -6>, <6, -0.501, 6>
  pigment { checker color rgb 1 color rgb <0, 0, 1> scale 1.5 } }
