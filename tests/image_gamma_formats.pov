// image_gamma_formats.pov - "gamma G" and "gamma srgb" after an
// image_map's file name for every format of stored samples ("Gamma in
// Input Images": "This applies in all contexts and to all file formats
// without exception"), and a TIFF's samples taken in the working space.
// tests/test_image_gamma_formats.sh writes g.bmp, g.ppm, g.tiff and
// g.png (32 x 16, eight flat 8 x 8 blocks) and copies
// tests/image_gamma.jpg (the same blocks, quality 100, no subsampling)
// to g.jpg.  Declare=K=1..11 under assumed_gamma 1; K=21..31 are the
// same under assumed_gamma 2.2.
#version 3.7;
#ifndef (K) #declare K = 1; #end
#declare C = (K > 20 ? K - 20 : K);
global_settings { assumed_gamma (K > 20 ? 2.2 : 1.0) }
camera { orthographic location <0.5, 0.5, -5> look_at <0.5, 0.5, 0>
         right x up y }
#declare F = finish { ambient 1 diffuse 0 }
#switch (C)
#case (1) plane { z, 0 pigment { image_map { jpeg "g.jpg" } } finish { F } } #break
#case (2) plane { z, 0 pigment { image_map { jpeg "g.jpg" gamma 1.8 } } finish { F } } #break
#case (3) plane { z, 0 pigment { image_map { jpeg "g.jpg" gamma srgb } } finish { F } } #break
#case (4) plane { z, 0 pigment { image_map { jpeg "g.jpg" gamma 1.0 } } finish { F } } #break
#case (5) plane { z, 0 pigment { image_map { bmp "g.bmp" gamma 1.8 } } finish { F } } #break
#case (6) plane { z, 0 pigment { image_map { ppm "g.ppm" gamma 1.8 } } finish { F } } #break
#case (7) plane { z, 0 pigment { image_map { ppm "g.ppm" } } finish { F } } #break
#case (8) plane { z, 0 pigment { image_map { bmp "g.bmp" } } finish { F } } #break
#case (9) plane { z, 0 pigment { image_map { png "g.png" gamma 1.8 } } finish { F } } #break
#case (10) plane { z, 0 pigment { image_map { tiff "g.tiff" gamma 1.8 } } finish { F } } #break
#case (11) plane { z, 0 pigment { image_map { tiff "g.tiff" } } finish { F } } #break
#end
