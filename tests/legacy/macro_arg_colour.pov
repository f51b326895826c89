// A macro argument followed by 'color' without a comma (t-o-k's
// FitHeightLineToPoints.pov: "ShowLine2D(MinU, MaxU, LineFnV, 0.02
// color rgbt <...>)"): POV-Ray 3.7 takes the colour as the next argument.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -5> look_at 0 }
light_source { <2, 4, -5> rgb 1 }
#macro Ball(P, R, C) sphere { P, R pigment { color C } } #end
Ball(<-1, 0, 0>, 0.8 color rgb <1, 0.2, 0.1>)
Ball(<1, 0, 0>, 0.5 color rgbt <0.1, 0.4, 1, 0.3>)
