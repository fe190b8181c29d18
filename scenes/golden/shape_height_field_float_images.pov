// height_field from float images, which POV-Ray 3.7 takes as if 8-bit colour (red * 256 +
// green): Radiance RGBE (each mantissa plus half a step) and OpenEXR (read in half
// precision: a 32-bit float file is rounded), and one without alpha `premultiplied` (no
// effect); a name without extension takes the output type, PNG.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 6.5, -6.5> look_at <0, 0, 0.3> angle 52 }
light_source { <-5, 10, -7> color rgb 1 }
light_source { <6, 5, -2> color rgb 0.35 }
#declare T = texture { pigment { gradient y color_map { [0 rgb <0.3, 0.5, 0.2>] [1 rgb <0.95, 0.9, 0.8>] } }
                       finish { specular 0.3 } }
#macro Place(X, Z) translate <-0.5, 0, -0.5> scale <1.7, 1, 1.7> translate <X, 0, Z> #end
height_field { hdr "images/hf_rgbe.hdr" texture { T } Place(-2.2, 1.6) }
height_field { "images/hf_float.exr" texture { T } Place(0, 1.6) }
height_field { exr "images/hf_half" premultiplied on texture { T } Place(2.2, 1.6) }
height_field { "images/hf_rgbe.hdr" smooth texture { T } Place(-2.2, -0.6) }
height_field { "images/hf_grey16" water_level 0.3 texture { T } Place(0, -0.6) }
height_field { exr "images/hf_float.exr" smooth texture { T } rotate 90*y Place(2.2, -0.6) }
