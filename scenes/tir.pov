// tir.pov - total internal reflection.
//
// Light inside a dense medium that meets the surface beyond the critical
// angle (asin(1/ior): 30 degrees for ior 2, 24.6 for 2.4) is reflected
// back entirely (Snell's law; POV-Ray reference, "Interior", ior).  A
// thick glass block of ior 2 stands before coloured stripes: seen
// through its front face, its side faces turn into mirrors showing the
// stripes again, where plain glass would show the floor.  A sphere of
// ior 2.4 shows the inverted stripes and, near its rim, the ring of rays
// that bounce inside it.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 12 }

camera { location <0, 2.2, -6> look_at <0, 0.8, 0> angle 50 }
light_source { <-5, 9, -6>, rgb 1 }
background { rgb <0.15, 0.15, 0.2> }

plane { y, 0 pigment { rgb <0.75, 0.75, 0.7> } }
box { <-5, 0, 2.5>, <-3, 3, 2.7> pigment { rgb <0.9, 0.2, 0.1> } }
box { <-3, 0, 2.5>, <-1, 3, 2.7> pigment { rgb <0.95, 0.8, 0.1> } }
box { <-1, 0, 2.5>, <1, 3, 2.7> pigment { rgb <0.2, 0.7, 0.2> } }
box { <1, 0, 2.5>, <3, 3, 2.7> pigment { rgb <0.1, 0.4, 0.9> } }
box { <3, 0, 2.5>, <5, 3, 2.7> pigment { rgb <0.6, 0.2, 0.7> } }

// Transparent objects float 0.01 above the floor: a face lying in the
// floor's plane would make the nearer of two equal hits a matter of
// rounding, in any renderer.
box {
  <-0.8, 0.01, -0.8>, <0.8, 1.8, 0.8>
  pigment { rgbf <0.97, 1, 1, 0.97> }
  finish { ambient 0 diffuse 0 }
  interior { ior 2.0 }
  rotate y * 25
  translate <-1.4, 0, 0>
}
sphere {
  <1.6, 0.9, 0>, 0.9
  pigment { rgbt <1, 1, 1, 0.95> }
  finish { ambient 0 diffuse 0 }
  interior { ior 2.4 }
}
