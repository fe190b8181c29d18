// Spotlight (radius, falloff, tightness), light fade, a 3x3 area light and a parallel light.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> look_at <0, 0.5, 0> angle 50 }
light_source { <0, 6, 0> color rgb <1, 0.9, 0.7> spotlight point_at <-2, 0, 0> radius 15 falloff 25 tightness 5 }
light_source { <4, 4, -4> color rgb <0.3, 0.3, 0.8> fade_distance 3 fade_power 2 }
light_source { <0, 8, -3> color rgb 0.5 area_light <2, 0, 0>, <0, 0, 2>, 3, 3 }
light_source { <0, 10, 0> color rgb 0.2 parallel point_at 0 }
plane { y, 0 pigment { color rgb 0.8 } }
sphere { <-2, 1, 0>, 1 pigment { color rgb 1 } }
box { <1, 0, -1>, <3, 1.5, 1> pigment { color rgb <0.9, 0.6, 0.3> } }
