// A radius-1e5 sphere as the ground: the quadratic's constant term is a difference of 1e10-sized
// numbers, the classic cancellation case.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1.5, -6> look_at <0, 0.5, 0> }
light_source { <20, 30, -20> rgb 1 }
background { rgb <0.5, 0.7, 1> }
sphere { <0, -1e5, 0>, 1e5 pigment { checker rgb 0.2, rgb 0.9 } }
sphere { <0, 1, 0>, 1 pigment { rgb <1, 0.4, 0.2> } }
box { <1.5, 0, -0.5>, <2.5, 1, 0.5> pigment { rgb <0.2, 0.8, 0.4> } }
torus { 0.6, 0.1 pigment { rgb <0.3, 0.3, 1> } translate <-2, 0.1, 0> }
sphere { <5e4, -1e5, 3e4>, 1e5 - 1e-3 pigment { rgb <0.7, 0.7, 0.2> } }
