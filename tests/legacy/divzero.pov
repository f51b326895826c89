// A division by zero (poliana-girl's aug31.pov divides by clock, 0):
// POV-Ray 3.7 warns "Divide by zero." and goes on with +inf whatever the
// sign of the dividend (measured: 5/0, -5/0 and 0/0 all print "inf",
// -5/0 < 0 is false); a box corner at infinity makes a box that reaches
// infinity, rotated here as aug31's are.
// expect: warning: Divide by zero.
// expect: divzero: inf inf inf -inf -nan 0 1 0.000000
#version 3.7;
global_settings { assumed_gamma 1 }
#declare A = 5/0;
#declare B = -5/0;
#declare C = 0/0;
#debug concat("divzero: ", str(A,0,3), " ", str(B,0,3), " ", str(C,0,3), " ",
  str(-A,0,3), " ", str(A-A,0,3), " ", str((B<0),0,0), " ",
  str((A>1e308),0,0), " ", str(1/A,0,6), "\n")
camera { location <0,2,-6> look_at <0,0,0> }
light_source { <5,10,-10> rgb 1 }
plane { y, -1 pigment { checker rgb 0.2 rgb 0.8 } }
box { <-1,-1,0>, <0,0,3/0> pigment { rgb <1,0.4,0.2> } rotate y*20 }
box { <0.5,-1,2>, <1.5,0,2/0> pigment { rgb <0.2,0.5,1> } rotate y*-15 }
