// image_gamma.pov - an image_map under assumed_gamma 2.2 ("Image File
// Gamma"): its colours go to the scene's gamma space, so ambient 1 shows
// the picture as it is, as POV-Ray 3.7 renders advanced/sunsethf.pov.
// test.png and fract003.png are in POV-Ray's include directory.
#version 3.7;
global_settings { assumed_gamma 2.2 }
camera { orthographic location <0.5, 0.5, -10> look_at <0.5, 0.5, 0>
         right x * 4 / 3 up y }
plane { z, 0 pigment { image_map { png "test.png" } }
  finish { ambient 1 diffuse 0 } clipped_by { box { <-1, -1, -1>, <0.5, 2, 1> } } }
plane { z, 0 pigment { image_map { png "fract003.png" } }
  finish { ambient 0.5 diffuse 0.5 } clipped_by { box { <0.5, -1, -1>, <2, 2, 1> } } }
light_source { <0, 0, -100> rgb 1 }
