// POV-Ray 1.0/2.0 textures, as POV-Ray 3.7 reads them below #version 3.0
// (Parse_Vers1_Texture): pigment, normal and finish items written straight in the
// texture. A pattern keyword sets the pigment's type alone (marble and wood keep the
// ramp wave there), checker and hexagon take their colours after the keyword, a bare
// number is crand, alpha is filter, ior and refraction go into the interior, and a
// texture identifier after items replaces them. No assumed_gamma: a 1.0 scene renders
// without gamma correction.
#version 1.0

camera { location <0, 3, -8> look_at <0, 0.3, 0> }
light_source { <-6, 10, -8> colour red 1 green 1 blue 1 }

#declare Stone = texture {
  granite colour_map { [0 0.5 colour red 0.9 green 0.8 blue 0.7 colour red 0.5 green 0.4 blue 0.3]
                       [0.5 1 colour red 0.5 green 0.4 blue 0.3 colour red 0.2 green 0.2 blue 0.2] }
  scale 0.5 phong 0.4 phong_size 30
}
#declare Red = colour red 1 green 0.1 blue 0.1

// The floor: checker with two colours, then scaled.
plane { <0, 1, 0>, -1
  texture { checker colour red 0.9 green 0.9 blue 0.8 colour red 0.2 green 0.3 blue 0.5
            scale 1.2 ambient 0.15 diffuse 0.7 reflection 0.1 }
}

// Back row: marble (turbulence before the type), wood, gradient, agate.
sphere { <-3, 1.6, 2>, 0.8
  texture { turbulence 0.6 octaves 5 omega 0.6 lambda 2.2
            colour_map { [0 0.5 colour red 0.7 green 0.6 blue 0.5 alpha 0.0
                                colour red 0.9 green 0.85 blue 0.8 alpha 0.0]
                         [0.5 1 colour red 0.9 green 0.85 blue 0.8 alpha 0.0
                                colour red 0.3 green 0.2 blue 0.2 alpha 0.0] }
            marble scale 0.7 rotate <0, 0, 30> quick_colour red 0.8 green 0.7 blue 0.6
            phong 1 }
}
sphere { <-1, 1.6, 2>, 0.8
  texture { wood turbulence 0.1 colour_map { [0 colour red 0.8 green 0.5 blue 0.2]
                                             [1 colour red 0.4 green 0.2 blue 0.1] }
            scale 0.2 rotate <40, 20, 0> specular 0.6 roughness 0.02 }
}
sphere { <1, 1.6, 2>, 0.8
  texture { gradient <1, 1, 0> colour_map { [0 colour Red] [1 colour red 0.1 green 0.2 blue 0.9] }
            brilliance 3 diffuse 0.8 }
}
sphere { <3, 1.6, 2>, 0.8
  texture { agate colour_map { [0 colour red 1 green 1 blue 1] [1 colour red 0.2 green 0.1 blue 0.3] }
            scale 0.6 metallic phong 0.8 }
}

// Front row: normals and finishes.
sphere { <-3, 0, 0>, 0.8
  texture { colour red 0.3 green 0.6 blue 0.9 bumps 0.6 scale 0.2 phong 1 phong_size 60 }
}
sphere { <-1, 0, 0>, 0.8
  texture { colour red 0.9 green 0.7 blue 0.2 ripples 0.5 frequency 3 phase 0.25 ambient 0.2 }
}
sphere { <1, 0, 0>, 0.8
  texture { Stone dents 0.8 scale 0.5 }
}
sphere { <3, 0, 0>, 0.8
  texture { bozo colour_map { [0 colour red 0.2 green 0.7 blue 0.3] [1 colour red 0.9 green 0.9 blue 0.7] }
            waves 0.4 frequency 2 scale 0.4 }
}

// Hexagon with three colours, wrinkles, and an identifier overwriting earlier items.
box { <-4.5, -1, -2.5>, <-2.5, -0.6, -1.5>
  texture { hexagon colour red 1 colour Red colour red 0.2 green 0.2 blue 0.9 scale 0.25 }
}
box { <2.5, -1, -2.5>, <4.5, -0.6, -1.5>
  texture { colour red 0 green 1 blue 0 wrinkles 1 Stone translate <0.3, 0, 0> }
}

// Glass with the old refraction items: filter through alpha.
sphere { <0, -0.3, -2>, 0.6
  texture { colour red 1 green 1 blue 1 alpha 0.9 refraction 1 ior 1.5 phong 1 }
}
