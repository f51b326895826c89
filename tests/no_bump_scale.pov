// no_bump_scale: scaling changes the bumps' size but not their depth
// (mjhorvath's GSprites terrain textures: normal { bozo 32 scale 32 }
// no_bump_scale).  POV-Ray 3.7 renders bozo 32 scale 32 no_bump_scale as
// bozo 1 scale 32.  Four strips: top to bottom, in a texture, in a
// normal, the same without no_bump_scale (deep), and bozo 2 scale 4
// no_bump_scale in a texture scaled by 2 afterwards.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> look_at 0 right 16*x up 12*y }
light_source { <-30, 40, -50> rgb 1 }
#declare P = pigment { rgb 0.6 }
box { <-8, 3, 0>, <8, 6, 1>
  texture { pigment { P } normal { bozo 32 scale 32 } no_bump_scale } }
box { <-8, 0, 0>, <8, 3, 1>
  texture { pigment { P } normal { bozo 32 scale 32 no_bump_scale } } }
box { <-8, -3, 0>, <8, 0, 1>
  texture { pigment { P } normal { bozo 32 scale 32 } } }
box { <-8, -6, 0>, <8, -3, 1>
  texture { pigment { P } normal { bozo 2 scale 4 } no_bump_scale scale 2 } }
