// isosurface_nan.pov - isosurfaces whose function is not a number in
// places (tests/test_isosurface_nan.sh).  povray 3.7 finds no crossing
// in a stretch of the ray with a NaN at either end and does not halve it
// further (lib/trace/obj_isosurface.c):
//   0: NaN outside the unit sphere, inside where r < 0.87: nothing drawn;
//   1: inside for z < 0.5, NaN behind (open container): nothing, no
//      surface at the NaN's edge;
//   2: a sphere behind a slab of NaN: drawn (the ray is not given up);
//   3: a sphere whose middle is cut by a slab of NaN: nothing drawn.
#version 3.7;
#ifndef (Case) #declare Case = 0; #end
global_settings { assumed_gamma 1 }
camera { location <0, 0, -6> look_at 0 angle 30 }
light_source { <-5, 5, -10> rgb 1 }
background { rgb <0, 0, 0.2> }
#declare F = finish { ambient 0.2 diffuse 0.8 }
#declare P = pigment { checker rgb <1, 0.5, 0.2> rgb <0.2, 1, 0.5> scale 0.25 }
#switch (Case)
#case (0)
isosurface { function { 0.5 - sqrt(1 - x*x - y*y - z*z) }
  contained_by { box { -2, 2 } } max_gradient 4 pigment { P } finish { F } }
#break
#case (1)
isosurface { function { -1 + 0*sqrt(0.5 - z) }
  contained_by { box { -1, 1 } } max_gradient 4 open
  pigment { P } finish { F } }
#break
#case (2)
isosurface { function { 0.1*(x*x + y*y + (z-0.5)*(z-0.5) - 0.81)
    + 0*sqrt((z+1.75)*(z+1.75) - 0.0225) }
  contained_by { box { -2, 2 } } max_gradient 4 pigment { P } finish { F } }
#break
#case (3)
isosurface { function { x*x + y*y + z*z - 1 + 0*sqrt(z*z - 0.01) }
  contained_by { box { -2, 2 } } max_gradient 4 pigment { P } finish { F } }
#break
#end
