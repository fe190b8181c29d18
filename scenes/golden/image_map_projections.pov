// image_map wrapped round objects: spherical (map_type 1) and cylindrical (map_type 2)
// with bilinear and bicubic (3) interpolation, an RGBA PNG whose alpha becomes transmit
// (shadows pass through the clear parts), and a texture behind it seen through.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -7> look_at <0, 0.6, 0> angle 55 }
light_source { <-6, 9, -8> color rgb 1 }
plane { y, -0.5 pigment { checker rgb <0.8, 0.8, 0.75> rgb <0.3, 0.35, 0.4> } }
sphere { <-2.3, 0.7, 0>, 1.1
  pigment { image_map { png "images/card.png" map_type 1 interpolate 2 } rotate y * 30 }
  finish { phong 0.5 } }
cylinder { <0, -0.5, 0>, <0, 2, 0>, 0.9
  pigment { image_map { png "images/card.png" map_type 2 interpolate 3 } scale <1, 2.5, 1>
            translate -0.5 * y rotate y * -40 } }
sphere { <2.3, 0.7, 0>, 1.1
  pigment { image_map { png "images/card_alpha.png" map_type 1 } rotate y * 200 } }
sphere { <2.3, 0.7, 0>, 0.5 pigment { rgb <1, 0.3, 0.1> } }
