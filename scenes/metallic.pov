// metallic.pov - metallic finishes.
//
// finish { metallic } tints highlights with the surface colour, and with
// reflection it tints reflections too (POV-Ray reference, "Metallic
// Highlight Modifier").  Gold, copper and steel balls with specular,
// phong and reflection stand beside a plastic one for contrast.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }

camera { location <0, 2.5, -7> look_at <0, 0.8, 0> angle 50 }
light_source { <-5, 9, -7>, rgb 1 }
light_source { <6, 4, -3>, rgb 0.4 }
background { rgb <0.3, 0.35, 0.45> }

plane { y, 0 pigment { rgb <0.35, 0.3, 0.3> } }
box { <-5, 0, 3>, <5, 3, 3.3> pigment { rgb <0.2, 0.5, 0.7> } }

sphere { <-2.4, 0.8, 0>, 0.8 pigment { rgb <1, 0.75, 0.3> }
  finish { ambient 0.05 diffuse 0.5 specular 0.8 roughness 0.02 metallic
           reflection 0.4 } }
sphere { <-0.8, 0.8, 0>, 0.8 pigment { rgb <0.85, 0.45, 0.3> }
  finish { ambient 0.05 diffuse 0.5 phong 0.9 phong_size 50 metallic 0.8
           reflection 0.3 } }
sphere { <0.8, 0.8, 0>, 0.8 pigment { rgb <0.7, 0.72, 0.75> }
  finish { ambient 0.05 diffuse 0.3 specular 0.9 roughness 0.005 metallic
           reflection 0.6 } }
sphere { <2.4, 0.8, 0>, 0.8 pigment { rgb <0.1, 0.6, 0.2> }
  finish { ambient 0.05 diffuse 0.7 specular 0.8 roughness 0.02 } }
