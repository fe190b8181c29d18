// An orthographic camera whose left rays start inside a glass box: each ray's own
// origin decides what it starts inside of.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { orthographic location <0, 0.5, -3> look_at <0, 0.5, 0> right x*4 up y*3 }
light_source { <-4, 6, -5> color rgb 1 }
plane { y, -1 pigment { checker color rgb 0.9 color rgb <0.1,0.3,0.6> scale 0.5 } }
box { <-3, -0.5, -4>, <0, 3, -2> pigment { rgbf <0.9, 1, 0.9, 0.9> } interior { ior 1.4 } }
sphere { <0.5, 0.3, 0>, 1 pigment { rgb <1, 0.4, 0.2> } }
