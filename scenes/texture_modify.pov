// texture_modify.pov - pigment { }, normal { } and finish { } without an
// identifier modify the current ones ("Pigment", "Normal", "Finish"):
// those of the texture identifier they follow, or those #default set.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2.5, -7> look_at <0, 0.8, 0> angle 50 }
light_source { <5, 10, -10> rgb 1 }
#declare T = texture {
  pigment { checker rgb <1, 0.2, 0.1> rgb <0.1, 0.3, 1> scale 0.5 }
  finish { phong 0.8 diffuse 0.5 }
}
#default {
  normal { gradient x, 0.8 scale 0.25 }
  finish { ambient 0.3 }
}
// quick_color alone: the checker of T stays.
sphere { <-1.6, 1, 0>, 1 texture { T pigment { quick_color rgb 1 } } }
// The checker scaled, T's phong kept under a new diffuse.
sphere { <1.6, 1, 0>, 1 texture { T pigment { scale 2 } finish { diffuse 0.9 } } }
// The default normal, turned; the default ambient.
plane { y, 0 pigment { rgb 0.8 } normal { rotate y * 45 } }
