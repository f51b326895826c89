// media2.pov - more media: Mie (hazy, murky) and Rayleigh scattering
// lit by a point light, a density_map and a block pattern's list of
// densities, two media in one interior, media in a CSG difference, a
// declared media, and interior_texture on an open shell.
//
// POV-Ray reference, "Media Types", "Density Maps and Density Lists",
// "Multiple Density vs. Multiple Media", "Interior Texture".
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -10> look_at <0, 1, 0> angle 55 }
light_source { <0, 8, -4>, rgb 1.2 }

plane { y, 0 pigment { rgb 0.7 } }
plane { -z, -5 pigment { rgb <0.35, 0.3, 0.3> } }

#declare Glow = media { emission <0.2, 0.5, 1> }

// Three scattering phase functions, side by side.
#declare Kind = array[3] { 2, 3, 4 }
#for (I, 0, 2)
  sphere { <-3 + 3 * I, 3.3, 0>, 0.9 hollow pigment { rgbt 1 }
    interior { media { scattering { Kind[I], 0.4 } } } }
#end

// A density_map and a checker list of densities.
box { <-3.9, 0, -0.9>, <-2.1, 1.8, 0.9> hollow pigment { rgbt 1 }
  interior { media { emission 0.8
    density { gradient x density_map { [0 rgb 0] [0.5 rgb <1, 0.3, 0.1>]
                                       [1 rgb <0.2, 1, 0.2>] }
              scale 1.8 translate -3.9*x } } }
}
box { <-0.9, 0, -0.9>, <0.9, 1.8, 0.9> hollow pigment { rgbt 1 }
  interior {
    media { Glow density { checker density { rgb 1 } density { rgb 0.2 }
                           scale 0.6 } }
    media { absorption 0.6 }
  }
}

// Media in a difference: a sphere with a bite taken out.
difference {
  sphere { <3, 0.9, 0>, 0.9 }
  box { <3, 0.9, -1>, <4, 2, 1> }
  hollow pigment { rgbt 1 }
  interior { media { emission <1, 0.6, 0.2> absorption 0.5 } }
}

// A half shell: its inside wears the interior_texture.
difference {
  sphere { 0, 0.6 }
  sphere { 0, 0.55 }
  plane { z, 0 rotate -30*x }
  pigment { rgb <0.9, 0.9, 0.2> }
  interior_texture { pigment { rgb <0.1, 0.3, 0.9> } }
  translate <1.5, 0.6, -2.5>
}
