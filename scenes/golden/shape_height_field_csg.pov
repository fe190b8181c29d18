// height_field in each kind of CSG (its inside: everything below the surface, down to
// -infinity below the box), clipped, inverse, and as glass.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 8 }
camera { location <0, 5.5, -7> look_at <0, 0, 0> angle 50 }
light_source { <-4, 9, -6> color rgb 1 }
light_source { <5, 4, -3> color rgb 0.4 }
plane { y, -0.6 pigment { checker rgb 0.9 rgb 0.5 scale 0.5 } }
#declare HF = height_field { png "images/hf_grey16.png" smooth
                             translate <-0.5, -0.2, -0.5> scale <1.8, 1, 1.8> }
#declare Glass = material { texture { pigment { rgbf <0.9, 1, 0.9, 0.85> }
                                      finish { specular 0.6 reflection 0.05 } }
                            interior { ior 1.45 } }
intersection {
  object { HF }
  box { <-0.8, -0.5, -0.8>, <0.8, 2, 0.8> }
  pigment { rgb <0.9, 0.4, 0.3> } translate <-2.3, 0, 1.3>
}
difference {
  box { <-0.8, -0.5, -0.8>, <0.8, 0.6, 0.8> }
  object { HF translate 0.15*y }
  pigment { rgb <0.3, 0.7, 0.9> } translate <0, 0, 1.3>
}
merge {
  object { HF }
  sphere { <0, 0.3, 0>, 0.45 }
  material { Glass } translate <2.3, 0, 1.3>
}
union {
  object { HF }
  cylinder { <-0.9, 0.2, 0>, <0.9, 0.2, 0>, 0.12 }
  clipped_by { sphere { 0, 0.85 } }
  pigment { rgb <0.4, 0.9, 0.4> } translate <-2.3, 0, -1.3>
}
intersection {
  box { <-0.8, -0.3, -0.8>, <0.8, 0.9, 0.8> rotate 20*y }
  object { HF inverse }
  pigment { rgb <0.8, 0.5, 0.9> } translate <0, 0, -1.3>
}
object { HF material { Glass } translate <2.3, 0, -1.3> }
