// pigment_pattern: the grey (0.297 r + 0.589 g + 0.114 b) of a pigment as a pattern, with
// its own transforms on top of the outer pattern's, in a pigment with a colour map, in a
// texture_map, and as a normal; an empty one is black.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0, 0> angle 50 }
light_source { <-4, 8, -5> color rgb 1 }
plane { y, -1
  pigment { pigment_pattern { checker rgb <1, 0, 0> rgb <0, 0, 1> scale 0.5 }
            color_map { [0 rgb <0.1, 0.3, 0.1>] [0.3 rgb <1, 0.9, 0.6>] } rotate y * 20 } }
sphere { <-1.6, 0, 0>, 1
  texture { pigment_pattern { gradient x color_map { [0 rgb 0] [1 rgb <1, 0.5, 0>] } scale 0.3 }
            texture_map { [0 pigment { rgb <0.2, 0.2, 0.8> } finish { phong 0.8 }]
                          [1 pigment { rgb <1, 1, 0.2> }] }
            turbulence 0.3 } }
sphere { <0.8, 0, 0.5>, 1
  pigment { rgb <0.9, 0.5, 0.3> }
  normal { pigment_pattern { bozo color_map { [0 rgb 0] [1 rgb 1] } scale 0.2 } 0.8 } }
box { <1.9, -1, -2.2>, <2.9, 0.2, -1.2>
  pigment { pigment_pattern { } color_map { [0 rgb <0, 1, 0>] [1 rgb <1, 0, 0>] } } }
