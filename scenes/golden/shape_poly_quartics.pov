// quartic and cubic (POV-Ray's poly of orders 4 and 3): shapesq.inc surfaces, the
// closed-form solvers and sturm, on their own and clipped.
#version 3.7;
#include "shapes.inc"
#include "shapesq.inc"
global_settings { assumed_gamma 1 }
camera { location <0, 6, -10> look_at <0, 0.2, 0> angle 48 }
light_source { <-5, 10, -7> color rgb 1 }
light_source { <6, 5, -4> color rgb 0.4 }
plane { y, -1.5 pigment { checker rgb 0.9 rgb 0.5 scale 0.8 } }
// A torus of major radius 40, minor 12, scaled down (closed-form quartic).
object { Torus_40_12 scale 0.15 rotate <-30, 20, 0> translate <-3.2, 0, 1.8>
         pigment { rgb <0.9, 0.5, 0.3> } }
// The same with sturm.
object { Torus_40_12 sturm scale 0.15 rotate <60, -10, 0> translate <0, 0, 1.8>
         pigment { rgb <0.4, 0.8, 0.4> } }
// Piriform (a teardrop), sturm.
object { Piriform sturm rotate -90*z scale 1.4 translate <3.2, 0.2, 1.8>
         pigment { rgb <0.5, 0.6, 0.95> } }
// Monkey saddle, clipped by a box.
object { Monkey_Saddle clipped_by { box { -1, 1 } } scale <1, 0.6, 1>
         rotate 20*y translate <-3.2, 0, -1.6> pigment { rgb <0.9, 0.9, 0.4> } }
// A cubic: y = x^3 - x (cubic { x^3 - x - y }) clipped by a box, seen obliquely.
cubic { <1, 0, 0, 0, 0, 0, 0, 0, 0, -1, 0, 0, 0, 0, 0, -1, 0, 0, 0, 0>
        clipped_by { box { <-1.4, -1.4, -0.6>, <1.4, 1.4, 0.6> } }
        rotate <10, 30, 0> translate <0, 0, -1.6> pigment { rgb <0.9, 0.4, 0.7> } }
// Steiner's surface, sturm, bounded.
object { Steiner_Surface sturm clipped_by { sphere { 0, 1.2 } } scale 1.3
         rotate <30, 40, 0> translate <3.2, 0, -1.6> pigment { rgb <0.4, 0.9, 0.9> } }
