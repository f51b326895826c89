// photon_bailout.pov - bench/photon_bailout.sh's probes of the rule by
// which povray 3.7 drops a photon branch (adc_bailout).  Every case
// shoots photons at one target under one light and collects them on one
// surface only after the branch being probed, so "Surface photons
// stored" is (nearly) zero when the branch is dropped.
//   Case 1: one mirror (a target) sends the light's photons to the
//     floor.  Refl picks its reflection block: 0 R; 1 { 0, R falloff
//     VF }; 2 { R, 0 falloff VF }; 3 { R, R * VM falloff VF }; 4 { 0, R
//     fresnel on } with ior FR; 5 rgb R * <RR, RG, RB>; 6 { R * VM, R
//     fresnel on }.  Met: its metallic; pigment rgb <PR, PG, PB> (or Pg);
//     light rgb LC.
//   Case 2: light straight above; mirror 1 (a target, reflection R1,
//     45 degrees) sends the photons along -x to mirror 2 (reflection R,
//     not a target), which sends them up to a ceiling plate.
//   Case 3: as case 2, the second mirror replaced by a clear slab
//     (rgbt T = R, ior 1, refraction on) before a collecting wall.
//   Case 4: a clear slab (a target, ior 1) whose transmit is Ta where
//     the photons enter it and Tb where they leave it.
//   Case 5: a metal ball (a target) under a light 150000 units away, as
//     benchmark.pov's ring is (its first hits, found from that far, were
//     off the surface and its photons bounced on inside it).
#version 3.7;
#ifndef (Case) #declare Case = 1; #end
#ifndef (R) #declare R = 0.5; #end
#ifndef (R1) #declare R1 = 1; #end
#ifndef (Ta) #declare Ta = 1; #end
#ifndef (Tb) #declare Tb = 1; #end
#ifndef (Adc) #declare Adc = 1/255; #end
#ifndef (Pg) #declare Pg = 1; #end
#ifndef (PR) #declare PR = Pg; #declare PG = Pg; #declare PB = Pg; #end
#ifndef (Met) #declare Met = 0; #end
#ifndef (LC) #declare LC = 1; #end
#ifndef (Refl) #declare Refl = 0; #end
#ifndef (VF) #declare VF = 1; #end
#ifndef (VM) #declare VM = 1; #end
#ifndef (FR) #declare FR = 1.5; #end
#ifndef (RR) #declare RR = 1; #declare RG = 1; #declare RB = 1; #end
global_settings { assumed_gamma 1.0 max_trace_level #if (Case = 5) 12 #else 10 #end
  photons { spacing #if (Case = 5) 0.007 #else 0.02 #end adc_bailout Adc } }
camera { location <0, 5, -10> look_at 0 }
#switch (Case)
#case (1)
  light_source { <-300, 400, 0> rgb LC }
  plane { y, 0 pigment { rgb 1 } }
  box { <1, 0.2, -1>, <1.05, 2, 1>
    pigment { rgb <PR, PG, PB> }
    finish { reflection {
      #switch (Refl)
      #case (0) R #break
      #case (1) 0, R falloff VF #break
      #case (2) R, 0 falloff VF #break
      #case (3) R, R * VM falloff VF #break
      #case (4) 0, R fresnel on #break
      #case (5) rgb R * <RR, RG, RB> #break
      #case (6) R * VM, R fresnel on #break
      #end
      metallic Met } }
    interior { ior FR }
    photons { target reflection on collect off } }
#break
#case (2)
#case (3)
  light_source { <0, 1000, 0> rgb 1 }
  plane { y, -2 pigment { rgb 1 } photons { collect off } }
  box { <-0.5, -0.01, -0.5>, <0.5, 0, 0.5> rotate 45 * z
    pigment { rgb 1 } finish { reflection { R1 } }
    photons { target reflection on collect off } }
  #if (Case = 2)
    box { <-0.6, -0.01, -0.6>, <0.6, 0, 0.6> rotate -45 * z translate -3 * x
      pigment { rgb 1 } finish { reflection { R } }
      photons { reflection on collect off } }
    box { <-4, 5, -1>, <-2, 5.1, 1> pigment { rgb 1 } }
  #else
    box { <-2.2, -1, -1>, <-2, 1, 1> pigment { rgbt <1, 1, 1, R> }
      interior { ior 1 } photons { refraction on collect off } }
    box { <-4.1, -1.5, -1.5>, <-4, 1.5, 1.5> pigment { rgb 1 } }
  #end
#break
#case (4)
  light_source { <0, 100, 0> rgb 0.4 }
  plane { y, 0 pigment { rgb 1 } }
  box { <-2, 1.3, -1>, <2, 1.5, 1>
    pigment { gradient y
      color_map { [0.3 rgbt <1, 1, 1, Tb>] [0.5 rgbt <1, 1, 1, Ta>] } }
    interior { ior 1 } photons { target refraction on collect off } }
#break
#case (5)
  light_source { <-0.7, 0.83, 0.24> * 150000 rgb <3.43, 2.87, 1.95> }
  plane { z, 0 pigment { rgb 1 } }
  sphere { 0.6 * z, 0.7 pigment { rgb <0.65, 0.55, 0.5> }
    finish { reflection { 0.8 metallic } }
    photons { target reflection on } }
#break
#end
