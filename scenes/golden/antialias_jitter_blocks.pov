// golden-args: +A0.2 +AM1 +R2 +J0.5 +BS8 +AG1.8
// Anti-aliasing method 1 as POV-Ray decides it per render block (+BS8: each block traces
// its own border row and column), with POV-Ray's jitter table (+J0.5), an anti-aliasing
// gamma (+AG1.8) combined with the scene's working gamma (assumed_gamma 2.2).
#version 3.7;
global_settings { assumed_gamma 2.2 }
camera { location <0, 1.5, -6> look_at <0, 0.8, 0> angle 50 }
light_source { <-3, 6, -5> color rgb 1 }
background { color rgb <0.9, 0.9, 0.95> }
plane { y, 0 pigment { color rgb 0.05 } }
sphere { <-1.6, 1, 0>, 0.8 pigment { color rgb <0.05, 0.05, 0.3> } finish { phong 0.8 } }
box { <-0.4, 0, -0.4>, <0.4, 2.2, 0.4> rotate y * 30 pigment { color rgb <1, 0.2, 0.1> } }
cylinder { <1.2, 0.1, -0.5>, <2.2, 2, 0.5>, 0.12 pigment { color rgb 0.02 } }
