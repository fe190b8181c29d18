// image_map in a #version 3.6 scene without assumed_gamma: the file's values are used raw
// (no input decoding, no output encoding), for PNG and TGA alike, and a bump_map.
#version 3.6;
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
light_source { <-5, 10, -20> color rgb 1 }
box { <-3.9, -2.9, 0>, <-0.1, 2.9, 0.5>
      pigment { image_map { png "images/card.png" interpolate 2 } scale <3.8, 5.8, 1> translate <-3.9, -2.9, 0> }
      finish { ambient 1 diffuse 0 } }
box { <0.1, 0.1, 0>, <3.9, 2.9, 0.5>
      pigment { image_map { tga "images/card.tga" } scale <3.8, 2.8, 1> translate <0.1, 0.1, 0> }
      finish { ambient 1 diffuse 0 } }
box { <0.1, -2.9, 0>, <3.9, -0.1, 0.5> pigment { rgb 0.8 }
      normal { bump_map { png "images/heights.png" bump_size 4 } scale <3.8, 2.8, 1> translate <0.1, -2.9, 0> } }
