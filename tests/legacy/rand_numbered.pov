// rand() given a float: POV-Ray numbers the streams seed() makes 0, 1, ...
// and rand(n) takes stream n (rand.inc's VRand(1) in poliana-girl's
// glasstestreal.pov).  Values measured with povray 3.7's #debug.
// expect: rand_numbered: 0.063883 0.953933 0.713254 0.610466 0.166852
#version 3.7;
global_settings { assumed_gamma 1 }
#declare S = seed(12);
#declare T = seed(7);
#declare A = rand(S);
#declare B = rand(T);
#declare C = rand(0);
#declare D = rand(1);
#declare E = rand(1.5);
#debug concat("rand_numbered: ", str(A,0,6), " ", str(B,0,6), " ",
  str(C,0,6), " ", str(D,0,6), " ", str(E,0,6), "\n")
camera { location <0,0,-6> look_at 0 }
light_source { <5,10,-10> rgb 1 }
#for (I, 0, 11)
  sphere { <rand(1)*4-2, rand(0)*3-1.5, rand(1)>, 0.4
    pigment { rgb <rand(0), rand(1), 0.5> } }
#end
