// poly of orders 2, 5, 6 and 8 (orders 5 and up: Sturm always, the term-by-term normal),
// with translate, rotate and scale, and a polynomial written by terms.
#version 3.7;
#include "shapes.inc"
#include "shapesq.inc"
global_settings { assumed_gamma 1 }
camera { location <0, 5, -10> look_at <0, 0, 0> angle 46 }
light_source { <-5, 10, -7> color rgb 1 }
light_source { <6, 5, -4> color rgb 0.4 }
plane { y, -1.6 pigment { checker rgb 0.9 rgb 0.5 scale 0.8 } }
// Order 2: a hyperboloid of one sheet, clipped.
poly { 2, <1, 0, 0, 0, -1, 0, 0, 1, 0, -0.3> clipped_by { box { -1.2, 1.2 } }
       rotate 30*x translate <-3.3, 0, 1.8> pigment { rgb <0.9, 0.5, 0.3> } }
// Order 5: Glob_5.
object { Glob_5 clipped_by { box { <-1.1, -1, -1>, <0.3, 1, 1> } } rotate 90*z scale 1.6 translate <0, -0.6, 1.8> pigment { rgb <0.4, 0.8, 0.4> } }
// Order 6: a rounded cube x^6 + y^6 + z^6 = 1, by terms, clipped by a sphere.
polynomial { 6, xyz(6, 0, 0): 1, xyz(0, 6, 0): 1, xyz(0, 0, 6): 1, xyz(0, 0, 0): -1
             clipped_by { sphere { 0, 1.15 } }
             scale 0.9 rotate <20, 30, 0> translate <3.3, 0, 1.8> pigment { rgb <0.5, 0.6, 0.95> } }
// Order 6: Twin_Glob.
object { Twin_Glob scale 1.5 rotate <0, 20, 10> translate <-3.3, 0, -1.6>
         pigment { rgb <0.9, 0.9, 0.4> } }
// Order 8: (x^2 + y^2 + z^2)^4 - 1 + 0.5 x^8... a rounded cube-ish blob, by terms.
polynomial { 8, xyz(8, 0, 0): 1, xyz(0, 8, 0): 1, xyz(0, 0, 8): 1, xyz(2, 2, 0): 0.6,
             xyz(0, 2, 2): 0.6, xyz(2, 0, 2): 0.6, xyz(0, 0, 0): -0.8
             rotate <30, 40, 0> translate <0, 0, -1.6> pigment { rgb <0.9, 0.4, 0.7> } }
// poly { 5.9, ... } is order 5: x^5 terms of Glob_5 with its coefficients.
poly { 5.9, <-0.5, 0, 0, -0.5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
              0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
              0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0>
       clipped_by { box { <-1.1, -1, -1>, <0.2, 1, 1> } } rotate <0, -30, 90> scale 1.2 translate <3.3, -0.5, -1.6> pigment { rgb <0.4, 0.9, 0.9> } }
