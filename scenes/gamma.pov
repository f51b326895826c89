// gamma.pov - a legacy scene in a gamma 2.2 working space.
//
// With assumed_gamma 2.2 the colours written in the scene are taken as
// gamma-encoded: the renderer computes in linear light from value ^ 2.2
// and the file shows the colours nearly as written (POV-Ray reference,
// "Gamma Handling" and global_settings assumed_gamma).  Three grey
// panels of 0.25, 0.5 and 0.75 and a colour ramp make the curve visible;
// ambient_light and adc_bailout are set as a 3.6-era scene would.
#version 3.7;
global_settings {
  assumed_gamma 2.2
  ambient_light rgb 1
  adc_bailout 0.01
  max_trace_level 5
}

camera { location <0, 0, -6> look_at <0, 0, 0> }
light_source { <0, 0, -20>, rgb 1 }
background { rgb <0.3, 0.35, 0.5> }

#declare Panel = box { <-0.9, -0.9, 0>, <0.9, 0.9, 0.1> }
#declare Flat = finish { ambient 0.2 diffuse 0.8 }
object { Panel pigment { rgb 0.25 } finish { Flat } translate <-2, 1, 0> }
object { Panel pigment { rgb 0.5 } finish { Flat } translate <0, 1, 0> }
object { Panel pigment { rgb 0.75 } finish { Flat } translate <2, 1, 0> }
sphere { <-2, -1.1, 0>, 0.8 pigment { rgb <0.8, 0.2, 0.1> }
         finish { Flat phong 0.5 } }
sphere { <0, -1.1, 0>, 0.8 pigment { rgb <0.2, 0.7, 0.2> }
         finish { Flat phong 0.5 } }
sphere { <2, -1.1, 0>, 0.8 pigment { rgb <0.2, 0.3, 0.9> }
         finish { Flat phong 0.5 } }
