// interior_path.pov - which interior a ray goes into or out of where it
// meets a surface (tests/test_interior_path.sh): a clipped glass
// half-sphere open at its back, so that a ray goes into it through its
// surface and out through the cut where no surface is, and a second
// sphere behind it; the cases join the two in several ways.
#version 3.7;
#ifndef (Case) #declare Case = 1; #end
global_settings { assumed_gamma 1 max_trace_level 10 }
camera { location <0.3, 0.2, -6> look_at <0, 0, 0> angle 24 }
plane {
  z, 12
  pigment { checker rgb 1 rgb <0.1, 0.3, 0.8> scale 0.5 }
  finish { ambient 1 diffuse 0 }
}
#declare G = texture { pigment { rgbf 1 } finish { ambient 0 diffuse 0 } }
#declare Front = sphere { 0, 1 clipped_by { plane { z, 0 } } }
#declare Back = sphere { <0, 0, 2.5>, 1 }
#switch (Case)
#case (1) // two objects, two interiors
  object { Front texture { G } interior { ior 1.5 } }
  object { Back texture { G } interior { ior 1.2 } }
#break
#case (2) // one merge, one interior: out through the cut, out again
  merge {
    object { Front } object { Back }
    texture { G } interior { ior 1.5 }
  }
#break
#case (3) // one union, one interior: as the merge
  union {
    object { Front } object { Back }
    texture { G } interior { ior 1.5 }
  }
#break
#case (4) // two objects with interior { I } of one declared I
  #declare I = interior { ior 1.5 }
  object { Front texture { G } interior { I } }
  object { Back texture { G } interior { I } }
#break
#case (5) // a union whose parts have interiors of their own
  union {
    object { Front interior { ior 1.5 } }
    object { Back interior { ior 1.5 } }
    texture { G }
  }
#break
#case (6) // a merge whose parts have interiors of their own
  merge {
    object { Front interior { ior 1.5 } }
    object { Back interior { ior 1.5 } }
    texture { G }
  }
#break
#case (7) // a union of two overlapping closed spheres, one interior
  union {
    sphere { <-0.3, 0, 0>, 1 }
    sphere { <0.4, 0, 0.8>, 1 }
    texture { G } interior { ior 1.5 }
  }
#break
#case (8) // two copies of one declared object, overlapping
  #declare S = sphere { 0, 1 texture { G } interior { ior 1.5 } }
  object { S translate <-0.3, 0, 0> }
  object { S translate <0.4, 0, 0.8> }
#break
#end
