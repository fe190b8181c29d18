// `function W, H { }` in place of an image file (POV-Ray 3.7.0's Make_Pattern_Image):
// sample (i, j) at x = j / (W - 1), y = i / (H - 1), z = 0, row 0 the image's top; a
// float function gives 16-bit grey, a pigment function 16-bit RGBA (alpha 1 - transmit);
// values wrap through the 16-bit channel (never clamped) and no gamma is applied. In
// image_map (planar with interpolate, spherical once), bump_map, image_pattern and
// material_map.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -3.2> look_at 0 angle 55 }
light_source { <-2, 3, -5> color rgb 1 }
light_source { <3, 1, -4> color rgb 0.3 }
#declare F = function { 0.5 + 0.5 * sin(x * 20) * cos(y * 13) }
plane { z, 0.6
  pigment { image_map { function 64, 48 { F(x, y, z) } interpolate 2 }
            translate -0.5 scale <2, 1.5, 1> translate <-1, 0, 0> }
  normal { bump_map { function 40, 40 { sqrt(x * x + y * y) } bump_size 2 } scale 1.3 }
  finish { phong 0.3 }
}
box { <0.1, -1.1, -0.5>, <1.5, -0.1, -0.1>
  pigment { image_map { function 32, 32 { pigment { checker rgbt <1, 0.2, 0.1, 0.7>
                                                    rgb <0.1, 0.3, 0.9> scale 0.25 } } }
            scale <1.4, 1, 1> translate <0.1, -1.1, 0> }
}
sphere { <-1.3, 0.8, -0.6>, 0.45
  pigment { image_pattern { function 20, 20 { x * y } }
            color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 1, 0>] } }
}
sphere { <-1.2, -0.6, -0.7>, 0.5
  pigment { image_map { function 50, 50 { pigment { gradient x color_map {
      [0 rgbf <1, 0, 0, 0.5>] [1 rgbt <0, 1, 1, 0.6>] } } } map_type 1 once } }
}
#declare T1 = texture { pigment { rgb <1, 0.5, 0> } }
#declare T2 = texture { pigment { rgb <0, 0.4, 1> } finish { phong 1 } }
box { <0.1, 0.1, -0.3>, <1.5, 1.2, 0.3>
  texture { material_map { function 8, 8 { x * 1.5 / 255 } texture { T1 } texture { T2 } }
            scale <1.4, 1.1, 1> translate <0.1, 0.1, 0> }
}
// Values beyond 0..1 wrap in the 16-bit channel.
disc { <0.3, 0, -0.9>, -z, 0.25
  pigment { image_map { function 30, 30 { 1.3 * x - 0.2 } } translate -0.5 scale 0.5
            translate <0.3, 0, 0> }
}
