// mesh_texture_list.pov - a mesh2 whose texture_list must move with the object (tests/test_mesh_textures.sh).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0.5,0.5,-5> look_at <0.5,0.5,0> up y*1.2 right x*1.2 }
#declare T = texture { pigment { agate color_map { [0 rgb 0] [1 rgb 1] } } finish { ambient 1 diffuse 0 } }
#declare M = mesh2 {
  vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }
  texture_list { 1, texture { T } }
  face_indices { 2, <0,1,2>, 0, <0,2,3>, 0 }
}
object { M scale 0.5 translate <0.25, 0.25, 0> }
