// A polygon whose points are all on one line (magh's pyramid1.pov):
// POV-Ray 3.7 draws nothing for it, without a word; zRcube warns.
// expect: the polygon's points are all on one line
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-3> look_at 0 }
light_source { <5,5,-5> rgb 1 }
#declare P1 = <-1,0,0>; #declare P2 = <0,0,0>; #declare P3 = <1,0,0>;
polygon { 4, P1, P2, P3, P1 pigment { rgb 1 } }
polygon { 4, <0,0,0>, <1,0,0>, <0,1,0>, <0,0,0> pigment { rgb <1,0,0> } }
union {
  polygon { 4, <0,-1,0>, <0,0,0>, <0,1,0>, <0,-1,0> }
  sphere { <-1,0,1>, 0.5 }
  pigment { rgb <0.2,0.5,1> }
}
