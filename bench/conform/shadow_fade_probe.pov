// shadow_fade_probe.pov - bench/conform/shadow_fade_probe.sh's scene:
// a white floor lit by a parallel light from straight above (rgb 0.5),
// seen from above (orthographic), under clear boxes (pigment rgbf F)
// whose interiors fade light: IA fade_distance FA power PA, IB FB PB,
// IC FC.  Boxes are no_image unless View = 1, which makes the floor
// emit (no light) and shows the boxes: the camera ray's fading instead
// of the shadow ray's.  Case picks the boxes (see each #case).
// TH: the thickness of case 28's and 29's single box (29: fade_color
// <0.5, 0.2, 0>), for bench/conform/fade_power_probe.sh.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (Case) #declare Case = 0; #end
#ifndef (FA) #declare FA = 0.5; #end
#ifndef (FB) #declare FB = 0.5; #end
#ifndef (PA) #declare PA = 1; #end
#ifndef (PB) #declare PB = 1; #end
#ifndef (TH) #declare TH = 1; #end
#ifndef (FC) #declare FC = 0; #end
camera { orthographic sky z location <0, 10, 0> look_at <0, 0, 0>
         up z * 4 right x * 4 }
#ifndef (View) #declare View = 0; #end
#if (View)
plane { y, 0 pigment { rgb 0.5 } finish { ambient 0 emission 1 diffuse 0 } }
#else
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
#end
light_source { <0, 1000, 0>, rgb 0.5 parallel point_at 0 }
#ifndef (F) #declare F = 1; #end
#declare T = texture { pigment { rgbf <1, 1, 1, F> } finish { ambient 0 diffuse 0 } }
#declare IA = interior { fade_distance FA fade_power PA }
#declare IB = interior { fade_distance FB fade_power PB }
#declare IC = interior { fade_distance FC fade_power 1 }
#switch (Case)
#case (0) #break
#case (1) box { <-100, 1, -100>, <100, 2, 100> texture { T } interior { IA } #if (!View) no_image #end } #break
// stacked merge A below (1..1.5), B above (1.5..2)
#case (2) merge { box { <-100, 1, -100>, <100, 1.5, 100> texture { T } interior { IA } }
                  box { <-100, 1.5, -100>, <100, 2, 100> texture { T } interior { IB } } #if (!View) no_image #end } #break
// stacked union
#case (3) union { box { <-100, 1, -100>, <100, 1.5, 100> texture { T } interior { IA } }
                  box { <-100, 1.5, -100>, <100, 2, 100> texture { T } interior { IB } } #if (!View) no_image #end } #break
// overlapping merge A 1..1.7, B 1.3..2
#case (4) merge { box { <-100, 1, -100>, <100, 1.7, 100> texture { T } interior { IA } }
                  box { <-100, 1.3, -100>, <100, 2, 100> texture { T } interior { IB } } #if (!View) no_image #end } #break
// stacked merge with its own interior IC
#case (5) merge { box { <-100, 1, -100>, <100, 1.5, 100> texture { T } interior { IA } }
                  box { <-100, 1.5, -100>, <100, 2, 100> texture { T } interior { IB } } interior { IC } #if (!View) no_image #end } #break
// gap merge: A 1..1.3, B 1.7..2
#case (6) merge { box { <-100, 1, -100>, <100, 1.3, 100> texture { T } interior { IA } }
                  box { <-100, 1.7, -100>, <100, 2, 100> texture { T } interior { IB } } #if (!View) no_image #end } #break
// nested merge: A 1..2 containing B 1.3..1.7
#case (7) merge { box { <-100, 1, -100>, <100, 2, 100> texture { T } interior { IA } }
                  box { <-100, 1.3, -100>, <100, 1.7, 100> texture { T } interior { IB } } #if (!View) no_image #end } #break
// gap union
#case (8) union { box { <-100, 1, -100>, <100, 1.3, 100> texture { T } interior { IA } }
                  box { <-100, 1.7, -100>, <100, 2, 100> texture { T } interior { IB } } #if (!View) no_image #end } #break
// stacked merge, both parts interior { IA }
#case (9) merge { box { <-100, 1, -100>, <100, 1.5, 100> texture { T } interior { IA } }
                  box { <-100, 1.5, -100>, <100, 2, 100> texture { T } interior { IA } } #if (!View) no_image #end } #break
// stacked merge, parts none, merge IA
#case (10) merge { box { <-100, 1, -100>, <100, 1.5, 100> texture { T } }
                  box { <-100, 1.5, -100>, <100, 2, 100> texture { T } } interior { IA } #if (!View) no_image #end } #break
