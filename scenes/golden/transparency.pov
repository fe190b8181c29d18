// rgbf filters light, rgbt transmits it; shadows through both.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.8, 0> angle 45 }
light_source { <3, 8, -4> color rgb 1 }
plane { y, 0 pigment { color rgb <0.9, 0.9, 0.9> } }
sphere { <-1.6, 1, 0>, 0.9 pigment { rgbf <1, 0.2, 0.2, 0.7> } }
sphere { <0.4, 1, 0>, 0.9 pigment { rgbt <0.2, 0.2, 1, 0.6> } }
box { <1.6, 0, -0.6>, <2.8, 1.6, 0.6> pigment { rgbft <0.2, 1, 0.2, 0.3, 0.3> } finish { phong 0.5 } }
box { <-1, 0, 2>, <1, 2.5, 2.2> pigment { color rgb <0.8, 0.6, 0.2> } }
