// golden-args: --block-mean 8
// Media whose sample positions are random in POV-Ray (method 1 always, methods 2 and 3
// with jitter): its noise differs between runs, so the images are compared as 8x8 block
// means. Densities vary along the ray, so the positions matter.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.2, -6> look_at <0, 0.9, 0> angle 55 }
light_source { <3, 6, -5> color rgb 1 }
background { color rgb 0.1 }
plane { y, -0.1 pigment { checker rgb 0.8 rgb 0.3 } }
sphere { 0, 0.9 hollow pigment { rgbt 1 }
  interior { media { method 1 intervals 8 samples 4 emission <1, 0.6, 0.2> absorption 0.6
                     density { spherical } } }
  translate <-1.8, 1, 0> }
box { -0.8, 0.8 hollow pigment { rgbt 1 }
  interior { media { method 2 intervals 4 samples 3 jitter 0.8 emission <0.2, 0.7, 1.1>
                     absorption 0.4 density { gradient y color_map { [0 rgb 0] [1 rgb 1.5] } } } }
  translate <0, 0.9, 0.3> }
sphere { 0, 0.9 hollow pigment { rgbt 1 }
  interior { media { samples 8 jitter 0.5 absorption <1.5, 0.8, 0.3> emission 0.3
                     density { spherical color_map { [0 rgb 0] [0.5 rgb 1] [1 rgb 2] } } } }
  translate <1.8, 1, 0> }
