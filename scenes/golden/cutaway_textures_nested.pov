// cutaway_textures with nested CSG: an intersection of two textured parts, cut by an
// untextured cylinder (the difference looks into its first part, averaging where both
// hold the point); an untextured difference inside a cutaway intersection (the flag
// comes down: its parts get no default texture); a cutaway CSG without any texture (the
// default texture); a texture on the CSG itself (it comes down to every part, so nothing
// is cut away); a cutaway difference inside a merge (POV-Ray asks the merge's parts,
// and the difference holds a point of its own cut only where rounding puts it outside
// the box: here on one face of three).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -8> look_at <0, 0.3, 0.6> angle 55 }
light_source { <-4, 9, -6> color rgb 1 }
light_source { <5, 5, -5> color rgb 0.4 }
plane { y, -0.6 pigment { color rgb 0.75 } }
difference {
  intersection {
    sphere { 0, 1 pigment { color rgb <1, 0.3, 0.1> } }
    box { -0.8, 0.8 pigment { gradient y color_map { [0 rgb <0.1, 0.3, 1>] [1 rgb 1] } scale 0.5 } }
  }
  cylinder { <0, -2, 0>, <0, 2, 0>, 0.5 }
  cutaway_textures
  rotate x*-35 translate <-2.6, 0.3, 0>
}
intersection {
  sphere { 0, 1 pigment { checker color rgb <0.2, 0.8, 0.3> color rgb 1 scale 0.3 } }
  difference { box { -0.9, 0.9 } sphere { <0, 0.9, -0.9>, 0.7 } }
  cutaway_textures
  rotate y*-20 translate <0, 0.3, 0>
}
intersection {
  sphere { 0, 0.7 }
  box { -0.55, 0.55 }
  cutaway_textures
  translate <2.6, 0.1, 0>
}
difference {
  sphere { 0, 0.8 pigment { color rgb <1, 0.9, 0.2> } }
  box { <-1, 0, -1>, <0, 1, 0> }
  pigment { color rgb <0.6, 0.2, 0.8> }
  cutaway_textures
  translate <-1.3, 0.2, 2.4>
}
merge {
  difference {
    sphere { 0, 0.8 pigment { color rgb <0.9, 0.5, 0.7> } }
    box { <-1, 0, -1>, <0, 1, 0> }
    cutaway_textures
  }
  cylinder { <0, -0.6, 0.3>, <0, 1.3, 0.3>, 0.25 pigment { color rgb <0.2, 0.9, 0.9> } }
  translate <1.3, 0.2, 2.4>
}
