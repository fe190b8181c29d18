// Triangle and mesh rules of POV-Ray 3.7 met in random scenes: a smooth_triangle's normals
// are made unit when parsed, and one whose normals do not all lie on one side of its face
// is degenerate (never drawn, with a warning); a mesh without inside_vector holds nothing,
// inverted or not, so a difference by it keeps only its surface inside the first part;
// a smooth mesh under a non-uniform scale or a shear interpolates its unit normals in its
// own space before they are turned out.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -7> look_at <0, 0.2, 0> angle 60 }
light_source { <3, 6, -6> rgb 1 }
light_source { <-6, 3, -2> rgb 0.4 }
background { rgb <0.2, 0.25, 0.35> }
plane { y, -1.2 pigment { checker rgb 0.8 rgb <0.4, 0.5, 0.7> } }
smooth_triangle { <-1, -1, 0>, <-1, 0.3, -1>, <1, -1, 0>, <1, 0.3, -1>, <0, 1.2, 0>, <0, 1, -0.2>
  pigment { rgb 1 } finish { phong 0.6 } scale 0.9 translate <-3, 0.5, 0> }
smooth_triangle { <-1, -1, 0>, <0, 0, -1>, <1, -1, 0>, <0, 0, -1>, <0, 1, 0>, <0, 0.2, 1>
  pigment { rgb <1, 0.3, 0.3> } translate <-1, 0.5, -1> }
difference {
  sphere { 0, 1 pigment { rgb 1 } }
  mesh { triangle { <0, 1, 0>, <0.9, -0.5, -0.5>, <0, -0.5, 0.9> } pigment { rgb <1, 0, 0> } }
  translate <1, 0, 0>
}
#declare Pyramid = mesh2 {
  vertex_vectors { 5, <-1, 0, -1>, <1, 0, -1>, <1, 0, 1>, <-1, 0, 1>, <0, 1.2, 0> }
  normal_vectors { 5, <-1, 0.3, -1>, <1, 0.3, -1>, <1, 0.3, 1>, <-1, 0.3, 1>, <0, 1, 0> }
  face_indices { 6, <0, 1, 4>, <1, 2, 4>, <2, 3, 4>, <3, 0, 4>, <0, 2, 1>, <0, 3, 2> }
  inside_vector y
}
object { Pyramid pigment { rgb <1, 0.9, 0.5> } finish { specular 0.6 }
         scale <1.5, 0.9, 0.5> translate <3, -0.8, 1> }
object { Pyramid
         material { texture { pigment { rgbt <0.9, 1, 0.9, 0.8> } } interior { ior 1.44 } }
         matrix <1, 0, 0, 0.3, 1, 0, 0.45, 0, 1, 0, 0, 0> translate <-0.8, -1.1, 2> }
