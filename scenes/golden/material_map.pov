// material_map: the palette index of each pixel picks a texture (wrapping past the
// count, the last for the count itself), planar and spherical, once (off the image:
// the first texture), and a truecolour image (the index is red * 255).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at <0, 0, 0> angle 50 }
light_source { <-10, 20, -20> color rgb 1 }
#declare T0 = texture { pigment { rgb <0.9, 0.2, 0.1> } finish { ambient 0.3 diffuse 0.7 } }
#declare T1 = texture { pigment { rgb <0.1, 0.7, 0.2> } normal { bumps 0.5 scale 0.1 }
                        finish { ambient 0.3 diffuse 0.7 } }
#declare T2 = texture { pigment { checker rgb 1 rgb <0.2, 0.2, 0.8> scale 0.2 }
                        finish { ambient 0.3 diffuse 0.7 } }
box { <-1, -1, 0>, <1, 1, 0.5>
      texture { material_map { png "images/palette.png" texture { T0 } texture { T1 }
                               texture { T2 } }
                scale 2 translate <-1, -1, 0> }
      translate <-2.5, 1.3, 0> }
box { <-1, -1, 0>, <1, 1, 0.5>
      texture { material_map { png "images/palette.png" once texture { T2 } texture { T0 } }
                scale 1.5 translate <-0.9, -0.6, 0> }
      translate <2.5, 1.3, 0> }
sphere { 0, 1.2
      texture { material_map { png "images/palette.png" map_type 1 texture { T1 }
                               texture { T0 } texture { T2 } texture { T0 } } }
      rotate 30 * y translate <-2.5, -1.6, 0> }
box { <-1, -1, 0>, <1, 1, 0.5>
      texture { material_map { png "images/card.png" texture { T0 } texture { T1 } texture { T2 } }
                scale 2 translate <-1, -1, 0> }
      translate <2.5, -1.6, 0> }
