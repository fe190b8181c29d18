// Patterned textures that let light through: a texture_map of transparent and opaque
// entries and a checker of textures cast shadows blended from their entries (POV-Ray's
// shadow texture), and refract per entry.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 2, -6> look_at <0, 0.2, 0> angle 45 }
light_source { <-3, 7, -4> color rgb 1 }
plane { y, -1 pigment { checker color rgb 0.9 color rgb <0.1, 0.3, 0.6> scale 0.5 } }
sphere { <-1.1, 0, 0>, 0.9
  texture { gradient y texture_map { [0.3 pigment { rgbt <1, 0.5, 0.3, 0.9> }]
                                     [0.7 pigment { rgb <0.2, 0.6, 1> } finish { phong 0.6 }] }
            scale 0.8 }
  interior { ior 1.2 } }
box { <0.4, -0.98, -0.6>, <1.8, 0.6, 0.6>
  texture { checker texture { pigment { rgbf <0.9, 1, 0.9, 0.9> } }
                    texture { pigment { rgbt <1, 0.9, 0.6, 0.5> } } scale 0.4 }
  rotate y*20 }
