// superellipsoid.pov - superquadric ellipsoids (POV-Ray reference,
// "Superquadric Ellipsoid"): a rounded box, a rounded cylinder, the
// sphere e = n = 1, a pinched star (e, n > 2) and a rotated, scaled one.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -10> look_at <0, 1, 0> angle 50 }
light_source { <-6, 10, -8>, rgb 1 }
light_source { <7, 5, -6>, rgb 0.3 }
background { rgb <0.6, 0.7, 0.85> }

#declare F = finish { ambient 0.08 diffuse 0.75 phong 0.4 phong_size 40 }

plane { y, 0 pigment { rgb <0.55, 0.6, 0.5> } finish { F } }
superellipsoid { <0.2, 0.2> scale 0.8 rotate y * 30 translate <-3, 0.8, 0>
                 pigment { rgb <0.9, 0.3, 0.2> } finish { F } }
superellipsoid { <1, 0.15> rotate x * 90 scale <0.7, 0.9, 0.7>
                 translate <-1, 0.9, 0>
                 pigment { rgb <0.2, 0.5, 0.9> } finish { F } }
superellipsoid { <1, 1> scale 0.8 translate <0.9, 0.8, 0>
                 pigment { rgb <0.95, 0.85, 0.2> } finish { F } }
superellipsoid { <2.5, 2.5> scale 1.1 rotate <20, 30, 0>
                 translate <3, 1.2, 0.5>
                 pigment { rgb <0.3, 0.8, 0.4> } finish { F } }
superellipsoid { <0.5, 2> scale <1.2, 0.4, 0.6> rotate y * -20
                 translate <0.3, 0.4, -2.5>
                 pigment { rgb <0.8, 0.4, 0.8> } finish { F } }
