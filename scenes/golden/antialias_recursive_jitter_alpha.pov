// golden-args: +A0.1 +AM2 +R4 +J +UA
// Anti-aliasing method 2 (corners per block, recursive subdivision to depth 4) with
// POV-Ray's jitter, and alpha: the background's transmit is averaged like a colour.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 0.8, 0> angle 50 }
light_source { <-3, 6, -5> color rgb 1 }
background { color rgbt <0.9, 0.9, 0.95, 0.6> }
plane { y, 0 pigment { color rgb 0.05 } }
sphere { <-1.6, 1, 0>, 0.8 pigment { color rgb <0.05, 0.05, 0.3> } finish { phong 0.8 } }
box { <-0.4, 0, -0.4>, <0.4, 2.2, 0.4> rotate y * 30 pigment { color rgb <1, 0.2, 0.1> } }
cylinder { <1.2, 0.1, -0.5>, <2.2, 2, 0.5>, 0.12 pigment { color rgb 0.02 } }
