// golden-args: +UA
// A camera normal on a fisheye: the pattern is evaluated at the fisheye's own
// coordinates (polar angle, angle from the axis); bumps use the noise generator.
#version 3.7;
global_settings { assumed_gamma 1.0 noise_generator 3 }
camera {
  fisheye angle 160 location <0, 1.2, -4> look_at <0, 0.8, 0>
  normal { bumps 0.2 scale 0.2 }
}
light_source { <-3, 6, -5> color rgb 1 }
background { color rgb <0.3, 0.5, 0.8> }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.1 } }
sphere { <-1.5, 1, 0>, 0.8 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
box { <-0.4, 0, -0.4>, <0.4, 1.6, 0.4> rotate y * 30 pigment { color rgb <0.2, 0.8, 0.3> } }
cylinder { <1.5, 0, 0>, <1.5, 2, 0>, 0.3 pigment { color rgb <0.9, 0.9, 0.2> } }
