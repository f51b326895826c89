// primitives.pov - every finite and infinite shape of the slice.
//
// sphere, box, cylinder, cone (truncated and pointed), disc (with and
// without a hole), triangle and plane (POV-Ray reference, "Finite Solid
// Primitives", "Finite Patch Primitives", "Infinite Solid Primitives").
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -10> look_at <0, 1, 0> angle 52 }
light_source { <-7, 12, -9>, rgb 1 }
light_source { <8, 6, -6>, rgb 0.35 }
background { rgb <0.6, 0.7, 0.85> }

#declare F = finish { ambient 0.08 diffuse 0.75 phong 0.3 phong_size 30 }

plane { y, 0 pigment { rgb <0.55, 0.6, 0.5> } finish { F } }
sphere { <-3.5, 0.8, 0>, 0.8 pigment { rgb <0.9, 0.2, 0.2> } finish { F } }
box { <-2.2, 0, -0.6>, <-0.8, 1.4, 0.6> pigment { rgb <0.2, 0.7, 0.2> }
      finish { F } }
cylinder { <0, 0, 0>, <0, 1.6, 0>, 0.6 pigment { rgb <0.2, 0.3, 0.9> }
           finish { F } }
cone { <1.8, 0, 0>, 0.7, <1.8, 1.6, 0>, 0.25
       pigment { rgb <0.9, 0.8, 0.2> } finish { F } }
cone { <3.5, 0, 0>, 0.6, <3.5, 1.8, 0>, 0
       pigment { rgb <0.8, 0.3, 0.8> } finish { F } }
// A lying cylinder, its ends seen in profile.
cylinder { <-3, 0.35, -2.5>, <-1.5, 0.35, -2.5>, 0.35
           pigment { rgb <0.3, 0.8, 0.8> } finish { F } }
// Discs: a full one raised on edge, a washer lying down.
disc { <0.2, 1.0, 2.5>, <0, 0, -1>, 1 pigment { rgb <0.95, 0.5, 0.1> }
       finish { F } }
disc { <0, 0.01, -2.5>, y, 0.9, 0.4 pigment { rgb <0.1, 0.1, 0.1> }
       finish { F } }
// A triangle, coloured the same on both sides.
triangle { <1.5, 0, -2>, <3.5, 0, -2.8>, <2.6, 1.8, -2.3>
           pigment { rgb <0.9, 0.9, 0.9> } finish { F } }
