// Sors that are nearly cylindrical (the cubic's leading terms vanish: the quadratic
// path), with sturm, tiny, and seen at grazing angles along the axis and the caps.
// (A near-flat step or a large scale makes POV-Ray's closed-form cubic ill-conditioned
// near knots: POV-Ray shows noise there, povwall the same kind of noise but not on the
// same pixels; left out here.)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.6, -9> look_at <0, 0.3, 0> angle 45 }
light_source { <10, 20, -10> rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
sor { 6, <0.5, -0.001>, <0.5, 0>, <0.5, 0.5>, <0.5, 1>, <0.5, 1.5>, <0.5, 1.501>
      pigment { rgb 1 } translate <-3, 0, 0> }
sor { 6, <0.1, -1>, <0.2, 0>, <1, 0.3>, <0.9, 0.6>, <0.3, 1>, <0.2, 2>
      pigment { rgb <1, 0.6, 0.2> } translate <-1, -0.2, 0> }
sor { 5, <0.3, -1>, <0.6, 0>, <0.2, 1>, <0.7, 2>, <0.4, 3> sturm
      pigment { rgb <0.6, 1, 0.2> } scale 0.5 rotate <0, 0, 89.9> translate <1.5, 0.3, 0> }
sor { 5, <0.3, -1>, <0.6, 0>, <0.2, 1>, <0.7, 2>, <0.4, 3>
      pigment { rgb 0.7 } scale 1e-3 translate <0, 0.55, -8.99> }
