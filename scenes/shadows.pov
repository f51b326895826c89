// shadows.pov - shadows from several lights, shadowless lights,
// no_shadow objects and coloured shadows through filtering glass.
//
// POV-Ray reference, "Light Source" (shadowless), "no_shadow", and
// "Filter and transmit": light passing a filtering surface takes its
// colour, light passing a transmitting one keeps its own.  Shadow rays
// are not bent by refraction (POV-Ray does not model caustics), so the
// glass shadows are tinted copies of the outlines.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 6, -8> look_at <0, 0.5, 0.5> angle 55 }
light_source { <-4, 9, -3>, rgb <0.8, 0.8, 0.75> }
light_source { <5, 6, -2>, rgb <0.3, 0.3, 0.4> }
light_source { <0, 5, -8>, rgb 0.2 shadowless }
background { rgb 0.2 }

plane { y, 0 pigment { rgb 0.85 } }

// An opaque ball: two shadows, one per shadowing light.
sphere { <-2.5, 0.7, 0>, 0.7 pigment { rgb <0.8, 0.8, 0.8> } }
// Transparent objects float 0.01 above the floor: a face lying in the
// floor's plane would make the nearer of two equal hits a matter of
// rounding, in any renderer.
// Red filtering glass: a red shadow.
box { <-0.6, 0.01, -0.6>, <0.6, 1.4, 0.6>
      pigment { rgbf <1, 0.2, 0.2, 0.9> } finish { ambient 0 diffuse 0.1 }
      interior { ior 1.5 } translate <0, 0, 0.5> }
// Blue-tinted glass that transmits: a paler, untinted shadow.
sphere { <2.5, 0.8, 0>, 0.8
         pigment { rgbt <0.2, 0.3, 1, 0.7> } finish { ambient 0 diffuse 0.3 }
         interior { ior 1.0 } }
// Both at once, rgbft.
cylinder { <1, 0.01, 2.5>, <1, 1.5, 2.5>, 0.4
           pigment { rgbft <0.2, 1, 0.2, 0.5, 0.3> }
           finish { ambient 0 diffuse 0.2 } }
// Casts no shadow at all.
cone { <-1.3, 0, 2.5>, 0.5, <-1.3, 1.6, 2.5>, 0
       pigment { rgb <0.9, 0.6, 0.1> } no_shadow }
