// tests/csg_area_shadow.pov - soft shadows of CSG objects
// (tests/test_csg_area_shadow.sh): an area light over a floor, casting
// the shadows of a difference (a tube cut by a box, as the corpus'
// truchet tiles) and of a merge.  The shadow
// cache keeps a whole CSG object as the last blocker of the light
// (lib/trace/shade.c): its penumbra must stay povray's.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -4> look_at <0, 0, 0.3> angle 50 }
light_source { <-3, 3, 2>, rgb 1 area_light <1.5, 0, 0>, <0, 0, 1.5>, 4, 4 }
plane { y, 0 pigment { rgb 0.8 } finish { ambient 0.1 diffuse 0.9 } }
intersection {
  difference {
    cylinder { <0, -50, 0>, <0, 1.2, 0>, 0.8 }
    cylinder { <0, -51, 0>, <0, 1.3, 0>, 0.6 }
  }
  box { <-1, 0.2, -1>, <0.9, 1.0, 0.3> }
  translate <-0.8, 0, 0.2>
  pigment { rgb <0.9, 0.5, 0.2> }
}
merge {
  sphere { <1.1, 0.9, 0.4>, 0.5 }
  box { <0.7, 0.1, -0.2>, <1.5, 0.6, 0.9> }
  pigment { rgb <0.2, 0.4, 0.9> }
}
