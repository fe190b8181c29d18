// A camera normal: the primary rays bent by a bump pattern at the image coordinates
// (-0.5..0.5), not moved by the camera's look_at and rotate.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  location <0, 1.5, -4> look_at <0, 0.8, 0> rotate y * 20
  normal { ripples 0.4 frequency 3 scale 0.3 translate <0.1, 0.05, 0> }
}
light_source { <-3, 6, -5> color rgb 1 }
background { color rgb <0.3, 0.5, 0.8> }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.1 } }
sphere { <-1.5, 1, 0>, 0.8 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
box { <-0.4, 0, -0.4>, <0.4, 1.6, 0.4> rotate y * 30 pigment { color rgb <0.2, 0.8, 0.3> } }
cylinder { <1.5, 0, 0>, <1.5, 2, 0>, 0.3 pigment { color rgb <0.9, 0.9, 0.2> } }
