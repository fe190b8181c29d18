// golden-args: --block-mean 8
// A glass sphere's caustic on a plane: photons refracted twice, stored where they land,
// gathered in the plane's diffuse light; the filtered shadow is black (the photons bring
// its light).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10
  photons { spacing 0.01 } }
camera { location <0, 4, -4> look_at <0, 0.3, 0> angle 40 }
light_source { <1, 7, 1> color rgb 1.2 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.6 } }
sphere { <0, 1, 0>, 0.8
  pigment { rgbf <0.95, 1, 0.95, 0.95> } finish { phong 0.5 reflection 0.05 }
  interior { ior 1.5 }
  photons { target refraction on reflection on } }
