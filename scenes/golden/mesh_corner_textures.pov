// A texture per corner, blended across the face by the hit's barycentric weights: a mesh2
// face with three texture indices next to faces with one, and a mesh triangle with a
// texture_list of three textures, over smooth normals.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0.3, 0> angle 45 }
light_source { <-4, 6, -5> color rgb 1 }
plane { y, -1 pigment { checker color rgb 0.9 color rgb <0.1, 0.3, 0.6> scale 0.5 } }
#declare Red = texture { pigment { rgb <1, 0.2, 0.1> } finish { phong 0.5 } }
#declare Green = texture { pigment { rgb <0.2, 0.9, 0.2> } }
#declare Blue = texture { pigment { rgb <0.1, 0.3, 1> } finish { phong 0.8 } }
mesh2 {
  vertex_vectors { 5, <-1, -1, 0>, <1, -1, 0>, <1, 1, 0>, <-1, 1, 0>, <0, 1.6, 0> }
  texture_list { 3, texture { Red }, texture { Green },
                 texture { pigment { checker rgb 1 rgb 0.2 scale 0.25 } } }
  face_indices { 3, <0, 1, 2>, 0, 1, 2, <0, 2, 3>, 1, <3, 2, 4>, 2 1 0 }
  translate <-1.2, 0, 0.1>
}
mesh {
  smooth_triangle { <-1, -1, 0>, <-0.3, 0, -1>, <1, -1, 0>, <0.3, 0, -1>, <0, 1, 0>, <0, 0.3, -1>
                    texture_list { Red Green Blue } }
  smooth_triangle { <-1, -1, 0>, <-0.3, 0, -1>, <0, 1, 0>, <0, 0.3, -1>, <-1, 1, 0>, <0, 0, -1>
                    texture { Green } }
  translate <1.2, 0.2, 0.1>
}
