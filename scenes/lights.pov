// lights.pov - the kinds of light source: a spotlight with a soft edge
// and tightness, a cylinder light, a parallel light, a faded point
// light, an adaptive area light with soft shadows and a looks_like
// lamp.
//
// POV-Ray reference, "Light Source": spotlights fall off between radius
// and falloff, cylinder lights within a tube, parallel lights along
// location - point_at everywhere, fade_distance/fade_power dim with
// distance, area lights are grids of points (adaptive sampling keeps
// the picture deterministic), and a looks_like object sits at the light
// and casts no shadow of it.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 7, -9> look_at <0, 0.5, 0.5> angle 55 }
background { rgb 0.05 }

light_source { <-3, 6, -2>, rgb <1, 0.9, 0.7>
  spotlight point_at <-2, 0, 1> radius 12 falloff 25 tightness 5 }
light_source { <3, 8, 2>, rgb <0.5, 0.7, 1>
  cylinder point_at <3, 0, 2> radius 1 falloff 1.8 }
light_source { <10, 10, -10>, rgb 0.25 parallel point_at 0 }
light_source { <0, 2.5, -1>, rgb 0.9 fade_distance 2 fade_power 2
  looks_like { sphere { 0, 0.2 pigment { rgb <1, 1, 0.6> }
                        finish { ambient 1 diffuse 0 } } } }
light_source { <-1, 9, -6>, rgb 0.35
  area_light 3*x, 3*z, 5, 5 adaptive 1 }

plane { y, 0 pigment { rgb 0.8 } }
sphere { <-2, 1, 1>, 1 pigment { rgb <1, 0.4, 0.2> }
  finish { phong 0.6 } }
box { <2.3, 0, 1.3>, <3.7, 1.4, 2.7> pigment { rgb <0.3, 0.9, 0.4> } }
cylinder { <0.5, 0, 2>, <0.5, 2, 2>, 0.5 pigment { rgb 0.9 } }
