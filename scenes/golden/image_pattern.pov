// image_pattern: an image's grey as a pattern (read without gamma decoding), with a
// colour_map, as a normal, with use_alpha on an image with an alpha channel and on one
// without (red), with interpolate and once, and as a texture_map pattern.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
light_source { <-5, 10, -20> color rgb 1 }
#declare Lit = finish { ambient 0.4 diffuse 0.6 }
box { <0, 0, 0>, <1, 1, 0.5>
      pigment { image_pattern { png "images/card.png" }
                color_map { [0 rgb <0, 0, 0.5>] [0.5 rgb <1, 0.5, 0>] [1 rgb 1] } }
      finish { Lit } scale <2.4, 2.6, 1> translate <-3.8, 0.2, 0> }
box { <0, 0, 0>, <1, 1, 0.5>
      pigment { rgb 0.8 }
      normal { image_pattern { png "images/card.png" interpolate 2 } 2 }
      finish { Lit } scale <2.4, 2.6, 1> translate <-1.2, 0.2, 0> }
box { <0, 0, 0>, <1, 1, 0.5>
      pigment { image_pattern { png "images/card_alpha.png" use_alpha }
                color_map { [0 rgb <0.1, 0.6, 0.1>] [1 rgb <1, 1, 0.3>] } }
      finish { Lit } scale <2.4, 2.6, 1> translate <1.4, 0.2, 0> }
box { <0, 0, 0>, <1, 1, 0.5>
      pigment { image_pattern { png "images/card.png" use_alpha once }
                color_map { [0 rgb <0.5, 0, 0.5>] [1 rgb <0.2, 1, 1>] } scale 0.8 translate 0.1 }
      finish { Lit } scale <2.4, 2.6, 1> translate <-3.8, -2.8, 0> }
box { <0, 0, 0>, <1, 1, 0.5>
      texture { image_pattern { png "images/palette.png" }
                texture_map { [0 pigment { rgb <0.9, 0.1, 0.1> } finish { Lit }]
                              [1 pigment { rgb <0.1, 0.1, 0.9> } finish { Lit }] } }
      scale <2.4, 2.6, 1> translate <-1.2, -2.8, 0> }
box { <0, 0, 0>, <1, 1, 0.5>
      pigment { image_pattern { png "images/card.png" map_type 0 }
                pigment_map { [0 checker rgb 0 rgb 1 scale 0.1] [1 rgb <1, 0.7, 0.2>] } }
      finish { Lit } scale <2.4, 2.6, 1> translate <1.4, -2.8, 0> }
