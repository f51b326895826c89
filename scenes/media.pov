// media.pov - participating media: a spotlight's beam through
// atmospheric scattering media, a glowing ball of emission with a
// spherical density and colour_map, an absorbing box, a Henyey-Greenstein
// scatterer in a hollow sphere, and shadows dimmed by media.
//
// POV-Ray reference, "Media", "Object Media", "Atmospheric Media",
// "Density".  Densities use smooth patterns only (spherical, gradient):
// zRcube's noise is not POV-Ray's bit for bit.  Method 3 without jitter
// is deterministic in both renderers.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2, -9> look_at <0, 1.2, 0> angle 60 }
light_source { <-6, 9, -7>, rgb 0.6 media_interaction off }
light_source {
  <3, 7, -1>, rgb 1.5
  spotlight point_at <1.5, 0, 1> radius 8 falloff 12 tightness 1
}

plane { y, 0 pigment { checker rgb 0.8 rgb 0.5 } }
plane { -z, -6 pigment { rgb <0.4, 0.45, 0.6> } }

// Thin haze everywhere: the spotlight's cone shows.
media { scattering { 1, 0.03 } }

// A glowing ball: emission strongest at its centre.
sphere { 0, 1 hollow no_shadow
  pigment { rgbt 1 }
  interior { media {
    emission 1.5
    density { spherical color_map { [0 rgb 0] [0.5 rgb <0.6, 0.2, 0>]
                                    [1 rgb <1, 0.9, 0.4>] } }
  } }
  translate <-2.2, 1.2, 0>
}

// An absorbing box: blue-green shows through, its shadow tinted.
box { <-0.8, 0, -0.8>, <0.8, 1.6, 0.8> hollow
  pigment { rgbt 1 }
  interior { media { absorption <0.9, 0.4, 0.2> } }
  rotate 30*y translate <0.2, 0, 1>
}

// Forward-scattering media in a clear sphere, lit by the spotlight.
sphere { <2.2, 1.1, -0.5>, 0.9 hollow
  pigment { rgbt 1 }
  interior { media {
    scattering { 5, <0.5, 0.6, 0.8> eccentricity 0.4 }
    absorption 0.1
    density { gradient y color_map { [0 rgb 0.2] [1 rgb 1] } scale 2
              translate 0.2*y }
  } }
}
