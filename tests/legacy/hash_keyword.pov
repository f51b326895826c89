// '#' before a word that is no directive (polymake's povray scenes write
// '#global_settings'): POV-Ray 3.7 reads the word as if the '#' were not
// there.  #render and #statistics (Open Babel's babel_povray3.inc) print
// to streams of their own and change nothing in the picture.
#version 3.1;
#global_settings { assumed_gamma 1.0 }
#declare Ball = sphere { 0, 0.8 pigment { rgb <0.9,0.5,0.2> } }
#render "a line for the render stream\n"
#statistics "a line for the statistics stream\n"
camera { location <0,1.5,-5> look_at 0 }
light_source { <3,8,-6> rgb 1 }
#box { <-2.5,-1.2,-1>, <-1.3,0.2,1> pigment { rgb <0.2,0.4,0.9> } }
# Ball
object { Ball translate 1.8*x }
#plane { y, -1.2 pigment { checker rgb 1, rgb 0.3 } }
