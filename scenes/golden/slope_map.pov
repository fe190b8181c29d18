// slope_map: pattern values turned into heights and slopes (cubic Hermite segments) before
// the normal is taken, on gradient, onion, marble and a turbulent bozo.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.3, 0> angle 50 }
light_source { <-6, 9, -5> color rgb 1 }
light_source { <5, 4, -6> color rgb 0.3 }
plane { y, 0 pigment { rgb <0.75, 0.7, 0.6> }
  normal { gradient x slope_map { [0 <0, 1>] [0.5 <1, 0>] [1 <0, -1>] } bump_size 1 scale 0.6 }
  finish { phong 0.5 } }
sphere { <-1.8, 1, 0>, 1 pigment { rgb <0.9, 0.4, 0.2> }
  normal { onion slope_map { [0 <0, 0>] [0.3 <1, 0>] [0.7 <1, 0>] [1 <0, 0>] } bump_size 0.8 scale 0.25 }
  finish { phong 0.7 } }
sphere { <0.3, 1, 0.5>, 1 pigment { rgb <0.3, 0.6, 0.9> }
  normal { marble slope_map { [0 <0.5, 1>] [1 <0.5, -1>] } bump_size 0.6 turbulence 0.4 scale 0.5 }
  finish { specular 0.6 } }
box { <1.6, 0, -1>, <3.2, 1.6, 0.6> pigment { rgb <0.5, 0.8, 0.4> }
  normal { bozo slope_map { [0 <0, 0>] [0.5 <0.2, 2>] [1 <1, 0>] } bump_size 1.5 scale 0.3 }
  finish { phong 0.4 } }
