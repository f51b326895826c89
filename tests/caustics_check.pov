// caustics_check.pov - simulated caustics ("Simulated Caustics"): a
// parallel light at TH degrees from the vertical shines through a clear
// disc (or a slab, Slab = 1) with interior caustics P onto a white
// floor; or, with P < 0, no disc and a light of strength Gain instead.
// tests/test_caustics.sh and bench/conform/caustics_probe.sh declare
// TH, P, Slab and Gain.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (TH) #declare TH = 20; #end
#ifndef (P) #declare P = 0.5; #end
#ifndef (Slab) #declare Slab = 0; #end
#ifndef (Gain) #declare Gain = 1; #end
#declare Th = radians(TH);
camera { orthographic sky z location <0, 10, 0> look_at <0, 0, 0>
         up z * 4 right x * 4 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
light_source { <sin(Th) * 1000, cos(Th) * 1000, 0>, rgb 0.4 * Gain
               parallel point_at 0 }
#if (P >= 0)
  #declare Clear = material {
    texture { pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 } }
    interior { ior 1.0 caustics P } }
  #if (Slab)
    box { <-100, 0.5, -100>, <100, 0.6, 100> material { Clear } no_image }
  #else
    disc { <0, 0.5, 0>, y, 100 material { Clear } no_image }
  #end
#end
