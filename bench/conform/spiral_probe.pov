// spiral_probe.pov - spiral1 and spiral2 values (ramp_wave, so the raw
// phase) printed by #debug, for lib/scene/pattern.c: povray
// +Ispiral_probe.pov -F -D Declare=ARMS=1 (also 2, 3).
#version 3.7;
#declare F = function { pigment { spiral1 ARMS ramp_wave color_map { [0 rgb 0] [1 rgb 1] } } }
#declare G = function { pigment { spiral2 ARMS ramp_wave color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 15)
  #declare T = I / 16 * 2 * pi;
  #declare R = 0.3;
  #debug concat("theta ", str(I/16, 0, 4), " ", str(F(R*cos(T), R*sin(T), 0).red, 0, 6), " ", str(G(R*cos(T), R*sin(T), 0).red, 0, 6), "\n")
#end
#for (I, 0, 12)
  #declare R = 0.05 + I * 0.05;
  #debug concat("r ", str(R, 0, 4), " ", str(F(R*cos(0.3), R*sin(0.3), 0).red, 0, 6), " ", str(G(R*cos(0.3), R*sin(0.3), 0).red, 0, 6), "\n")
#end
#for (I, 0, 8)
  #declare Z = I * 0.05;
  #debug concat("z ", str(Z, 0, 4), " ", str(F(0.3*cos(0.3), 0.3*sin(0.3), Z).red, 0, 6), " ", str(G(0.3*cos(0.3), 0.3*sin(0.3), Z).red, 0, 6), "\n")
#end
