// image_map, planar (map_type 0): repeated tiles without interpolation, bilinear (2) and
// normalised-distance (4) interpolation, `once` over a coloured plane, filter all and
// transmit all, repeat/offset. 8-bit PNG without a gamma chunk: decoded as sRGB (#version 3.7).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
light_source { <-5, 10, -20> color rgb 1 }
plane { z, 1 pigment { checker rgb <0.9, 0.9, 0.2> rgb <0.2, 0.4, 0.9> scale 0.5 } }
#declare Card = pigment { image_map { png "images/card.png" } }
box { <-3.9, 0.1, 0>, <-1.4, 2.9, 0.5> pigment { Card scale <1.25, 0.7, 1> }
      finish { ambient 0.3 diffuse 0.7 } }
box { <-1.3, 0.1, 0>, <1.3, 2.9, 0.5>
      pigment { image_map { png "images/card.png" interpolate 2 } scale <2.6, 2.8, 1>
                translate <-1.3, 0.1, 0> }
      finish { ambient 1 diffuse 0 } }
box { <1.4, 0.1, 0>, <3.9, 2.9, 0.5>
      pigment { image_map { png "images/card.png" interpolate 4 } scale <2.5, 2.8, 1>
                translate <1.4, 0.1, 0> }
      finish { ambient 1 diffuse 0 } }
// once: only the unit square shows the card, the rest of the face is clear.
box { <-3.9, -2.9, 0>, <-1.4, -0.1, 0.5>
      pigment { image_map { png "images/card.png" once } scale 1.5 translate <-3.4, -2.4, 0> }
      finish { ambient 1 diffuse 0 } }
box { <-1.3, -2.9, 0>, <1.3, -0.1, 0.5>
      pigment { image_map { png "images/card.png" filter all 0.6 transmit all 0.2 }
                scale <2.6, 2.8, 1> translate <-1.3, -2.9, 0> }
      finish { ambient 1 diffuse 0 } }
box { <1.4, -2.9, 0>, <3.9, -0.1, 0.5>
      pigment { image_map { png "images/card.png" repeat <2, 1> offset <0.25, 0.5> }
                scale <2.5, 2.8, 1> translate <1.4, -2.9, 0> }
      finish { ambient 1 diffuse 0 } }
