// isosurface evaluate: a noisy sphere (functions.inc's f_sphere and f_noise3d) whose
// max_gradient is found along each ray (POV-Ray's `evaluate 1, 10, 0.99`), and a wavy
// sheet whose max_gradient 0.5 is far too low (gradient ~3.6) but which evaluate lifts.
// (With `evaluate 0.5, 1.5, 0.95` on the sheet 15 pixels differ: holes where POV-Ray's
// estimate, shared by all its rays, had grown on earlier rays.)
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1 }
camera { location <0, 3, -11> look_at <0, 0, 0> angle 50 }
light_source { <-5, 10, -8> color rgb 1 }
light_source { <6, 5, -4> color rgb 0.4 }
background { rgb <0.2, 0.3, 0.4> }
isosurface {
  function { f_sphere(x, y, z, 1.6) + f_noise3d(x*2, y*3.3, z*2.5)*0.5 }
  contained_by { sphere { 0, 2 } }
  evaluate 1, 10, 0.99
  max_gradient 1.4
  pigment { rgb <0.9, 0.6, 0.3> }
  translate <-2.2, 0, 0>
}
isosurface {
  function { y - 0.4*sin(6*x)*cos(5*z) }
  contained_by { box { <-1.5, -0.6, -1.5>, <1.5, 0.6, 1.5> } }
  evaluate 0.5, 3, 0.95
  max_gradient 0.5
  pigment { rgb <0.4, 0.8, 0.5> }
  rotate <-20, 20, 0> translate <2.2, 0, 0>
}
