// Clipped isosurfaces in CSG: the clip is the isosurface's own, tested inside its search
// (all_intersections here, as an isosurface in CSG needs), then the CSG keeps what its
// other children say. Left: a union with a box; middle: an intersection with a sphere;
// right: a difference cutting a clipped, transparent isosurface (shadows through it).
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 10 }
camera { location <0, 4, -9> look_at <0, 0.2, 0> angle 50 }
light_source { <-5, 10, -8> color rgb 1 }
light_source { <6, 5, -4> color rgb 0.4 }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.5 scale 0.8 } }
#declare Ball = isosurface { function { x*x + y*y + z*z - 1 } max_gradient 2.5
  contained_by { box { -1.2, 1.2 } } all_intersections }
union {
  object { Ball clipped_by { plane { -z, 0.1 } } pigment { rgb <0.9, 0.5, 0.3> } }
  box { <-0.4, -1, -0.4>, <0.4, 1.2, 0.4> pigment { rgb 0.8 } }
  translate <-2.4, 0, 0.5> }
intersection {
  object { Ball clipped_by { plane { y, 0.5 } } pigment { rgb <0.3, 0.8, 0.4> } }
  sphere { <0, 0, -0.6>, 1 pigment { rgb <0.9, 0.9, 0.3> } }
  translate <0.1, 0, 0.8> }
difference {
  object { Ball clipped_by { box { <-0.3, -2, -2>, <0.3, 2, 2> inverse } }
    pigment { rgbf <0.6, 0.7, 1, 0.6> } }
  cylinder { <0, 0.3, -2>, <0, 0.3, 2>, 0.45 pigment { rgb <1, 0.3, 0.3> } }
  translate <2.5, 0, -0.4> }
