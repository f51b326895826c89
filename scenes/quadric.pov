// quadric.pov - quadric surfaces (POV-Ray reference, "Quadric") and the
// shapes.inc objects built from them, made finite by intersections and
// clipped_by.  An infinite cylinder, a paraboloid, a cone and a
// hyperboloid, each cut to a box; an ellipsoid written as a quadric; a
// torus written as a quartic ("Poly, Cubic and Quartic").
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "shapes.inc"

camera { location <0, 5, -10> look_at <0, 1, 0> angle 50 }
light_source { <-6, 10, -7>, rgb 1 }
light_source { <6, 5, -5>, rgb 0.3 }
background { rgb <0.25, 0.3, 0.35> }
plane { y, 0 pigment { rgb <0.75, 0.72, 0.68> } }

#declare Shiny = finish { phong 0.6 phong_size 60 }

// shapes.inc: Cylinder_Y is x^2 + z^2 = 1, cut by a box.
intersection {
  object { Cylinder_Y scale <0.6, 1, 0.6> }
  box { <-1, 0, -1>, <1, 2, 1> }
  pigment { rgb <0.85, 0.2, 0.1> } finish { Shiny }
  translate <-3, 0, 0>
}
// A paraboloid, open at the top: y = x^2 + z^2.
quadric {
  <1, 0, 1>, <0, 0, 0>, <0, -1, 0>, 0
  clipped_by { plane { y, 2 } }
  pigment { rgb <0.3, 0.8, 0.4> } finish { Shiny }
  translate <-1, 0, 1>
}
// shapes.inc: Cone_Y, a double cone, cut to its upper nappe.
intersection {
  object { Cone_Y scale <0.5, 1, 0.5> }
  box { <-1, 0, -1>, <1, 2, 1> }
  pigment { rgb <0.2, 0.5, 0.9> } finish { Shiny }
  translate <1, 0, 1>
}
// A hyperboloid of one sheet: x^2 - y^2 + z^2 = 0.25.
intersection {
  quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, -0.25 }
  box { <-2, -1, -2>, <2, 1, 2> }
  pigment { rgb <0.9, 0.8, 0.3> } finish { Shiny }
  translate <3, 1, 0>
}
// An ellipsoid: x^2 / 1.2^2 + y^2 / 0.5^2 + z^2 / 0.8^2 = 1.
quadric {
  <0.6944444, 4, 1.5625>, <0, 0, 0>, <0, 0, 0>, -1
  pigment { rgb <0.7, 0.4, 0.8> } finish { Shiny }
  translate <0, 0.5, -2>
}
// (x^2 + y^2 + z^2 + 3)^2 - 16 (x^2 + z^2): a torus of radii 2 and 1.
quartic {
  <1, 0, 0, 0, 2, 0, 0, 2, 0, -10,
   0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
   1, 0, 0, 2, 0, 6, 0, 0, 0, 0,
   1, 0, -10, 0, 9>
  sturm
  pigment { rgb <0.95, 0.6, 0.3> } finish { Shiny }
  scale 0.3 rotate x * -30 translate <2.2, 0.4, -2.6>
}
