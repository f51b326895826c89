// normal_stencil_probe.pov - where povray samples a pattern for its
// normal (bench/conform/normal_stencil_probe.sh): a plane lit by three
// coloured parallel lights, normal { gradient G } whose ramp jumps from
// 1 to 0 at the origin, seen by an orthographic camera across the jump
// along G (the image's x).  Cfg picks the plane and the axis.
#version 3.7;
global_settings { assumed_gamma 1 ambient_light 0 }
#ifndef (Acc) #declare Acc = 0.02; #end
#ifndef (Cfg) #declare Cfg = 1; #end
#switch (Cfg)
#case (1) #declare N = -z; #declare R = x; #declare S = y; #declare G = x; #break
#case (2) #declare N = -z; #declare R = y; #declare S = x; #declare G = y; #break
#case (3) #declare N = -y; #declare R = z; #declare S = x; #declare G = z; #break
#case (4) #declare N = -y; #declare R = x; #declare S = z; #declare G = x; #break
#case (5) #declare N = -x; #declare R = y; #declare S = z; #declare G = y; #break
#case (6) #declare N = -x; #declare R = z; #declare S = y; #declare G = z; #break
#case (7) #declare N = z; #declare R = x; #declare S = y; #declare G = x; #break
#end
camera { orthographic location N*10 sky S look_at 0 right R*0.121 up S*0.0002 }
light_source { N*100 + R*100 color rgb <1, 0, 0> parallel point_at 0 }
light_source { N*100 - R*100 color rgb <0, 1, 0> parallel point_at 0 }
light_source { N*100 + S*100 color rgb <0, 0, 1> parallel point_at 0 }
plane { N, 0
  pigment { rgb 1 }
  finish { ambient 0 diffuse 1 specular 0 phong 0 }
  normal { gradient G 0.5 accuracy Acc }
}
