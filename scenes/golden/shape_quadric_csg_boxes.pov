// quadrics whose CSG siblings or clips are other shapes: POV-Ray cuts the range a quadric's
// box is computed in by those objects' own bounding boxes (CSG::Compute_BBox,
// Quadric::Compute_BBox's clip step), so the quadric's box, and what it culls, follow a
// transformed box, a sphere, a cylinder and a CSG.
#version 3.7;
#include "shapes.inc"
global_settings { assumed_gamma 1 }
camera { location <0, 6, -11> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 10, -7> color rgb 1 }
light_source { <6, 5, -4> color rgb 0.4 }
plane { y, -2 pigment { checker rgb 0.9 rgb 0.5 scale 0.8 } }
// A cylinder cut by a sphere (chess2's pawns do this).
intersection {
  object { Cylinder_Y }
  sphere { <0, 0.5, 0>, 1.3 }
  translate <-3.5, 0, 1> pigment { rgb <0.9, 0.5, 0.3> }
}
// A paraboloid moved along its axis (POV-Ray's box lands on the wrong side) in a turned box.
intersection {
  quadric { <1, 0, 1>, 0, <0, -1, 0>, 0 translate -y }
  box { -1.5, 1.5 rotate 20*y }
  scale 0.8 translate <0, 0, 1.5> pigment { rgb <0.4, 0.8, 0.4> }
}
// A cone minus a cylinder: the inverted sibling does not bound it; a sphere does.
difference {
  intersection { object { Cone_Y } sphere { 0, 1.5 } }
  cylinder { -2*y, 2*y, 0.3 }
  translate <3.5, 0, 1> pigment { rgb <0.4, 0.5, 0.9> }
}
// Clipped by a sphere and by a union.
object { Cylinder_X clipped_by { sphere { 0, 1.2 } } translate <-2, 2.5, 3>
         pigment { rgb <0.9, 0.8, 0.3> } }
object { Ellipsoid scale <2, 1, 1>
         clipped_by { union { box { <-2, -1, -1>, <0.5, 1, 1> } sphere { <1, 0, 0>, 0.6 } } }
         translate <2, 2.5, 3> pigment { rgb <0.8, 0.4, 0.8> } }
// A quadric with its own clips in an intersection: Compute_BBox(range) cuts the CSG's
// range by the clip's box first; for this paraboloid moved along its axis the box it
// gets misses the visible part, and POV-Ray shows nothing (without the clip it shows).
intersection {
  quadric { <1, 0, 1>, 0, <0, -1, 0>, 0 translate -y clipped_by { box { -1.2, 1.2 rotate 30*y } } }
  sphere { 0, 1.5 }
  scale 0.6 translate <0, 1.2, 5.5> pigment { rgb <0.3, 0.8, 0.8> }
}
