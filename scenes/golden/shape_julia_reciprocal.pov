// julia_fractal: the hypercomplex reciprocal, alone (a dusty set: its thin parts are
// found or missed by the march exactly as POV-Ray's).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -8> look_at <0, 0, 0.5> angle 30 }
light_source { <-5, 9, -6> color rgb 1 }
julia_fractal { <-0.3, 0.5, -0.2, -0.5> hypercomplex reciprocal max_iteration 5 precision 20
  pigment { rgb <0.5, 0.9, 0.9> } }
