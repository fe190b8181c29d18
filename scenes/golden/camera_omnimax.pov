// golden-args: +UA
// Omnimax camera (default 4:3 right/up: the image circle is widened and sits low); what it
// cannot see (outside the circle, over 45 degrees below the axis) is black and transparent.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { omnimax location <0, 1.2, -4> look_at <0, 0.8, 0> rotate y * 10 }
light_source { <-3, 6, -5> color rgb 1 }
background { color rgb <0.3, 0.5, 0.8> }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.1 } }
sphere { <-1.5, 1, 0>, 0.8 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
box { <-0.4, 0, -0.4>, <0.4, 1.6, 0.4> rotate y * 30 pigment { color rgb <0.2, 0.8, 0.3> } }
cylinder { <1.5, 0, 0>, <1.5, 2, 0>, 0.3 pigment { color rgb <0.9, 0.9, 0.2> } }
sphere { <0, 3, -2>, 0.7 pigment { color rgb <0.8, 0.2, 0.9> } }
