// tests/light_fade.pov - a light's fade_distance below 0 (tests/test_light_fade.sh).
// A white plane seen square on, lit at normal incidence by a light DD
// units in front of it (rgb 0.25, fade_distance FD, fade_power FP),
// and with Second = 1 a second, unfaded light of rgb 0.5: the whole
// picture is one colour, 0.25 fade + 0.5 Second, fade = 2 / (1 + (DD /
// FD)^FP).  Case selects the settings.
#version 3.7;
#ifndef (Case) #declare Case = 1; #end
#declare FD = -5;
#declare Second = 0;
#switch (Case)
  #case (1) #declare FP = 1; #declare DD = 2; #break
  #case (2) #declare FP = 1; #declare DD = 10; #break
  #case (3) #declare FP = 1; #declare DD = 10; #declare Second = 1; #break
  #case (4) #declare FP = 3; #declare DD = 10; #declare Second = 1; #break
  #case (5) #declare FP = 0.5; #declare DD = 2; #declare Second = 1; #break
  #case (6) #declare FP = 2; #declare DD = 10; #break
  #case (7) #declare FP = 3; #declare DD = 2; #break
  #case (8) #declare FP = 1001; #declare DD = 2; #break
  #case (9) #declare FP = 1; #declare DD = 2; #declare FD = 5; #break
#end
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -1> look_at <0, 0, 0>
  right x * 0.1 up y * 0.075 }
light_source { <0, 0, -DD>, rgb 0.25 fade_distance FD fade_power FP }
#if (Second) light_source { <0, 0, -3>, rgb 0.5 } #end
plane { z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
