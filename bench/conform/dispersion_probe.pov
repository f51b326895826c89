// dispersion_probe.pov - POV-Ray 3.7's dispersion measured
// (bench/conform/dispersion_probe.py).  An orthographic camera looks
// along +z through a clear slab of thickness 1 turned 45 degrees about y
// at an emitting wall, white for x < 0 and black beyond.  A ray through
// the slab comes out parallel, moved along +x by
// d = sin 45 (1 - cos 45 / sqrt(n^2 - sin^2 45)) for its ior n, so the
// columns near x = -d show which of the spectrum's samples still see
// white: each edge gives a sample's ior, each level the colour the
// samples left carry.  Declare Ds (dispersion_samples), Dv (dispersion),
// Ior, and Cx, Rw (the centre and width of the view in x).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
#ifndef (Ds) #declare Ds = 7; #end
#ifndef (Dv) #declare Dv = 1.2; #end
#ifndef (Ior) #declare Ior = 1.5; #end
#ifndef (Cx) #declare Cx = -0.33; #end
#ifndef (Rw) #declare Rw = 0.16; #end
camera { orthographic location <Cx, 0, -5> look_at <Cx, 0, 0>
         right Rw*x up 0.01*y }
plane { z, 3
  pigment { gradient x color_map { [0 rgb 1] [0.5 rgb 1] [0.5 rgb 0] [1 rgb 0] }
            scale 20 translate -10*x }
  finish { ambient 0 diffuse 0 emission 1 } }
box { <-3, -3, -0.5>, <3, 3, 0.5> rotate 45*y
  pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 }
  interior { ior Ior dispersion Dv dispersion_samples Ds } }
