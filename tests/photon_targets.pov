// photon_targets.pov - tests/test_photon_targets.sh and
// bench/photon_targets.sh: which photons a target's lattice brings
// (lib/trace/photons.c).  Case 1: a clear slab of ior 1 that is a
// target, above a white floor, seen from above; case 2: a second such
// slab above it, overlapping half of it (povray lights the floor under
// the overlap as under one slab: a photon shot at one target that
// meets the other first is not kept); case 3: a glass ball that
// reflects and refracts photons, max_trace_level Mtl (default 5);
// case 4: case 3 with a shadowless light added (it shoots no photons);
// case 5: case 3 with a plain light added (it does); case 6: a mirror
// mesh with a texture per triangle, which reflects photons to the
// floor (the tracer reports such a mesh's hits by per-texture copies,
// which are the same target).
#version 3.7;
#ifndef (Case) #declare Case = 1; #end
#ifndef (Mtl) #declare Mtl = 5; #end
global_settings { assumed_gamma 1.0 max_trace_level Mtl
  photons { spacing #if (Case <= 2) 0.02 #else 0.01 #end } }
#if (Case = 6)
camera { location <0, 5, -10> look_at 0 }
light_source { <-300, 400, 200> rgb 1 }
plane { y, 0 pigment { rgb 1 } }
#declare Mirror = texture { pigment { rgb 0.5 } finish { reflection 0.8 } }
mesh {
  triangle { <1, 0.2, -1>, <1, 0.2, 1>, <1, 2, 1> texture { Mirror } }
  triangle { <1, 0.2, -1>, <1, 2, 1>, <1, 2, -1> texture { Mirror } }
  photons { target reflection on collect off }
}
#elseif (Case <= 2)
camera { orthographic location <0, 10, 0> look_at 0 right 8 * x up 6 * z }
light_source { <0, 100, 0> rgb 0.4 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
#declare Slab = box { <-2, 0, -1>, <2, 0.2, 1>
  pigment { rgbf 1 } finish { ambient 0 diffuse 0 } interior { ior 1 }
  photons { target refraction on collect off } }
object { Slab translate <-1, 1, 0> }
#if (Case = 2) object { Slab translate <1, 2, -0.5> } #end
#else
camera { location <0, 3, -3> look_at <0, 0.2, 0> angle 40 }
light_source { <-300, 400, 200> rgb 1 }
#if (Case = 4) light_source { <300, 400, 0> rgb 1 shadowless } #end
#if (Case = 5) light_source { <300, 400, 0> rgb 1 } #end
plane { y, -0.01 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
sphere { 0.3 * y, 0.3 pigment { rgbf <1, 1, 1, 0.9> }
  finish { ambient 0 diffuse 0 reflection 0.5 } interior { ior 1.5 }
  photons { target reflection on refraction on collect off } }
#end
