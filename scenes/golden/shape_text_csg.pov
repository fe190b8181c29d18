// text in CSG: a difference cutting a word from a box, an intersection with a sphere,
// a merge of glass text, a union with clipped_by (not split, so its glyphs are tested
// without their own boxes), inverse text in an intersection, and glass text over a
// checker. Also rendered in every mode (tests/distrib/tcp_test.cpp).
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 8 }
camera { location <0, 3, -9> look_at <0, 0.3, 0> angle 52 }
light_source { <-4, 9, -6> color rgb 1 }
light_source { <5, 4, -3> color rgb 0.4 }
plane { y, -1.5 pigment { checker rgb 0.9 rgb 0.5 scale 0.7 } }
#declare Glass = material { texture { pigment { rgbf <0.9, 1, 0.9, 0.85> }
                                      finish { specular 0.6 reflection 0.05 } }
                            interior { ior 1.45 } }
difference {
  box { <-0.2, -0.4, 0.1>, <2.6, 1, 0.6> }
  text { ttf "timrom.ttf" "AVE" 1, 0 translate <0, 0, -0.1> }
  pigment { rgb <0.9, 0.4, 0.3> } translate <-4, 0.5, 0>
}
intersection {
  text { ttf "cyrvetic.ttf" "Oo" 2, 0 scale 1.5 translate <-1, -0.4, -1> }
  sphere { 0, 1.1 }
  pigment { rgb <0.3, 0.7, 0.9> } translate <0.3, 0.6, 0>
}
merge {
  text { ttf "crystal.ttf" "Gl" 0.5, 0 }
  text { ttf "crystal.ttf" "as" 0.5, 0 translate <0.3, 0.2, -0.2> }
  material { Glass } scale 1.3 translate <2, 0.3, -0.5>
}
union {
  text { ttf "timrom.ttf" "Clip" 0.3, 0 }
  text { ttf "cyrvetic.ttf" "ped" 0.6, 0 translate <0, -0.8, 0> }
  clipped_by { sphere { <1, 0, 0>, 1.2 } }
  pigment { rgb <0.4, 0.9, 0.4> } translate <-4, -1.3, -1>
}
intersection {
  box { <-0.1, -0.3, 0>, <1.8, 0.9, 0.4> }
  text { ttf "timrom.ttf" "in" 0.6, 0 translate <0.1, 0, -0.1> inverse }
  pigment { rgb <0.8, 0.5, 0.9> } translate <-1, -1.3, -1.5>
}
text { ttf "timrom.ttf" "@" 0.5, 0 material { Glass } scale 1.8 rotate <-20, 10, 0>
       translate <1.5, -1.4, -2> }
