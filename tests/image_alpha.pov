// image_alpha.pov - an image_map's alpha ("Using the Alpha Channel"):
// tests/test_image_alpha.sh writes alpha.png (4 x 2 RGBA, 8 bit),
// palette.png (4 x 2, a palette whose tRNS makes entry 1 100/255 and
// entry 2 0 opaque) and grey16.png (4 x 2 grey + alpha, 16 bit).  The
// picture lies on the unit square of z = 0 in front of a green plane;
// each of its pixels is a 4 x 4 block of a 16 x 8 render.
// Declare=K=1..19 (10-12: image_pattern's use_alpha; 13-17: 32-bit TGA
// and BMP files, alpha.tga, noattr.tga, alpha.bmp, clear.tga, clear.bmp;
// 18-19: TIFF RGBA, alpha.tiff and assoc.tiff; 20-24: premultiplied).
#version 3.7;
#ifndef (K) #declare K = 1; #end
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0.5, 0.5, -5> look_at <0.5, 0.5, 0>
         right x up y }
plane { z, 1 pigment { rgb <0.2, 0.4, 0.2> } finish { ambient 1 diffuse 0 } }
#declare F = finish { ambient 1 diffuse 0 }
#declare Grey = color_map { [0 rgb 0] [1 rgb 1] }
#switch (K)
#case (1) plane { z, 0 pigment { image_map { png "alpha.png" } } finish { F } } #break
#case (2) plane { z, 0 pigment { image_map { png "palette.png" } } finish { F } } #break
#case (3) plane { z, 0 pigment { image_map { png "grey16.png" } } finish { F } } #break
// "transmit all" adds to 1 - alpha, unclamped
#case (4) plane { z, 0 pigment { image_map { png "alpha.png" transmit all 0.3 } } finish { F } } #break
#case (5) plane { z, 0 pigment { image_map { png "alpha.png" transmit all 0.8 } } finish { F } } #break
#case (6) plane { z, 0 pigment { image_map { png "alpha.png" filter all 0.3 } } finish { F } } #break
#case (7) plane { z, 0 pigment { image_map { png "alpha.png" interpolate 2 transmit all 0.2 } } finish { F } } #break
// an entry's own transmit overrides its tRNS, "transmit all" every one
#case (8) plane { z, 0 pigment { image_map { png "palette.png" transmit 1, 0.5 } } finish { F } } #break
#case (9) plane { z, 0 pigment { image_map { png "palette.png" transmit all 0.3 } } finish { F } } #break
// image_pattern's use_alpha: the value is 1 - alpha
#case (10) plane { z, 0 pigment { image_pattern { png "alpha.png" use_alpha } color_map { Grey } } finish { F } } #break
#case (11) plane { z, 0 pigment { image_pattern { png "palette.png" use_alpha } color_map { Grey } } finish { F } } #break
#case (12) plane { z, 0 pigment { image_pattern { png "grey16.png" use_alpha } color_map { Grey } } finish { F } } #break
// 32-bit TGA and BMP: the fourth byte is straight alpha
#case (13) plane { z, 0 pigment { image_map { tga "alpha.tga" } } finish { F } } #break
#case (14) plane { z, 0 pigment { image_map { tga "noattr.tga" } } finish { F } } #break
#case (15) plane { z, 0 pigment { image_map { bmp "alpha.bmp" } } finish { F } } #break
#case (16) plane { z, 0 pigment { image_map { tga "clear.tga" } } finish { F } } #break
#case (17) plane { z, 0 pigment { image_map { bmp "clear.bmp" } } finish { F } } #break
// TIFF RGBA, unassociated and associated alpha
#case (18) plane { z, 0 pigment { image_map { tiff "alpha.tiff" } } finish { F } } #break
#case (19) plane { z, 0 pigment { image_map { tiff "assoc.tiff" } } finish { F } } #break
// premultiplied B after the file name, before or after its gamma
#case (20) plane { z, 0 pigment { image_map { png "alpha.png" premultiplied on } } finish { F } } #break
#case (21) plane { z, 0 pigment { image_map { tga "alpha.tga" premultiplied on gamma srgb } } finish { F } } #break
#case (22) plane { z, 0 pigment { image_map { tiff "alpha.tiff" gamma srgb premultiplied off } } finish { F } } #break
#case (23) plane { z, 0 pigment { image_map { png "alpha.png" premultiplied off } } finish { F } } #break
#case (24) plane { z, 0 pigment { image_map { tiff "alpha.tiff" premultiplied off } } finish { F } } #break
#end
