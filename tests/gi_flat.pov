// tests/gi_flat.pov - a flat emitter in a closed room (tests/test_gi_flat.sh):
// povray's emitting surfaces shine from both sides, so neither the
// winding of the lamp nor which way its normal points may change the
// picture.  Kind: 0 two triangles, 1 a polygon, 2 a disc, 3 two
// triangles as wide as the ceiling; Up 1: the
// lamp's normal points up, away from the room; Y: the lamp's height (2.99,
// a hair below the ceiling at 3, or 2, hanging in the room).  The shelf
// is a flat receiver whose normal points down, lit on its top (its back).
#version 3.7;
#ifndef (Kind) #declare Kind = 0; #end
#ifndef (Up) #declare Up = 0; #end
#ifndef (Y) #declare Y = 2.99; #end
global_settings { assumed_gamma 1.0
  radiosity { count 200 error_bound 0.3 recursion_limit 3 pretrace_end 0.02
              nearest_count 10 } }
camera { location <0, 2.0, -1.95> look_at <0, 1.3, 1> angle 100 }
background { rgb 0 }
#declare W = finish { diffuse 0.75 ambient 0 emission 0 }
box { <-2, 0, -2>, <2, 3, 2> hollow pigment { rgb 1 } finish { W } }
#declare L = texture { pigment { rgb 1 } finish { diffuse 0 ambient 0 emission 6 } }
#declare A = <-0.5, Y, -0.5>; #declare B = <0.5, Y, -0.5>;
#declare C = <0.5, Y, 0.5>;   #declare D = <-0.5, Y, 0.5>;
#switch (Kind)
#case (0)
  #if (Up) union { triangle { A, C, B } triangle { A, D, C } texture { L } }
  #else    union { triangle { A, B, C } triangle { A, C, D } texture { L } } #end
#break
#case (1)
  #if (Up) polygon { 5, A, D, C, B, A texture { L } }
  #else    polygon { 5, A, B, C, D, A texture { L } } #end
#break
#case (2)
  disc { <0, Y, 0>, <0, (Up ? 1 : -1), 0>, 0.5642 texture { L } }
#break
#case (3)
  // a panel as wide as the ceiling, emission 1: its front faces the
  // floor 2.99 away, so none of its light is trapped
  #declare A = <-1.99, Y, -1.99>; #declare B = <1.99, Y, -1.99>;
  #declare C = <1.99, Y, 1.99>;   #declare D = <-1.99, Y, 1.99>;
  #declare L = texture { pigment { rgb 1 }
                         finish { diffuse 0 ambient 0 emission 1 } }
  #if (Up) union { triangle { A, C, B } triangle { A, D, C } texture { L } }
  #else    union { triangle { A, B, C } triangle { A, C, D } texture { L } } #end
#break
#end
// a shelf whose normal points down, lit on its top (its back)
union { triangle { <-1.7, 0.9, 0.0>, <-0.5, 0.9, 0.0>, <-0.5, 0.9, 1.2> }
        triangle { <-1.7, 0.9, 0.0>, <-0.5, 0.9, 1.2>, <-1.7, 0.9, 1.2> }
        pigment { rgb 1 } finish { W } }
