// A missing include on the first line is the error, not a character no
// token begins with further down (gnu0000's POV1/MISC/3D1.POV: "Colors.inc"
// on line 1, "@define" on line 6; POV-Ray 3.7: "Cannot open include file
// Colors.inc").
#include "No_Such_File.inc"
// expect-error: bad_char_later.pov:5:10: error: cannot find include file 'No_Such_File.inc'
sphere { 0, 1 pigment { rgb 1 } }
@define X 1
