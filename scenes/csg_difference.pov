// csg_difference.pov - difference, intersection, merge and clipped_by.
//
// POV-Ray reference, "Constructive Solid Geometry": a difference keeps
// the first object's inside minus the others' (the cut faces take the
// cutting objects' textures), an intersection keeps what lies inside
// all, a merge drops the inner surfaces a union keeps (seen through
// glass), and clipped_by keeps only the part of a surface inside the
// clipping objects (here an open hemisphere showing its inside).
// Shadows and refraction pass through the CSG objects.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -9> look_at <0, 0.9, 0> angle 50 }
light_source { <-6, 10, -7>, rgb 1 }
light_source { <6, 5, -5>, rgb 0.3 }
background { rgb <0.25, 0.3, 0.35> }
plane { y, 0 pigment { checker rgb <0.8, 0.78, 0.72>, rgb <0.55, 0.5, 0.45> } }

// A cube with a spherical bite and a drilled hole.
difference {
  box { <-1, 0, -1>, <1, 2, 1> pigment { rgb <0.85, 0.2, 0.1> } }
  sphere { <-1, 2, -1>, 1.1 pigment { rgb <0.95, 0.85, 0.3> } }
  cylinder { <0, 1, -2>, <0, 1, 2>, 0.4 }
  finish { phong 0.5 }
  rotate y * 25
  translate <-2.6, 0, 0.4>
}

// A lens: the intersection of two spheres, as a declared object.
#declare Lens = intersection {
  sphere { <0, 0, -0.7>, 1.2 }
  sphere { <0, 0, 0.7>, 1.2 }
  pigment { rgb <0.2, 0.5, 0.9> }
  finish { specular 0.6 roughness 0.02 }
}
object { Lens rotate x * 90 translate <0, 0.45, -1.2> }

// Merged glass spheres: no inner walls.
merge {
  sphere { <-0.4, 1, 0>, 0.7 }
  sphere { <0.4, 1, 0>, 0.7 }
  pigment { rgbf <0.9, 1, 0.9, 0.85> }
  interior { ior 1.3 }
  translate <0.3, 0, 1.8>
}

// An open hemisphere: the sphere clipped by a plane.
sphere {
  <0, 0, 0>, 1
  clipped_by { plane { y, 0 } }
  pigment { rgb <0.3, 0.8, 0.4> }
  rotate x * -60
  translate <2.6, 1.1, 0.3>
}
