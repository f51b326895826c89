// Being a number, seed() needs the ';' of a float #declare (povray: "All
// #declares of float, vector, and color require semi-colon").
#version 3.7;
// expect-error: seed_semicolon.pov:5:14: error: '#declare' of a float, vector or colour needs ';'
#declare S = seed(5)
sphere { 0, rand(S) pigment { rgb 1 } }
