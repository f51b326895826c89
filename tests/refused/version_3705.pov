// POV-Ray 3.7 rounds the version to hundredths: 3.705 asks for 3.71.
// expect-error: version_3705.pov:3:2: error: the scene needs POV-Ray version 3.71 or later
 #version 3.705;
sphere { 0, 1 pigment { rgb 1 } }
