// layered.pov - layered textures (POV-Ray reference, "Layered
// Textures"): each layer lit with its own finish and normal, the layers
// below showing through its pigment's transmit and filter (filter tints
// them by the layer's colour); a declared layered texture; a texture
// given to an object that already has one, which goes on top as a layer;
// and "texture { Layered pigment {...} }", which changes the bottom layer.
// Only exact patterns (checker, gradient) so the picture is POV-Ray's.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -10> look_at <0, 0.9, 0> angle 52 }
light_source { <-5, 12, -9>, rgb 1 }
background { rgb <0.5, 0.6, 0.75> }

#declare F = finish { ambient 0.2 diffuse 0.7 }

// Floor: a checker under stripes that are clear half of the time.
plane { y, 0
  texture { pigment { checker rgb <0.8, 0.8, 0.75>, rgb <0.3, 0.35, 0.4> }
            finish { F } }
  texture { pigment { gradient x
                      color_map { [0.0 rgbt <0.9, 0.2, 0.1, 0.3>]
                                  [0.4 rgbt <0.9, 0.2, 0.1, 0.3>]
                                  [0.4 rgbt 1]
                                  [1.0 rgbt 1] }
                      scale 3 }
            finish { ambient 0.1 diffuse 0.5 } } }

// A declared three-layer texture: solid blue bottom, a transmit
// gradient, then filter bands with a phong highlight of their own.
#declare Layers =
  texture { pigment { rgb <0.1, 0.2, 0.8> } finish { F } }
  texture { pigment { gradient y
                      color_map { [0 rgbt <1, 1, 0.2, 0>]
                                  [1 rgbt <1, 1, 0.2, 1>] } scale 2.2 }
            finish { F } }
  texture { pigment { gradient x
                      color_map { [0.0 rgbf <1, 0.3, 0.3, 0.9>]
                                  [0.5 rgbf <1, 0.3, 0.3, 0.9>]
                                  [0.5 rgbt 1]
                                  [1.0 rgbt 1] }
                      scale 0.8 }
            finish { phong 0.6 phong_size 30 ambient 0.1 diffuse 0.4 } }

sphere { <-2.4, 1.1, 0>, 1.1 texture { Layers } }

// The same layers with another bottom pigment, moved with the object.
box { <-0.9, 0, -0.9>, <0.9, 1.8, 0.9>
  texture { Layers pigment { rgb <0.2, 0.7, 0.3> } }
  rotate y * 25 translate <0.6, 0, 0.8> }

// An object that has a texture, given another one on top.
#declare Ball = sphere { 0, 1
  texture { pigment { checker rgb <0.9, 0.9, 0.9>, rgb <0.2, 0.2, 0.2>
                      scale 0.5 }
            finish { F } } }
object { Ball
  texture { pigment { rgbt <0.9, 0.5, 0.1, 0.5> } finish { F } }
  translate <3.0, 1, 0> }

// A disc whose only layer above the bottom is fully clear.
disc { <0, 0.01, 0>, y, 0.9
  texture { pigment { rgb <0.9, 0.8, 0.2> } finish { F } }
  texture { pigment { rgbt 1 } }
  translate <-0.6, 0, -2.6> }
