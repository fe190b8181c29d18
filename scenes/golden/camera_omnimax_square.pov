// Omnimax camera with a square frame (right and up of equal length: no widening) and an
// oblique, rolled view.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { omnimax right x up y location <1, 2, -3> look_at <0, 0.5, 0> sky <0.3, 1, 0> }
light_source { <-3, 6, -5> color rgb 1 }
background { color rgb <0.3, 0.5, 0.8> }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.1 } }
sphere { <-1.5, 1, 0>, 0.8 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
box { <-0.4, 0, -0.4>, <0.4, 1.6, 0.4> rotate y * 30 pigment { color rgb <0.2, 0.8, 0.3> } }
cylinder { <1.5, 0, 0>, <1.5, 2, 0>, 0.3 pigment { color rgb <0.9, 0.9, 0.2> } }
