// tests/parametric_gradient.pov - a parametric whose max_gradient is far
// below its partial derivatives (tests/test_parametric_gradient.sh): the
// water sheet of the corpus' GSprites_Terrain_demo.pov, <64 u - 32,
// 0.25 (sin 8 pi u + sin 8 pi v), 64 v - 32>, whose x and z change by 64
// a unit of u or v.  Case selects its max_gradient:
//   1 none given (POV-Ray's default, 1);
//   2 max_gradient 0.1;
//   3 max_gradient 100, above the slopes (control).
#version 3.7;
#ifndef (Case) #declare Case = 1; #end
global_settings { assumed_gamma 1 }
camera { location <0, 40, -60> look_at <0, 0, 0> }
light_source { <100, 200, -100> rgb 1 }
background { rgb <0, 0, 1> }
parametric {
  function { u * 64 - 32 }
  function { 0.25 * (sin(u * 2 * pi * 4) + sin(v * 2 * pi * 4)) }
  function { v * 64 - 32 }
  <0, 0>, <1, 1>
  #if (Case = 2) max_gradient 0.1 #end
  #if (Case = 3) max_gradient 100 #end
  accuracy 0.01
  contained_by { box { -32, 32 } }
  pigment { rgb <1, 0.5, 0> }
}
