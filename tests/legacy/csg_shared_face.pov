// Faces two CSG children share (thejov's church-window.pov, mjhorvath's
// GSprites walls): POV-Ray 3.7 counts a box's faces and a plane's
// surface as inside, so a shared face stays in an intersection and
// leaves a difference, and of two crossings at one distance an
// intersection shows its later child's, a union its earlier child's.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.25, 0.25, -9> look_at <0, 0, 0> angle 30 }
background { rgb 0 }
#declare F = finish { ambient 1 diffuse 0 }
#declare R = texture { pigment { rgb <1, 0, 0> } finish { F } }
#declare G = texture { pigment { rgb <0, 1, 0> } finish { F } }
#declare B = texture { pigment { rgb <0, 0, 1> } finish { F } }
// Top left: the same box twice, intersected: the later one's colour.
intersection {
  box { <0, 0, 0>, <1, 1, 1> texture { R } }
  box { <0, 0, 0>, <1, 1, 1> texture { G } }
  translate <-1.5, 0.25, 0>
}
// Top right: a box less one that touches its front face: the front face
// goes, the cutter's face stays.
difference {
  box { <0, 0, 0>, <1, 1, 1> texture { G } }
  box { <-1, -1, -1>, <2, 2, 0> texture { B } }
  translate <0.5, 0.25, 0>
}
// Bottom left: the same box twice in a union: the earlier one's colour.
union {
  box { <0, 0, 0>, <1, 1, 1> texture { B } }
  box { <0, 0, 0>, <1, 1, 1> texture { R } }
  translate <-1.5, -1.25, 0>
}
// Bottom right: a box and a plane through its front face: the plane's.
intersection {
  box { <0, 0, 0>, <1, 1, 1> texture { G } }
  plane { -z, 0 texture { R } }
  translate <0.5, -1.25, 0>
}
