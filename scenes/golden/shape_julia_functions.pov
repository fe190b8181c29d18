// julia_fractal: the hypercomplex functions built from complex ones (duplex form), six
// of them side by side with different parameters, precisions and iteration counts.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -9> look_at <0, 0, 0> angle 40 }
light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 2, -8> color rgb 0.4 }
#declare C = <0.3, 0.2, 0.1, 0.05>;
julia_fractal { C hypercomplex exp max_iteration 6 precision 20
  pigment { rgb <0.9, 0.6, 0.3> } scale 0.3 translate <-2.2, 1, 0> }
julia_fractal { C hypercomplex sin max_iteration 6 precision 20
  pigment { rgb <0.4, 0.8, 0.5> } scale 0.2 translate <0, 1, 0> }
julia_fractal { <-0.2, 0.4, 0.1, 0> hypercomplex cos max_iteration 7 precision 30
  pigment { rgb <0.5, 0.6, 0.9> } scale 0.2 translate <2.2, 1, 0> }
julia_fractal { C hypercomplex tan max_iteration 5 precision 15
  pigment { rgb <0.9, 0.9, 0.5> } scale 0.3 rotate y * 30 translate <-2.2, -1.2, 0> }
julia_fractal { C hypercomplex sinh max_iteration 6 precision 20 slice <0, 0.2, 0, 1>, 0.1
  pigment { rgb <0.9, 0.5, 0.8> } scale <0.3, 0.22, 0.3> translate <0, -1.2, 0> }
julia_fractal { <0.1, 0.3, -0.2, 0.1> hypercomplex pwr(2, 0.5) max_iteration 6 precision 20
  pigment { rgb <0.6, 0.9, 0.9> } scale 0.3 translate <2.2, -1.2, 0> }
