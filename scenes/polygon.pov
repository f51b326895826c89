// polygon.pov - polygons (POV-Ray reference, "Polygon"): the manual's
// letter P with its hole, its triangle with three holes and three
// islands, a tilted pentagon given by 3-D points, and their shadows.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -9> look_at <0, 1.5, 0> angle 55 }
light_source { <-5, 9, -9>, rgb 1 }
light_source { <6, 4, -7>, rgb 0.3 }
background { rgb <0.6, 0.7, 0.85> }

#declare F = finish { ambient 0.1 diffuse 0.75 }

plane { y, 0 pigment { rgb <0.55, 0.6, 0.5> } finish { F } }
polygon { 12, <0, 0>, <0, 6>, <4, 6>, <4, 3>, <1, 3>, <1, 0>, <0, 0>,
          <1, 4>, <1, 5>, <3, 5>, <3, 4>, <1, 4>
          scale 0.5 translate <-3.5, 0, 0.5>
          pigment { rgb <0.9, 0.3, 0.2> } finish { F } }
polygon { 28,
  <0, 0> <1, 0> <0, 1> <0, 0>
  <.3, .7> <.4, .7> <.3, .8> <.3, .7>
  <.5, .5> <.6, .5> <.5, .6> <.5, .5>
  <.7, .3> <.8, .3> <.7, .4> <.7, .3>
  <.5, .2> <.6, .2> <.5, .3> <.5, .2>
  <.2, .5> <.3, .5> <.2, .6> <.2, .5>
  <.1, .1> <.2, .1> <.1, .2> <.1, .1>
  scale 3 rotate y * -20 translate <-0.6, 0.2, 0>
  pigment { rgb <0.2, 0.5, 0.9> } finish { F } }
// A pentagon in the plane x + z = 2.5, not closed (a warning), and
// lying on the ground a square.
polygon { 5, <2.5, 0.5, 0>, <3.5, 1.2, -1>, <3.2, 2.6, -0.7>,
          <1.8, 2.6, 0.7>, <1.5, 1.2, 1>
          pigment { rgb <0.95, 0.85, 0.2> } finish { F } }
polygon { 5, <-1, 0.01, -3>, <1, 0.01, -3>, <1, 0.01, -1.5>,
          <-1, 0.01, -1.5>, <-1, 0.01, -3>
          pigment { rgb <0.8, 0.8, 0.8> } finish { F } }
