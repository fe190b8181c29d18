// A parametric in an inverse CSG and in a union cut from a difference: POV-Ray inverts
// such a CSG child by child, and a parametric's Invert does nothing (no inside, its normal
// kept), as a triangle's.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -9> look_at <0, 0, 0> angle 50 }
light_source { <-5, 10, -8> color rgb 1 }
light_source { <6, 5, -4> color rgb 0.4 }
plane { y, -1.3 pigment { checker rgb 0.9 rgb 0.5 scale 0.8 } }
#declare Sheet = parametric {
  function { u }
  function { 0.3*sin(2*u)*sin(2*v) }
  function { v }
  <-1.2, -1.2>, <1.2, 1.2>
  contained_by { box { <-1.2, -0.4, -1.2>, <1.2, 0.4, 1.2> } }
  max_gradient 1.2
  accuracy 0.004
}
// Inverse union: the intersection of the inverted sphere and the sheet: the sheet outside
// the sphere (the sheet holds nothing, so none of the sphere is left).
union {
  object { Sheet }
  sphere { 0, 0.8 }
  inverse
  clipped_by { box { -1.5, 1.5 } }
  pigment { rgb <0.9, 0.5, 0.3> }
  translate <-2.6, 0, 0>
}
// Inverse intersection: the merge of the inverted sphere and the sheet: the sheet inside
// the sphere, and the whole sphere.
intersection {
  object { Sheet }
  sphere { 0, 0.8 }
  inverse
  clipped_by { box { -1.5, 1.5 } }
  pigment { rgbf <0.3, 0.7, 0.9, 0.5> }
  rotate 30*y translate <0, 0, 1.5>
}
// A box minus the union of a sheet and a sphere (an intersection of inverted children,
// the sheet left as it is, holding nothing): the sheet in the box outside the sphere, no
// box.
difference {
  box { -0.9, 0.9 }
  union { object { Sheet } sphere { <0, 0.9, 0>, 0.5 } }
  pigment { rgb <0.5, 0.9, 0.4> }
  translate <2.6, 0, 0>
}
// A sphere minus an inverse intersection (inverted twice: the sheet in the box).
difference {
  sphere { 0, 0.8 }
  intersection { object { Sheet } box { -0.6, 0.6 } inverse }
  pigment { rgb <0.9, 0.8, 0.3> }
  translate <0, -0.3, -3>
}
