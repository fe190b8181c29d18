// golden-args: --block-mean 8
// A jittered area light: POV-Ray moves each sample randomly inside its cell, so its
// penumbra is noisy and differs between runs; compared as 8x8 block means.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -5> look_at <0, 0, 0> angle 45 }
light_source { <-2, 5, -2> color rgb 1 area_light x * 3, z * 3, 5, 5 jitter adaptive 1 circular orient }
plane { y, -1 pigment { rgb 0.9 } }
sphere { <0, 0, 0>, 1 pigment { rgb <0.8, 0.4, 0.2> } }
box { <1.3, -1, -0.5>, <2, 0.5, 0.2> pigment { rgb <0.2, 0.5, 0.8> } }
