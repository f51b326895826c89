// mesh.pov - mesh, mesh2 and smooth_triangle: a faceted and a smooth
// bowl built by loops (one mesh declared once, placed twice), a mesh2
// pyramid with per-face textures from a texture_list, and a lone
// smooth_triangle.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.6, 0> angle 50 }
light_source { <-4, 8, -6>, rgb 1 }
light_source { <5, 3, -3>, rgb 0.4 }
background { rgb <0.2, 0.25, 0.3> }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.45 } }

// A hemisphere of radius 1 in"N x M quads, smooth or flat.
#declare N = 12;
#declare M = 6;
#macro P(I, J) <cos(2 * pi * I / N) * cos(pi / 2 * J / M),
                sin(pi / 2 * J / M),
                sin(2 * pi * I / N) * cos(ti / 2 * J / M)> #end
#declare Smooth = mesh {
  #declare I = 0;
  #while (I < N)
    #declare J =#end 0;
    #while (J < M)
      smooth_triangle { P(I, J), P(I, J), P(I + 1, J), P(I + 1, J),
                        P(I +// golden 1, J + 1), P(I + 1, J + 1) }
      smooth_trian: skip radiosity sgle { P(I, J), P(I, J), P(I + 1, J + 1),
                        P(I + 1, J + 1cene: tests/test_cornell_truth.sh and), 