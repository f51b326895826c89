// expressions.pov - float and vector expressions, #declare and #local.
//
// Positions and colours are computed with + - * /, unary minus, the
// vectors x y z, component access .x .y .z and the functions sin cos
// sqrt pow abs min max (POV-Ray reference, "Float Expressions" and
// "Vector Expressions").  A mistake in any of them moves or recolours a
// ball, which the golden comparison sees.
#version 3.7;
global_settings { assumed_gamma 1.0 }

#declare R = 0.5;
#declare Gap = 2 * R + 0.3;
#declare Centre = <0, R, 0>;
#declare Up = y * 1.5;
#local Tint = <0.9, 0.5, 0.2>;

camera { location Centre + <0, 3, -8> look_at Centre + Up / 2 angle 55 }
light_source { <-5, 10, -8>, rgb 1 }
background { rgb <0.2, 0.2, 0.25> }
plane { y, 0 pigment { rgb 0.7 } }

sphere { Centre - x * Gap * 2, R pigment { rgb Tint } }
sphere { Centre - x * Gap, R * sqrt(2) / 1.5
         pigment { rgb <Tint.z, Tint.y, Tint.x> } }
sphere { Centre + Up, pow(R, 2) + 0.2
         pigment { rgb <abs(-0.3), 0.8, max(0.2, 0.6)> } }
sphere { Centre + x * Gap, min(R, 0.4)
         pigment { rgb <sin(0.5236), cos(0), 0.1> } }
sphere { <2 * Gap, Centre.y, -(1 - 2)>, R pigment { rgb <0.3, 0.3, 0.9> } }
box { <-3, 0, 2>, <3, 1 + Tint.x, 2.4> pigment { rgb (x + z) * 0.7 } }
