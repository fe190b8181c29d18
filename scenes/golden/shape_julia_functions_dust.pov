// julia_fractal: the hypercomplex functions exp ... atanh and pwr (inverse trigonometric
// and hyperbolic ones give dust; the march finds or misses each grain as POV-Ray's, and
// their shadows on each other need its shadow-ray bits).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -9> look_at <0, 0, 0> angle 40 }
light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 2, -8> color rgb 0.4 }
#declare C = <0.3, 0.2, 0.1, 0.05>;
julia_fractal { C hypercomplex ln max_iteration 6 precision 20
  pigment { rgb <0.9, 0.6, 0.3> } scale 0.22 translate <-2.2, 1.5, 0> }
julia_fractal { C hypercomplex asin max_iteration 6 precision 20
  pigment { rgb <0.4, 0.8, 0.5> } scale 0.22 translate <0, 1.5, 0> }
julia_fractal { C hypercomplex acos max_iteration 6 precision 20
  pigment { rgb <0.5, 0.6, 0.9> } scale 0.22 translate <2.2, 1.5, 0> }
julia_fractal { C hypercomplex atan max_iteration 6 precision 20
  pigment { rgb <0.9, 0.9, 0.5> } scale 0.22 translate <-2.2, 0, 0> }
julia_fractal { C hypercomplex asinh max_iteration 6 precision 20
  pigment { rgb <0.9, 0.5, 0.8> } scale 0.22 translate <0, 0, 0> }
julia_fractal { C hypercomplex cosh max_iteration 6 precision 20
  pigment { rgb <0.6, 0.9, 0.9> } scale 0.22 translate <2.2, 0, 0> }
julia_fractal { C hypercomplex acosh max_iteration 6 precision 20
  pigment { rgb <0.9, 0.6, 0.3> } scale 0.22 translate <-2.2, -1.5, 0> }
julia_fractal { C hypercomplex tanh max_iteration 6 precision 20
  pigment { rgb <0.4, 0.8, 0.5> } scale 0.22 translate <0, -1.5, 0> }
julia_fractal { <0.1, -0.3, 0.2, 0> hypercomplex atanh max_iteration 8 precision 25
  pigment { rgb <0.5, 0.6, 0.9> } scale 0.22 translate <2.2, -1.5, 0> }
julia_fractal { <-0.2, 0.1, 0.3, 0.1> hypercomplex pwr(3, 0) max_iteration 5 precision 20
  pigment { rgb 0.9 } scale 0.15 translate <1.1, -0.75, -1> }
