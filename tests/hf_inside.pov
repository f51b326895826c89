// hf_inside.pov - a clear height field of ior 1.5 turned upside down
// (scale y -2): a camera ray enters its solid through the open side,
// where no surface is, and first meets the surface from inside.
// povray 3.7 refracts it into the glass there (its statistics count
// the crossing as refracted, not transmitted); NEG=0 is the same slab
// the right way up.  tests/test_hf_inside.sh.
#version 3.7;
global_settings { assumed_gamma 1 }
#ifndef(NEG) #declare NEG=1; #end
camera { location <0, 4, -5> look_at <0, -1, 0> angle 50 }
light_source { <2, 10, -3> rgb 1 }
plane { y, -3
  pigment { checker rgb 1 rgb <0.2, 0.3, 0.8> scale 0.5 }
  finish { ambient 0.3 }
}
height_field {
  function 8, 8 { 0.5 }
  translate <-0.5, 0, -0.5>
  #if (NEG) scale <6, -2, 6> #else scale <6, 2, 6> translate <0, -1, 0> #end
  pigment { rgbf 1 }
  finish { ambient 0 diffuse 0 }
  interior { ior 1.5 }
}
