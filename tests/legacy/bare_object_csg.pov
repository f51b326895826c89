// A declared object's name alone as the last child of a CSG, as Voro++'s
// irregular.pov writes it: union { particles translate <-4,0,0> }.
// POV-Ray 3.7 reads it as object { Name }: the modifiers after it go to
// the whole CSG as usual (measured: the same picture as with object { })
// and it refuses another object after them.
#version 3.6;
#declare Ball = sphere { 0, 1 }
#declare Slab = box { <-2,-0.4,-2>, <2,0.4,2> }
camera { location <0,3,-7> look_at 0 }
light_source { <3,8,-6> rgb 1 }
union { object { Slab scale 0.5 } Ball translate -2.4*x
        pigment { rgb <0.9,0.5,0.2> } }
difference { box { <-1,-0.4,-1>, <1,0.4,1> pigment { rgb <1,1,0.3> } }
             Ball scale 0.6 translate -0.6*z pigment { rgb <0.2,0.6,0.9> } }
intersection { object { Slab pigment { rgb <0.5,0.9,0.3> } } Ball
               translate 2.4*x }
merge { Ball scale 0.5 translate <0,1.4,0> pigment { rgb 1 } }
