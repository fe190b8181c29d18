// quadrics bounded by planes in intersections and differences (CSG::Compute_BBox gives
// each quadric a box from the planes), with POV-Ray's two box bugs: a paraboloid moved
// along its axis is centred on the wrong side, and a hyperboloid's box assumes |J| = 1.
// Both cull visible parts in POV-Ray; povwall reproduces them.
#version 3.7;
#include "shapes.inc"
global_settings { assumed_gamma 1 max_trace_level 8 }
camera { location <0, 6, -11> look_at <0, 0, 0> angle 50 }
light_source { <-5, 10, -7> color rgb 1 }
light_source { <6, 5, -4> color rgb 0.4 }
plane { y, -2 pigment { checker rgb 0.9 rgb 0.5 scale 0.8 } }
#declare Glass = material { texture { pigment { rgbf <0.9, 1, 0.9, 0.85> }
                                      finish { specular 0.6 reflection 0.05 } }
                            interior { ior 1.45 } }
// A tube: Cylinder_Y minus a thinner one, between two planes, one of them slanted.
intersection {
  object { Cylinder_Y scale <1, 1, 1> }
  object { Cylinder_Y scale <0.8, 1, 0.8> inverse }
  plane { y, 0 inverse }
  plane { y, 1.5 rotate -30*x }
  rotate <-20, 0, 15> translate <-3.5, -0.5, 1.5> pigment { rgb <0.9, 0.5, 0.3> }
}
// Bug 1: a paraboloid moved down along its axis, cut by planes.
intersection {
  quadric { <1, 0, 1>, 0, <0, -1, 0>, 0 translate -y }
  plane { y, 1.5 } plane { -y, 1.5 }
  plane { x, 1.5 } plane { -x, 1.5 } plane { z, 1.5 } plane { -z, 1.5 }
  scale 0.8 translate <0, 0, 1.5> pigment { rgb <0.4, 0.8, 0.4> }
}
// Bug 2: a hyperboloid with J = -4 between two planes.
intersection {
  quadric { <1, -1, 1>, 0, 0, -4 }
  plane { y, 1 } plane { -y, 1 }
  scale 0.5 translate <3.5, 0, 1.5> pigment { rgb <0.5, 0.6, 0.95> }
}
// A glass lens: two spheres as quadrics intersected (finite boxes), then a difference
// of a cone and a cylinder.
intersection {
  quadric { <1, 1, 1>, 0, <0, 0, -0.8>, -0.84 }
  quadric { <1, 1, 1>, 0, <0, 0, 0.8>, -0.84 }
  scale 1.5 rotate 30*y translate <-3, 0, -2> material { Glass }
}
difference {
  object { QCone_Y scale <0.5, 1, 0.5> }
  object { Cylinder_Y scale 0.3 }
  plane { y, 1.2 inverse } plane { y, -1.2 }
  rotate 20*z translate <0.5, 0, -2> pigment { rgb <0.9, 0.9, 0.4> }
}
