// patterns.pov - the patterns whose definitions are exact, so zRcube
// must paint them as POV-Ray does: checker, gradient, brick, hexagon,
// marble without turbulence, radial, onion and wood, with colour lists,
// color_map interpolation and sharp steps, frequency, a wave type and
// pattern transforms that follow their objects (POV-Ray reference,
// "Pattern", "Color Maps", "Color List Pigments", "Waveforms").
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 6, -11> look_at <0, 0.8, 0> angle 55 }
light_source { <-6, 14, -10>, rgb 1 }
background { rgb <0.55, 0.65, 0.8> }

#declare F = finish { ambient 0.25 diffuse 0.7 }
#declare Rainbow = color_map {
  [0.0 rgb <0.9, 0.1, 0.1>]
  [0.5 rgb <0.9, 0.9, 0.2>]
  [0.5 rgb <0.1, 0.3, 0.9>]
  [1.0 rgb <0.1, 0.8, 0.3>]
}

plane { y, 0
  pigment { checker rgb <0.85, 0.85, 0.8>, rgb <0.25, 0.3, 0.35> scale 1.5 }
  finish { F } }
// Brick wall with its default colours, scaled down.
box { <-6, 0, 3>, <6, 3.5, 3.5>
  pigment { brick scale 0.12 } finish { F } }
// A gradient block, the pattern rotated with the object.  The scale
// keeps the top face (y = 2, 2.86 periods) off the map's sharp step at
// 0.5, where rounding alone would pick the colour.
box { <-1, 0, -1>, <1, 2, 1>
  pigment { gradient y color_map { Rainbow } scale 0.7 }
  finish { F } rotate y * 30 translate <-3.6, 0, 0.5> }
// Marble sphere (triangle wave) and a sine-wave onion sphere.
sphere { <0, 1.1, 0.3>, 1.1
  pigment { marble color_map { [0 rgb 0.95] [1 rgb <0.3, 0.1, 0.5>] }
            scale 0.6 rotate z * 40 }
  finish { F } }
sphere { <3.4, 0.9, 0.3>, 0.9
  pigment { onion sine_wave frequency 2
            color_map { [0 rgb <1, 0.6, 0.1>] [1 rgb <0.2, 0.1, 0.05>] } }
  finish { F } }
// Hexagon tiles on a slab, radial and wood on discs in front.
box { <-5.5, 0, -4.5>, <-1.5, 0.2, -2>
  pigment { hexagon rgb <0.9, 0.2, 0.2>, rgb <0.95, 0.95, 0.95>,
            rgb <0.2, 0.4, 0.9> scale 0.35 }
  finish { F } }
cylinder { <0, 0, 0>, <0, 0.3, 0>, 1.1
  pigment { radial frequency 6 color_map { Rainbow } }
  finish { F } translate <0.2, 0, -3.2> }
cylinder { <0, 0, 0>, <0, 0.3, 0>, 1.1
  pigment { wood color_map { [0 rgb <0.8, 0.55, 0.3>]
                             [1 rgb <0.4, 0.2, 0.08>] }
            scale 0.15 rotate x * 90 }
  finish { F } translate <3.2, 0, -3.0> }
