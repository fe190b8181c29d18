// image_map with map_type 5 (torus, major radius 1): angle round y across the image, angle
// round the tube down it, bilinear interpolation.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.3, 0> angle 55 }
light_source { <-6, 9, -8> color rgb 1 }
torus { 1, 0.45 pigment { image_map { png "images/card.png" map_type 5 interpolate 2 } }
        rotate -35 * x }
