// A closed mesh with inside_vector is a solid in CSG: a sphere minus a cube mesh, a cube
// mesh2 intersected with a sphere, and the same meshes without inside_vector (surfaces only).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.6, 0> angle 55 }
light_source { <-4, 8, -6> color rgb 1 }
background { color rgb <0.4, 0.5, 0.7> }
plane { y, -1 pigment { checker color rgb 0.8 color rgb 0.3 } }
#declare Cube = mesh {
  triangle { <-1,-1,-1>, < 1,-1,-1>, < 1, 1,-1> } triangle { <-1,-1,-1>, < 1, 1,-1>, <-1, 1,-1> }
  triangle { <-1,-1, 1>, < 1, 1, 1>, < 1,-1, 1> } triangle { <-1,-1, 1>, <-1, 1, 1>, < 1, 1, 1> }
  triangle { <-1,-1,-1>, <-1, 1, 1>, <-1,-1, 1> } triangle { <-1,-1,-1>, <-1, 1,-1>, <-1, 1, 1> }
  triangle { < 1,-1,-1>, < 1,-1, 1>, < 1, 1, 1> } triangle { < 1,-1,-1>, < 1, 1, 1>, < 1, 1,-1> }
  triangle { <-1, 1,-1>, < 1, 1,-1>, < 1, 1, 1> } triangle { <-1, 1,-1>, < 1, 1, 1>, <-1, 1, 1> }
  triangle { <-1,-1,-1>, < 1,-1, 1>, < 1,-1,-1> } triangle { <-1,-1,-1>, <-1,-1, 1>, < 1,-1, 1> }
  inside_vector <0.1, 0.3, 1>
}
#declare Cube2 = mesh2 {
  vertex_vectors { 8, <-1,-1,-1>, <1,-1,-1>, <1,1,-1>, <-1,1,-1>, <-1,-1,1>, <1,-1,1>, <1,1,1>, <-1,1,1> }
  face_indices { 12, <0,1,2>, <0,2,3>, <4,6,5>, <4,7,6>, <0,7,4>, <0,3,7>,
                     <1,5,6>, <1,6,2>, <3,2,6>, <3,6,7>, <0,5,1>, <0,4,5> }
  inside_vector <0.2, 1, 0.1>
}
difference {
  sphere { 0, 1 }
  object { Cube scale 0.6 rotate <20, 30, 0> translate <0.5, 0.3, -0.6> }
  pigment { color rgb <0.9, 0.4, 0.2> } translate <-1.8, 0.2, 0>
}
intersection {
  object { Cube2 scale 0.8 rotate y * 25 }
  sphere { 0, 1.05 }
  pigment { color rgb <0.2, 0.7, 0.9> } translate <0.6, 0, 0>
}
difference {
  box { -0.7, 0.7 }
  object { Cube2 scale 0.5 translate <0.4, 0.4, -0.4> }
  pigment { color rgb <0.6, 0.9, 0.3> } rotate y * -20 translate <2.4, -0.3, 1>
}
