// Glass intersections: a lens of two spheres (shared interior), the same with each sphere's
// own interior, and a box-cylinder intersection with a transmitting texture.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 12 }
camera { location <0, 2.2, -6> look_at <0, 0.2, 0> angle 48 }
light_source { <-4, 7, -5> color rgb 1 }
light_source { <5, 3, -4> color rgb 0.4 shadowless }
plane { y, -1 pigment { checker color rgb 0.9 color rgb <0.1, 0.3, 0.6> scale 0.5 } }
intersection { sphere { <0, 0, -0.5>, 0.8 } sphere { <0, 0, 0.5>, 0.8 }
  pigment { rgbf <0.8, 1, 0.8, 0.9> } interior { ior 1.45 } rotate y*20 translate <-1.6, 0, 0> }
intersection { sphere { <0, 0, -0.5>, 0.8 interior { ior 1.45 } } sphere { <0, 0, 0.5>, 0.8 interior { ior 1.45 } }
  pigment { rgbf <0.8, 1, 0.8, 0.9> } rotate y*20 }
intersection { box { -0.55, 0.55 } cylinder { -y, y, 0.65 }
  pigment { rgbt <1, 0.8, 0.6, 0.7> } finish { reflection 0.1 } interior { ior 1.6 } rotate <20, 30, 0> translate <1.6, 0, 0> }
