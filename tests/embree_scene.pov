// embree_scene.pov - meshes as tests/embree.sh renders them with both
// backends: a flat-shaded terrain of 2 x 30 x 30 triangles (edges in
// every pixel row, shadows cast by the terrain onto itself), a closed
// smooth mesh with an inside_vector cut by CSG and placed twice (a
// transform on the shared mesh), and a mirror sphere that sees them.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> look_at <0, 0.3, 0> angle 55 }
light_source { <-6, 4, -2>, rgb 1 }
light_source { <5, 9, -6>, rgb 0.5 }
background { rgb <0.3, 0.35, 0.45> }
#declare K = 30;
#macro H(I, J) <I / K * 10 - 5, 0.6 * sin(I * 0.61) * cos(J * 0.47) +
                0.25 * sin(I * J * 0.05), J / K * 10 - 5> #end
mesh {
  #declare J = 0;
  #while (J < K)
    #declare I = 0;
    #while (I < K)
      triangle { H(I, J), H(I + 1, J), H(I + 1, J + 1) }
      triangle { H(I, J), H(I + 1, J + 1), H(I, J + 1) }
      #declare I = I + 1;
    #end
    #declare J = J + 1;
  #end
  pigment { rgb <0.7, 0.6, 0.4> }
}
// A closed octahedron-like bulb: smooth triangles around the y axis.
#declare N = 16;
#macro P(A, B) <cos(2 * pi * A / N) * sin(pi * B / 8),
                cos(pi * B / 8), sin(2 * pi * A / N) * sin(pi * B / 8)> #end
#declare Bulb = mesh {
  #declare A = 0;
  #while (A < N)
    #declare B = 0;
    #while (B < 8)
      smooth_triangle { P(A, B), P(A, B), P(A + 1, B), P(A + 1, B),
                        P(A + 1, B + 1), P(A + 1, B + 1) }
      smooth_triangle { P(A, B), P(A, B), P(A + 1, B + 1),
                        P(A + 1, B + 1), P(A, B + 1), P(A, B + 1) }
      #declare B = B + 1;
    #end
    #declare A = A + 1;
  #end
  inside_vector y
}
difference {
  object { Bulb }
  box { <-2, 0.3, -2>, <2, 2, 2> }
  pigment { rgb <0.2, 0.5, 0.9> }
  translate <-2, 1.6, 0>
}
object { Bulb scale <1, 0.7, 1> rotate <20, 30, 0> translate <2, 1.5, 1>
         pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
sphere { <0, 2.2, 2.5>, 1 pigment { rgb 0.1 } finish { reflection 0.8 } }
