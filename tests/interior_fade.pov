// tests/interior_fade.pov - an interior's fade_distance below 0
// (tests/test_interior_fade.sh, bench/conform/interior_fade_negative.sh).
// A clear box (pigment rgbf 1) TH thick, interior fade_distance FA
// fade_power PA (and with FC fade_color <0.5, 0.2, 0>), over a floor
// seen from straight above: with View the floor emits rgb 0.5 and the
// box is seen (the camera ray's fading), else the box is no_image and
// the floor (ambient 0.2, diffuse 1) is lit through it by a parallel
// light of rgb 0.5 from above (the shadow ray's).  Each picture is one
// colour.  Case picks the settings; Case 0 takes FA, PA, TH, View, FC
// as declared.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (Case) #declare Case = 0; #end
#ifndef (FA) #declare FA = -1; #end
#ifndef (PA) #declare PA = 1; #end
#ifndef (TH) #declare TH = 1; #end
#ifndef (View) #declare View = 0; #end
#ifndef (FC) #declare FC = 0; #end
#switch (Case)
  #case (1) #declare View = 1; #declare PA = 1; #declare TH = 0.1; #break
  #case (2) #declare View = 1; #declare PA = 3; #declare TH = 0.5; #break
  #case (3) #declare View = 1; #declare PA = 0.5; #declare TH = 0.5; #break
  #case (4) #declare View = 1; #declare PA = -1; #declare TH = 3; #break
  #case (5) #declare View = 1; #declare PA = 1000; #declare TH = 0.5; #break
  #case (6) #declare View = 0; #declare PA = 1; #declare TH = 3; #break
  #case (7) #declare View = 0; #declare PA = 3; #declare TH = 3; #break
  #case (8) #declare View = 0; #declare PA = 0.5; #declare TH = 0.5; #break
  #case (9) #declare View = 0; #declare PA = 2; #declare TH = 0.5; #break
  #case (10) #declare View = 1; #declare PA = 1; #declare TH = 0.1; #declare FC = 1; #break
  #case (11) #declare View = 0; #declare PA = 3; #declare TH = 3; #declare FC = 1; #break
#end
camera { orthographic sky z location <0, 10, 0> look_at <0, 0, 0>
  up z * 4 right x * 4 }
#if (View)
plane { y, 0 pigment { rgb 0.5 } finish { ambient 0 emission 1 diffuse 0 } }
#else
plane { y, 0 pigment { rgb 1 } finish { ambient 0.2 diffuse 1 } }
#end
light_source { <0, 1000, 0>, rgb 0.5 parallel point_at 0 }
box { <-100, 1, -100>, <100, 1 + TH, 100>
  texture { pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 } }
  interior { fade_distance FA fade_power PA
    #if (FC) fade_color <0.5, 0.2, 0> #end }
  #if (!View) no_image #end }
