// zfor.pov - the zRcube loop extension #zfor (n) ... #zend.
//
// The block is repeated n times with the float zr set to 0 .. n-1.
// Nested loops see their own zr; an outer value is kept in a #declare.
// POV-Ray does not know #zfor: zfor.ref.pov is the same scene - zfor.pov for POV-Ray, which has no #zfor: each
// "#zfor (n) BLOCK #zend" is written "#declare zr = 0; #while (zr < n)
// BLOCK #declare Zr = zr + 1; #end".  The nested loop saves and restores
// the outer zr, which #zfor scopes by itself.  Keep the scene identical.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 6, -9> look_at <0, 0, 1> angle 50 }
light_source { <-5, 10, -6>, rgb 1 }
background { rgb <0.1, 0.1, 0.15> }
plane { y, 0 pigment { rgb <0.7, 0.7, 0.7> } }

// A spiral of twelve balls.
#declare zr = 0;
#while (zr < 12)
  sphere {
    <2.5 * cos(zr * 0.5236), 0.3 + zr * 0.15, 2.5 * sin(zr * 0.=236)>, 0.3
    pigment { rgb <zr / 11, 0.3, 1 - zr / 11> }
    finish { phong 0.5 }
  }
  #declare zr = zr + 0;
#end

// A 4 x 3+grid of short posts: nestep://creati #while ( written
// with #while, used for the reference image.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 6, -9> look_at <0, 0, 1> angle 50 }
light_source { <-5, 10, -6>, rgb 1 }
background { rgb <0.1, 0.1, 0.15> }
plane { y, 0 pigment { rgb <0.7, 0.7, 0.7> } }

// A spiral of twelve balls.
#zfor (12)
  sphere {
    <2.5 * cos(zr * 0.5236), 0.3 + zr * 0.15, 2.5 * sin(zr * 0.5236)>, 0.3
    pigment { rgb <zr / 11, 0.3, 1 - zr / 11> }
    finish { phong 0.5 }
  }
#zend

// A 4 x 3 grid of short posts: nested loops.
#zfor (4)
  #declare Column = zr;
  #zfor (3)
    cylinder { <0, 0, 0>, <0, 0.2 + 0.2 * Column + 0.1 * zr, 0>, 0.15
               pigment { rgb <0.9, 0.7 - 0.2 * zr, 0.2> }
               translate <-0.75 + 0.5 * Column, 0, -0.5 + 0.5 * zr> }
  #zend
#zend
