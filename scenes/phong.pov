// phong.pov - Phong highlights: finish { phong phong_size }.
//
// Five spheres from broad to tight highlights (phong_size 5 to 200), the
// upper row with phong 1, the lower with phong 0.4 (POV-Ray reference,
// "Phong Highlights").
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -9> look_at <0, 0, 0> angle 55 }
light_source { <-10, 10, -10>, rgb 1 }
background { rgb 0.1 }

#declare Ball = sphere { 0, 0.8 }
#declare Base = rgb <0.2, 0.35, 0.8>;

object { Ball pigment { Base } finish { phong 1 phong_size 5 }
         translate <-3.6, 1, 0> }
object { Ball pigment { Base } finish { phong 1 phong_size 15 }
         translate <-1.8, 1, 0> }
object { Ball pigment { Base } finish { phong 1 phong_size 40 }
         translate <0, 1, 0> }
object { Ball pigment { Base } finish { phong 1 phong_size 90 }
         translate <1.8, 1, 0> }
object { Ball pigment { Base } finish { phong 1 phong_size 200 }
         translate <3.6, 1, 0> }

object { Ball pigment { Base } finish { phong 0.4 phong_size 5 }
         translate <-3.6, -1, 0> }
object { Ball pigment { Base } finish { phong 0.4 phong_size 15 }
         translate <-1.8, -1, 0> }
object { Ball pigment { Base } finish { phong 0.4 phong_size 40 }
         translate <0, -1, 0> }
object { Ball pigment { Base } finish { phong 0.4 phong_size 90 }
         translate <1.8, -1, 0> }
object { Ball pigment { Base } finish { phong 0.4 phong_size 200 }
         translate <3.6, -1, 0> }
