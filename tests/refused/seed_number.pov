// seed(n) is a number, the new stream's place among those made (0, 1,
// ...); a random stream can be computed with (mjhorvath's
// GSprites_Scenery_prototypes.inc: "(Rotate_Y + clock) * City_Seed"), and
// rand(n) draws from stream n.  Measured with povray's #debug.
#version 3.7;
global_settings { assumed_gamma 1 }
#declare A = seed(5);
#declare B = seed(5);
#declare C = B;
#macro M() #local L = seed(1); #debug concat("L=", str(L, 0, 0), "\n") #end
// expect-debug: L=2
// expect-debug: L=3
M() M()
#declare D = seed(9);
#declare X = (1 + clock) * D;
#declare R1 = rand(C);
#declare R2 = rand(1);
// expect-debug: A=0 B=1 C=1 D=4 X=4 R1=0.109953 R2=0.569351
#debug concat("A=", str(A, 0, 0), " B=", str(B, 0, 0), " C=", str(C, 0, 0),
              " D=", str(D, 0, 0), " X=", str(X, 0, 0), " R1=",
              str(R1, 0, 6), " R2=", str(R2, 0, 6), "\n")
sphere { 0, 1 pigment { rgb rand(A) } }
camera { location <0, 0, -5> look_at 0 }
light_source { <0, 10, -10> rgb 1 }
