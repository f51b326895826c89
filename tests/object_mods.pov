// tests/object_mods.pov - an object's pigment { }, normal { } and finish { }
// after its texture (tests/test_object_mods.sh).  Case selects the scene:
//   1 a sphere whose texture has finish { ambient 0 diffuse 0 }, then the
//     object's finish { ambient 0.4 }: ambient 0.4 with diffuse still 0
//     (the corpus' glasstestreal.pov: texture { Glass } finish { ambient
//     ... phong ... } on a blob);
//   2 the same through object { S finish { ... } };
//   3 a union whose child has that texture, finish { ambient 0.4 } on the
//     union: the child keeps its own texture (black);
//   4 a union with the texture, then finish { ambient 0.4 };
//   5 a checker texture, then pigment { scale 5 } finish { ambient 1 }:
//     the checker grows, its first colour fills the middle;
//   6 a bumps normal scaled 0.3 in the texture, then normal { scale 3 };
//   7 the same, then normal { bumps 1 scale 0.9 };
//   8 a sphere without a texture, pigment and finish given: the built-in
//     defaults as before (control);
//   9 an object moved after its pigment, then given pigment { checker }:
//     the checker starts from the moved pigment, so it is moved too (the
//     corpus' church-window.pov: object { RedWindow pigment { crackle
//     ... } } after RedWindow's translate and scale).
#version 3.7;
#ifndef (Case) #declare Case = 1; #end
global_settings { assumed_gamma 1 }
camera { location <0, 0, -5> look_at 0 }
background { rgb 0 }
#declare T = texture { pigment { rgb <1, 0.5, 0.25> }
                       finish { ambient 0 diffuse 0 } }
#declare S = sphere { 0, 1.5 texture { T } }
#declare B = texture { pigment { rgb 1 } normal { bumps 1 scale 0.3 }
                       finish { ambient 0 diffuse 1 } }
#switch (Case)
#case (1) sphere { 0, 1.5 texture { T } finish { ambient 0.4 } } #break
#case (2) object { S finish { ambient 0.4 } } #break
#case (3) union { object { S } finish { ambient 0.4 } } #break
#case (4) union { sphere { 0, 1.5 } texture { T } finish { ambient 0.4 } }
  #break
#case (5)
  sphere { 0, 1.5
    texture { pigment { checker rgb <1, 0.5, 0.25> rgb 0.5 }
              finish { ambient 0 diffuse 0 } }
    pigment { scale 5 } finish { ambient 1 } }
  #break
#case (6) sphere { 0, 1.5 texture { B } normal { scale 3 } } #break
#case (7) sphere { 0, 1.5 texture { B } normal { bumps 1 scale 0.9 } } #break
#case (8)
  sphere { 0, 1.5 pigment { rgb <1, 0.5, 0.25> } finish { ambient 0.4 } }
  #break
#case (9)
  #declare R = object { box { <-2, -2, 0>, <2, 2, 0.1> pigment { gradient x } }
                        pigment { rgb <1, 0, 0> }
                        translate <-0.7, 0.3, 0> scale 1.2 }
  object { R pigment { checker rgb 1 rgb 0.2 scale 0.8 }
           finish { ambient 1 diffuse 0 } }
  #break
#end
light_source { <-10, 10, -10> rgb 1 }
