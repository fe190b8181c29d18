// #version 3.6 with assumed_gamma 2.2: gamma handling is on, working space is gamma 2.2, so
// colours are linearised (v^2.2) before the sRGB output encoding.
#version 3.6;
global_settings { assumed_gamma 2.2 }
camera { location <0, 1, -5> look_at <0, 0.5, 0> }
light_source { <3, 6, -4> color rgb <1, 0.95, 0.9> }
background { color rgb <0.3, 0.4, 0.6> }
plane { y, -1 pigment { color rgb <0.5, 0.5, 0.45> } }
sphere { <-1, 0.3, 0>, 1 pigment { color rgb <0.8, 0.3, 0.2> } finish { phong 0.6 } }
box { <0.5, -1, -0.5>, <2, 0.5, 1> pigment { color rgb <0.25, 0.5, 0.75> } finish { ambient 0.3 } }
