// Glass merges: the inner surfaces are gone; filter and transmit, a shared interior and
// children with their own (POV-Ray then does not refract the exit), and a nested sphere.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 12 }
camera { location <0, 2.2, -6> look_at <0, 0.2, 0> angle 48 }
light_source { <-4, 7, -5> color rgb 1 }
light_source { <5, 3, -4> color rgb 0.4 shadowless }
plane { y, -1 pigment { checker color rgb 0.9 color rgb <0.1, 0.3, 0.6> scale 0.5 } }
merge { cylinder { <0, -0.6, 0>, <0, 0.3, 0>, 0.35 } sphere { <0, 0.3, 0>, 0.5 }
  pigment { rgbt <0.7, 0.9, 1, 0.6> } interior { ior 1.33 } translate <-1.6, 0, 0> }
merge { sphere { <-0.3, 0, 0>, 0.55 interior { ior 1.5 } } sphere { <0.3, 0, 0>, 0.55 interior { ior 1.5 } }
  pigment { rgbf <0.9, 1, 0.9, 0.9> } }
merge { box { -0.5, 0.5 } sphere { 0, 0.65 } sphere { 0, 0.25 interior { ior 2 } }
  pigment { rgbf <1, 1, 0.8, 0.9> } finish { phong 0.6 } interior { ior 1.4 } rotate y*30 translate <1.6, 0, 0> }
