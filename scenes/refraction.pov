// refraction.pov - transparent objects with an index of refraction.
//
// A glass sphere (ior 1.5) and a water-like cylinder (ior 1.33) stand in
// front of coloured posts; the posts appear inverted and magnified
// through the sphere.  Transmission comes from the pigment's filter and
// transmit channels, bending from interior { ior } (POV-Ray reference,
// "Interior" and "Filter and transmit").
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }

camera { location <0, 1.5, -6> look_at <0, 1, 0> angle 50 }
light_source { <3, 8, -6>, rgb 1 }
background { rgb <0.9, 0.9, 0.95> }

plane { y, 0 pigment { rgb <0.6, 0.6, 0.6> } }

#declare Post = cylinder { <0, 0, 0>, <0, 2.5, 0>, 0.25 }
object { Post pigment { rgb <0.9, 0.1, 0.1> } translate <-1.5, 0, 3> }
object { Post pigment { rgb <0.1, 0.8, 0.1> } translate <-0.5, 0, 3> }
object { Post pigment { rgb <0.1, 0.2, 0.9> } translate <0.5, 0, 3> }
object { Post pigment { rgb <0.9, 0.8, 0.1> } translate <1.5, 0, 3> }

sphere {
  <-0.8, 1, 0>, 0.9
  pigment { rgbf <1, 1, 1, 0.95> }
  finish { ambient 0 diffuse 0 specular 0.6 roughness 0.005 }
  interior { ior 1.5 }
}
// Transparent objects float 0.01 above the floor: a face lying in the
// floor's plane would make the nearer of two equal hits a matter of
// rounding, in any renderer.
cylinder {
  <1.3, 0.01, 0>, <1.3, 1.8, 0>, 0.5
  pigment { rgbt <0.8, 0.95, 1, 0.9> }
  finish { ambient 0 diffuse 0.1 }
  interior { ior 1.33 }
}
