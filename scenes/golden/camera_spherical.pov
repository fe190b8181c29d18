// Spherical camera, the whole sphere (default angle 360 x 180), from a rotated, tilted
// view: longitude across, latitude up.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { spherical location <0, 1, 0> look_at <1, 0.5, 2> rotate z * 15 }
light_source { <-3, 6, -5> color rgb 1 }
background { color rgb <0.3, 0.5, 0.8> }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.1 } }
sphere { <-2, 1, 1>, 0.8 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
box { <-0.4, 0, 2>, <0.4, 1.6, 2.8> rotate y * 30 pigment { color rgb <0.2, 0.8, 0.3> } }
cylinder { <2, 0, -1>, <2, 2, -1>, 0.3 pigment { color rgb <0.9, 0.9, 0.2> } }
sphere { <0, 1, -3>, 1 pigment { color rgb <0.8, 0.2, 0.9> } }
