// media_cells.pov - tests/test_media_cells.sh: how bright a thick medium
// is with POV-Ray's method 3 cells (lib/trace/media.c, gather_cell();
// bench/media_quadrature.py).  Case 1: a box of scattering {1, 2}
// absorption 1 lit from above, default samples (the issue's box, which
// came out 15-20% darker than povray's); case 2: an emitting, absorbing
// slab with samples 3 (two cells); case 3: emission whose density rises
// along the ray as z^2 with samples 5 (the mean of each cell's ends and
// middle; aa_threshold 100 keeps povray from halving cells, whose
// test zRcube only brackets); case 4: case 1 with Henyey-Greenstein
// scattering and intervals 3.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (Case) #declare Case = 1; #end
camera { orthographic location <0, 0, -5> look_at 0 right 4 * x up 3 * y }
background { rgb <0.1, 0.2, 0.3> }
light_source { <0, 10, 0>, rgb 1 }
box { <-1.5, -1, -1>, <1.5, 1, 1> hollow pigment { rgbt 1 }
  interior {
    #switch (Case)
    #case (1) media { scattering { 1, 2 } absorption 1 } #break
    #case (2) media { emission <0.5, 0.3, 0.2> absorption 2 samples 3 }
    #break
    #case (3) media { emission 1 absorption 0.5 samples 5 aa_threshold 100
      density { function { (z + 1) * (z + 1) / 4 } } } #break
    #case (4) media { scattering { 5, <2, 1, 0.5> eccentricity 0.3 }
      absorption 0.5 intervals 3 } #break
    #end
  } }
