// blob.pov - blobs (POV-Ray reference, "Blob"): the manual's three
// spheres, a chain of cylinders with a negative sphere denting it, a
// component scaled into an ellipsoid and the obsolete component syntax.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -11> look_at <0, 1, 0> angle 50 }
light_source { <-6, 12, -8>, rgb 1 }
light_source { <7, 5, -6>, rgb 0.3 }
background { rgb <0.6, 0.7, 0.85> }

#declare F = finish { ambient 0.1 diffuse 0.75 phong 0.4 }

plane { y, 0 pigment { rgb <0.55, 0.6, 0.5> } finish { F } }
blob { threshold 0.6
  sphere { <.75, 0, 0>, 1, 1 }
  sphere { <-.375, .64952, 0>, 1, 1 }
  sphere { <-.375, -.64952, 0>, 1, 1 }
  scale 0.8 rotate x * 90 translate <-3, 0.8, 0>
  pigment { rgb <0.9, 0.3, 0.2> } finish { F } }
blob { threshold 0.5
  cylinder { <-1, 0, 0>, <1, 0, 0>, 0.6, 1 }
  cylinder { <1, 0, 0>, <1, 1.5, 0>, 0.6, strength 1 }
  sphere { <0, 0.4, -0.3>, 0.5, -1.5 }
  translate <0.2, 0.6, 0> pigment { rgb <0.2, 0.5, 0.9> } finish { F } }
blob { threshold 0.4
  sphere { 0, 1, 1 scale <1.5, 0.6, 0.8> rotate y * 30 }
  component 1, 0.8, <0.6, 0.6, 0>
  hierarchy off sturm
  translate <3, 0.6, -0.5> pigment { rgb <0.3, 0.8, 0.4> } finish { F } }
