// A reflection exponent over negative light: a parallel light's fade turns negative far
// behind the light's plane (POV-Ray's depth there is negative, 1 + d / fade_distance < 0),
// and the floor reflected from there is a negative colour. POV-Ray raises each channel to
// 1 / exponent as it is: a non-integer power of a negative channel is NaN, written as 0
// (black pixels); an integer power (exponent 0.5) squares it.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1.2, -5> look_at <0, 0.3, 0> angle 45 }
light_source { <0, 4, -3> color rgb 1 parallel point_at <0, 0, 0> fade_distance 2 fade_power 1 }
light_source { <3, 5, -6> color rgb 0.3 }
plane { y, -1 pigment { checker color rgb 0.9 color rgb <0.2, 0.4, 0.8> } }
sphere { <-0.8, 0, 0>, 0.8 pigment { rgb 0.3 } finish { reflection { 0.4 exponent 1.25 } } }
sphere { <0.8, 0, 0>, 0.8 pigment { rgb 0.3 } finish { reflection { 0.4 exponent 0.5 } } }
