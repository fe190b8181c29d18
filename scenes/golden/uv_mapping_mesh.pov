// Mesh texture coordinates under uv_mapping: a mesh2 with uv_vectors and uv_indices, a
// mesh2 whose uv_vectors are indexed like its vertices (no uv_indices), a mesh of
// triangles with uv_vectors (and one without: (0, 0)), with an image_map and a checker.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -10> look_at <0, 0.5, 0> angle 50 }
light_source { <-10, 20, -20> color rgb 1 }
#declare Lit = finish { ambient 0.35 diffuse 0.65 }
mesh2 {
  vertex_vectors { 5, <-1, 0, -1>, <1, 0, -1>, <1, 0, 1>, <-1, 0, 1>, <0, 1.2, 0> }
  uv_vectors { 6, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0.5, 0.5>, <0.5, 1> }
  face_indices { 4, <0, 1, 4>, <1, 2, 4>, <2, 3, 4>, <3, 0, 4> }
  uv_indices { 4, <0, 1, 4>, <1, 2, 5>, <2, 3, 4>, <3, 0, 5> }
  pigment { uv_mapping image_map { png "images/card.png" } }
  finish { Lit }
  scale 1.6 rotate 30 * y translate <-3, 0, 0>
}
mesh2 {
  vertex_vectors { 4, <-1, 0, 0>, <1, 0, 0>, <1, 2, 0>, <-1, 2, 0> }
  uv_vectors { 4, <0, 0>, <3, 0>, <3, 2>, <0, 2> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  uv_mapping
  texture { pigment { checker rgb <0.9, 0.2, 0.1> rgb 1 } finish { Lit } }
  rotate <10, -20, 0> scale 1.2 translate <0.2, 0, 1>
}
mesh {
  triangle { <-1, 0, -1>, <1, 0, -1>, <0, 2, 0> uv_vectors <0, 0>, <1, 0>, <0.5, 1> }
  triangle { <1, 0, -1>, <1, 0, 1>, <0, 2, 0> uv_vectors <0, 0>, <1, 0>, <0.5, 1> }
  triangle { <1, 0, 1>, <-1, 0, 1>, <0, 2, 0> }
  triangle { <-1, 0, 1>, <-1, 0, -1>, <0, 2, 0> uv_vectors <0, 0.2>, <1, 0.2>, <0.5, 0.8> }
  pigment { uv_mapping image_map { png "images/card.png" interpolate 2 } }
  finish { Lit }
  rotate -25 * y translate <3.2, 0, -0.5>
}
plane { y, 0 pigment { checker rgb 0.8 rgb 0.5 } }
