// text.pov - the text object with POV-Ray's stock fonts: extruded
// glyphs (caps and side walls), kerning and advance widths, the offset
// vector, a font chosen by 'internal', and text seen at an angle.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -6> look_at <0, 0.5, 0> angle 55 }
light_source { <-3, 6, -8>, rgb 1 }
light_source { <4, 2, -4>, rgb 0.3 }
background { rgb <0.15, 0.15, 0.2> }
plane { y, -0.5 pigment { checker rgb 0.8, rgb 0.5 scale 0.5 } }

text { ttf "timrom.ttf" "zRcube AV" 0.4, 0
       pigment { rgb <0.9, 0.4, 0.1> } finish { phong 0.5 }
       scale 1.1 translate <-2.6, 0.9, 0> }
text { ttf "cyrvetic.ttf" "Mesh2 & Text" 0.2, <0.05, 0, 0>
       pigment { rgb <0.2, 0.6, 0.9> }
       rotate y * 25 translate <-2.4, -0.3, -0.8> }
text { internal 3 "crystal" 1, 0
       pigment { rgb <0.6, 0.9, 0.3> }
       rotate <-60, 0, 0> translate <0.6, -0.49, -2.2> }
text { ttf "povlogo.ttf" "P" 0.3, 0
       pigment { rgb <0.9, 0.9, 0.9> }
       translate <2.2, 0.9, 0.5> }
