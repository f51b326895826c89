// gradient_wrap_probe.pov - the values of a gradient pattern (through a
// black-to-white colour_map, so red = the value after the wave) at
// negative, large and boundary coordinates, without and with frequency 3.
// Writes gradient_wrap.txt: x, value, value with frequency 3.
// Run by bench/conform/gradient_wrap_probe.sh and tests/test_gradient_wrap.sh.
#version 3.7;
global_settings { assumed_gamma 1 }
#declare F = function { pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } } }
#declare G = function { pigment { gradient x frequency 3 color_map { [0 rgb 0] [1 rgb 1] } } }
#fopen Out "gradient_wrap.txt" write
#declare Xs = array[16] { -0.25, -0.5, -0.99999, -1.000005, -1.00001, -1.5,
  -2.00003, -7.3, -123.456, -1e5-0.3, -1e9-0.5, 0.25, 1.5, 123.456, 1, 0 }
#for (i, 0, 15)
  #write(Out, str(Xs[i], 0, 6), " ", str(F(Xs[i], 0, 0).red, 0, 12), " ",
    str(G(Xs[i], 0, 0).red, 0, 12), "\n")
#end
#fclose Out
camera { location -z look_at 0 }
