// Meshes of triangle runs (lib/sdl/tokens.c keeps a plain triangle's
// corners; build_mesh.c lets a mesh of runs take them as its vertices),
// mixed with faces that are not runs.  tests/test_mesh_runs.sh renders it
// against a copy in which no triangle is a run: the same picture.
#include "colors.inc"
camera { location <2, 5, -9> look_at <2, 0.5, 2> }
light_source { <-5, 10, -10>, color rgb 1 }
#declare T = texture { pigment { Red } }
// 1. runs only
mesh { triangle { <0,0,0>, <1,0,0>, <0,0,1> } triangle { <1,0,0>, <1,0,1>, <0,0,1> }
       triangle { <0,0,1>, <1,0,1>, <0,1,2> } pigment { Green } translate <-3,0,0> }
// 2. runs, a face whose corner is an expression, runs
mesh { triangle { <0,0,0>, <1,0,0>, <0,0,1> } triangle { <1,0,0>, <1,0,1>, <0,0,1> + 0 }
       triangle { <0,0,1>, <1,0,1>, <0,1,2> } triangle { <1,0,1>, <1,1,2>, <0,1,2> }
       pigment { Blue } }
// 3. a smooth_triangle first, then runs
mesh { smooth_triangle { <0,0,0>, <0,1,0>, <1,0,0>, <0,1,0>, <0,0,1>, <0,1,0> }
       triangle { <1,0,0>, <1,0,1>, <0,0,1> } triangle { <0,0,1>, <1,0,1>, <0,1,2> }
       pigment { Yellow } translate <3,0,0> }
// 4. a face with a texture of its own, then runs
mesh { triangle { <0,0,0>, <1,0,0>, <0,0,1> texture { T } }
       triangle { <1,0,0>, <1,0,1>, <0,0,1> } triangle { <0,0,1>, <1,0,1>, <0,1,2> }
       pigment { White } translate <6,0,0> }
// 5. the same runs read again by a loop: meshes whose corners are one
// array
#declare I = 0;
#while (I < 3)
  mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } triangle { <1,0,0>, <1,1,0>, <0,1,0> }
         pigment { rgb <0.3 * I, 0.6, 1 - 0.3 * I> } translate <-3 + 3 * I, 0, 4> }
  #declare I = I + 1;
#end
// 6. a declared mesh of runs, used twice
#declare M = mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } triangle { <1,0,0>, <1,1,0>, <0,1,0> } }
object { M pigment { Cyan } translate <-2,0,7> }
object { M pigment { Magenta } translate <4,0,7> }
// 7. runs around an include of runs (another file's corners)
mesh { triangle { <0,0,0>, <1,0,0>, <0,0,1> }
#include "mesh_runs.inc"
       triangle { <0,0,1>, <1,0,1>, <0,1,2> } pigment { Orange } translate <0,0,-3> }
// Smooth triangle runs (tokens.c keeps their corners and normals;
// build_mesh.c lets a mesh of them take both arrays as they lie).
// 8. smooth runs only
mesh { smooth_triangle { <0,0,0>, <0.6,1,0>, <1,0,0>, <-0.4,1,0.2>, <0,0,1>, <0,1,-0.7> }
       smooth_triangle { <1,0,0>, <-0.4,1,0.2>, <1,0,1>, <0.3,1,0.9>, <0,0,1>, <0,1,-0.7> }
       smooth_triangle { <0,0,1>, <0,1,-0.7>, <1,0,1>, <0.3,1,0.9>, <0,1,2>, <-1,0.2,0> }
       pigment { Green } scale 1.8 translate <-7,0,10> }
// 9. smooth runs, a plain run, smooth runs
mesh { smooth_triangle { <0,0,0>, <0.6,1,0>, <1,0,0>, <-0.4,1,0.2>, <0,0,1>, <0,1,-0.7> }
       triangle { <1,0,0>, <1,0,1>, <0,0,1> }
       smooth_triangle { <0,0,1>, <0,1,-0.7>, <1,0,1>, <0.3,1,0.9>, <0,1,2>, <-1,0.2,0> }
       smooth_triangle { <1,0,1>, <0.3,1,0.9>, <1,1,2>, <0.8,0.5,0>, <0,1,2>, <-1,0.2,0> }
       pigment { Blue } scale 1.8 translate <-3,0,10> }
// 10. plain runs, then smooth runs
mesh { triangle { <0,0,0>, <1,0,0>, <0,0,1> } triangle { <1,0,0>, <1,0,1>, <0,0,1> }
       smooth_triangle { <0,0,1>, <0,1,-0.7>, <1,0,1>, <0.3,1,0.9>, <0,1,2>, <-1,0.2,0> }
       smooth_triangle { <1,0,1>, <0.3,1,0.9>, <1,1,2>, <0.8,0.5,0>, <0,1,2>, <-1,0.2,0> }
       pigment { Yellow } scale 1.8 translate <1,0,10> }
// 11. smooth runs read again by a loop
#declare I = 0;
#while (I < 2)
  mesh { smooth_triangle { <0,0,0>, <0.6,1,0>, <1,0,0>, <-0.4,1,0.2>, <0,1,0>, <0,1,-0.7> }
         smooth_triangle { <1,0,0>, <-0.4,1,0.2>, <1,1,0>, <0.3,1,0.9>, <0,1,0>, <0,1,-0.7> }
         pigment { rgb <1, 0.3 + 0.4 * I, 0.2> } scale 1.8 translate <5 + 3 * I, 0, 10> }
  #declare I = I + 1;
#end
// 12. smooth runs, then a smooth_triangle with a texture of its own
mesh { smooth_triangle { <0,0,0>, <0.6,1,0>, <1,0,0>, <-0.4,1,0.2>, <0,0,1>, <0,1,-0.7> }
       smooth_triangle { <1,0,0>, <-0.4,1,0.2>, <1,0,1>, <0.3,1,0.9>, <0,0,1>, <0,1,-0.7> texture { T } }
       pigment { White } scale 1.8 translate <-6,3,10> }
