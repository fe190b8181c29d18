// poly shapes in each kind of CSG (all crossings along the ray and the inside test
// F < 1e-4), clipped, inverse, and as glass.
#version 3.7;
#include "shapes.inc"
#include "shapesq.inc"
global_settings { assumed_gamma 1 max_trace_level 8 }
camera { location <0, 5, -9> look_at <0, 0.3, 0> angle 50 }
light_source { <-4, 9, -6> color rgb 1 }
light_source { <5, 4, -3> color rgb 0.4 }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.5 scale 0.7 } }
#declare Glass = material { texture { pigment { rgbf <0.9, 1, 0.9, 0.85> }
                                      finish { specular 0.6 reflection 0.05 } }
                            interior { ior 1.45 } }
// A sphere of radius 0.9 as an order-2 poly, cut by a box.
intersection {
  poly { 2, <1, 0, 0, 0, 1, 0, 0, 1, 0, -0.81> }
  box { -0.7, 0.7 rotate <20, 30, 0> }
  pigment { rgb <0.9, 0.4, 0.3> } translate <-3, 0, 1.5>
}
// A quartic torus minus a cylinder and a sphere.
difference {
  object { Torus_40_12 scale 0.13 rotate 70*x }
  cylinder { <-2, 0, 0>, <2, 0, 0>, 0.3 }
  sphere { <0.5, 0.6, -0.5>, 0.45 }
  pigment { rgb <0.3, 0.7, 0.9> } translate <0, 0.1, 1.5>
}
// Two quartic tori merged, glass.
merge {
  quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, -2.5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
             1, 0, 0, 2, 0, 1.5, 0, 0, 0, 0, 1, 0, -2.5, 0, 0.5625> sturm }
  quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, -2.5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
             1, 0, 0, 2, 0, 1.5, 0, 0, 0, 0, 1, 0, -2.5, 0, 0.5625> rotate 90*x }
  scale 0.7 material { Glass } translate <3, 0, 1.5>
}
// An order-6 poly (Twin_Glob) and a box, clipped by a plane.
union {
  object { Twin_Glob scale 1.2 rotate <0, 30, 20> }
  box { <-1.2, -0.15, -0.15>, <1.2, 0.15, 0.15> }
  clipped_by { plane { z, 0.1 } }
  pigment { rgb <0.4, 0.9, 0.4> } translate <-3, 0, -1.5>
}
// A box minus the inside of a quartic paraboloid: the inverse poly's inside.
intersection {
  box { -0.9, 0.9 rotate <10, 20, 0> }
  object { Quartic_Paraboloid rotate <0, 90, -30> scale 0.6 translate -0.5*y inverse }
  pigment { rgb <0.8, 0.5, 0.9> } translate <0, 0, -1.5>
}
// A polynomial (a glass ellipsoid of order 4 written by terms), sturm.
polynomial { 4, xyz(4, 0, 0): 1, xyz(0, 4, 0): 2, xyz(0, 0, 4): 1, xyz(2, 2, 0): 0.5,
             xyz(0, 0, 0): -0.6 sturm
             material { Glass } translate <3, 0, -1.5> }
