// tests/irid_turbulence.pov - irid's turbulence against povray 3.7
// (tests/test_irid_turbulence.sh): a white plane with a thin film whose
// thickness the turbulence varies over the picture; Declare=Case=N:
// 0 thickness 0.5 turbulence 0.75, 1 thickness 2 turbulence 0.1,
// 2 thickness 0.1 turbulence 0.5 (scaled down: finer variation).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (Case) #declare Case = 0; #end
camera { orthographic location <1.5, 1, -1> look_at <1.5, 1, 0>
         right x*4 up y*3 }
light_source { <1.5, 1, -1000> color rgb 0.6 parallel point_at <1.5, 1, 0> }
plane { -z, 0
  pigment { rgb 1 }
  finish { ambient 0 diffuse 1
    #switch (Case)
      #case (0) irid { 0.5 thickness 0.5 turbulence 0.75 } #break
      #case (1) irid { 0.5 thickness 2 turbulence 0.1 } #break
      #case (2) irid { 0.5 thickness 0.1 turbulence 0.5 } #break
    #end
  }
  #if (Case = 2) scale 0.3 #end
}
