// pigment_keep.pov - a pigment that starts with a colour modifies the
// pigment it is given to (tests/test_pigment_keep.sh): B's pigment is a
// gradient x with a blue-green colour_map, scale 2; each case gives it
// a plain colour first, then a pattern.  Declare=K=1..16 (11-16: normals).
#ifndef (K) #declare K = 1; #end
camera { orthographic location <0, 0, -10> look_at 0 right 8*x up 6*y }
background { rgb 0 }
#declare B = box { <-4, -3, 0>, <4, 3, 1>
  pigment { gradient x color_map { [0 rgb <0, 0, 1>] [1 rgb <0, 1, 0>] }
            scale 2 }
  finish { ambient 1 diffuse 0 } }
#declare U = union { box { <-4, -3, 0>, <0, 3, 1> } box { <0, -3, 0>, <4, 3, 1> }
  pigment { gradient x scale 2 } finish { ambient 1 diffuse 0 } }
#declare Grey = pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } }
#macro Grey_map() gradient x color_map { [0 rgb 0] [1 rgb 1] } #end
// N's normal: a sine-wave gradient x of bump size 1, period 2, lit from the
// left, so the shading shows the pattern's phase and period.
#declare N = box { <-4, -3, 0>, <4, 3, 1>
  pigment { rgb 1 } normal { gradient x 1 sine_wave scale 2 }
  finish { ambient 0 diffuse 1 } }
#declare Light = light_source { <-60, 0, -100> rgb 1 parallel point_at 0 }
#switch (K)
// a pigment identifier replaces the whole pigment: period 1
#case (1) object { object { B pigment { rgb <1, 0, 0> } } pigment { Grey } } #break
// the colour keeps B's scale 2 and colour_map for the pattern given next
#case (2) object { object { B pigment { rgb <1, 0, 0> } } pigment { gradient x } } #break
// a scale after the colour composes with the kept one: period 1
#case (3) object { object { B pigment { rgb <1, 0, 0> scale 0.5 } }
                   pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } } } #break
// a union's pigment, moved with the object (church-window.pov's way)
#case (4) #declare R = object { U pigment { rgb <1, 0, 0> } scale 0.5 }
          object { R pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } } } #break
// the colour alone is drawn plain
#case (5) object { B pigment { rgb <1, 0, 0> } } #break
// a pattern named later keeps the modifiers of the pigment it modifies:
// turbulence with octaves 1
#case (6) object { object { B pigment { octaves 1 turbulence 0.5 } } pigment { Grey_map() } } #break
// frequency 2
#case (7) object { object { B pigment { frequency 2 } } pigment { Grey_map() } } #break
// phase 0.5
#case (8) object { object { B pigment { phase 0.5 } } pigment { Grey_map() } } #break
// a turbulence warp
#case (9) object { object { B pigment { warp { turbulence 0.5 } } } pigment { Grey_map() } } #break
// triangle_wave
#case (10) object { object { B pigment { triangle_wave } } pigment { Grey_map() } } #break
// normal blocks modify a normal the same way: a pattern named later keeps
// frequency 2, phase 0.5, scallop_wave, turbulence, a warp
#case (11) Light object { object { N normal { frequency 2 } } normal { gradient x 1 } } #break
#case (12) Light object { object { N normal { phase 0.5 } } normal { gradient x 1 } } #break
#case (13) Light object { object { N normal { scallop_wave } } normal { gradient x 1 } } #break
#case (14) Light object { object { N normal { octaves 1 turbulence 0.5 } } normal { gradient x 1 } } #break
#case (15) Light object { object { N normal { warp { turbulence 0.5 } } } normal { gradient x 1 } } #break
// the normal alone, for the record
#case (16) Light object { N } #break
#end
