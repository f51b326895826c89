// tests/fog_turbulence.pov - fog turbulence against povray 3.7
// (tests/test_fog_turbulence.sh).  A black plane behind a white fog
// seen by a wide camera, so the turbulence varies over the picture;
// Declare=Case=N: 0 constant fog, 1 ground fog with turb_depth 1,
// 2 ground fog over a far plane (the turbulence fades with distance),
// 3 constant fog, 3 octaves, omega 0.7, turbulence <0.4, 0.2, 0.6>.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (Case) #declare Case = 0; #end
camera { location <0.3, 1, -3> look_at <0.3, 1, 0> angle 60 right x*4/3 }
plane { z, (Case = 2 ? 60 : 4) hollow
        pigment { rgb 0 } finish { ambient 0 diffuse 0 } }
fog {
  distance 20 color rgb 1
  #switch (Case)
    #case (0) turbulence 0.5 #break
    #case (1) fog_type 2 fog_offset 0.1 fog_alt 1.5 turbulence 0.8
              turb_depth 1 #break
    #case (2) fog_type 2 fog_offset 0.1 fog_alt 1.5 turbulence 1.8 #break
    #case (3) turbulence <0.4, 0.2, 0.6> octaves 3 omega 0.7 #break
  #end
}
