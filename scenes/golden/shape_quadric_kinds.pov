// quadric: an ellipsoid (POV-Ray's finite box), a cylinder, a cone, a paraboloid and a
// hyperboloid (infinite boxes), with transforms folded into the coefficients step by
// step (rotate 180*z leaves mixed terms of 1e-16), in unions and merges, inverse.
#version 3.7;
#include "shapes.inc"
global_settings { assumed_gamma 1 max_trace_level 8 }
camera { location <0, 5, -10> look_at <0, 0, 0> angle 48 }
light_source { <-5, 10, -7> color rgb 1 }
light_source { <6, 5, -4> color rgb 0.4 }
plane { y, -1.6 pigment { checker rgb 0.9 rgb 0.5 scale 0.8 } }
#declare Glass = material { texture { pigment { rgbf <0.9, 1, 0.9, 0.85> }
                                      finish { specular 0.6 reflection 0.05 } }
                            interior { ior 1.45 } }
// An ellipsoid with a linear term (its box centred by POV-Ray's step 4).
quadric { <1, 2, 1.5>, 0, <0.4, 0, -0.3>, -1 rotate <20, 30, 0> scale 1.1
          translate <-3.3, 0, 1.8> pigment { rgb <0.9, 0.5, 0.3> } }
// A merge of two glass ellipsoids with mixed terms.
merge {
  quadric { <1, 1, 1>, <0.8, 0, 0>, 0, -0.8 }
  quadric { <2, 0.5, 2>, <0, 0.5, 0.3>, 0, -0.5 translate 0.3*y }
  material { Glass } translate <0, 0, 1.8>
}
// Paraboloid_Y turned upside down with rotate 180*z, then moved.
object { Paraboloid_Y scale <0.5, 1, 0.5> rotate 180*z translate <3.3, 1, 1.8>
         pigment { rgb <0.5, 0.6, 0.95> } }
// A union of an inverse quadric cone and a hyperboloid, the union clipped.
union {
  object { QCone_Y scale <0.3, 1, 0.3> inverse translate <-0.6, 0, 0> }
  object { Hyperboloid_Y scale <0.3, 0.6, 0.3> rotate 30*x translate <0.6, 0, 0> }
  clipped_by { box { <-1.3, -1.2, -1>, <1.3, 1.2, 1> } }
  translate <-3, 0, -2> pigment { rgb <0.9, 0.9, 0.4> }
}
// A cylinder along x inside an intersection, inverted (a box with a round hole).
intersection {
  box { -0.9, 0.9 rotate <10, 20, 0> }
  object { Cylinder_X scale 0.5 rotate 25*y inverse }
  pigment { rgb <0.9, 0.4, 0.7> } translate <0, 0, -1.6>
}
// The saddle of shapes.inc (no box case) and a sphere in a clipped union.
union {
  object { Hyperboloid scale 0.5 rotate <10, 20, 0> }
  sphere { 0, 0.3 }
  clipped_by { sphere { 0, 1 } }
  translate <3.3, 0, -1.6> pigment { rgb <0.4, 0.9, 0.9> }
}
// A paraboloid clipped by a box (its box from the clip), then scaled and turned, as in
// textures/pigments/mappr2.pov, and Cylinder_Z clipped by planes.
object { Paraboloid_Y clipped_by { box { <-2, 0, -2>, <2, 1, 2> } }
         translate -0.5*y scale <0.5, 1, 0.5> rotate <-40, 0, 0> translate <1.6, 2.2, 3>
         pigment { rgb <0.95, 0.6, 0.6> } }
object { Cylinder_Z clipped_by { plane { z, 1 } plane { -z, 1 } } scale 0.3
         rotate <0, 30, 0> translate <-1.6, 2, 3> pigment { rgb <0.6, 0.95, 0.6> } }
