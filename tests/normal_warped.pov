// tests/normal_warped.pov - pattern normals with turbulence and warps
// against povray 3.7 (tests/test_normal_warped.sh).  A plane lit by red,
// green and blue parallel lights from three sides, so its colour shows
// the normal; Declare=Case=N picks the normal: 0 bozo with turbulence,
// 1 crackle with turbulence and a turbulence warp (Sea_*.pov's water),
// 2 crackle through a slope_map with turbulence, 3 granite with warps and a rotate
// between them.
#version 3.7;
global_settings { assumed_gamma 1 ambient_light 0 }
#ifndef (Case) #declare Case = 0; #end
camera { orthographic location <0,0,-10> look_at 0 right x*2 up y*1.5 }
light_source { <100, 0, -100> color rgb <1,0,0> parallel point_at 0 }
light_source { <-100, 0, -100> color rgb <0,1,0> parallel point_at 0 }
light_source { <0, 100, -100> color rgb <0,0,1> parallel point_at 0 }
plane { -z, 0
  pigment { rgb 1 }
  finish { ambient 0 diffuse 1 specular 0 phong 0 }
  normal {
    #switch (Case)
      #case (0) bozo 2 turbulence 0.5 scale 0.3 #break
      #case (1) crackle 2 turbulence 0.5 warp { turbulence 0.3 } scale 0.3
      #break
      #case (2) crackle 2 slope_map { [0 <0,1>] [1 <1,0>] } turbulence 0.3
                scale 0.3 #break
      #case (3) granite 1 warp { turbulence 0.2 } rotate z*30
                warp { planar } scale 0.5 #break
    #end
  }
}
