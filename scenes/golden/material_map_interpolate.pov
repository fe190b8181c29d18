// material_map with interpolate: POV-Ray weights the corner pixels' palette indices as
// their colours (bilinear 2, bicubic 3, normalised distance 4) and truncates the sum to
// the texture's number; a truecolour image's corners count as index -1 each, so where
// their weights sum to exactly 1 the interpolated red * 255 picks, and where they sum to
// a hair under 1 the truncation gives texture 0.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
#declare T0 = texture { pigment { rgb <0.9, 0.2, 0.1> } finish { ambient 1 diffuse 0 } }
#declare T1 = texture { pigment { rgb <0.1, 0.7, 0.2> } finish { ambient 1 diffuse 0 } }
#declare T2 = texture { pigment { rgb <0.2, 0.2, 0.8> } finish { ambient 1 diffuse 0 } }
#declare T3 = texture { pigment { rgb <0.9, 0.9, 0.3> } finish { ambient 1 diffuse 0 } }
#macro Tile(File, Interpolation, X, Y)
  box { <0, 0, 0>, <2.5, 2.7, 0.5>
        texture { material_map { png File interpolate Interpolation
                                 texture { T0 } texture { T1 } texture { T2 } texture { T3 } }
                  scale <2.5, 2.7, 1> }
        translate <X, Y, 0> }
#end
Tile("images/palette.png", 2, -3.95, 0.1)
Tile("images/palette.png", 3, -1.25, 0.1)
Tile("images/palette.png", 4, 1.45, 0.1)
Tile("images/card.png", 2, -3.95, -2.9)
Tile("images/card.png", 3, -1.25, -2.9)
Tile("images/card.png", 4, 1.45, -2.9)
