// ovus in each kind of CSG (all crossings along the ray and the inside test), clipped,
// inverse, and as glass.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 8 }
camera { location <0, 5, -9> look_at <0, 0.3, 0> angle 50 }
light_source { <-4, 9, -6> color rgb 1 }
light_source { <5, 4, -3> color rgb 0.4 }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.5 scale 0.7 } }
#declare Glass = material { texture { pigment { rgbf <0.9, 1, 0.9, 0.85> }
                                      finish { specular 0.6 reflection 0.05 } }
                            interior { ior 1.45 } }
intersection {
  ovus { 1, 0.6 translate -0.3*y rotate <20, 30, 0> }
  box { -0.75, 0.75 }
  pigment { rgb <0.9, 0.4, 0.3> } translate <-3, 0, 1.5>
}
difference {
  ovus { 0.8, 1.2 translate -0.8*y }
  ovus { 0.5, 0.4 rotate 90*x translate <0, 0.2, -0.6> }
  sphere { <0.5, 0.9, -0.4>, 0.5 }
  pigment { rgb <0.3, 0.7, 0.9> } translate <0, 0, 1.5>
}
merge {
  ovus { 0.7, 0.5 translate -0.5*y }
  ovus { 0.4, 0.3 rotate 90*z translate <0, 0.1, 0> }
  material { Glass } translate <3, 0, 1.5>
}
union {
  ovus { 0.9, 0.8 translate -0.6*y rotate <30, 40, 10> }
  box { <-1.2, -0.2, -0.2>, <1.2, 0.2, 0.2> }
  clipped_by { plane { z, 0.2 } }
  pigment { rgb <0.4, 0.9, 0.4> } translate <-3, 0, -1.5>
}
intersection {
  box { -0.9, 0.9 rotate <10, 20, 0> }
  ovus { 0.6, 0.5 translate -0.4*y inverse }
  pigment { rgb <0.8, 0.5, 0.9> } translate <0, 0, -1.5>
}
ovus { 0.7, 0.9 sturm translate -0.7*y rotate <-20, 10, 0>
       material { Glass } translate <3, 0, -1.5> }
