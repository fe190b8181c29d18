// cutaway_textures with see-through textures: a filtering glass sphere cut by an
// untextured box (the cut takes its filter and shadows as it; the box's interior is its
// own, ior 1), an intersection of two filtering boxes of different colours with an
// untextured sphere (their textures averaged, transparency included), and a cut whose
// sphere transmits and reflects.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 3, -7> look_at <0, 0.5, 0> angle 50 }
light_source { <-3, 8, -6> color rgb 1 }
light_source { <5, 4, -5> color rgb 0.4 }
plane { y, -0.6 pigment { checker color rgb 0.9 color rgb <0.2, 0.3, 0.5> scale 0.5 } }
difference {
  sphere { 0, 1 pigment { rgbf <0.6, 1, 0.7, 0.8> } finish { phong 0.6 } interior { ior 1.4 } }
  box { <-1.2, 0.2, -1.2>, <0.1, 1.2, 0.1> }
  cutaway_textures
  rotate y*-25 translate <-2.3, 0.4, 0>
}
intersection {
  box { -0.8, 0.8 pigment { rgbf <1, 0.3, 0.3, 0.7> } rotate y*35 }
  box { -0.8, 0.8 pigment { rgbf <0.3, 0.3, 1, 0.5> } rotate x*35 }
  sphere { 0, 0.9 }
  cutaway_textures
  translate <0, 0.3, 0>
}
difference {
  sphere { 0, 1 pigment { rgbt <1, 0.9, 0.5, 0.6> } finish { reflection 0.2 } }
  cylinder { <0, 0, -2>, <0, 0, 2>, 0.55 }
  cutaway_textures
  rotate y*30 translate <2.3, 0.4, 0>
}
