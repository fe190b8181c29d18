// Focal blur in a 3.1 scene (the old camera syntax, items applied where they stand):
// `blur_samples` takes one number, and without a focal point the focal distance is the
// direction's length as angle and look_at left it.
#version 3.1;
global_settings { assumed_gamma 1.0 }
camera {
  location <0, 1.5, -5> angle 50 look_at <0, 0.8, 0>
  aperture 0.5 blur_samples 12 confidence 0.8
}
light_source { <-3, 6, -5> color rgb 1 }
background { color rgb <0.3, 0.5, 0.8> }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.1 } }
sphere { <-1.5, 1, 2>, 0.8 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
box { <-0.4, 0, -0.4>, <0.4, 1.6, 0.4> rotate y * 30 pigment { color rgb <0.2, 0.8, 0.3> } }
