// Mesh normals as POV-Ray 3.7 reads and uses them: a face whose three vertex normals
// are equal is flat (the face's own normal, not the one given: PyMOL and other exporters
// write one shared normal per flat face); a smooth face keeps its interpolated normals in
// CSG and under clipped_by as outside them.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0.5, -9> look_at <0, 0, 0> angle 55 }
light_source { <-4, 6, -8> rgb 1 }
light_source { <5, 2, -3> rgb 0.4 }
// Equal normals that are not the face's: flat in POV-Ray (mesh2 and mesh).
mesh2 {
  vertex_vectors { 4, <-1, -1, -0.5>, <1, -1, 0.5>, <-1, 1, -0.5>, <1, 1, 0.5> }
  normal_vectors { 2, <0, 0, -1>, <0.3, 0.2, -1> }
  face_indices { 2, <0, 1, 2>, <1, 3, 2> }
  normal_indices { 2, <0, 0, 0>, <1, 1, 1> }
  pigment { rgb <1, 0.8, 0.5> } finish { phong 0.7 phong_size 20 }
  translate <-3.2, 1.3, 0>
}
mesh {
  smooth_triangle { <-1, -1, 0>, <0, 0.3, -1>, <1, -1, 0.6>, <0, 0.6, -2>, <-1, 1, 0>, <0, 0.3, -1> }
  smooth_triangle { <1, -1, 0.6>, <1, 0, -1>, <1, 1, 0.6>, <1, 0, -1>, <-1, 1, 0>, <1, 0, -1> }
  pigment { rgb <0.6, 0.9, 0.6> } finish { phong 0.7 phong_size 20 }
  translate <0, 1.3, 0>
}
// Smooth faces inside CSG, clipped and scaled unevenly.
#declare Sheet = mesh {
  smooth_triangle { <-1.2, -1.2, 0>, <-0.6, -0.4, -1>, <1.2, -1.2, 0>, <0.6, -0.4, -1>, <-1.2, 1.2, 0>, <-0.5, 0.5, -1> }
  smooth_triangle { <1.2, -1.2, 0>, <0.6, -0.4, -1>, <1.2, 1.2, 0>, <0.6, 0.5, -1>, <-1.2, 1.2, 0>, <-0.5, 0.5, -1> }
}
intersection {
  object { Sheet } box { -1, 1 }
  pigment { rgb <0.6, 0.7, 1> } finish { phong 0.8 phong_size 30 }
  translate <3.2, 1.3, 0>
}
object {
  Sheet clipped_by { sphere { 0, 1.1 } }
  pigment { rgb 1 } finish { phong 0.8 phong_size 30 }
  scale <1.3, 0.8, 1> translate <-3, -1.5, 0>
}
difference {
  object { Sheet } cylinder { -z, z, 0.4 }
  pigment { rgb <1, 0.6, 0.7> } finish { phong 0.8 phong_size 30 }
  rotate 20 * y translate <0.2, -1.5, 0>
}
merge {
  object { Sheet scale 0.8 } sphere { <0, 0, 0.3>, 0.5 }
  pigment { rgb <0.9, 0.9, 0.5> } finish { phong 0.8 phong_size 30 }
  translate <3.2, -1.5, 0>
}
