// default_normal.pov - which bump size a normal pattern written without
// one takes (tests/test_default_normal.sh).  Case 1: #default's normal
// { bump_size 1.5 } reaches "normal { gradient x ... }"; case 2: the
// #default normal's bumps 0.3 gives its 0.3; case 3: a normal_map's
// entries start from the #default normal too; case 4: "normal { N
// gradient x ... }" keeps N's bumps 0.3; case 5: no #default normal, 0.5.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (Case) #declare Case = 1; #end
camera { location <0, 0, -31> right x*4/3 direction 3*z }
light_source { <200, 200, -100> color rgb 1 }
#declare N = normal { bumps 0.3 }
#switch (Case)
#case (2) #declare Def = normal { bumps 0.3 } #break
#case (5) #declare Def = normal { } #break
#else #declare Def = normal { bump_size 1.5 }
#end
#default { pigment { rgb 1 } normal { Def } finish { phong 0.8 phong_size 200 } }
box { <-4, -4, 0>, <4, 4, 1>
  #switch (Case)
  #case (3)
    normal { gradient y normal_map { [0.5 gradient x triangle_wave scale 1.37]
                                     [0.5 gradient x scallop_wave scale 0.7] } }
  #break
  #case (4) normal { N gradient x triangle_wave scale 1.37 } #break
  #else normal { gradient x triangle_wave scale 1.37 }
  #end
}
