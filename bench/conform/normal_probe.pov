// normal_probe.pov - a plane whose shading normal can be read back from
// its colour (bench/conform/normal_probe.sh, normal_probe.py): PAT picks
// the normal pattern, AMT its bump size, SC a uniform scale, SIDE the
// side the camera and lights are on, EXTRA a file of more normal items.
#version 3.7;
global_settings { assumed_gamma 1 ambient_light 0 }
#ifndef (PAT) #declare PAT = 0; #end
#ifndef (AMT) #declare AMT = 0.5; #end
#ifndef (SC) #declare SC = 1; #end
#ifndef (SIDE) #declare SIDE = 1; #end
camera { orthographic location <0,0,-10*SIDE> look_at 0 right x*2 up y*2 }
light_source { <100, 0, -100*SIDE> color rgb <1,0,0> parallel point_at 0 }
light_source { <-100, 0, -100*SIDE> color rgb <0,1,0> parallel point_at 0 }
light_source { <0, 100, -100*SIDE> color rgb <0,0,1> parallel point_at 0 }
plane { -z, 0
  pigment { rgb 1 }
  finish { ambient 0 diffuse 1 specular 0 phong 0 }
  normal {
    #switch (PAT)
    #case (0) gradient x, AMT #break
    #case (1) bumps AMT #break
    #case (2) ripples AMT #break
    #case (3) waves AMT #break
    #case (4) wrinkles AMT #break
    #case (5) dents AMT #break
    #case (6) granite AMT #break
    #case (8) gradient <1,0,1>, AMT #break
    #case (9) gradient <1,0,-1>, AMT #break
    #case (10) gradient z, AMT #break
    #case (7) gradient x, AMT slope_map { [0 <0,1>] [1 <1,1>] } #break
    #end
    #if (EXTRA != "") #include EXTRA #end
    scale SC
  }
}
