// reflection.pov - mirror reflection: finish { reflection }.
//
// Two mirror spheres face each other over a two-tone floor, so rays
// bounce several times (POV-Ray reference, "Reflection" in the finish
// section).  A coloured mirror checks that reflection is tinted only by
// the reflection amount, not by the pigment, in POV-Ray's model.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }

#declare Red = rgb <0.8, 0.15, 0.1>;
#declare Blue = rgb <0.1, 0.25, 0.8>;

camera { location <0, 2.2, -7> look_at <0, 1, 0> }
light_source { <-4, 8, -6>, rgb 1 }
background { rgb <0.2, 0.25, 0.35> }

plane { y, 0 pigment { rgb <0.7, 0.7, 0.65> } finish { diffuse 0.8 } }
box { <-6, 0, 4>, <0, 3, 4.5> pigment { Red } }
box { <0, 0, 4>, <6, 3, 4.5> pigment { Blue } }

sphere {
  <-1.2, 1, 0>, 1
  pigment { rgb 0.9 }
  finish { ambient 0 diffuse 0.1 reflection 0.9 }
}
sphere {
  <1.2, 1, 0>, 1
  pigment { rgb <1, 0.8, 0.3> }
  finish { ambient 0.05 diffuse 0.4 reflection 0.5 }
}
sphere { <0, 0.4, -1.6>, 0.4 pigment { rgb <0.2, 0.8, 0.3> } }
