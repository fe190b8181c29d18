// bump_map: a grey height image as planar bumps (bump_size, bilinear interpolation), the
// same wrapped spherically, and a colour image's greyscale as heights with use_color.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6.5> look_at <0, 0.3, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
light_source { <6, 3, -3> color rgb 0.4 }
plane { y, 0 pigment { rgb <0.7, 0.7, 0.65> }
  normal { bump_map { png "images/heights.png" interpolate 2 bump_size 3 } rotate x * 90 scale 2 }
  finish { phong 0.6 } }
sphere { <-1.6, 1, 0>, 1 pigment { rgb <0.9, 0.5, 0.3> }
  normal { bump_map { png "images/heights.png" map_type 1 bump_size 6 } }
  finish { phong 0.8 phong_size 30 } }
box { <0.5, 0.01, -0.8>, <2.6, 1.8, 0.8> pigment { rgb <0.4, 0.6, 0.9> }
  normal { bump_map { png "images/card.png" use_color bump_size 2 } scale <2.1, 1.8, 1> translate <0.5, 0, 0> }
  finish { specular 0.5 } }
