// golden-args: +A0.3
// Anti-aliasing with POV-Ray's defaults (method 1, depth 3, jitter on) in a scene without
// #version: no working gamma, so the anti-aliasing gamma applies to the raw colours.
camera { location <0, 1.5, -6> look_at <0, 0.8, 0> angle 50 }
light_source { <-3, 6, -5> color rgb 1 }
background { color rgb <0.9, 0.9, 0.95> }
plane { y, 0 pigment { color rgb 0.05 } }
sphere { <-1.6, 1, 0>, 0.8 pigment { color rgb <0.05, 0.05, 0.3> } finish { phong 0.8 } }
box { <-0.4, 0, -0.4>, <0.4, 2.2, 0.4> rotate y * 30 pigment { color rgb <1, 0.2, 0.1> } }
cylinder { <1.2, 0.1, -0.5>, <2.2, 2, 0.5>, 0.12 pigment { color rgb 0.02 } }
