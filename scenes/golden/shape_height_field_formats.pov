// height_field from each image container POV-Ray 3.7 derives heights from differently:
// 8-bit grey PNG (read through a grey palette: some values one lower), 16-bit grey PNG
// (exact), palette PNG (index * 256), 8-bit RGB PNG and Targa (red * 256 + green),
// 16-bit RGB PNG (grey weights), 8-bit PGM (v * 257); type from the extension too.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 6.5, -6.5> look_at <0, 0, 0.3> angle 52 }
light_source { <-5, 10, -7> color rgb 1 }
light_source { <6, 5, -2> color rgb 0.35 }
#declare T = texture { pigment { gradient y color_map { [0 rgb <0.3, 0.5, 0.2>] [1 rgb <0.95, 0.9, 0.8>] } }
                       finish { specular 0.3 } }
#macro Place(X, Z) translate <-0.5, 0, -0.5> scale <1.7, 1, 1.7> translate <X, 0, Z> #end
height_field { png "images/hf_grey8.png" texture { T } Place(-2.2, 1.6) }
height_field { png "images/hf_grey16.png" texture { T } Place(0, 1.6) }
height_field { png "images/hf_palette.png" texture { T } Place(2.2, 1.6) }
height_field { png "images/hf_rgb8.png" texture { T } Place(-2.2, -0.6) }
height_field { "images/hf_rgb16.png" texture { T } Place(0, -0.6) }
height_field { tga "images/hf_rgb8.tga" texture { T } Place(2.2, -0.6) }
height_field { pgm "images/hf_grey8" texture { T } Place(0, -2.6) }
