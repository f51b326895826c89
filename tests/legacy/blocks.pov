// A block pattern given fewer pigments than it has blocks: the rest are
// black ("checker pigment { Green }", an old tutorial's floor).
#version 3.7;
global_settings { assumed_gamma 1 }
background { rgb 1 }
camera { location <0,5,-0.1> look_at 0 }
light_source { <0,10,-10> rgb 1 }
plane { y, -1 texture { pigment { checker pigment { color rgb <0,1,0> } } }
        finish { ambient 1 diffuse 0 } }
sphere { <1,0,0>, 1 pigment { hexagon pigment { rgb <1,0,0> } pigment { rgb <0,0,1> } scale 0.3 } }
