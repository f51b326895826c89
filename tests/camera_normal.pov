// tests/camera_normal.pov - a camera's normal { } against povray 3.7
// (tests/test_camera_normal.sh).  The camera sits at the centre of a
// large sphere whose colour is the direction of the ray that hits it
// (red, green, blue = x, y, z from -1 to 1), so a picture is a map of
// the camera's ray directions.  Declare=Case=N picks the normal; cases 5
// to 7 (waves, ripples, 3 waves) are tests/test_waves_normal.sh's.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (Case) #declare Case = 0; #end
#if (Case = 7) global_settings { number_of_waves 3 } #end
#declare Loc = <0, 0, 0>;
#if (Case = 4) #declare Loc = <3.3, 1.7, -2.1>; #end
#declare LX = Loc.x; #declare LY = Loc.y; #declare LZ = Loc.z;
camera {
  location Loc direction z right x*4/3 up y
  #if (Case = 3) look_at Loc + x #end
  #switch (Case)
    #case (1) normal { function { 0.5 + 0.8*x*x } 4 } #break
    #case (2) normal { function { 0.5 + 0.8*y*y } 4 } #break
    #case (3) normal { function { 0.5 + 0.4*z + 0.4*x*y } 4 } #break
    #case (4) normal { bumps 0.5 } #break
    #case (5) normal { waves 0.5 frequency 2 scale 0.2 } #break
    #case (6) normal { ripples 0.6 phase 0.2 scale 0.3 } #break
    #case (7) normal { waves 0.6 scale 0.3 } #break
  #end
}
#declare R = 1000;
sphere { Loc, R
  texture {
    pigment { average pigment_map {
      [1 function { (x - LX)/R*0.5 + 0.5 } color_map { [0 rgb 0] [1 rgb <3,0,0>] }]
      [1 function { (y - LY)/R*0.5 + 0.5 } color_map { [0 rgb 0] [1 rgb <0,3,0>] }]
      [1 function { (z - LZ)/R*0.5 + 0.5 } color_map { [0 rgb 0] [1 rgb <0,0,3>] }] } }
    finish { ambient 1 diffuse 0 } }
  hollow }
