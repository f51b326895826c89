// hf_smooth.pov - smooth height field normals as POV-Ray 3.7 makes them
// (tests/test_hf_smooth.sh): a 5 x 5 function height field, its normals
// at grid points and inside squares through trace() and #debug.
#version 3.7;
#declare F = function(x, y, z) { 0.3*x*y + 0.6*x*x - 0.4*y*y*y + 0.3 }
#declare HF = height_field { function 5, 5 { F(x, y, z) } smooth }
#declare R = function(x, y, z) { x }
#declare Ramp = height_field { function 5, 5 { R(x, y, z) } smooth }
#macro Probe(Obj, Name, X, Z)
  #local Nr = <0, 0, 0>;
  #local P = trace(Obj, <X, 5, Z>, -y, Nr);
  #debug concat("normal ", Name, " ", str(X, 0, 2), " ", str(Z, 0, 2), " ",
                str(Nr.x, 0, 5), " ", str(Nr.y, 0, 5), " ", str(Nr.z, 0, 5), "\n")
#end
Probe(HF, "hf", 0.5, 0.5)
Probe(HF, "hf", 0.25, 0.25)
Probe(HF, "hf", 0.75, 0.25)
Probe(HF, "hf", 0.5, 0)
Probe(HF, "hf", 0.6, 0.3)
Probe(HF, "hf", 0.3, 0.6)
Probe(HF, "hf", 0.7, 0.8)
Probe(Ramp, "ramp", 0.5, 0.5)
Probe(Ramp, "ramp", 0.62, 0.4)
camera { location <0.5, 2, -1> look_at <0.5, 0, 0.5> }
light_source { <-5, 5, -10> rgb 1 }
object { HF pigment { rgb 1 } }
