// Algebraic surfaces where their polynomials are stiff: a thin quartic torus edge-on
// (closed form and sturm), tiny and huge, a quartic cylinder nearly along its axis, an
// order-8 poly (always Sturm), and quadrics seen along their axes. (shapesq.inc's
// Twin_Glob is left out: POV-Ray's Sturm misses roots near its pinch, which povwall
// reproduces pixel for pixel but the oracle does not.)
#version 3.7;
#include "shapes.inc"
#include "shapesq.inc"
global_settings { assumed_gamma 1 }
camera { location <0, 0.32, -9> look_at <0, 0.3, 0> angle 45 }
light_source { <10, 20, -10> rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
// (x^2 + y^2 + z^2 + R^2 - r^2)^2 = 4 R^2 (x^2 + z^2) with R = 1, r = 0.05.
#declare Thin = quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, -2.005, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
                           1, 0, 0, 2, 0, 1.995, 0, 0, 0, 0, 1, 0, -2.005, 0, 0.99500625> }
object { Thin rotate 1*x translate <-2.6, 0.3, 0> pigment { rgb <1, 0.6, 0.2> } }
object { Thin sturm rotate <0.5, 30, 0> translate <0, 0.3, 0> pigment { rgb <1, 0.8, 0.4> } }
object { Quartic_Cylinder sturm scale 0.4 rotate <0, 89, 0.3> translate <2.6, 0.3, 1>
         pigment { rgb <0.4, 0.8, 0.4> } }
polynomial { 8, xyz(8, 0, 0): 1, xyz(0, 8, 0): 1, xyz(0, 0, 8): 1, xyz(0, 0, 0): -1
             scale 0.5 rotate <40, 30, 0> translate <2.2, -1.2, -1> pigment { rgb 0.8 } }
object { Thin scale 1e-3 rotate 2*x translate <0.3, 0.32, -8.99> pigment { rgb 0.7 } }
object { Thin scale 1e3 rotate 0.01*x translate <0, 0.3, 5e3> pigment { rgb 0.5 } }
quadric { <1, 0, 1>, 0, 0, -0.04 translate <-1, 0.3, 0> pigment { rgb <0.9, 0.5, 0.7> } }
object { QCone_Z scale <0.1, 0.1, 1> translate <1.8, 0.32, 3> pigment { rgb <0.5, 0.9, 0.9> } }
