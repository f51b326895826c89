// image_pattern.pov - image_pattern { } ("Image Pattern"): the grey of
// a picture as a pattern's value, for pigments, textures and normals
// (tests/test_image_pattern.sh, which writes image_pattern.png: 4 x 3
// pixels of distinct colours).  The picture lies on the unit square of
// the plane z = 0 (map_type 0), seen straight on: each of its pixels is a
// 4 x 4 block of a 16 x 12 render.  Declare=K=1..6.
#version 3.7;
#ifndef (K) #declare K = 1; #end
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0.5, 0.5, -5> look_at <0.5, 0.5, 0>
         right x up y }
#declare Grey = color_map { [0 rgb 0] [1 rgb 1] }
#switch (K)
// the grey, the file's numbers as they are
#case (1) plane { z, 0 pigment { image_pattern { png "image_pattern.png" }
                                 color_map { Grey } }
                  finish { ambient 1 diffuse 0 } } #break
// gamma 2.2 decodes them first
#case (2) plane { z, 0 pigment { image_pattern { png "image_pattern.png"
                                                 gamma 2.2 }
                                 color_map { Grey } }
                  finish { ambient 1 diffuse 0 } } #break
// interpolate 2: bilinear between pixel centres
#case (3) plane { z, 0 pigment { image_pattern { png "image_pattern.png"
                                                 interpolate 2 }
                                 color_map { Grey } }
                  finish { ambient 1 diffuse 0 } } #break
// once, at half size: 0 off the picture
#case (4) plane { z, 0 pigment { image_pattern { png "image_pattern.png"
                                                 once }
                                 color_map { Grey } scale 0.5 }
                  finish { ambient 1 diffuse 0 } } #break
// a texture_map
#case (5) plane { z, 0 texture { image_pattern { png "image_pattern.png" }
                    texture_map {
                      [0 pigment { rgb <1, 0, 0> } finish { ambient 1 diffuse 0 }]
                      [1 pigment { rgb <0, 0, 1> } finish { ambient 1 diffuse 0 }] } } }
  #break
// a normal, lit from the left
#case (6) light_source { <-100, 0, -100> rgb 1 parallel point_at 0 }
          plane { z, 0 pigment { rgb 1 }
                  normal { image_pattern { png "image_pattern.png"
                                           interpolate 2 } 1 scale 0.5 }
                  finish { ambient 0 diffuse 1 } } #break
#end
