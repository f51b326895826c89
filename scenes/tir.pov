// tir.pov - total internal reflection.
//
// Light inside a dense medium that meets the surface beyond the critical
// angle (asin(1/ior), 30 degrees for ior 2) is reflected back entirely
// (Snell's law; POV-Ray reference, "Interior", ior).  A thick slab of
// ior 2 seen from a grazing angle shows a mirror-like band where the
// rays that entered its top face hit its far side, and a dense sphere
// shows the bright internal ring near its rim.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 12 }

camera { location <0, 3, -6> look_at <0, 0.6, 0> angle 45 }
light_source { <-5, 9, -4>, rgb 1 }
background { rgb <0.15, 0.15, 0.2> }

plane { y, 0 pigment { rgb <0.3, 0.5, 0.3> } }
box { <-4, 0, 3>, <4, 2.5, 3.2> pigment { rgb <0.9, 0.5, 0.1> } }

box {
  <-1, 0, -1>, <1, 1.2, 1>
  pigment { rgbf <0.95, 1, 1, 0.97> }
  finish { ambient 0 diffuse 0 }
  interior { ior 2.0 }
  rotate y * 35
  translate <-1.2, 0, 0>
}
sphere {
  <1.6, 0.9, 0>, 0.9
  pigment { rgbt <1, 1, 1, 0.95> }
  finish { ambient 0 diffuse 0 }
  interior { ior 2.4 }
}
