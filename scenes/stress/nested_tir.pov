// Nested transparent spheres (glass in water in glass) with total internal reflection and
// max_trace_level 256: rays bounce inside the dense shells for many levels.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 256 }
camera { location <0, 0.5, -4> look_at <0, 0, 0> }
light_source { <5, 10, -5> rgb 1 }
background { rgb <0.4, 0.5, 0.7> }
plane { y, -1.2 pigment { checker rgb 0.1, rgb 0.9 } }
sphere { 0, 1.2 pigment { rgbf <1, 1, 1, 0.95> } finish { reflection 0.1 } interior { ior 2.4 } }
sphere { 0, 0.8 pigment { rgbf <0.8, 1, 0.8, 0.9> } interior { ior 1.33 } }
sphere { 0, 0.4 pigment { rgbf <1, 0.8, 0.8, 0.9> } interior { ior 1.9 } }
box { <-0.15, -0.15, -0.15>, <0.15, 0.15, 0.15> pigment { rgbf <1, 1, 1, 0.8> } interior { ior 2.4 } rotate <30, 40, 0> }
