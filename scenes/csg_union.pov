// csg_union.pov - unions, declared objects and texture inheritance.
//
// A union's texture goes to the parts that have none of their own; a
// part's own texture wins (POV-Ray reference, "Union" and "Textures").
// Declared objects are reused with object { Name } and transformed;
// unions nest.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -9> look_at <0, 1, 0> angle 50 }
light_source { <-6, 10, -7>, rgb 1 }
light_source { <6, 5, -5>, rgb 0.3 }
background { rgb <0.25, 0.3, 0.35> }
plane { y, 0 pigment { rgb <0.75, 0.72, 0.68> } }

#declare Red_Plastic = texture {
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.05 diffuse 0.7 phong 0.7 phong_size 40 }
}
#declare Pale = texture { pigment { rgb <0.9, 0.9, 0.8> } }

// A snowman-like stack: the union's texture on two balls, the hat its own.
#declare Figure = union {
  sphere { <0, 0.6, 0>, 0.6 }
  sphere { <0, 1.5, 0>, 0.4 }
  cylinder { <0, 1.8, 0>, <0, 2.3, 0>, 0.25 texture { Red_Plastic } }
  texture { Pale }
}
object { Figure translate <-2.5, 0, 0> }
object { Figure scale 0.7 rotate y * 20 translate <-1, 0, 1.5> }

// Nested unions: a table of a box top and four legs.
#declare Leg = cylinder { <0, 0, 0>, <0, 1, 0>, 0.08 }
#declare Table = union {
  box { <-1, 1, -0.6>, <1, 1.1, 0.6> }
  union {
    object { Leg translate <-0.9, 0, -0.5> }
    object { Leg translate <0.9, 0, -0.5> }
    object { Leg translate <-0.9, 0, 0.5> }
    object { Leg translate <0.9, 0, 0.5> }
    pigment { rgb <0.3, 0.2, 0.1> }
  }
  pigment { rgb <0.6, 0.4, 0.2> }
}
object { Table translate <1.8, 0, 0.5> }
sphere { <1.8, 1.35, 0.5>, 0.25 texture { Red_Plastic } }
