// #version 3.1 with no noise_generator: POV-Ray uses the original noise (generator 1)
// for the whole scene, so skies.inc's clouds and a bozo pigment look as in 3.1; the scene
// is raised to 3.5 once parsed and has no gamma handling.
#version 3.1;
#include "colors.inc"
#include "skies.inc"
camera { location <0, 1, -5> look_at <0, 1.5, 0> }
light_source { <-3, 5, -4> color rgb 1 }
sky_sphere { S_Cloud1 }
plane { y, 0 pigment { bozo color_map { [0 rgb <0.2, 0.5, 0.1>] [1 rgb <0.9, 0.8, 0.5>] } scale 0.5 } }
sphere { <0, 1, 0>, 1 pigment { granite scale 2 } }
