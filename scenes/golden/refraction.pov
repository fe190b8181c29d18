// A transparent box with ior 1.33 refracts the wall and floor behind it.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 3, -7> look_at <0, 0.8, 0> angle 50 }
light_source { <3, 8, -5> color rgb 1 }
plane { y, 0 pigment { color rgb <0.9, 0.9, 0.6> } }
box { <-4, 0, 3>, <4, 4, 3.2> pigment { color rgb <0.3, 0.5, 0.9> } }
box { <0.5, 0, -0.7>, <2.2, 1.7, 0.7> pigment { rgbt <1, 0.8, 0.8, 0.9> } interior { ior 1.33 } }
