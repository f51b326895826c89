// The character is an error where the scene reaches it (povray:
// "Expected 'object or directive', @ found instead").
#version 3.7;
sphere { 0, 1 pigment { rgb 1 } }
// expect-error: bad_char_reached.pov:6:1: error: unexpected character '@'
@define X 1
