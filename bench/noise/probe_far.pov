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
// Turbulence far out: its vector noise follows the same rule (cells
// past the 32-bit range taken as -2^31, so the displacement is huge):
//   povray +Ibench/noise/probe_far.pov -F +W8 +H8 -D 2>&1 | grep '^dfar'
// prints "dfar CASE X Y Z value" lines for bumps with turbulence 1,
// lambda 50 (six octaves reach 50^5 p: poliana-girl's aug4.pov) and
// bumps with warp { turbulence 0.001 octaves 1 }; tests/test_noise.c
// (noise_dfar) holds the values povray 3.7.0.10 printed.
#declare T50 = function { pattern { bumps turbulence 1 lambda 50 } }
#declare T1 = function { pattern { bumps warp { turbulence 0.001 octaves 1 } } }
#declare Q = array[12][3] {
  {0.37, -0.2, -3}, {2.3, 1.1, -0.7}, {-4.1, 2.2, 0.9}, {6.5, -1.3, 2.2},
  {-7.9, 0.4, -5.5}, {9.6, 3.3, 4.1}, {2.1e9, 0.5, 0.7}, {3e9, 0.3, 0.7},
  {-3e9, 5.2, 3.1}, {0.3, 0.2, 3e9}, {-2147483649.5, 0.5, 0.7},
  {2147483648.3, 0.5, 0.7} }
#for (I, 0, 11)
  #debug concat("dfar 50 ", str(Q[I][0], 0, 2), " ", str(Q[I][1], 0, 2), " ",
    str(Q[I][2], 0, 2), " ", str(T50(Q[I][0], Q[I][1], Q[I][2]), 0, 12), "\n")
  #debug concat("dfar 1 ", str(Q[I][0], 0, 2), " ", str(Q[I][1], 0, 2), " ",
    str(Q[I][2], 0, 2), " ", str(T1(Q[I][0], Q[I][1], Q[I][2]), 0, 12), "\n")
#end
