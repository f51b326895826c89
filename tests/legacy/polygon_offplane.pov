// Polygons whose points are not in one plane (forste's ex1/cylinder.pov):
// POV-Ray 3.7 draws nothing for one with a point more than 1e-10 off
// the plane of its first three points, whatever its size, without a
// word; zRcube warns.
// expect: the polygon's points are not in one plane
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -9> look_at 0 angle 30 }
background { rgb 0 }
#declare F = finish { ambient 1 diffuse 0 }
// 1e-10 off: drawn (top left: size 1; top right: size 100 scaled down).
polygon { 5, <-1,-1,0>, <1,-1,0>, <1,1,0>, <-1,1,1e-10>, <-1,-1,0>
  pigment { rgb <1, 0, 0> } finish { F } scale 0.5 translate <-0.8, 0.8, 0> }
polygon { 5, <-100,-100,0>, <100,-100,0>, <100,100,0>, <-100,100,1e-10>,
  <-100,-100,0>
  pigment { rgb <0, 1, 0> } finish { F } scale 0.005 translate <0.8, 0.8, 0> }
// 2e-10 off: not drawn (bottom left: size 0.01 scaled up; bottom right:
// the first three points in a line, the off point last but one).
polygon { 5, <-0.01,-0.01,0>, <0.01,-0.01,0>, <0.01,0.01,0>,
  <-0.01,0.01,2e-10>, <-0.01,-0.01,0>
  pigment { rgb <0, 0, 1> } finish { F } scale 50 translate <-0.8, -0.8, 0> }
polygon { 7, <-1,-1,0>, <0,-1,0>, <1,-1,0>, <1,0,0>, <1,1,0>,
  <-1,1,2e-10>, <-1,-1,0>
  pigment { rgb <1, 1, 0> } finish { F } scale 0.5 translate <0.8, -0.8, 0> }
// forste's polygon: far from flat, not drawn.
polygon { 7, <0,0,-1>, <0,0.1,-1>, <0,0,0>, <3,0,0>, <3,0.1,-1>, <3,0,-1>,
  <0,0,-1> pigment { rgb 1 } finish { F } rotate 90*y translate <-1.5, 0, 0> }
