// A scene for a newer POV-Ray (mjhorvath's SolarSystem_sample_d.pov has
// "#version 3.8;", poliana-girl's blender_POV_scene.pov "#version 3.71;"):
// POV-Ray 3.7 refuses it, "Your scene file requires POV-Ray version 3.8
// or later!", before reading further.
// expect-error: version_38.pov:7:1: error: the scene needs POV-Ray version 3.8 or later
#declare Size = 1;
#version 3.8;
sphere { 0, Size pigment { rgb 1 } }
