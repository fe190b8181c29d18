// golden-args: --block-mean 8
// crand: each point's diffuse light loses a random share. POV-Ray's random numbers and
// ours differ pixel for pixel, so the images are compared by 8x8 block means.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0.3, 0> angle 45 }
light_source { <-4, 6, -5> color rgb 1 }
plane { y, -1 pigment { checker color rgb 0.9 color rgb <0.1, 0.3, 0.6> scale 0.5 } }
sphere { <0, 0.2, 0>, 1 pigment { rgb <0.8, 0.6, 0.4> } finish { crand 0.3 } }
