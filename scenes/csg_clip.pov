// csg_clip.pov - clipped_by on every kind of object.
//
// "Clipped_By": only the part of the object inside the clipping object
// is seen and the clipping object's surface is not added, so a clipped
// solid is open.  Here a union (two rings of tori, as in an arcade), a
// merge, an intersection, a difference and a single sphere are each cut
// by a box or an inverted plane; the union's clip also moves with a
// transform written after it, and a part of the union keeps a clip of
// its own (the two clips both apply).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -10> look_at <0, 1, 0> angle 55 }
light_source { <-6, 10, -8>, rgb 1 }
light_source { <6, 6, -6>, rgb 0.35 }
background { rgb <0.25, 0.3, 0.35> }
plane { y, 0 pigment { rgb <0.75, 0.72, 0.68> } }

// A union of two rings and a ball, cut to the upper half; the ball keeps
// only its front by its own clip as well.
union {
  torus { 1, 0.2 rotate x * 90 }
  torus { 1, 0.2 rotate x * 90 translate z * 1.2 }
  sphere { 0, 0.5 clipped_by { plane { z, 0 } } }
  clipped_by { plane { y, 0 inverse } }
  pigment { rgb <0.9, 0.85, 0.6> }
  translate <-3, 0.8, 0>
}

// A merge of two spheres, its top sliced off by a box.
merge {
  sphere { <-0.4, 0, 0>, 0.7 }
  sphere { <0.4, 0, 0>, 0.7 }
  clipped_by { box { <-2, -1, -2>, <2, 0.3, 2> } }
  pigment { rgb <0.3, 0.6, 0.9> }
  translate <0, 0.7, -1>
}

// An intersection (a lens) and a difference (a cup), cut by planes.
intersection {
  sphere { <0, 0, -0.5>, 1 }
  sphere { <0, 0, 0.5>, 1 }
  clipped_by { plane { x, 0.2 } }
  pigment { rgb <0.85, 0.3, 0.25> }
  rotate y * 30
  translate <2.8, 1, 0>
}
difference {
  box { -0.7, 0.7 }
  sphere { 0, 0.85 }
  clipped_by { plane { -z, 0.3 } }
  pigment { rgb <0.4, 0.8, 0.4> }
  rotate y * -25
  translate <1.2, 0.7, 2>
}

// A single sphere, its front cut away: the inside shows.
sphere {
  0, 0.8
  clipped_by { plane { z, -0.2 inverse } }
  pigment { rgb <0.8, 0.6, 0.9> }
  translate <-1.2, 0.8, 2.2>
}
