// The shapes povwall has had longest, each cut by a sphere in a different kind of CSG,
// two of them glass, one clipped: the shape layer's hits, normals and inside tests
// together. Also rendered in every mode (tests/distrib/tcp_test.cpp).
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 8 }
camera { location <0, 5, -9> look_at <0, 0.3, 0> angle 50 }
light_source { <-4, 9, -6> color rgb 1 }
light_source { <5, 4, -3> color rgb 0.4 }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.5 scale 0.7 } }
#declare Glass = material { texture { pigment { rgbf <0.9, 1, 0.9, 0.85> }
                                      finish { specular 0.6 reflection 0.05 } }
                            interior { ior 1.45 } }
// Row 1: intersection, difference, merge (glass)
intersection {
  box { <-0.8, -0.8, -0.8>, <0.8, 0.8, 0.8> rotate <20, 30, 0> }
  sphere { 0, 1.05 }
  pigment { rgb <0.9, 0.4, 0.3> } translate <-3, 0, 1.5>
}
difference {
  cylinder { <0, -0.9, 0>, <0, 0.9, 0>, 0.8 }
  sphere { <0.3, 0.6, -0.4>, 0.7 }
  torus { 0.8, 0.2 rotate 90*x translate <0, 0, -0.3> }
  pigment { rgb <0.3, 0.7, 0.9> } translate <0, 0, 1.5>
}
merge {
  cone { <0, -0.9, 0>, 0.9, <0, 0.8, 0>, 0.1 }
  sphere { <0, 0.2, 0>, 0.55 }
  material { Glass } translate <3, 0, 1.5>
}
// Row 2: a torus and an open cylinder clipped, a mesh with an inside vector in an
// intersection (glass), a disc and a polygon in a union with a box
union {
  torus { 0.7, 0.25 rotate <30, 0, 20> }
  cylinder { <-0.9, 0, 0>, <0.9, 0, 0>, 0.35 open }
  clipped_by { plane { z, 0.1 } }
  pigment { rgb <0.4, 0.9, 0.4> } translate <-3, 0, -1.5>
}
intersection {
  mesh {
    triangle { <-1, -1, -1>, <1, -1, -1>, <0, 1, 0> }
    triangle { <1, -1, -1>, <0, -1, 1>, <0, 1, 0> }
    triangle { <0, -1, 1>, <-1, -1, -1>, <0, 1, 0> }
    triangle { <-1, -1, -1>, <0, -1, 1>, <1, -1, -1> }
    inside_vector <0.31, 0.17, 0.93>
  }
  sphere { <0, -0.3, 0>, 1.1 }
  pigment { rgb <0.8, 0.5, 0.9> } translate <0, 0, -1.5>
}
union {
  disc { <0, 0.4, 0>, <0.2, 1, -0.3>, 0.8, 0.3 }
  polygon { 5, <-0.6, -0.8>, <0.6, -0.8>, <0.8, 0.3>, <0, 0.9>, <-0.8, 0.3>
            rotate -20*x }
  box { <-0.3, -0.9, -0.3>, <0.3, -0.2, 0.3> }
  pigment { rgb <0.9, 0.8, 0.3> } translate <3, 0, -1.5>
}
