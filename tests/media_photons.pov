// media_photons.pov - photons in media (tests/test_media_photons.sh,
// lib/trace/photons.c): a spotlight shines through a clear box that is
// a photon target and holds scattering media; a mirror inside it,
// turned 45 degrees, has no photons block of its own.  Camera above.
//   Case 1: a white mirror: the beam it reflects is made of media
//           photons (povray 3.7: as bright as the incoming beam).
//   Case 2: a mirror that reflects red and lets cyan through (filter).
//   Case 3: the white mirror with photons { reflection off }: no beam.
//   Case 4: case 1 with media photons off (media 0): the box's target
//           then only lets surface photons through.
//   Case 5: case 1 with Mie murky scattering: the photons' phase is the
//           medium's, for their own direction.
#version 3.7;
#ifndef (Case) #declare Case = 1; #end
global_settings { assumed_gamma 1 max_trace_level 5
  photons { spacing 0.02 media #if (Case = 4) 0 #else 100, 2 #end } }
camera { location <0, 10, 0> look_at <0, 0, 0> right x*4/3 angle 40 }
light_source { <-20, 0.5, 0>, rgb 1
  spotlight radius 3 falloff 3.5 point_at <0, 0.5, 0>
  photons { refraction on reflection on } }
box { <-100, -1, -100>, <100, 0, 100>
  pigment { rgb 0.2 } finish { ambient 0 diffuse 1 } }
box { <-3, 0.01, -2>, <3, 1, 2> hollow
  pigment { rgbf 1 } finish { ambient 0 diffuse 0 }
  interior { media { scattering { #if (Case = 5) 3 #else 1 #end, rgb 0.5
                                  extinction 0 }
                     method 3 intervals 1 samples 4 } }
  photons { target } }
box { <-0.05, 0.05, -0.8>, <0.05, 0.95, 0.8>
  #if (Case = 2)
    pigment { rgbf <0, 1, 1, 1> }
    finish { ambient 0 diffuse 0 reflection <1, 0, 0> }
  #else
    pigment { rgb 1 } finish { ambient 0 diffuse 0 reflection 1 }
  #end
  #if (Case = 3) photons { reflection off } #end
  rotate y*45 }
