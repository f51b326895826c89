// An object identifier alone in clipped_by { } (old scenes write it).
#version 3.7;
global_settings { assumed_gamma 1 }
#declare ClipBox = box { <-2,-0.5,-2>, <2,0.5,2> }
camera { location <0,2,-5> look_at 0 }
light_source { <0,10,-10> rgb 1 }
sphere { 0, 1.2 pigment { rgb <1,0.6,0.2> } clipped_by { ClipBox } }
plane { y, -1 pigment { rgb 0.5 } }
