// height_field seen along its surface: rays almost parallel to a flat field and to the
// cells' edges (the DDA's corner and near-parallel rules), from below, and a vertical
// view down onto a field (the single-cell test).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <-0.2, 0.52, -2.8> look_at <0.3, 0.5, 0.5> angle 40 }
light_source { <-5, 10, -7> color rgb 1 }
light_source { <3, -4, -5> color rgb 0.5 }
height_field { png "images/hf_flat.png" pigment { checker rgb 1 rgb 0.3 scale 0.05 }
               scale <2, 1, 2> translate <-1, 0, -0.5> }
height_field { png "images/hf_grey8.png" pigment { rgb <0.8, 0.6, 0.4> }
               scale <1.2, 0.4, 1.2> translate <-0.2, 0.35, 0> }
height_field { png "images/hf_rgb8.png" smooth pigment { rgb <0.5, 0.7, 0.9> }
               scale <1, 0.3, 1> rotate 45*y translate <0.8, 0.5, 0.2> }
