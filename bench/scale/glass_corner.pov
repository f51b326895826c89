// bench/balance.sh: a scene whose cost sits in one corner of the image:
// a glass sphere (reflection and refraction, several bounces) in the top
// left, a plain floor and sky elsewhere.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 12 }
camera { location <0, 1, -5> look_at <0, 1, 0> angle 60 }
light_source { <5, 8, -6>, rgb 1 }
sky_sphere { pigment { rgb <0.5, 0.6, 0.9> } }
plane { y, 0 pigment { checker rgb 0.8, rgb 0.3 } }
sphere { <-2.1, 2.2, 0>, 0.6
  pigment { rgbf <1, 1, 1, 0.95> }
  finish { reflection 0.2 phong 0.8 }
  interior { ior 1.5 } }
