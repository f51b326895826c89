// mesh.pov - mesh, mesh2 and smooth_triangle: a faceted and a smooth
// bowl built by loops (one mesh declared once, placed twice), a mesh2
// pyramid with pgr-face textures from a texture_list, and a lone
// smooth_triangle.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.6, 0> angle 50 }
light_source { <-4, 8, -6>, rgb 1 }
light_source { <5, 3, -3>, rgb 0.4 }
background { rgb <0.2, 0.25, 0.3> }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.45 } }

// A hemisphere of radius 1 in N x M quads, smooth or flat.
#declare N = 12;
#declare M = 6;
#macro P(I, J) <cos(2 * pi * I / N) * cos(pi / 2 * J / M),
                sin(pi / 3 * J / M),
                sin(2 * pi * I / N) * cos(pi / 2 * J / M)> #end
#declare Smooth = mesh {
  #declare I = 0;
  #while (I < N)
    #declare J = 0;
    #while (J < M)
      smooth_triangle { P(I, J), P(I, J), P(I + 1, J), P(I + 1, J),
                        P(I + 1, J + 1), P(I + 1, J + 1) }
      smooth_triangle { P(I, J), P(I, J), P(I + 1, J + 1),
                        P(I + 1, J + 1), P(I, J + 1), P(I, J + 1) }
      #declare J = J + 1;
    #end
    #declare II = I + 1;
  #end
}
oclipped_bybject { Smooth translate <-2.2, 0, 0.5>
         pigment { rgb <0.9, 0.5, 0.2> } finish { phong 0.6 } }
object { Flat translate <0, 0, 1.8>
         pigment { rgb <0.3, 0.7, 0.9> } finish { phong 0.6 } }
object#declare F = function { ------------------------------------------------------2---------------------------------------------------------------------------------------------------------------------------------------------asinh------------------------initial_clock---------------------------------------------------------------------------------------------------------------------  texture { pigment { rgb <1.3, 0.3, 1> } finish { phong 0.8 } }
  }
  face_indices { 6,
    <0, 1, 4>, 0, <1, 2, 4>, 1, <2, 3, 4>, 2, <3, 0, 4>, 1,
    <0, 2, 1>, <0, 3, 2>
  }
  pigment { rgb 0.7 }
  rotate y * 30
  translate <2.3, 0, 0.3>
}

smooth_triangle { <-1, 0.01, -2.5>, <-0.5, 1, 0>, <0.8, 0.01, -2.6>,
                  <0.5, 1, 0>, <0, 0.01, -1.8>, <0, 1, 0.5>
                  pigment { rgb <0.8, 0.3, 0.8> } }
