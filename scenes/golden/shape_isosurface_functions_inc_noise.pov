// functions.inc's noise-based internal functions: an f_ridged_mf terrain as in POV-Ray's
// benchmark.pov, an f_hetero_mf and an f_ridge surface, and f_ridge as a pigment's
// function pattern.
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1 }
camera { location <0, 5, -10> look_at <0, 0, 1> angle 50 }
light_source { <-8, 14, -6> color rgb 1 }
light_source { <6, 6, -8> color rgb 0.3 }
sky_sphere { pigment { rgb <0.6, 0.7, 0.9> } }
isosurface {
  function { y - f_ridged_mf(x * 0.4, 0, z * 0.4, 0.8, 2.2, 6, 1.0, 2.5, 1) * 0.9 }
  contained_by { box { <-7, -0.5, -1>, <7, 2.2, 9> } }
  max_gradient 12
  pigment { rgb <0.55, 0.5, 0.4> }
  translate <0, -1.6, 2>
}
isosurface {
  function { f_sphere(x, y, z, 0.9) - f_hetero_mf(x * 2, y * 2, z * 2, 0.6, 2, 4.5, 0.1, 1, 2) * 0.25 }
  contained_by { box { -1.3, 1.3 } }
  max_gradient 5
  pigment { rgb <0.9, 0.45, 0.3> }
  translate <-2.6, 0.6, -1>
}
isosurface {
  function { f_sphere(x, y, z, 0.8) + f_ridge(x * 2, y * 2, z * 2, 2, 3.5, 0.5, 0.2, 0.5, 3) * 0.3 }
  contained_by { box { -1.2, 1.2 } }
  max_gradient 5
  pigment { rgb <0.3, 0.6, 0.9> }
  translate <0, 0.6, -1.5>
}
#declare Ridge = function { f_ridge(x, y, z, 2, 4, 0.5, 0.3, 0.6, 2) }
sphere {
  0, 1
  pigment {
    function { Ridge(x * 2, y * 2, z * 2) }
    color_map { [0 rgb <0.1, 0.2, 0.1>] [1 rgb <0.9, 1, 0.7>] }
  }
  translate <2.6, 0.6, -1>
}
