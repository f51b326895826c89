// grazing_normal.pov: a bumpy chrome plane seen at grazing angles
// (templates/Basic_Scenes/Sea_blue_sky.pov's water): some tilted
// normals mirror the eye ray into the plane (tests/test_grazing_normal.sh).
camera { location <0, 1, -3> look_at <0, 0.6, 10> angle 70 }
light_source { <-100, 200, -300> rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.7, 0.8, 1>] [1 rgb <0.1, 0.3, 0.8>] } } }
plane { y, 0
  texture {
    pigment { rgb <0.4, 0.4, 0.4> }
    finish { ambient 0.1 diffuse 0.1 reflection 0.6 specular 0.6 roughness 0.01 }
    normal { bumps 0.25 scale 0.125 turbulence 0.5 }
  }
}
