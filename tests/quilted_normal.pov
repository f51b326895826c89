// quilted_normal.pov - a quilted normal read back as colour
// (tests/test_quilted_normal.sh): a plane lit by three coloured parallel
// lights (red from +x, green from -x, blue from +y) so that each pixel's
// colour shows its shading normal.  Case 1: the default controls (1, 1);
// case 2: control0 -2, control1 3 (a negative Bezier in the middle of
// each cube); case 3: control0 0.5, control1 1 under turbulence, as
// advanced/quilt1.pov's mirror sphere; case 4: case 1 seen from behind
// the plane's normal.
#version 3.7;
global_settings { assumed_gamma 1 ambient_light 0 }
#ifndef (Case) #declare Case = 1; #end
#declare Side = (Case = 4 ? -1 : 1);
camera { orthographic location <0, 0, -10> look_at 0 right x*2 up y*1.5 }
light_source { <100, 0, -100> color rgb <1, 0, 0> parallel point_at 0 }
light_source { <-100, 0, -100> color rgb <0, 1, 0> parallel point_at 0 }
light_source { <0, 100, -100> color rgb <0, 0, 1> parallel point_at 0 }
plane { -Side*z, 0
  pigment { rgb 1 }
  finish { ambient 0 diffuse 1 specular 0 phong 0 }
  normal {
    quilted 0.6
    #switch (Case)
    #case (2) control0 -2 control1 3 #break
    #case (3) control0 0.5 control1 1 turbulence 0.5 lambda 0.5 omega 0.707
      octaves 4 #break
    #end
    translate <0.1, 0.2, 0.3>
    scale 0.45
  }
}
