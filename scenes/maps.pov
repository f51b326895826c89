// maps.pov - the map forms of POV-Ray 3.7's textures (reference,
// "Color Maps", "Pigment Maps and Pigment Lists", "Texture Maps",
// "Patterned Textures", "Average", "Pigment Pattern", "Material"):
// a pigment_map blending pigments along a gradient, block patterns of
// pigments and of textures, a texture_map whose entries have their own
// finishes, an average of two pigments, pigment_pattern, the legacy
// colour_map entry [a, b color C1 color C2], and a material.  Only exact
// patterns (checker, gradient, radial) so the picture is POV-Ray's.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5.5, -10.5> look_at <0, 0.8, 0> angle 55 }
light_source { <-6, 13, -9>, rgb 1 }
background { rgb <0.55, 0.6, 0.7> }

#declare F = finish { ambient 0.2 diffuse 0.7 }

// Floor: checker of two pigments, one itself a gradient.
plane { y, 0
  pigment { checker
            pigment { rgb <0.8, 0.8, 0.75> }
            pigment { gradient x color_map { [0 rgb <0.2, 0.3, 0.5>]
                                             [1 rgb <0.5, 0.2, 0.2>] } }
            scale 1.5 }
  finish { F } }

// pigment_map: solid red, then a checker, blended along y.
box { <-1, 0, -1>, <1, 2, 1>
  pigment { gradient y
            pigment_map { [0.0 rgb <0.9, 0.2, 0.1>]
                          [0.3 rgb <0.9, 0.2, 0.1>]
                          [0.7 checker rgb 1, rgb <0.1, 0.1, 0.4> scale 0.25]
                          [1.0 checker rgb 1, rgb <0.1, 0.1, 0.4> scale 0.25] }
            scale 2 }
  finish { F } rotate y * 20 translate <-3.4, 0, 0.6> }

// texture_map: a matte and a shiny texture along x.
#declare Matte = texture { pigment { rgb <0.2, 0.6, 0.3> } finish { F } }
#declare Shiny = texture { pigment { rgb <0.9, 0.8, 0.3> }
                           finish { ambient 0.1 diffuse 0.5 phong 0.8
                                    phong_size 40 } }
sphere { <0, 1.1, 0.4>, 1.1
  texture { gradient x
            texture_map { [0.0 Matte] [0.45 Matte]
                          [0.55 Shiny] [1.0 Shiny] }
            scale 1.1 translate x * 0.55 } }

// checker of textures, and the legacy colour_map entries.
#declare Legacy = color_map {
  [0.0, 0.5 color rgb <0.95, 0.95, 0.9> color rgb <0.3, 0.1, 0.5>]
  [0.5, 1.0 color rgb <0.3, 0.1, 0.5> color rgb <0.95, 0.6, 0.2>]
}
box { <-0.9, 0, -0.9>, <0.9, 1.8, 0.9>
  texture { checker
            texture { pigment { radial frequency 4 color_map { Legacy } }
                      finish { F } }
            texture { pigment { rgb <0.7, 0.1, 0.1> }
                      finish { ambient 0.1 diffuse 0.9 } }
            scale 0.6 }
  rotate y * -25 translate <3.4, 0, 0.8> }

// average of two gradients, and pigment_pattern of a checker.
cylinder { <0, 0, 0>, <0, 0.4, 0>, 1.0
  pigment { average
            pigment_map {
              [1 gradient x color_map { [0 rgb 0] [1 rgb <1, 0, 0>] }]
              [3 gradient z color_map { [0 rgb 0] [1 rgb <0, 0, 1>] }] }
            scale 0.7 }
  finish { F } translate <-1.8, 0, -2.8> }
cylinder { <0, 0, 0>, <0, 0.4, 0>, 1.0
  pigment { pigment_pattern { checker rgb 1, rgb 0 scale 0.5 }
            pigment_map { [0 rgb <0.1, 0.5, 0.9>]
                          [1 gradient x color_map { [0 rgb <1, 1, 0>]
                                                    [1 rgb <1, 0.4, 0>] }
                             scale 0.4] } }
  finish { F } translate <1.8, 0, -2.8> }

// A material: texture and interior together.
#declare Glass = material {
  texture { pigment { rgbf <0.8, 0.9, 1, 0.8> }
            finish { ambient 0 diffuse 0.1 phong 0.5 } }
  interior { ior 1.3 }
}
sphere { <0, 0.5, -3.6>, 0.5 material { Glass } }
