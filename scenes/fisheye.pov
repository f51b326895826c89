// fisheye.pov - a 180 degree fisheye camera inside a ring of coloured
// spheres, with a cylinder of stripes around it: every projection goes
// through lib/trace/camera.c, whose formulas were fitted to povray 3.7
// renders (see tests/test_camlight.c for the others).
//
// POV-Ray reference, "Fisheye projection": the image is a circle of
// radius 0.5 in (u |right|, v |up|) units, black outside.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { fisheye location <0, 1, 0> look_at <0, 1, 1> angle 180
         right x up y }
light_source { <0, 8, 0>, rgb 1 }
background { rgb <0.3, 0.4, 0.6> }

plane { y, 0 pigment { checker rgb 0.9, rgb 0.3 } }
#declare I = 0;
#while (I < 8)
  sphere { <4 * sin(I * pi / 4), 1, 4 * cos(I * pi / 4)>, 0.8
    pigment { rgb <mod(I, 2), mod(I, 3) / 2, mod(I, 4) / 3> } }
  #declare I = I + 1;
#end
