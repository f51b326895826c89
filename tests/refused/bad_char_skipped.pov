// POV-Ray 3.7 passes over such a character in a skipped #if branch and in
// a macro that is never called (EBS2.POV's "(step/7)%1" is MegaPOV's
// modulo operator).
#version 3.7;
global_settings { assumed_gamma 1 }
#if (0)
  #declare Riple = (7 / 7) % 1;
#end
#macro Unused() @ #end
sphere { 0, 1 pigment { rgb 1 } }
camera { location <0, 0, -5> look_at 0 }
light_source { <0, 10, -10> rgb 1 }
