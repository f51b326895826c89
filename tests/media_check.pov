// media_check.pov - a small media scene for tests/test_media_povray.sh:
// a spotlight's beam through scattering haze, an emitting ball with a
// spherical density, an absorbing box, a Henyey-Greenstein sphere with
// a gradient density and a Rayleigh one.  Every media block takes
// `samples Samples` (default 20): the test renders POV-Ray once as it
// is and once with Declare=Samples=80 to know POV-Ray's picture is
// converged before it compares zRcube's with it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (Samples) #declare Samples = 20; #end

camera { location <0, 2, -9> look_at <0, 1.2, 0> angle 60 }
light_source { <-6, 9, -7>, rgb 0.6 media_interaction off }
light_source { <3, 7, -1>, rgb 1.5
  spotlight point_at <1.5, 0, 1> radius 8 falloff 12 tightness 1 }

plane { y, 0 pigment { checker rgb 0.8 rgb 0.5 } }
plane { -z, -6 pigment { rgb <0.4, 0.45, 0.6> } }

media { scattering { 1, 0.03 } samples Samples }

sphere { 0, 1 hollow no_shadow pigment { rgbt 1 }
  interior { media { emission 1.5 samples Samples
    density { spherical color_map { [0 rgb 0] [0.5 rgb <0.6, 0.2, 0>]
                                    [1 rgb <1, 0.9, 0.4>] } } } }
  translate <-2.2, 1.2, 0> }

box { <-0.8, 0, -0.8>, <0.8, 1.6, 0.8> hollow pigment { rgbt 1 }
  interior { media { absorption <0.9, 0.4, 0.2> samples Samples } }
  rotate 30*y translate <0.2, 0, 1> }

sphere { <2.2, 1.1, -0.5>, 0.9 hollow pigment { rgbt 1 }
  interior { media { samples Samples
    scattering { 5, <0.5, 0.6, 0.8> eccentricity 0.4 } absorption 0.1
    density { gradient y color_map { [0 rgb 0.2] [1 rgb 1] } scale 2
              translate -0.5 * y } } } }

sphere { <-0.4, 3.1, 0.5>, 0.7 hollow pigment { rgbt 1 }
  interior { media { scattering { 4, 0.6 } samples Samples } } }
