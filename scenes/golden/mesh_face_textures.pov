// Per-face textures of mesh and mesh2 (texture_list with face indices, triangle
// texture identifiers), over a plain mesh texture and with none: each face is shaded with
// its own texture.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0.3, 0> angle 45 }
light_source { <-4, 6, -5> color rgb 1 }
plane { y, -1 pigment { checker color rgb 0.9 color rgb <0.1, 0.3, 0.6> scale 0.5 } }
#declare Red = texture { pigment { rgb <1, 0.2, 0.1> } }
#declare Blue = texture { pigment { rgb <0.1, 0.3, 1> } finish { phong 0.8 } }
mesh2 {
  vertex_vectors { 4, <-1, -1, 0>, <1, -1, 0>, <1, 1, 0>, <-1, 1, 0> }
  texture_list { 2, texture { pigment { rgb <0.2, 0.9, 0.2> } }, texture { pigment { checker rgb 1 rgb 0.2 scale 0.25 } } }
  face_indices { 2, <0, 1, 2>, 0, <0, 2, 3>, 1 }
  translate <-1.2, 0.2, 0.1>
}
mesh {
  triangle { <-1, -1, 0>, <1, -1, 0>, <1, 1, 0> texture { Red } }
  triangle { <-1, -1, 0>, <1, 1, 0>, <-1, 1, 0> texture { Blue } }
  pigment { rgb 0.5 }
  translate <1.2, 0.2, 0.1>
}
