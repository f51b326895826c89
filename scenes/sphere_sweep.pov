// sphere_sweep.pov - sphere sweeps (POV-Ray reference, "Sphere Sweep"):
// a linear one with changing radii, a b_spline and a cubic_spline loop
// through the same points, one of them scaled unevenly and rotated.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -10> look_at <0, 1, 0> angle 50 }
light_source { <-6, 12, -8>, rgb 1 }
light_source { <7, 5, -6>, rgb 0.3 }
background { rgb <0.6, 0.7, 0.85> }

#declare F = finish { ambient 0.1 diffuse 0.75 phong 0.4 }

plane { y, 0 pigment { rgb <0.55, 0.6, 0.5> } finish { F } }
sphere_sweep { linear_spline 4,
  <-1, 0, 0>, 0.25, <0, 1.5, 0>, 0.5, <1, 0.5, 0.5>, 0.15, <1.5, 1.8, 0>, 0.3
  translate <-3, 0.3, 0> pigment { rgb <0.9, 0.3, 0.2> } finish { F } }
sphere_sweep { b_spline 6,
  <-1.5, 0, 0>, 0.3, <-1, 2, 0>, 0.5, <0, 0, -1>, 0.2, <1, 2, 0>, 0.4,
  <1.5, 0, 0>, 0.3, <2, 1, 1>, 0.1
  tolerance 1e-4
  translate <0, 0.4, 0> pigment { rgb <0.2, 0.5, 0.9> } finish { F } }
sphere_sweep { cubic_spline 6,
  <-1, -1, 0>, 0.2, <-1, 0, 0>, 0.3, <0, 1, 0>, 0.25, <1, 0, 0>, 0.35,
  <1, 1.5, 0>, 0.2, <2, 2, 0>, 0.2
  scale <1, 1.3, 1> rotate y * 30
  translate <3.2, 0.5, 0> pigment { rgb <0.3, 0.8, 0.4> } finish { F } }
