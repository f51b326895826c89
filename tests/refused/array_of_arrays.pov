// An array of arrays indexed twice, "Coordinates[PointIndex][DigitIndex]"
// (watchduck's permutohedron scenes): POV-Ray 3.7 reads it.
#version 3.7;
global_settings { assumed_gamma 1 }
#declare C = array[2] {array[3] {1, 2, 3}, array[3] {4, 5, 6}};
#declare D = C[1][2] + 1;
#declare E = C[0];
// expect-debug: D=7 C01=2 E2=3 dims=1,3
#debug concat("D=", str(D, 0, 0), " C01=", str(C[0][1], 0, 0), " E2=",
              str(E[2], 0, 0), " dims=", str(dimensions(C), 0, 0), ",",
              str(dimension_size(C[1], 1), 0, 0), "\n")
sphere { 0, C[1][0] / 4 pigment { rgb 1 } }
camera { location <0, 0, -5> look_at 0 }
light_source { <0, 10, -10> rgb 1 }
