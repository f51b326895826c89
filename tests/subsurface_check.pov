// subsurface_check.pov - a broad translucent slab (or plane) under a
// parallel light, seen from above; tests/test_subsurface.sh declares
// Plane, PC (pigment), Dif (diffuse), LA (light tilt, degrees), SSS (1:
// subsurface on) and Gain (the light's brightness), and renders it
// small.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 0
  #if (SSS) mm_per_unit 10 subsurface { samples 100, 50 } #end }
camera { orthographic location <0, 10, 0> look_at <0, 0, 0>
  right x * 4 up z * 4 }
light_source { <0, 100, 0> rgb Gain parallel point_at 0 rotate z * LA }
#if (Plane) plane { y, 0 #else box { <-100, -10, -100>, <100, 0, 100> #end
  pigment { rgb PC }
  finish { ambient 0 diffuse Dif #if (SSS) subsurface { translucency 1 } #end }
  interior { ior 1.5 } }
