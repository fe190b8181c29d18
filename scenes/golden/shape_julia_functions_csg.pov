// julia_fractal: hypercomplex functions in CSG (every crossing along the ray, the inside
// test with POV-Ray's z = y start of the plain iteration), clipped, and as glass.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 8 }
camera { location <0, 3, -9> look_at <0, -0.2, 0> angle 40 }
light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 2, -8> color rgb 0.4 }
plane { y, -2.3 pigment { checker rgb 0.2 rgb 0.8 scale 0.7 } }
#declare C = <0.3, 0.2, 0.1, 0.05>;
difference {
  julia_fractal { C hypercomplex sin max_iteration 6 precision 20 scale 0.3 }
  box { <-2, -0.1, -2>, <2, 2, 0> }
  pigment { rgb <0.4, 0.8, 0.5> } translate <-2.2, 1, 0>
}
intersection {
  julia_fractal { <0.1, 0.3, -0.2, 0.1> hypercomplex pwr(2, 0.5) max_iteration 6
    precision 20 scale 0.35 }
  sphere { 0, 0.8 }
  pigment { rgb <0.6, 0.9, 0.9> } translate <0, 1, 0>
}
merge {
  julia_fractal { <-0.2, 0.4, 0.1, 0> hypercomplex cos max_iteration 7 precision 30
    scale 0.2 }
  sphere { <0, -0.4, 0>, 0.35 }
  pigment { rgb <0.5, 0.6, 0.9> } translate <2.2, 1, 0>
}
julia_fractal { C hypercomplex tan max_iteration 5 precision 15
  clipped_by { plane { z, 0 } }
  pigment { rgb <0.9, 0.9, 0.5> } scale 0.3 rotate y * 30 translate <-2.2, -1.2, 0> }
julia_fractal { C hypercomplex exp max_iteration 6 precision 20
  pigment { rgbf <0.8, 0.9, 1, 0.8> } finish { specular 0.6 }
  interior { ior 1.3 } scale 0.35 translate <0.2, -1.2, -1> }
union {
  julia_fractal { C hypercomplex sinh max_iteration 6 precision 20 scale 0.3 }
  sphere { <0.5, 0, 0>, 0.3 }
  pigment { rgb <0.9, 0.5, 0.8> } rotate x * 20 translate <2.2, -1.2, 0>
}
