// Palette images keep their indices (a palette PNG that names one colour at two indices,
// and a GIF): bump_map use_index takes the index itself as the height, use_colour the
// colour's grey; an image_map's `filter N, V` and `transmit N, V` act on palette entry N
// (`all` on every entry).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
light_source { <-5, 5, -10> color rgb 1 }
plane { z, 1 pigment { checker rgb 0.2 rgb 0.9 scale 0.4 } finish { ambient 1 diffuse 0 } }
box { <0, 0, 0>, <2.4, 2.6, 0.5> pigment { rgb 0.8 } finish { ambient 0.1 diffuse 0.9 }
      normal { bump_map { png "images/palette.png" use_index bump_size 0.4 } scale <2.4, 2.6, 1> }
      translate <-3.9, 0.1, 0> }
box { <0, 0, 0>, <2.4, 2.6, 0.5> pigment { rgb 0.8 } finish { ambient 0.1 diffuse 0.9 }
      normal { bump_map { png "images/palette.png" use_colour bump_size 3 } scale <2.4, 2.6, 1> }
      translate <-1.2, 0.1, 0> }
box { <0, 0, 0>, <2.4, 2.6, 0.5> pigment { rgb 0.8 } finish { ambient 0.1 diffuse 0.9 }
      normal { bump_map { png "images/palette.png" use_index bump_size 0.25 once } scale <2.4, 2.6, 1> }
      translate <1.5, 0.1, 0> }
box { <0, 0, 0>, <2.4, 2.6, 0.5>
      pigment { image_map { png "images/palette.png" filter 0, 0.8 transmit 3, 1 } scale <2.4, 2.6, 1> }
      finish { ambient 1 diffuse 0 } translate <-3.9, -2.7, 0> }
box { <0, 0, 0>, <2.4, 2.6, 0.5>
      pigment { image_map { png "images/palette.png" transmit all 0.5 filter 5, 1 } scale <2.4, 2.6, 1> }
      finish { ambient 1 diffuse 0 } translate <-1.2, -2.7, 0> }
box { <0, 0, 0>, <2.4, 2.6, 0.5>
      pigment { image_map { gif "images/card.gif" filter 1, 0.9 transmit all 0.3 } scale <2.4, 2.6, 1> }
      finish { ambient 1 diffuse 0 } translate <1.5, -2.7, 0> }
