// Below version 3.5 POV-Ray 3.7 only warns ("Possible Parse Error: All
// #version and #declares of float, vector, and color require semi-colon
// ';' at end") and renders: so does zRcube.
#version 3.1;
// expect: '#declare' of a float, vector or colour should end with ';'
#declare Size = 2
#declare Colour = color red 1 green 0.5
sphere { 0, Size pigment { Colour } }
camera { location <0, 0, -5> look_at 0 }
light_source { <0, 10, -10> rgb 1 }
