// tests/sky_layers.pov - sky_sphere layers with filter and transmit
// against povray 3.7 (tests/test_sky_layers.sh).  Declare=Case=N picks
// the stack of layers (bottom first); the background is black.
#version 3.6;
global_settings { assumed_gamma 1.0 }
#ifndef (Case) #declare Case = 0; #end
camera { location 0 direction z right x*4/3 up y }
sky_sphere {
  #switch (Case)
    #case (0)
      pigment { rgb <0.2,0.4,0.8> } pigment { rgbf <0.9,0.1,0.1,0.5> }
    #break
    #case (1)
      pigment { rgb <0.2,0.4,0.8> } pigment { rgbf <0.5,0.5,0.5,0.5> }
      pigment { rgbft <0.9,0.1,0.1,0.2,0.3> }
    #break
    #case (2)
      pigment { rgb <0.2,0.4,0.8> } pigment { rgbft <0.3,0.6,0.5,0.3,0.4> }
      pigment { rgbft <0.9,0.1,0.1,0.6,0.1> }
    #break
    #case (3)
      pigment { rgbft <0.2,0.4,0.8,0.3,0.2> }
      pigment { rgbft <0.3,0.6,0.5,0.1,0.4> }
      pigment { rgbft <0.9,0.1,0.1,0.6,0.1> }
    #break
  #end
}
