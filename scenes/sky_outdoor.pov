// golden: skip compared with povray's render in tests/test_gi_cli.sh (SSIM)
// sky_outdoor.pov - an open scene lit by a sky and the sun: a ground
// plane, a few objects, a sky_sphere and POV-Ray's radiosity block with
// its defaults (issue 11).  Shadows take the sky's blue, and the objects
// bleed colour onto the ground.  zrcube's auto model picks the
// irradiance cache here (the sky lights the scene).
#version 3.7;
global_settings { assumed_gamma 1.0 radiosity { } }
camera { location <0, 2.5, -7> look_at <0, 0.8, 0> angle 50 }
light_source { <30, 50, -20> rgb 1.2 }
sky_sphere {
  pigment { gradient y color_map { [0 rgb <0.75, 0.85, 1.0>]
                                   [1 rgb <0.25, 0.45, 0.9>] } }
}
plane { y, 0 pigment { rgb 0.7 } finish { diffuse 0.8 } }
sphere { <-1.6, 1, 0>, 1 pigment { rgb <0.9, 0.2, 0.15> }
         finish { diffuse 0.8 } }
box { <0.2, 0, -0.6>, <1.4, 1.6, 0.6> rotate y * 25
      pigment { rgb <0.2, 0.7, 0.3> } finish { diffuse 0.8 } }
cylinder { <2.4, 0, 1.5>, <2.4, 2.2, 1.5>, 0.5
           pigment { rgb <0.9, 0.85, 0.6> } finish { diffuse 0.8 } }
