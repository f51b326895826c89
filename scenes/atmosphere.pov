// atmosphere.pov - a layered sky_sphere, a ground fog, a constant fog
// with transmit, and a partial rainbow.
//
// POV-Ray reference, "Sky Sphere", "Fog", "Rainbow".  The sky's
// pigments use gradients only: zRcube's noise is not POV-Ray's bit for
// bit, so a noisy sky would differ.  Ground fog follows the density
// povray 3.7 renders, 1 / (1 + x^2) above fog_offset.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 1.5, -8> look_at <0, 1.5, 0> angle 70 }
light_source { <5, 10, -6>, rgb 1 }

sky_sphere {
  pigment { gradient y color_map { [0.5 rgb <0.9, 0.9, 1>]
                                   [1.0 rgb <0.2, 0.3, 0.8>] }
            scale 2 translate -1 }
  pigment { gradient x color_map { [0.4 rgbt 1] [0.5 rgbf <1, 0.8, 0.8, 0.6>]
                                   [0.6 rgbt 1] } scale 0.5 }
  emission rgb <1, 0.95, 0.9>
  rotate 10*z
}
fog { fog_type 2 distance 4 fog_offset 0.3 fog_alt 0.6
      color rgbt <0.8, 0.85, 0.9, 0.1> }
fog { distance 60 rgbt <0.7, 0.7, 0.75, 0.3> }
rainbow {
  angle 20 width 6 distance 1e7 direction <0, -0.2, 1>
  arc_angle 140 falloff_angle 80 up y
  color_map { [0.0 rgbt <1, 0, 0, 0.6>] [0.5 rgbt <0, 1, 0, 0.6>]
              [1.0 rgbt <0, 0, 1, 0.6>] }
}

plane { y, 0 pigment { rgb <0.5, 0.6, 0.4> } }
sphere { <-2, 1, 2>, 1 pigment { rgb <0.9, 0.3, 0.2> } }
sphere { <2, 1, 6>, 1 pigment { rgb <0.2, 0.4, 0.9> } }
box { <-0.5, 0, 12>, <0.5, 4, 13> pigment { rgb 0.9 } }
