// tests/sky_transform.pov - a sky_sphere's transform against povray 3.7
// (tests/test_sky_transform.sh): it acts as its pigments' transform,
// on the unit direction taken as a point.  Declare=Case=N picks it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (Case) #declare Case = 0; #end
camera { location 0 look_at <0.3, 0.2, 1> right x*4/3 up y angle 90 }
#declare Sky = pigment {
  gradient x color_map { [0 rgb <1, 0.2, 0>] [1 rgb <0, 0.4, 1>] }
  scale 0.7
}
sky_sphere {
  pigment { Sky }
  #switch (Case)
    #case (0) scale 0.8 #break
    #case (1) translate <0.3, 0.2, 0.1> #break
    #case (2) scale <1, 2, 1> rotate 30*y translate 0.2*x #break
    #case (3) scale -1.5 #break
  #end
}
