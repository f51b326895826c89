// ortho_id.pov - an orthographic camera with angle, declared and then used
// as camera { Name }: sized once, when declared ("Orthographic
// projection"; templates/Basic_Scenes/Orthographic_isometric.pov).
#version 3.7;
global_settings { assumed_gamma 1 }
#declare C1 = camera { orthographic angle 15 location <20,20,-20> right x*4/3 look_at <0,0.5,0> }
#ifdef (DIRECT_CAMERA)
camera { orthographic angle 15 location <20,20,-20> right x*4/3 look_at <0,0.5,0> }
#else
camera { C1 }
#end
light_source { <10,20,-5> rgb 1 }
plane { y, 0 pigment { checker rgb 1 rgb 0.3 } }
sphere { <0,1,0>, 1 pigment { rgb <1,0.5,0.2> } }
