// golden-args: +UA
// sky_sphere emission scales the sky's pigments (not the background); the background's
// filter and transmit count with +UA in a 3.7 scene.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -5> look_at <0, 1, 0> }
light_source { <-3, 5, -4> color rgb 1 }
background { rgbft <0.3, 0.6, 0.2, 0.3, 0.4> }
sky_sphere {
  pigment { gradient y color_map { [0 rgbt <1, 0.5, 0.2, 0.5>] [1 rgbt <0.2, 0.3, 0.9, 1>] } }
  emission 0.7
}
sphere { <0, 0.5, 0>, 1 pigment { rgb <0.8, 0.2, 0.2> } }
