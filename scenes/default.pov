// default.pov - the zRcube demo scene, rendered by `make demo`.
//
// A glass sphere, a mirror sphere, a row of coloured balls made with the
// zRcube #zfor extension, and a few solids on a warm floor under two
// lights.  It uses only the language slice zRcube supports today, so
// colours are declared here rather than taken from colors.inc.
// POV-Ray cannot read #zfor; default.ref.pov is the same scene with
// #while for a reference render.
#version 3.7;

global_settings {
  assumed_gamma 1.0
  max_trace_level 10
  ambient_light rgb <1, 1, 1>
}

#declare Floor_Colour = rgb <0.75, 0.62, 0.48>;
#declare Sky_Colour = rgb <0.45, 0.6, 0.85>;
#declare Gold = rgb <0.95, 0.7, 0.25>;
#declare Teal = rgb <0.1, 0.55, 0.55>;
#declare Plum = rgb <0.55, 0.2, 0.45>;

#declare Shiny = finish { ambient 0.05 diffuse 0.75 phong 0.6 phong_size 60 }
#declare Matte = finish { ambient 0.05 diffuse 0.85 }

camera {
  location <0, 2.9, -9.5>
  look_at <0, 0.8, 0.4>
  angle 48
}

light_source { <-6, 10, -8>, rgb <1, 0.96, 0.9> }
light_source { <7, 6, -3>, rgb <0.35, 0.4, 0.5> }

background { Sky_Colour }

plane {
  y, 0
  pigment { Floor_Colour }
  finish { ambient 0.05 diffuse 0.8 reflection 0.08 }
}

// A back wall, so reflections and refractions have something to show.
plane {
  z, 7
  pigment { rgb <0.85, 0.85, 0.8> }
  finish { Matte }
}

// Glass: almost fully filtering, refracting with the index of crown glass.
sphere {
  <-1.6, 1.1, 0.2>, 1.1
  pigment { rgbf <0.97, 1, 0.98, 0.93> }
  finish { ambient 0 diffuse 0.05 specular 0.8 roughness 0.003
           reflection 0.08 }
  interior { ior 1.5 }
}

// Mirror.
sphere {
  <1.5, 1.0, 1.2>, 1.0
  pigment { rgb <0.9, 0.9, 0.92> }
  finish { ambient 0 diffuse 0.05 reflection 0.85 specular 0.6
           roughness 0.01 metallic }
}

// Solids.
box {
  <-0.6, 0, -0.6>, <0.6, 1.2, 0.6>
  pigment { Gold }
  finish { ambient 0.05 diffuse 0.6 specular 0.5 roughness 0.02
           metallic reflection 0.25 }
  rotate y * 30
  translate <3.4, 0, 2.6>
}
cylinder {
  <0, 0, 0>, <0, 1.6, 0>, 0.45
  pigment { Teal }
  finish { Shiny }
  translate <-3.6, 0, 2.2>
}
cone {
  <0, 0, 0>, 0.6, <0, 1.4, 0>, 0
  pigment { Plum }
  finish { Shiny }
  translate <0.1, 0, 2.6>
}

// A row of seven balls whose colour runs around the hue circle.
#zfor (7)
  sphere {
    <-2.7 + zr * 0.9, 0.28, -2.4>, 0.28
    pigment { rgb <0.5 + 0.45 * cos(zr * 0.9),
                   0.5 + 0.45 * cos(zr * 0.9 - 2.094),
                   0.5 + 0.45 * cos(zr * 0.9 + 2.094)> }
    finish { Shiny }
  }
#zend
