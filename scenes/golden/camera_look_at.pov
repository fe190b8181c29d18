// Camera: location, look_at, angle, sky; a point light with colour; background.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <3, 4, -6> look_at <0, 0.5, 0> angle 55 sky <0.2, 1, 0> }
light_source { <6, 8, -4> color rgb <1, 0.9, 0.8> }
background { color rgb <0.2, 0.3, 0.5> }
plane { y, 0 pigment { color rgb <0.6, 0.6, 0.55> } }
sphere { <0, 1, 0>, 1 pigment { color rgb <0.9, 0.3, 0.2> } }
box { <-2.5, 0, -0.5>, <-1.5, 1.5, 0.5> pigment { color rgb <0.2, 0.4, 0.9> } }
