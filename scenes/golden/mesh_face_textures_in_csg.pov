// A mesh2 with a texture per face and a texture per corner (texture_list, three indices a
// face: what VMD, Jmol and VTK write) clipped by a box (Jmol's slab), inside an
// intersection, and inverse in a difference: each face keeps its own texture, as in the
// mesh alone (POV-Ray's Determine_Textures on the hit mesh; a clip or CSG changes nothing).
// The mesh is solid (inside_vector): as a part it cuts with all its inside holds, far past
// its vertices, which the black boxes must reach.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 0.2, 0> angle 50 }
light_source { <-4, 6, -5> color rgb 1 }
light_source { <5, 3, -2> color rgb 0.4 }
plane { y, -1.2 pigment { checker color rgb 0.9 color rgb <0.1, 0.3, 0.6> scale 0.5 } }
#declare Sheet = mesh2 {
  vertex_vectors { 6, <-1, -1, 0>, <1, -1, 0>, <1, 1, 0>, <-1, 1, 0>, <0, 1.6, -0.4>, <0, -1.6, -0.4> }
  texture_list { 4,
    texture { pigment { rgb <1, 0.1, 0.1> } finish { ambient 0.2 diffuse 0.8 } },
    texture { pigment { rgb <0.1, 0.2, 1> } finish { ambient 0.2 diffuse 0.8 phong 0.5 } },
    texture { pigment { rgbt <0.1, 1, 0.2, 0.6> } finish { ambient 0.2 diffuse 0.7 } },
    texture { pigment { rgb <1, 0.9, 0.1> } finish { ambient 0.3 diffuse 0.6 } } }
  face_indices { 4, <0, 1, 2>, 0, 1, 3, <0, 2, 3>, 2, <2, 3, 4>, 1, 2, 3, <0, 1, 5>, 3 }
  inside_vector z
}
object { Sheet clipped_by { box { <-0.7, -2, -1>, <2, 1.3, 1> } } translate <-2.4, 0, 0> }
intersection { object { Sheet } sphere { <0, 0, 0>, 1.2 } pigment { rgb 0.7 } translate <0, 0, 0> }
difference {
  box { <-1, -1, -0.2>, <1, 1, 0.3> pigment { rgb <0.8, 0.6, 0.4> } }
  object { Sheet scale 0.8 translate -z * 0.5 }
  translate <2.4, 0, 0>
}
