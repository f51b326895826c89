// A float #declare without its ';' and no #version (gnu0000's
// ALTAR/ALTAR1.POV and 56 more corpus scenes): POV-Ray 3.7 refuses it,
// "All #declares of float, vector, and color require semi-colon ';' at
// end if the language version is set to 3.5 or higher".
// expect-error: semicolon.pov:6:17: error: '#declare' of a float, vector or colour needs ';'
#declare Size = 2
sphere { 0, Size pigment { rgb 1 } }
camera { location <0, 0, -5> look_at 0 }
light_source { <0, 10, -10> rgb 1 }
