// clipped_by on isosurfaces: POV-Ray tests the clip inside the search. With max_trace 1
// a clipped first root ends the search, so through the cut of the sphere on the left the
// floor shows (its back wall is not seen); with max_trace 2 (middle) the back wall
// shows. A closed container's face where F < 0, clipped, neither counts as a trace nor
// turns the search around (right: a noise surface cut by an inverse box, as the benchmark
// scene's ground). Shadows of clipped isosurfaces restart past each kept crossing.
#version 3.7;
global_settings { assumed_gamma 1 }
#include "functions.inc"
camera { location <0, 4, -9> look_at <0, 0.2, 0> angle 50 }
light_source { <-5, 10, -8> color rgb 1 }
light_source { <6, 5, -4> color rgb 0.4 }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.5 scale 0.8 } }
isosurface { function { x*x + y*y + z*z - 1 } max_gradient 2.5
  contained_by { box { -1.2, 1.2 } }
  pigment { rgb <0.9, 0.5, 0.3> }
  clipped_by { plane { -z, 0.1 } }
  translate <-2.3, 0, 0.5> }
isosurface { function { x*x + y*y + z*z - 1 } max_gradient 2.5 max_trace 2
  contained_by { box { -1.2, 1.2 } }
  pigment { rgb <0.3, 0.8, 0.4> }
  clipped_by { plane { -z, 0.1 } plane { y, 0.6 } }
  translate <0.2, 0, 0.8> }
// Cut by its container (closed): the container's faces where F < 0 are surfaces too.
isosurface { function { y - 0.3 * f_noise3d(x * 3, y * 3, z * 3) } max_gradient 3
  contained_by { box { <-1.2, -1, -1.2>, <1.2, 0.2, 1.2> } }
  pigment { rgb <0.5, 0.6, 0.95> } finish { specular 0.3 }
  clipped_by { box { <-0.6, -2, -0.6>, <0.4, 2, 0.5> inverse } }
  translate <2.6, 0, -0.6> }
