// golden-args: +MV3.7
// No #version in the scene: +MV3.7 starts it as an explicit 3.7 scene (sRGB output, the
// 3.7 opacity of a filtered layer).
camera { location <0, 1.5, -5> look_at <0, 0.5, 0> }
light_source { <-3, 5, -4> color rgb 1 }
plane { y, -0.5 pigment { checker color rgb 0.4 color rgb 0.9 } }
sphere { <0, 0.5, 0>, 1 pigment { rgbf <1, 0.5, 0.2, 0.6> } }
