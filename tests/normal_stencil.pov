// normal_stencil.pov - where a pattern is sampled for its normal
// (tests/test_normal_stencil.sh): a plane lit by three coloured
// parallel lights (red from +x, green from -x, blue from +y), its
// normal's tilt shown as colour.  Case 1: radial 0.5 frequency 20
// sine_wave, as objects/quartic/witch.pov; case 2: gradient x 0.5,
// whose ramp jumps at x = 0, seen across the jump (0.0075 units a
// pixel: the band the jump disturbs); case 3: the same along y.
#version 3.7;
global_settings { assumed_gamma 1 ambient_light 0 }
#ifndef (Case) #declare Case = 1; #end
#if (Case = 1)
camera { orthographic location <0, 0, -10> look_at 0 right x*2 up y*1.5 }
#else
camera { orthographic location <0, 0, -10> look_at 0 right x*0.12 up y*0.09 }
#end
light_source { <100, 0, -100> color rgb <1, 0, 0> parallel point_at 0 }
light_source { <-100, 0, -100> color rgb <0, 1, 0> parallel point_at 0 }
light_source { <0, 100, -100> color rgb <0, 0, 1> parallel point_at 0 }
plane { -z, 0
  pigment { rgb 1 }
  finish { ambient 0 diffuse 1 specular 0 phong 0 }
  #switch (Case)
  #case (1) normal { radial 0.5 frequency 20 sine_wave rotate x*90 } #break
  #case (2) normal { gradient x 0.5 } #break
  #case (3) normal { gradient y 0.5 } #break
  #end
}
