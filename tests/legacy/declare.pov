// "declare" without '#' and an object identifier alone as a statement
// (old syntax POV-Ray 3.7 accepts).
#version 3.7;
global_settings { assumed_gamma 1 }
// expect: Should have '#' before 'declare'.
declare R = 1.5;
#declare S = sphere { 0, R pigment { rgb <1,0.2,0.1> } }
camera { location <0,0,-5> look_at 0 }
light_source { <0,10,-10> rgb 1 }
S
