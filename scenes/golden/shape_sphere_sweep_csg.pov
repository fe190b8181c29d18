// sphere_sweep in each kind of CSG (all crossings along the ray and POV-Ray's root test
// of inside), clipped, inverse, and as glass; linear, cubic and B-spline parts.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 8 }
camera { location <0, 5, -9> look_at <0, 0.3, 0> angle 50 }
light_source { <-4, 9, -6> color rgb 1 }
light_source { <5, 4, -3> color rgb 0.4 }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.5 scale 0.7 } }
#declare Glass = material { texture { pigment { rgbf <0.9, 1, 0.9, 0.85> }
                                      finish { specular 0.6 reflection 0.05 } }
                            interior { ior 1.45 } }
#declare Zig = sphere_sweep { linear_spline 4, <-1, -0.5, 0>, 0.3, <-0.3, 0.5, 0>, 0.4,
                              <0.3, -0.5, 0>, 0.3, <1, 0.5, 0>, 0.2 }
#declare Curl = sphere_sweep { cubic_spline 6, <-1.2, 0, -0.5>, 0.3, <-0.8, 0, 0>, 0.3,
                               <0, 0.5, 0.4>, 0.35, <0.8, 0, 0>, 0.3, <0.4, -0.4, -0.4>, 0.25,
                               <0, 0, -1>, 0.2 }
#declare Soft = sphere_sweep { b_spline 5, <-1.2, 0, 0>, 0.5, <-0.5, 0.6, 0>, 0.4,
                               <0.5, -0.4, 0>, 0.45, <1.2, 0.3, 0>, 0.3, <1.4, 1, 0>, 0.3 }
intersection {
  object { Zig rotate <20, 30, 0> }
  box { <-0.9, -0.6, -0.6>, <0.9, 0.6, 0.6> }
  pigment { rgb <0.9, 0.4, 0.3> } translate <-3, 0, 1.5>
}
difference {
  object { Soft }
  sphere { <0, 0.2, -0.3>, 0.45 }
  object { Zig scale 0.6 translate <0, 0, -0.3> }
  pigment { rgb <0.3, 0.7, 0.9> } translate <0, 0, 1.5>
}
merge {
  object { Curl }
  object { Zig scale <0.7, 0.7, 1> }
  material { Glass } translate <3, 0, 1.5>
}
union {
  object { Curl rotate <30, 40, 10> }
  box { <-1.2, -0.2, -0.2>, <1.2, 0.2, 0.2> }
  clipped_by { plane { z, 0.1 } }
  pigment { rgb <0.4, 0.9, 0.4> } translate <-3, 0, -1.5>
}
intersection {
  box { -0.9, 0.9 rotate <10, 20, 0> }
  object { Soft scale 0.7 inverse }
  pigment { rgb <0.8, 0.5, 0.9> } translate <0, 0, -1.5>
}
object { Soft scale 0.8 rotate <-20, 10, 0> material { Glass } translate <3, 0, -1.5> }
