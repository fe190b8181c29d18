// POV-Ray folds translate, rotate and scale of a plane into its normal and offset until
// a `matrix` or `transform` makes it keep one (Plane::Translate, Rotate, Scale), and an
// intersection's box is cut by each plane whose normal lies along an axis: the folded
// plane's own half-space, or, once it keeps a matrix, POV-Ray's formula through that
// matrix. Rays that miss the box never meet the object. Slabs and half-spaces made of
// turned, scaled and moved planes, in intersections with large spheres, seen from above
// at an angle so that a wrong box cuts their sides away.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <10, 45, -70> look_at <4, 0, 0> angle 52 }
light_source { <-1000, 2000, -3000> rgb 1 }
background { rgb <0.1, 0.15, 0.4> }
// A slab |z| <= 4 from y-planes turned about x and moved (the GameSprites walls).
intersection {
  plane { y, 0 rotate x * 90 translate z * 4 }
  plane { y, 0 rotate x * -90 translate z * -4 }
  sphere { 0, 12 }
  pigment { rgb <0.9, 0.5, 0.2> } translate x * -22
}
// Turned on the plane, moved on the intersection; then scaled.
intersection {
  plane { y, 0 rotate x * 90 scale 2 }
  sphere { 0, 10 }
  translate z * 4
  pigment { rgb <0.3, 0.8, 0.4> } translate x * -2
}
// Non-uniform scale then a move along the normal.
intersection {
  plane { y, 0 scale <1, 2, 1> translate y * 4 }
  sphere { 0, 8 }
  pigment { rgb <0.5, 0.6, 0.95> } translate <14, 0, 0>
}
// A matrix kept after the fold: the box follows POV-Ray's formula through it.
intersection {
  plane { y, 0 rotate x * 90 translate z * 4 transform { scale 1 } }
  plane { x, 2 matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0> rotate y * 90 }
  sphere { 0, 9 }
  pigment { rgb <0.9, 0.9, 0.5> } translate <30, 0, 0>
}
