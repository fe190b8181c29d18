// Triangles, smooth triangles and polygons cut from a box: POV-Ray's Invert does nothing
// to them, so the difference keeps only their surface inside the box (they have no
// inside for the box's faces to be in); `inverse` on one changes nothing either.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -7> look_at 0 angle 55 }
light_source { <-5, 10, -8> color rgb 1 }
light_source { <6, 5, -4> color rgb 0.4 }
plane { y, -1.5 pigment { checker rgb 0.9 rgb 0.5 } }
difference {
  box { -1, 1 }
  triangle { <-2, -2, 0>, <2, -2, 0>, <0, 2, 0> }
  pigment { rgb <0.9, 0.5, 0.3> }
  rotate 30*y translate -2.4*x
}
difference {
  box { -1, 1 }
  polygon { 5, <-2, -2>, <2, -2>, <2, 2>, <-2, 2>, <-2, -2> }
  pigment { rgb <0.3, 0.5, 0.9> }
  rotate -30*y
}
difference {
  box { -1, 1 }
  smooth_triangle { <-2, -2, 0>, <0, 0, -1>, <2, -2, 0>, <0, 0, -1>, <0, 2, 0>, <0, 0, -1> }
  pigment { rgb <0.5, 0.9, 0.4> }
  rotate 20*y translate 2.4*x
}
intersection {
  sphere { 0, 0.8 }
  triangle { <-2, -2, 0>, <2, -2, 0>, <0, 2, 0> inverse }
  pigment { rgb <0.9, 0.9, 0.3> }
  translate <0, 1.6, 1>
}
