// flat_interior.pov - a clear cube of twelve triangles, a union with
// interior { ior 1.5 }: povray 3.7 refracts it as a solid of glass
// (tests/test_flat_interior.sh), though a triangle has no inside.
// Declare=F=1 gives the interior an exponential fade (case 2).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <1.5, 2, -4> look_at <0, 0, 0> angle 40 }
light_source { <3, 10, -6> rgb 1 }
plane { z, 3
  pigment { checker rgb 1 rgb <0.2, 0.3, 0.8> scale 0.4 }
  finish { ambient 1 diffuse 0 }
}
#declare P = array[8] { <-1,-1,-1>, <1,-1,-1>, <1,1,-1>, <-1,1,-1>,
                        <-1,-1,1>, <1,-1,1>, <1,1,1>, <-1,1,1> }
#macro Quad(A, B, C, D)
  triangle { P[A], P[B], P[C] }
  triangle { P[A], P[C], P[D] }
#end
union {
  Quad(0, 1, 2, 3) Quad(4, 5, 6, 7) Quad(0, 1, 5, 4)
  Quad(3, 2, 6, 7) Quad(0, 3, 7, 4) Quad(1, 2, 6, 5)
  pigment { rgbf 1 }
  finish { ambient 0 diffuse 0 }
  interior { ior 1.5 #ifdef (F) fade_distance 1 fade_power 1001 #end }
}
