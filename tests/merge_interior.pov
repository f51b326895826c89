// merge_interior.pov - interiors of CSG parts and of nested objects
// (tests/test_merge_interior.sh).  An emitting wall seen through clear
// blocks whose interiors fade light (fade_distance 1, fade_power 1)
// or not, by an orthographic camera along +x (Dir 1) or -x (Dir -1).
// Case 1: a block nested in the middle of a fading one; case 2: two
// overlapping blocks in a union, the first fading; case 3: the same
// two blocks merged; case 4: a merge of two glass spheres, each with
// its own interior of ior 1.5, over a checker floor (povray refracts
// through each part's interior; the whole has none of its own).
#version 3.7;
global_settings { assumed_gamma 1 ambient_light 0 max_trace_level 10 }
#ifndef (Case) #declare Case = 1; #end
#ifndef (Dir) #declare Dir = 1; #end
#declare T = texture { pigment { rgbt <1, 1, 1, 1> } finish { ambient 0 diffuse 0 } }
#declare IA = interior { ior 1 fade_distance 1 fade_power 1 }
#declare IB = interior { ior 1 }
#if (Case < 4)
camera { orthographic location <-10*Dir, 0, 0> look_at 0 right z*4*Dir up y*3 }
plane { x*Dir, 6 pigment { rgb 1 } finish { ambient 0 emission 1 diffuse 0 } }
#declare A = box { <-2, -1, -1>, <0.1, 1, 1> texture { T } interior { IA } }
#declare B = box { <0, -1, -1>, <2, 1, 1> texture { T } interior { IB } }
#switch (Case)
#case (1)
box { <-2, -1, -1>, <2, 1, 1> texture { T } interior { IA } }
box { <-0.5, -0.5, -0.5>, <0.5, 0.5, 0.5> texture { T } interior { IB } }
#break
#case (2) union { object { A } object { B } } #break
#case (3) merge { object { A } object { B } } #break
#end
#else
camera { location <0, 1.2, -4> look_at <0, 0.3, 0> angle 40 }
light_source { <10, 50, -35> rgb 1 }
plane { y, -0.5 pigment { checker rgb 0.1 rgb 0.9 scale 0.5 }
  finish { ambient 0.2 diffuse 0.8 } }
#declare G = texture { pigment { rgbf <1, 1, 1, 0.9> }
  finish { ambient 0 diffuse 0 } }
merge {
  sphere { <-0.4, 0.3, 0>, 0.7 texture { G } interior { ior 1.5 } }
  sphere { <0.4, 0.3, 0>, 0.7 texture { G } interior { ior 1.5 } }
}
#end
