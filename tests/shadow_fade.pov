// shadow_fade.pov - shadows through clear blocks whose interiors fade
// light (fade_distance, fade_power 1), and through merges of several
// blocks (tests/test_shadow_fade.sh; lib/trace/shade.c shadow_fade,
// lib/trace/bvh.c visit_leaf), and fade_power 0.  A white floor lit from straight above
// by a parallel light, seen from above by an orthographic camera; the
// blocks are no_image unless the case needs the camera's ray inside one.
// IA: fade_distance 0.5; IB: 0.25; T: clear (filter F).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (Case) #declare Case = 1; #end
camera { orthographic sky z location <0, 10, 0> look_at <0, 0, 0>
         up z * 3 right x * 4 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
light_source { <0, 1000, 0>, rgb 0.5 parallel point_at 0 }
#declare F = (Case = 2 ? 0.5 : 1);
#declare T = texture { pigment { rgbf <1, 1, 1, F> }
                       finish { ambient 0 diffuse 0 } }
#declare IA = interior { fade_distance 0.5 fade_power 1 }
#declare IB = interior { fade_distance 0.25 fade_power 1 }
#macro Slab(Lo, Hi) box { <-100, Lo, -100>, <100, Hi, 100> texture { T } } #end
#switch (Case)
// 1: two blocks stacked in a merge, each its own interior: entered by
// one, left by the other, nothing faded (povray 1.00 of the light).
#case (1) merge { object { Slab(1, 1.5) interior { IA } }
                  object { Slab(1.5, 2) interior { IB } } no_image } #break
// 2: two blocks of filter 0.5 apart in a merge, no fading: all four
// surfaces filter (0.0625; the first two alone give 0.25).
#case (2) merge { object { Slab(1, 1.3) } object { Slab(1.7, 2) } no_image }
#break
// 3: the same merge, clear, fading: each block faded (0.2841).
#case (3) merge { object { Slab(1, 1.3) interior { IA } }
                  object { Slab(1.7, 2) interior { IB } } no_image } #break
// 4: overlapping blocks 1..1.7 (IA) and 1.3..2 (IB): 1.3..1.7 faded by
// IA, 1.7..2 by IB (0.2525; the reverse order gives 0.2404).
#case (4) object { Slab(1, 1.7) interior { IA } no_image }
          object { Slab(1.3, 2) interior { IB } no_image } #break
// 5: a clear block without fading inside a fading one: only the
// stretch after it is faded (0.625).
#case (5) object { Slab(1, 2) interior { IA } no_image }
          object { Slab(1.3, 1.7) no_image } #break
// 6: the floor inside a fading block the camera sees it through: the
// shadow ray starts inside and is faded over its 2 units (0.2).
#case (6) object { Slab(-1, 2) interior { IA } } #break
// 7: as 6 with a block of IB inside (shadow 0.2404, times 0.3846 seen
// through it: 0.0925).
#case (7) object { Slab(-1, 2) interior { IA } }
          object { Slab(1.3, 1.7) interior { IB } } #break
// 8: a merge whose parts take its interior: faded over the whole
// (0.3333).
#case (8) merge { Slab(1, 1.5) Slab(1.5, 2) interior { IA } no_image } #break
// 9: a block 1 thick of fade_distance 1, fade_power 0, seen through:
// the camera's ray is halved (the formula's (d / 1)^0 = 1), the shadow
// ray is not faded (0.5).
#case (9) object { Slab(1, 2) interior { fade_distance 1 fade_power 0 } }
#break
// 10: the same block with fade_power 1: both are halved (0.25).
#case (10) object { Slab(1, 2) interior { fade_distance 1 fade_power 1 } }
#break
// 11: two blocks stacked in a merge, the lower with IA, the upper with
// no interior: neither leaves nor enters IA, nothing is faded (1.00;
// with the lower's interior given to the upper, 0.3333).
#case (11) merge { object { Slab(1, 1.5) interior { IA } } Slab(1.5, 2)
                   no_image } #break
// 12: the same seen through: the camera's ray is not faded, but it
// went into IA by the lower block's bottom face, so the shadow ray,
// leaving IA by that face, fades the 1 unit up from the floor (0.3333).
#case (12) merge { object { Slab(1, 1.5) interior { IA } } Slab(1.5, 2) }
#break
#end
