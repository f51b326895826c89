// The .hf component of a pigment function ("Function Pattern":
// hf = (Red + Green/255) * 0.996093), used by khayyam90's organ.pov in an
// isosurface.  Values measured with povray 3.7's #debug.
// expect: pigment_hf: 0.499023 0.249512 0.598828 0.250000
#version 3.7;
global_settings { assumed_gamma 1 }
#declare P = function { pigment { gradient x
  color_map { [0 rgbf <0,0,0,0>][1 rgbf <1,0.5,0.2,0.5>] } } }
#declare F = function { P(x,y,z).hf }
#declare G = function { P(x,y,z).filter }
#debug concat("pigment_hf: ", str(F(0.5,0,0),0,6), " ", str(F(0.25,0,0),0,6),
  " ", str(F(0.6,0,0),0,6), " ", str(G(0.5,0,0),0,6), "\n")
camera { location <0,1,-4> look_at 0 }
light_source { <5,10,-10> rgb 1 }
#declare Q = function { pigment { function { (sin(x*3)+1)/2 }
  color_map { [0 rgb 0][1 rgb <1,0.5,0>] } } }
isosurface {
  function { sqrt(x*x+y*y+z*z) - 1 + 0.3*Q(x,y,z).hf }
  contained_by { box { -1.5, 1.5 } }
  max_gradient 3
  pigment { rgb <1,0.8,0.6> }
}
