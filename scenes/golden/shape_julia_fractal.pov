// julia_fractal: quaternion sqr and cube, hypercomplex sqr and cube, a
// sliced one, an unevenly scaled one, and one in an intersection (all its crossings,
// whose depths lag their points in POV-Ray).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -8> look_at <0, 0, 0.5> angle 52 }
light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 5, -2> color rgb 0.35 }
plane { y, -1.3 pigment { checker rgb 0.9 rgb 0.6 scale 0.8 } }
julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 15
  pigment { rgb <0.9, 0.4, 0.3> } translate <-3, 0, 1.5> }
julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion cube max_iteration 8 precision 20
  pigment { rgb <0.3, 0.6, 0.9> } translate <0, 0, 1.5> }
julia_fractal { <-0.745, 0, 0.113, 0.05> hypercomplex sqr max_iteration 9 precision 20
  pigment { rgb <0.4, 0.85, 0.4> } scale <1, 1.5, 1> translate <3, 0, 1.5> }
julia_fractal { <-0.745, 0, 0.113, 0.05> hypercomplex cube max_iteration 6 precision 30
  pigment { rgb <0.9, 0.8, 0.3> } scale 0.6 translate <-3, 0, -1.5> }
julia_fractal { <0.2, 0.1, 0.59, -0.2> quaternion sqr max_iteration 7 slice <0, 0.3, 0, 1>, 0.1
  precision 20 pigment { rgb <0.8, 0.5, 0.9> } rotate 30*y translate <0, 0, -1.5> }
intersection {
  julia_fractal { <-0.3, 0.5, -0.2, -0.5> quaternion sqr max_iteration 8 precision 20 }
  box { -1, <1, 0.2, 1> }
  pigment { rgb <0.5, 0.9, 0.9> } scale 0.7 translate <3, 0, -1.5> }

