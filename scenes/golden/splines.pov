// Splines in a scene: spheres along each kind of spline, and cones flown along a cubic
// path with transforms.inc's Spline_Trans (which calls the spline through a macro
// parameter and keeps a #local from a macro call).
#version 3.7;
#include "transforms.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -9> look_at <0, 0.5, 0> angle 45 }
light_source { <-4, 10, -6>, rgb 1 }
plane { y, -0.5 pigment { checker rgb 0.9, rgb 0.6 } }
#declare Path = spline {
  -1, <-4, 0, 1>, 0, <-3, 0.5, -1>, 1, <-1, 1.5, 0.5>, 2, <1, 0.5, -1>,
  3, <3, 1.2, 0.8>, 4, <4, 0, 1>,
}
#declare Kinds = array[4] {
  spline { Path linear_spline }, spline { Path quadratic_spline },
  spline { Path cubic_spline }, spline { Path natural_spline }
}
#declare K = 0;
#while (K < 4)
  #declare S = Kinds[K];
  #declare I = 0;
  #while (I <= 30)
    sphere { S(I / 10) + <0, 0, 2.2 - 1.1 * K>, 0.09
      pigment { rgb <(K = 0 | K = 3), (K = 1 | K = 3), (K = 2)> } }
    #declare I = I + 1;
  #end
  #declare K = K + 1;
#end
#declare I = 0;
#while (I < 5)
  cone { <0, 0, -0.3>, 0.2, <0, 0, 0.3>, 0
    Spline_Trans(Path, 0.2 + I * 0.6, y, 0.3, 0.5)
    translate 1.5 * y
    pigment { rgb <1, 0.6, 0.1> } }
  #declare I = I + 1;
#end
