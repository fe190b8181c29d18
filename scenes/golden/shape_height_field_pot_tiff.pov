// height_field from POT (a GIF twice as wide holding 16-bit heights: high bytes left, low
// bytes right) and from TIFF, which POV-Ray 3.7 reads through libtiff's 8-bit RGBA
// interface (red * 256 + green; 16-bit grey keeps its high byte, 16-bit colour rounds);
// types from keywords, from extensions, and a name without extension.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 6.5, -6.5> look_at <0, 0, 0.3> angle 52 }
light_source { <-5, 10, -7> color rgb 1 }
light_source { <6, 5, -2> color rgb 0.35 }
#declare T = texture { pigment { gradient y color_map { [0 rgb <0.3, 0.5, 0.2>] [1 rgb <0.95, 0.9, 0.8>] } }
                       finish { specular 0.3 } }
#macro Place(X, Z) translate <-0.5, 0, -0.5> scale <1.7, 1, 1.7> translate <X, 0, Z> #end
height_field { pot "images/hf_heights.pot" texture { T } Place(-2.2, 1.6) }
height_field { tiff "images/hf_grey8" texture { T } Place(0, 1.6) }
height_field { "images/hf_grey16.tif" texture { T } Place(2.2, 1.6) }
height_field { tiff "images/hf_rgb8.tif" texture { T } Place(-2.2, -0.6) }
height_field { "images/hf_rgb16.tif" smooth texture { T } Place(0, -0.6) }
height_field { pot "images/hf_heights.pot" smooth texture { T } rotate 90*y Place(2.2, -0.6) }
