// fractals.pov - the fractal patterns, function patterns, pigment
// functions and transform blocks (POV-Ray reference, "Fractal Pattern",
// "Function Pattern", "Transformations"): their values are exact
// iteration counts and sums, so zRcube must paint them as POV-Ray does.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { orthographic location <0, 0, -10> look_at 0
         right x * 8 up y * 6 }
#declare F = finish { ambient 1 diffuse 0 }
#declare Fire = color_map {
  [0.0 rgb <0.1, 0.0, 0.3>]
  [0.3 rgb <0.9, 0.2, 0.1>]
  [0.7 rgb <1.0, 0.9, 0.2>]
  [1.0 rgb <0.05, 0.05, 0.05>]
}
// A transform identifier made of a block with inverse, used on a box
// and inside another block.
#declare Shift = transform { translate <2.7, -1.5, 0> inverse }
#declare Place = transform { scale 0.75 transform Shift }

// mandel, with the default colouring, top left.
box { <-1, -1, 0>, <1, 1, 0.1>
  pigment { mandel 40 color_map { Fire } translate <0.5, 0, 0> scale 0.9 }
  finish { F } translate <-2.7, 1.5, 0> }
// julia, exponent 3, interior and exterior colouring, top middle.
box { <-1, -1, 0>, <1, 1, 0.1>
  pigment { julia <0.353, 0.288>, 30 exponent 3
            interior 1, 1.5 exterior 6, 0.2 color_map { Fire } }
  finish { F } translate <0, 1.5, 0> }
// magnet 1 mandel, top right.
box { <-1, -1, 0>, <1, 1, 0.1>
  pigment { magnet 1 mandel 25 color_map { Fire } scale 1.5
            translate <0.8, 0, 0> }
  finish { F } translate <2.7, 1.5, 0> }
// A function pattern, bottom left.
#declare Ring = function(a, b) { sqrt(a * a + b * b) * 2 }
box { <-1, -1, 0>, <1, 1, 0.1>
  pigment { function { Ring(x, y) + 0.25 * sin(6 * x) } color_map { Fire } }
  finish { F } translate <-2.7, -1.5, 0> }
// A pigment function's channels mixed again by an average, as the
// stock woods scenes do, bottom middle.
#declare Cells = pigment { checker rgb <1, 0.3, 0>, rgb <0, 0.4, 1>
                           scale 0.5 }
#declare Cells_fn = function { pigment { Cells } }
#declare Pat_fn = function { pattern { gradient x scale 2 } }
box { <-1, -1, 0>, <1, 1, 0.1>
  pigment { average pigment_map {
    [function { Cells_fn(x, y, z).red * Pat_fn(x + 1, 0, 0) }
     color_map { [0 rgb 0] [1 rgb <3, 0, 0>] }]
    [function { Cells_fn(x, y, z).green }
     color_map { [0 rgb 0] [1 rgb <0, 3, 0>] }]
    [function { Cells_fn(x, y, z).blue }
     color_map { [0 rgb 0] [1 rgb <0, 0, 3>] }]
  } }
  finish { F } translate <0, -1.5, 0> }
// A box placed by transform identifiers, bottom right: Place inverted
// moves it by <2.7, -1.5>, then scales it by 4/3 about the origin.
box { <-1, -1, 0>, <1, 1, 0.1>
  pigment { gradient x color_map { Fire } transform Place }
  finish { F } transform { Place inverse } }
