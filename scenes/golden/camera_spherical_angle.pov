// golden-args: +UA
// Spherical camera with `angle h` alone (the vertical angle is half of it) and a
// transparent background.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { spherical angle 200 location <0, 1.5, -3> look_at <0, 0.8, 0> }
light_source { <-3, 6, -5> color rgb 1 }
background { color rgbt <0.3, 0.5, 0.8, 0.4> }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.1 } }
sphere { <-1.5, 1, 0>, 0.8 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
box { <-0.4, 0, -0.4>, <0.4, 1.6, 0.4> rotate y * 30 pigment { color rgb <0.2, 0.8, 0.3> } }
cylinder { <1.5, 0, 0>, <1.5, 2, 0>, 0.3 pigment { color rgb <0.9, 0.9, 0.2> } }
