// A vector #local without ';' in a scene that sets #version 3.5 after an
// older one (gnu0000's Trnsport scenes mix them): 3.5 is enough to refuse.
#version 3.1;
#declare Old = 1
#version 3.5;
// expect-error: semicolon_local.pov:8:12: error: '#local' of a float, vector or colour needs ';'
// expect-error: (it is 3.5 here)
#local V = <1, 2, 3>
sphere { V, Old pigment { rgb 1 } }
