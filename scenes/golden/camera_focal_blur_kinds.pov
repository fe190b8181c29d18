// Focal blur on an orthographic camera: POV-Ray starts every blurred ray at the camera
// location plus the aperture point (not on the image plane), aimed at the direction
// times the focal distance; and a camera normal on top of the blur.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  orthographic location <0, 1.5, -5> look_at <0, 0.8, 0>
  aperture 0.2 blur_samples 7 focal_point <0, 0.8, 0>
  normal { bumps 0.1 scale 0.3 }
}
light_source { <-3, 6, -5> color rgb 1 }
background { color rgb <0.3, 0.5, 0.8> }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.1 } }
sphere { <-1.5, 1, 2>, 0.8 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
box { <-0.4, 0, -0.4>, <0.4, 1.6, 0.4> rotate y * 30 pigment { color rgb <0.2, 0.8, 0.3> } }
