// Three rules of POV-Ray 3.7's parser that older and course scenes rely on:
// - clipped_by { } and bounded_by { } take transforms after their objects, each moving
//   every object of the block (Parse_Bound_Clip);
// - an image_map (bump_map, image_pattern, material_map) may start with POV-Ray 1.0's
//   orientation vector, which it warns about and ignores (Parse_Image);
// - up to #version 3.1 a texture layer laid over another lets it through by transmit,
//   not filter (Link_Textures), in plain colours, colour maps and pigment maps.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1.5, -7> look_at <0, 0.2, 0> angle 60 }
light_source { <-4, 8, -6> color rgb 1 }
light_source { <5, 3, -4> color rgb 0.4 }
plane { y, -1 pigment { checker color rgb 0.85 color rgb <0.3, 0.45, 0.7> } }
sphere { <-3, 0, 0>, 1 pigment { rgb <1, 0.5, 0.2> }
  clipped_by { box { -1, 1 } box { -1.2, 0.9 } scale <0.5, 2, 2> rotate 30*y translate <-3, 0, 0> } }
sphere { <-1.2, 0, 0>, 0.8 pigment { rgb <0.2, 0.6, 1> }
  bounded_by { sphere { 0, 0.6 } translate <-1.2, 0.2, 0> } }
box { <-0.5, -1, -0.1>, <0.5, 1, 0.1>
  pigment { image_map { <1, -1, 0> png "images/card.png" } translate <-0.5, -0.5, 0> scale 1.2 }
  translate <0.4, 0.2, 0> }
#version 3.1;
sphere { <1.9, 0, 0>, 0.7
  texture { pigment { rgb <0.8, 0.7, 0.6> } }
  texture { pigment { rgbf <1, 0, 0, 0.95> } } }
#declare Veil = texture { pigment { gradient y colour_map { [0 rgbf <0, 0, 1, 0.9>] [1 rgbf <0, 1, 0, 0.6>] } } }
  texture { pigment { checker rgbf <1, 1, 0, 0.8>, rgbf <1, 0, 1, 0.5> scale 0.3 } }
sphere { <3.3, 0, 0>, 0.6 texture { pigment { rgb <0.9, 0.9, 0.9> } } texture { Veil } }
#version 3.7;
