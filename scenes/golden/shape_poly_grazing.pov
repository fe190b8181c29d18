// Quartics seen at grazing angles: a thin torus edge-on, a quartic cylinder nearly along
// its axis, and a cubic x^3 + y along the view (pitfall: exact-zero leading terms).
#version 3.7;
#include "shapes.inc"
#include "shapesq.inc"
global_settings { assumed_gamma 1 }
camera { location <0, 0.35, -8> look_at <0, 0.3, 0> angle 40 }
light_source { <-5, 10, -7> color rgb 1 }
light_source { <6, 5, -4> color rgb 0.4 }
plane { y, -1.2 pigment { checker rgb 0.9 rgb 0.5 scale 0.8 } }
quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, -2.02, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
           1, 0, 0, 2, 0, 1.98, 0, 0, 0, 0, 1, 0, -2.02, 0, 0.9801>
          rotate 2*x translate <-1.6, 0.3, 0> pigment { rgb <0.9, 0.5, 0.3> } }
object { Quartic_Cylinder sturm scale 0.5 rotate <0, 88, 0.5> translate <1.6, 0.3, 2>
         pigment { rgb <0.4, 0.8, 0.4> } }
cubic { <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0>
        clipped_by { box { -0.8, 0.8 } } rotate 0.5*z translate <0, -0.2, -2>
        pigment { rgb <0.5, 0.6, 0.95> } }
