// photons_check.pov - photon mapping probes (tests/test_photons.sh).
//   Case 1: a clear slab of ior 1 between a point light and a floor, a
//     photon target: the photons must bring the floor the light it gets
//     with no slab at all (Case 0), near the floor (Far = 0) and three
//     times nearer the light than the floor (Far = 1).
//   Case 2: a glass sphere, a target lens, on a floor lit from the side;
//     Lights = 0 switches the light's photons off, which must give the
//     picture of Case 3, the same scene without photons.
#version 3.7;
#ifndef (Case) #declare Case = 2; #end
#ifndef (Far) #declare Far = 0; #end
#ifndef (Lights) #declare Lights = 1; #end
global_settings { assumed_gamma 1.0
  #if (Case = 1 | Case = 2) photons { #if (Case = 1) spacing 0.01 #else count 50000 #end
                           jitter 0 } #end }
#if (Case < 2)
  camera { orthographic sky z location <0, 20, 0> look_at <0, 0, 0>
           up z * 4 right x * 4 }
  light_source { <0, 9, 0>, rgb 0.25 }
  #if (Case = 1)
    box { #if (Far) <-2, 5.9, -2>, <2, 6, 2> #else <-3, 0.9, -3>, <3, 1, 3> #end
          pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 }
          interior { ior 1.0 } photons { target refraction on } }
  #end
#else
  camera { sky z location <4.5, 8, -0.001> look_at <4.5, 0, 0> angle 50 }
  light_source { <-10, 5, 0>, rgb 0.25
    #if (!Lights) photons { refraction off reflection off } #end }
  sphere { <0, 1.5, 0>, 1 pigment { rgbf <1, 1, 1, 0.9> }
           finish { ambient 0 diffuse 0 } interior { ior 1.5 }
           photons { target refraction on reflection off } }
#end
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
