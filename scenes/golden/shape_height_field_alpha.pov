// height_field from images with an alpha channel (opacity 0.6): POV-Ray 3.7 takes its
// heights from the colours as stored, alpha ignored: 8-bit RGBA PNG, Targa and BMP (red
// * 256 + green), 16-bit RGBA PNG (grey weights), grey with alpha (a grey container, not
// the palette plain 8-bit grey is read through).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 6.5, -6.5> look_at <0, 0, 0.3> angle 52 }
light_source { <-5, 10, -7> color rgb 1 }
light_source { <6, 5, -2> color rgb 0.35 }
#declare T = texture { pigment { gradient y color_map { [0 rgb <0.3, 0.5, 0.2>] [1 rgb <0.95, 0.9, 0.8>] } }
                       finish { specular 0.3 } }
#macro Place(X, Z) translate <-0.5, 0, -0.5> scale <1.7, 1, 1.7> translate <X, 0, Z> #end
height_field { png "images/hf_rgba8.png" texture { T } Place(-2.2, 1.6) }
height_field { png "images/hf_greya8.png" texture { T } Place(0, 1.6) }
height_field { png "images/hf_rgba16.png" texture { T } Place(2.2, 1.6) }
height_field { tga "images/hf_rgba8.tga" texture { T } Place(-1.1, -1.2) }
height_field { bmp "images/hf_rgba8.bmp" texture { T } Place(1.1, -1.2) }
