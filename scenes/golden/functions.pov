// User functions against POV-Ray: function patterns in a sky_sphere, pigments and a
// normal; declared functions calling each other; pattern, pigment, spline and internal
// (functions.inc) functions; u/v aliases; int, select, min/max; SDL calls placing objects.
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -8> right x*image_width/image_height look_at <0, 1.5, 20> angle 75 }
light_source { <5, 10, -10>, rgb 1 }
sky_sphere { pigment { function { abs(y) } turbulence 0.1
  color_map { [0.0, rgb <0, 0, 0.6>] [1.0, rgb 1] } } }
#declare Scale = 3;
#declare Wave = function(a, b) { sin(a * Scale) * 0.5 + b }
#declare Rings = function { pattern { onion scale 0.3 } }
#declare Wood = function { pigment { wood color_map { [0 rgb <1, 0.5, 0>] [1 rgb <0.3, 0.1, 0>] } scale 0.2 } }
#declare Path = function { spline { natural_spline 0, <0, 0.2, 0>, 1, <1, 0.9, 0>, 2, <2, 0.1, 0>, 3, <3, 0.7, 0> } }
#declare UV = function(u, v) { u * 10 + v }
sphere { <0, 2.5, 3>, 1
  pigment { function { x * x - 2 * y + min(z, 0.3, x) * 3 } frequency 2 sine_wave
    color_map { [0 rgb <1, 0, 0>] [0.5 rgb <0, 1, 0>] [1 rgb <0, 0, 1>] } }
  finish { ambient 1 diffuse 0 } }
sphere { <2.5, 2.5, 3>, 1
  pigment { function { select(x, -x * 3, 0.5, pow(y, 2) + int(z * 7) / 7) } }
  finish { ambient 1 diffuse 0 } }
sphere { <-2.5, 2.5, 3>, 1 normal { function { abs(sin(x * 9)) } 0.8 } pigment { rgb 1 } }
sphere { <0, 0, 3>, 1
  pigment { function { Wave(x, Rings(x, y, z)) * 0.8 + f_noise3d(x * 4, y * 4, z * 4) * 0.2 } } }
sphere { <2.5, 0, 3>, 1
  pigment { function { Wood(x, y, z).gray * 0.5 + Wood(x, y, z).red * 0.5 }
    color_map { [0 rgb <0.2, 0, 0.3>] [1 rgb <1, 1, 0.5>] } } }
sphere { <-2.5, 0, 3>, 1
  pigment { function { Path(x + 1.5).y + f_sphere(x, y, z, 0.5) * 0.1 + (v > 0.2) * 0.1 } } }
#declare I = 0;
#while (I < 12)
  sphere { <-4.5 + I * 0.8, -1.2 + Path(I / 4).y + Wave(I, 0) * 0.3, 1>, 0.15 + UV(0, I / 100)
    pigment { rgb <Rings(I / 8, 0, 0), 0.5, 1 - Rings(I / 8, 0, 0)> } }
  #declare I = I + 1;
#end
