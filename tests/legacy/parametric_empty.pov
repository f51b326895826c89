// A parametric whose v range is empty (poliana-girl's sep05.pov: <0,0>,
// <2*pi, pi*clock> at clock 0): POV-Ray 3.7 draws nothing, without a
// word; zRcube warns.
// expect: the parametric's u or v range is empty
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-8> look_at 0 }
light_source { <5,5,-5> rgb 1 }
parametric {
  function { sin(u)*cos(v) }
  function { sin(u)*sin(v) }
  function { cos(u) }
  <0,0>, <2*pi, pi*clock>
  contained_by { sphere { 0, 5 } }
  pigment { rgb 1 }
}
sphere { <2,0,0>, 1 pigment { rgb <1,0.5,0> } }
