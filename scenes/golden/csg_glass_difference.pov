// Glass differences: a hollow sphere (the hollow shares the shell's interior: air
// inside), a hollow whose subtracted sphere has its own interior (the hollow is filled
// with it), and an inverse sphere clipped by a box, filter and transmit.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 12 }
camera { location <0, 2.2, -6> look_at <0, 0.2, 0> angle 48 }
light_source { <-4, 7, -5> color rgb 1 }
light_source { <5, 3, -4> color rgb 0.4 shadowless }
plane { y, -1 pigment { checker color rgb 0.9 color rgb <0.1, 0.3, 0.6> scale 0.5 } }
difference { sphere { 0, 0.7 } sphere { <0, 0, -0.15>, 0.45 }
  pigment { rgbf <1, 1, 1, 0.9> } interior { ior 1.5 } translate <-1.6, 0, 0> }
difference { sphere { 0, 0.7 } sphere { <0, 0, -0.15>, 0.45 interior { ior 1.2 } }
  pigment { rgbt <1, 0.9, 0.9, 0.8> } interior { ior 1.5 } }
intersection { box { -0.6, 0.6 } sphere { 0, 0.75 inverse }
  pigment { rgbf <0.9, 0.9, 1, 0.9> } interior { ior 1.4 } rotate y*25 translate <1.6, 0, 0> }
sphere { <1.6, 0.95, 0>, 0.45 clipped_by { plane { y, 0.9 } }
  pigment { rgbt <1, 1, 0.7, 0.7> } interior { ior 1.3 } }
