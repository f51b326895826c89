// dispersion.pov - interior { dispersion } (tests/test_dispersion.sh): a
// clear slab of thickness 1 turned 45 degrees about y, seen by an
// orthographic camera along +z in front of an emitting wall, white for
// x < 0 and black beyond.  Through the slab a ray moves along +x by an
// amount that grows with its ior, so near the edge each column sees white
// in fewer of the spectrum's colours (bench/conform/dispersion_probe.pov
// is the same scene at 8000 columns).  Declare=K=1..4 picks the case.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
#ifndef (K) #declare K = 1; #end
camera { orthographic location <-0.33, 0, -5> look_at <-0.33, 0, 0>
         right 0.16*x up 0.12*y }
plane { z, 3
  pigment { gradient x color_map { [0 rgb 1] [0.5 rgb 1] [0.5 rgb 0] [1 rgb 0] }
            scale 20 translate -10*x }
  finish { ambient 0 diffuse 0 emission 1 } }
box { <-3, -3, -0.5>, <3, 3, 0.5> rotate 45*y
  pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 }
  #switch (K)
  #case (1) interior { ior 1.5 dispersion 1.2 } #break
  #case (2) interior { ior 1.5 dispersion 1.2 dispersion_samples 3 } #break
  #case (3) interior { ior 1.5 dispersion 0.8 dispersion_samples 2.7 } #break
  #case (4) interior { dispersion 1.2 } #break // no ior: no dispersion
  #end
}
