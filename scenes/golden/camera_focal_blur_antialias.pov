// golden-args: +A0.1 +AM2 +R2
// Focal blur with anti-aliasing: POV-Ray blurs each anti-aliasing sample on its own
// (every sample's rays from its own sub-pixel positions).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  location <0, 1.5, -5> look_at <0, 0.8, 0> angle 50
  aperture 0.25 blur_samples 4, 7 focal_point <0, 0.8, 0>
}
light_source { <-3, 6, -5> color rgb 1 }
background { color rgb <0.3, 0.5, 0.8> }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.1 } }
sphere { <-1.5, 1, 2>, 0.8 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
box { <-0.4, 0, -0.4>, <0.4, 1.6, 0.4> rotate y * 30 pigment { color rgb <0.2, 0.8, 0.3> } }
