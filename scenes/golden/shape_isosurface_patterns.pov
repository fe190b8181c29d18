// isosurfaces of pattern functions: functions.inc's f_noise3d (its noise generator from
// a global_settings that comes after the object), a declared pattern function, and a
// pigment function's gray value.
#version 3.7;
#include "functions.inc"
camera { location <0, 4, -9> look_at <0, 0.2, 0> angle 50 }
light_source { <-5, 10, -8> color rgb 1 }
light_source { <6, 5, -4> color rgb 0.4 }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.5 scale 0.8 } }
isosurface {
  function { x*x + y*y + z*z - 0.7 + f_noise3d(x*4, y*4, z*4)*0.5 }
  max_gradient 3
  pigment { rgb <0.9, 0.4, 0.3> }
  translate <-2.6, 0, 0.5>
}
#declare Bozo = function { pattern { bozo scale 0.4 } }
isosurface {
  function { y + 0.6 - Bozo(x, y, z)*0.8 }
  contained_by { box { <-1.1, -0.8, -1.1>, <1.1, 0.8, 1.1> } }
  max_gradient 4
  pigment { rgb <0.3, 0.7, 0.9> }
  translate <0, -0.1, 1.2>
}
#declare Marble = function { pigment { marble color_map { [0 rgb 0] [1 rgb 1] } scale 0.5 } }
isosurface {
  function { sqrt(x*x + y*y + z*z) - 0.6 - Marble(x, y, z).gray*0.3 }
  contained_by { sphere { 0, 1 } }
  max_gradient 3
  pigment { rgb <0.5, 0.9, 0.4> }
  translate <2.5, 0, 0.3>
}
global_settings { assumed_gamma 1 noise_generator 1 }