// stacked merge, part A IA, part B none
#case (12) merge { box { <-100, 1, -100>, <100, 1.5, 100> texture { T } interior { IA } }
                  box { <-100, 1.5, -100>, <100, 2, 100> texture { T } } #if (!View) no_image #end } #break
// stacked merge, part A none, part B IB
#case (13) merge { box { <-100, 1, -100>, <100, 1.5, 100> texture { T } }
                  box { <-100, 1.5, -100>, <100, 2, 100> texture { T } interior { IB } } #if (!View) no_image #end } #break
// two separate boxes, gap, same IA
#case (14) box { <-100, 1, -100>, <100, 1.3, 100> texture { T } interior { IA } #if (!View) no_image #end }
           box { <-100, 1.7, -100>, <100, 2, 100> texture { T } interior { IA } #if (!View) no_image #end } #break
// overlapping separate boxes A 1..1.7 IA, B 1.3..2 IB
#case (15) box { <-100, 1, -100>, <100, 1.7, 100> texture { T } interior { IA } #if (!View) no_image #end }
           box { <-100, 1.3, -100>, <100, 2, 100> texture { T } interior { IB } #if (!View) no_image #end } #break
// overlapping union A 1..1.7 IA, B 1.3..2 IB
#case (16) union { box { <-100, 1, -100>, <100, 1.7, 100> texture { T } interior { IA } }
           box { <-100, 1.3, -100>, <100, 2, 100> texture { T } interior { IB } } #if (!View) no_image #end } #break
// nested union A 1..2 containing B 1.3..1.7
#case (17) union { box { <-100, 1, -100>, <100, 2, 100> texture { T } interior { IA } }
                  box { <-100, 1.3, -100>, <100, 1.7, 100> texture { T } interior { IB } } #if (!View) no_image #end } #break
// stacked merge with slight overlap, both IA
#case (18) merge { box { <-100, 1, -100>, <100, 1.6, 100> texture { T } interior { IA } }
                  box { <-100, 1.4, -100>, <100, 2, 100> texture { T } interior { IA } } #if (!View) no_image #end } #break
// A 1..2 IA containing a plain clear B 1.3..1.7
#case (19) union { box { <-100, 1, -100>, <100, 2, 100> texture { T } interior { IA } }
                  box { <-100, 1.3, -100>, <100, 1.7, 100> texture { T } } #if (!View) no_image #end } #break
// floor inside A (-1..2)
#case (20) box { <-100, -1, -100>, <100, 2, 100> texture { T } interior { IA } #if (!View) no_image #end } #break
// merge of two copies of one declared box, stacked
#case (21) #declare BA = box { <-100, 1, -100>, <100, 1.5, 100> texture { T } interior { IA } }
           merge { object { BA } object { BA translate y * 0.5 } #if (!View) no_image #end } #break
// separate overlapping, same declared interior identifier IA (two interior { IA } blocks)
#case (22) box { <-100, 1, -100>, <100, 1.7, 100> texture { T } interior { IA } #if (!View) no_image #end }
           box { <-100, 1.3, -100>, <100, 2, 100> texture { T } interior { IA } #if (!View) no_image #end } #break
// A 1..1.7 IA, B 1.3..2 IB separate, fade_color on B
#case (23) box { <-100, 1, -100>, <100, 1.7, 100> texture { T } interior { IA } #if (!View) no_image #end }
           box { <-100, 1.3, -100>, <100, 2, 100> texture { T } interior { IB fade_color <0.5,0.5,0.5> } #if (!View) no_image #end } #break
// sphere (curved, one object) radius 0.5 centre y 1.5
#case (24) sphere { <0, 1.5, 0>, 0.5 texture { T } interior { IA } #if (!View) no_image #end } #break
// floor inside a visible fading box A (-1..2)
#case (25) box { <-100, -1, -100>, <100, 2, 100> texture { T } interior { IA } } #break
// floor inside a visible fading box A (-1..2) that holds a clear B 1.3..1.7 (IB)
#case (26) box { <-100, -1, -100>, <100, 2, 100> texture { T } interior { IA } }
           box { <-100, 1.3, -100>, <100, 1.7, 100> texture { T } interior { IB } } #break
// floor inside visible A (-1..2, no fade), fading B (1.3..1.7) inside it
#case (27) box { <-100, -1, -100>, <100, 2, 100> texture { T } }
           box { <-100, 1.3, -100>, <100, 1.7, 100> texture { T } interior { IB } } #break
// single box of thickness TH
#case (28) box { <-100, 1, -100>, <100, 1 + TH, 100> texture { T } interior { IA } #if (!View) no_image #end } #break
// single box of thickness TH, fade_color red 0.5
#case (29) box { <-100, 1, -100>, <100, 1 + TH, 100> texture { T } interior { IA fade_color <0.5, 0.2, 0> } #if (!View) no_image #end } #break
#end
