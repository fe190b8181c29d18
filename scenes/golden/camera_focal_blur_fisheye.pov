// golden-args: +UA
// Focal blur on a fisheye: rays outside the image circle are none (POV-Ray counts them
// in the variance as transparent black but leaves them out of the colour).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  fisheye angle 170 location <0, 1.2, -4> look_at <0, 0.8, 0>
  aperture 0.3 blur_samples 4, 19 focal_point <0, 0.8, 0>
}
light_source { <-3, 6, -5> color rgb 1 }
background { color rgb <0.3, 0.5, 0.8> }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.1 } }
sphere { <-1.5, 1, 0>, 0.8 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
box { <-0.4, 0, -0.4>, <0.4, 1.6, 0.4> rotate y * 30 pigment { color rgb <0.2, 0.8, 0.3> } }
