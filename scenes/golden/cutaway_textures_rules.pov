// cutaway_textures, the finer rules: an untextured box cutting three overlapping textured
// spheres (one, two or three textures averaged; one bumped); an inverse untextured part
// cutting a clipped textured one; a cutaway difference in a union with clipped_by
// (POV-Ray asks the union's parts: the cut lies on the closed cylinder's surface, outside
// it by POV-Ray's margin); a texture_map with reflection on the textured part; an inverse
// difference (a merge to POV-Ray) in a cutaway intersection.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> look_at <0, 0.3, 0.5> angle 55 }
light_source { <-4, 9, -6> color rgb 1 }
light_source { <5, 5, -5> color rgb 0.4 }
plane { y, -0.6 pigment { color rgb 0.75 } }
intersection {
  union {
    sphere { <-0.3, 0, 0>, 0.8 pigment { color rgb <1, 0, 0> } }
    sphere { <0.3, 0, 0>, 0.8 pigment { color rgb <0, 1, 0> } }
    sphere { <0, 0.4, 0>, 0.8 pigment { color rgb <0, 0, 1> } finish { phong 0.8 } normal { bumps 0.5 scale 0.1 } }
  }
  box { <-1.2, -0.3, -0.35>, <1.2, 1.3, 1> }
  cutaway_textures
  translate <-2.6, 0.3, 0>
}
intersection {
  sphere { 0, 0.9 pigment { checker color rgb 1 color rgb <0.9, 0.6, 0.1> scale 0.3 } clipped_by { plane { z, 0.5 } } }
  sphere { <0, 0.5, -0.5>, 0.6 inverse }
  cutaway_textures
  translate <0, 0.3, 0>
}
union {
  difference {
    sphere { 0, 0.8 pigment { color rgb <0.9, 0.5, 0.2> } }
    cylinder { <-1, 0.2, -2>, <-1, 0.2, 2>, 0.9 }
    cutaway_textures
  }
  sphere { <0, 0, 0.3>, 0.5 pigment { color rgb <0.3, 0.3, 1> } }
  clipped_by { plane { z, 0.6 } }
  translate <2.6, 0.3, 0>
}
difference {
  box { -0.6, 0.6 texture { checker texture { pigment { rgb <1, 1, 0> } finish { reflection 0.3 } } texture { pigment { rgb <0.2, 0.2, 0.2> } } scale 0.25 } }
  sphere { <-0.6, 0.6, -0.6>, 0.7 }
  cutaway_textures
  rotate y*30 translate <-1.2, 0, 2.3>
}
intersection {
  sphere { 0, 1.5 pigment { color rgb <0.5, 1, 0.5> } }
  difference { sphere { 0, 0.7 } box { <-1, 0, -1>, <0, 1, 0> } inverse }
  cutaway_textures
  translate <1.4, 0.2, 2.3>
}
