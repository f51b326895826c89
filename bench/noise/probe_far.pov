// probe_far.pov - f_noise3d far from the origin, where POV-Ray's lattice
// cell leaves the 32-bit range (lib/core/noise.c, "Far out"):
//   povray +Ibench/noise/probe_far.pov -F +W8 +H8 -D 2>&1 | grep '^far'
// prints "far X Y Z value" lines; tests/test_noise.c (noise_far) holds
// the values povray 3.7.0.10 printed.
#include "functions.inc"
#declare P = array[12][3] {
  {2.1e9, 0.3, 0.7}, {2147483000, 0.5, 0.7}, {2147483647.5, 1.2, 0.7},
  {2147483648.0, 0.3, 0.7}, {2147483648.0, 0.75, 0.7}, {3e9, 0.3, 0.7},
  {3e9, 1.0, 0.7}, {-3e9, 1.0, 0.7}, {-2147483648.5, 0.75, 0.7},
  {-2147483648.5, 1.1, 0.7}, {0.5, 0.7, 3e9}, {1e12, 0.75, 0.7} }
#for (I, 0, 11)
  #debug concat("far ", str(P[I][0], 0, 1), " ", str(P[I][1], 0, 2), " ",
    str(P[I][2], 0, 2), " ", str(f_noise3d(P[I][0], P[I][1], P[I][2]), 0, 12), "\n")
#end
