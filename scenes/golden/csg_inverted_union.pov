// A union seen inverted (subtracted in a difference, or `inverse`) is, as POV-Ray inverts
// it, an intersection of its inverted children: the union's inner surfaces, where its
// members overlap, do not show in the cut. Crossing channels cut from a block (seen from
// below), a union of spheres cut from a box, an inverse union intersected with a box, and
// a union inside a union inside a difference.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, -3.5, -6> look_at <0, 0.3, 0> angle 60 }
light_source { <-3, -6, -8> rgb 1 }
light_source { <4, 8, -3> rgb 0.5 }
difference {
  box { <-4, 0, -1>, <-0.5, 1.5, 3> }
  union { cylinder { <-5, 0, 1>, <0, 0, 1>, 0.6 } cylinder { <-2.2, 0, -2>, <-2.2, 0, 4>, 0.6 } }
  pigment { rgb <0.9, 0.7, 0.5> }
}
difference {
  box { <0.5, -0.5, -1>, <3.5, 1.5, 2> }
  union { sphere { <1.6, -0.5, 0>, 0.8 } sphere { <2.4, -0.5, 0.2>, 0.8 } pigment { rgb <0.3, 0.6, 1> } }
  pigment { rgb 0.8 }
}
intersection {
  box { <-3, 2, -1>, <0, 3.5, 2> }
  union { sphere { <-1.5, 2, 0>, 0.9 } sphere { <-0.9, 2.2, 0.4>, 0.8 } inverse }
  pigment { rgb <0.6, 1, 0.6> }
}
difference {
  sphere { <2, 2.7, 0.5>, 1.2 }
  union {
    union { box { <1, 1, -0.2>, <3, 2.4, 0.2> } cylinder { <2, 1, 0>, <2, 4, 0>, 0.35 } }
    sphere { <2, 2, -0.6>, 0.6 }
  }
  pigment { rgb <1, 0.6, 0.6> }
}
