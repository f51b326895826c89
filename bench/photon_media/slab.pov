// Probe (bench/photon_media.sh): a spotlight through a clear ior-1 slab
// (photon target) inside a hollow scattering box; camera above.  With
// BOXTARGET the box is a target too: its media are lit by photons only.
#version 3.7;
#ifndef (MEDIA_PH) #declare MEDIA_PH = 1; #end
#ifndef (FACTOR) #declare FACTOR = 1; #end
#ifndef (SPACING) #declare SPACING = 0.02; #end
global_settings { assumed_gamma 1 max_trace_level 5
  photons { spacing SPACING #if (MEDIA_PH) media 100, FACTOR #end } }
camera { location <0, 10, 0> look_at <0, 0, 0> right x*4/3 angle 40 }
light_source { <-20, 0.5, 0>, rgb 1
  spotlight radius 3 falloff 3.5 point_at <0, 0.5, 0>
  photons { refraction on reflection on }
  #ifdef (NOMI) media_interaction off #end }
box { <-100, -1, -100>, <100, 0, 100> pigment { rgb 0.2 } finish { ambient 0 diffuse 1 } }
box { <-3, 0.01, -2>, <3, 1, 2> hollow
  pigment { rgbf 1 } finish { ambient 0 diffuse 0 }
  interior { media { scattering { 1, rgb 0.5 extinction 0 } method 3 intervals 1 samples 4 } }
  #ifdef (BOXTARGET) photons { target } #end
}
#ifndef (SLABCOL) #declare SLABCOL = rgbf 1; #end
box { <-0.05, 0.05, -0.8>, <0.05, 0.95, 0.8>
  pigment { SLABCOL } finish { ambient 0 diffuse 0 }
  interior { ior 1 }
  photons { target refraction on reflection off collect off }
}
