// golden-args: +UA
// +UA: the background is transparent; a transmitting sphere gives partial alpha, written
// straight (non-premultiplied) as POV-Ray writes it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -4> look_at 0 }
light_source { <2, 4, -3> color rgb 1 }
sphere { 0, 1 pigment { rgbt <1, 0.5, 0.2, 0.5> } finish { phong 0.5 } }
sphere { <1, 1, 1>, 1 pigment { rgb <0.2, 0.5, 1> } }
