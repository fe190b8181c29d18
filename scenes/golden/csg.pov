// CSG: difference, intersection, merge (inner surfaces removed) and union, with textures pushed down.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -8> look_at <0, 0.8, 0> angle 50 }
light_source { <-4, 9, -6> color rgb 1 }
light_source { <4, 5, -6> color rgb 0.4 }
plane { y, 0 pigment { color rgb 0.7 } }
difference {
  box { -1, 1 }
  sphere { 0, 1.3 }
  pigment { color rgb <1, 0.4, 0.2> }
  translate <-2.5, 1, 0>
}
intersection {
  sphere { <-0.5, 0, 0>, 1 }
  sphere { <0.5, 0, 0>, 1 }
  pigment { color rgb <0.2, 0.8, 0.3> }
  finish { phong 0.7 }
  translate <0, 1, 0>
}
merge {
  cylinder { <0, -1, 0>, <0, 1, 0>, 0.4 }
  sphere { 0, 0.8 pigment { color rgb <0.2, 0.4, 1> } }
  pigment { color rgb <1, 1, 0.2> }
  translate <2.5, 1, 0>
}
union { sphere { <0, 0.3, -2.5>, 0.3 } box { <-0.2, 0, -3.2>, <0.2, 0.4, -2.9> } pigment { rgb <1, 0, 1> } }
