// Camera given by direction, right and up (no look_at), then rotated; square aspect.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  location <0, 1, -5>
  direction <0, 0, 1.5>
  right x * 4/3
  up y
  rotate <10, -15, 0>
}
light_source { <-4, 6, -6> color rgb 1 }
plane { y, -0.5 pigment { color rgb <0.4, 0.5, 0.4> } }
sphere { <-1, 0.5, 1>, 1 pigment { color rgb <1, 1, 0> } }
sphere { <1.5, 0, 2>, 0.5 pigment { color rgb <0, 1, 1> } }
