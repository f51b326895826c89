// specular.pov - Blinn specular highlights: finish { specular roughness }.
//
// Rows of spheres with roughness 0.2 down to 0.001 and specular 1 and
// 0.4 (POV-Ray reference, "Specular Highlight"), plus brilliance, which
// sharpens the fall-off of the diffuse term.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -9> look_at <0, 0, 0> angle 55 }
light_source { <-10, 10, -10>, rgb 1 }
light_source { <10, 2, -6>, rgb 0.3 }
background { rgb 0.1 }

#declare Ball = sphere { 0, 0.8 }
#declare Base = color red 0.8 green 0.25 blue 0.15;

object { Ball pigment { Base } finish { specular 1 roughness 0.2 }
         translate <-3.6, 1, 0> }
object { Ball pigment { Base } finish { specular 1 roughness 0.05 }
         translate <-1.8, 1, 0> }
object { Ball pigment { Base } finish { specular 1 roughness 0.02 }
         translate <0, 1, 0> }
object { Ball pigment { Base } finish { specular 1 roughness 0.005 }
         translate <1.8, 1, 0> }
object { Ball pigment { Base } finish { specular 1 roughness 0.001 }
         translate <3.6, 1, 0> }

object { Ball pigment { Base } finish { specular 0.4 roughness 0.05
         brilliance 0.5 } translate <-3.6, -1, 0> }
object { Ball pigment { Base } finish { specular 0.4 roughness 0.05
         brilliance 1 } translate <-1.8, -1, 0> }
object { Ball pigment { Base } finish { specular 0.4 roughness 0.05
         brilliance 2 } translate <0, -1, 0> }
object { Ball pigment { Base } finish { specular 0.4 roughness 0.05
         brilliance 4 } translate <1.8, -1, 0> }
object { Ball pigment { Base } finish { specular 0.4 roughness 0.05
         brilliance 8 } translate <3.6, -1, 0> }
