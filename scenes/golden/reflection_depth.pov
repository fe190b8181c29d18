// Mirrors facing each other: max_trace_level cuts the reflection chain (refused rays are black).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 3 }
camera { location <0, 2, -4> look_at <0, 1, 2> angle 70 }
light_source { <2, 5, -3> color rgb 1 }
background { color rgb <0.3, 0.2, 0.1> }
box { <-3, 0, 4>, <3, 3, 4.2> pigment { color rgb 0.9 } finish { reflection 0.8 } }
box { <-3, 0, -6>, <3, 3, -5.8> pigment { color rgb 0.9 } finish { reflection 0.8 } }
plane { y, 0 pigment { color rgb <0.3, 0.5, 0.3> } finish { reflection { 0.1, 0.6 falloff 2 } } }
sphere { <0, 1, 1>, 0.7 pigment { color rgb <1, 0.2, 0.2> } finish { reflection 0.4 phong 1 } }
