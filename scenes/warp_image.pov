// warp_image.pov - an image_map bent by its pigment's warps and
// turbulence (POV-Ray 3.7 moves the point before the picture is read,
// as textures/pigments/warp1.pov shows), and warp { cubic } wrapping a
// pattern around a sphere.  test.png is in POV-Ray's include directory.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -10> look_at 0 angle 36 }
light_source { <-5, 10, -20> rgb 1 }
#declare Pic = pigment { image_map { png "test.png" } translate -1/2 scale 2 }
plane { z, 0 pigment { Pic rotate 90*z warp { turbulence 0.4*x octaves 2 } }
  finish { ambient 1 diffuse 0 } clipped_by { box { <-1, -1, -1>, <1, 1, 1> } }
  translate <-2.2, 1.1, 0> }
plane { z, 0 pigment { Pic turbulence 0.3 }
  finish { ambient 1 diffuse 0 } clipped_by { box { <-1, -1, -1>, <1, 1, 1> } }
  translate <0, 1.1, 0> }
plane { z, 0 pigment { Pic warp { repeat x*0.5 flip y } }
  finish { ambient 1 diffuse 0 } clipped_by { box { <-1, -1, -1>, <1, 1, 1> } }
  translate <2.2, 1.1, 0> }
sphere { 0, 1 rotate <30, 40, 0>
  pigment { hexagon rgb <1, 0.2, 0.1>, rgb <0.1, 0.3, 1>, rgb 1
    scale 0.04 warp { cubic } rotate <30, 40, 0> }
  translate <-1.2, -1.2, 0> }
sphere { 0, 1 pigment { Pic scale 0.5 warp { cubic } rotate <20, -30, 0> }
  finish { ambient 0.6 diffuse 0.4 } translate <1.2, -1.2, 0> }
