// map_type outside POV-Ray 3.7's four in a bump_map, an image_pattern and a material_map:
// only image_map refuses one (Parse_Image_Map); the others keep any value and map it as
// planar (map_pos's default), so each surface is its map_type 0 image.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6.5> look_at <0, 0.3, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
light_source { <6, 3, -3> color rgb 0.4 }
plane { y, 0 pigment { rgb <0.7, 0.7, 0.65> }
  normal { bump_map { png "images/heights.png" map_type 3 interpolate 2 bump_size 3 } rotate x * 90 scale 2 }
  finish { phong 0.6 } }
sphere { <-1.6, 1, 0>, 1
  pigment { image_pattern { png "images/heights.png" map_type 4 }
            color_map { [0 rgb <0.9, 0.5, 0.3>] [1 rgb <0.2, 0.3, 0.9>] } translate -0.5 * (x + y) }
  finish { phong 0.8 phong_size 30 } }
box { <0.5, 0.01, -0.8>, <2.6, 1.8, 0.8>
  texture { material_map { png "images/card.png" map_type 6
    texture { pigment { rgb <0.9, 0.2, 0.2> } }
    texture { pigment { rgb <0.2, 0.8, 0.3> } finish { specular 0.5 } } }
    scale <2.1, 1.8, 1> translate <0.5, 0, 0> } }
