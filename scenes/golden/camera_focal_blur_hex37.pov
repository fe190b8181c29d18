// golden-args: +UA
// Focal blur with `blur_samples min, max` on the 37-point hexagonal grid (batches 7, 6,
// 6, 4, ...), stricter confidence and variance, a rotated camera without look_at (the
// default focal distance: 1, POV-Ray's initial direction length) and a transparent
// background.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  location <0, 1.5, -5> direction 1.5 * z rotate <10, 15, 0>
  aperture 0.3 blur_samples 10, 37 confidence 0.95 variance 1/5000
}
light_source { <-3, 6, -5> color rgb 1 }
background { color rgbt <0.3, 0.5, 0.8, 0.5> }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.1 } }
sphere { <-1.5, 1, 2>, 0.8 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
box { <-0.4, 0, -0.4>, <0.4, 1.6, 0.4> rotate y * 30 pigment { color rgb <0.2, 0.8, 0.3> } }
