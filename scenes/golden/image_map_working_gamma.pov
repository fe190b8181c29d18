// image_map with assumed_gamma 2.2 in a #version 3.7 scene: PNG decoded from sRGB and
// re-encoded in the working gamma; a 3.6 scene's rules are covered by image_map_legacy.
#version 3.7;
global_settings { assumed_gamma 2.2 }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
box { <-3.9, -2.9, 0>, <-0.1, 2.9, 0.5>
      pigment { image_map { png "images/card.png" } scale <3.8, 5.8, 1> translate <-3.9, -2.9, 0> }
      finish { ambient 1 diffuse 0 } }
box { <0.1, -2.9, 0>, <3.9, 2.9, 0.5>
      pigment { image_map { png "images/card_alpha.png" gamma 1.8 } scale <3.8, 5.8, 1> translate <0.1, -2.9, 0> }
      finish { ambient 1 diffuse 0 } }
