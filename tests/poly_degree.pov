// poly_degree.pov - a quartic seen by rays nearly across its x axis
// (tests/test_poly_degree.sh): objects/quartic/teardrop.pov's Piriform,
// 4x^4 - 4x^3 + y^2 + z^2 = 0, with the camera at the height of the
// plane x = 0.5 through it and a view only 0.1 high, so the middle
// rows' rays have an x^4 term of 1e-11 beside terms of 16.
#version 3.7;
global_settings { assumed_gamma 1 }
quartic {
  < 4, 0, 0, -4, 0, 0, 0, 0, 0, 0,  0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 1, 0, 0, 0, 0,  0, 0, 1, 0, 0 >
  sturm
  rotate -90*z translate 0.5*y scale <3, 10, 3>
  pigment { rgb <0.3, 0.6, 0.8> }
  finish { ambient 0.2 diffuse 0.8 }
}
camera { location <0, 0, -12> look_at 0 right x*4/3 up y*0.1 }
light_source { <200, 30, -500> rgb 1 }
background { rgb 0.02 }
