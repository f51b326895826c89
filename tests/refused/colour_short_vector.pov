// A colour item given a shorter vector gets zeros: "color srgbt
// PureColors[3]" with 3-D vectors (watchduck's tesseract labels.pov);
// POV-Ray 3.7 pads, "rgb <0.2, 0.3>" included.
#version 3.7;
global_settings { assumed_gamma 1 }
#declare P = array[2] {<1, 0.5, 0.25>, <0, 1, 0>};
#declare C1 = color rgbt P[0];
#declare C2 = color srgbt P[0];
#declare C3 = color rgbft <0.2, 0.3, 0.4>;
#declare C4 = color rgb <0.2, 0.3>;
// expect-debug: C1=1.000,0.500,0.250,0.000,0.000
// expect-debug: C2=1.000,0.214,0.051,0.000,0.000
// expect-debug: C3=0.200,0.300,0.400,0.000,0.000
// expect-debug: C4=0.200,0.300,0.000,0.000,0.000
#debug concat("C1=", vstr(5, C1, ",", 0, 3), "\n")
#debug concat("C2=", vstr(5, C2, ",", 0, 3), "\n")
#debug concat("C3=", vstr(5, C3, ",", 0, 3), "\n")
#debug concat("C4=", vstr(5, C4, ",", 0, 3), "\n")
sphere { 0, 1 pigment { color srgbt P[1] } }
camera { location <0, 0, -5> look_at 0 }
light_source { <0, 10, -10> rgb 1 }
