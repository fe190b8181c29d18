// Focal blur with a bokeh pigment (the aperture's shape: points kept by the pigment's
// grey, POV-Ray's Halton and Mersenne Twister rejection sampling) and a focal_point
// off the axis.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  location <0, 1.5, -5> look_at <0, 0.8, 0> angle 50
  aperture 0.6 blur_samples 30 focal_point <1.2, 1, -2>
  bokeh { pigment { leopard color_map { [0 rgb 0] [1 rgb 1] } scale 0.1 } }
}
light_source { <-3, 6, -5> color rgb 1 }
background { color rgb <0.3, 0.5, 0.8> }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.1 } }
sphere { <-1.5, 1, 2>, 0.8 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
sphere { <0.5, 2.2, 4>, 0.2 pigment { color rgb 1 } finish { ambient 1 diffuse 0 } }
cylinder { <1.2, 0, -2>, <1.2, 2, -2>, 0.3 pigment { color rgb <0.9, 0.9, 0.2> } }
