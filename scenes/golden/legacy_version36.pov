// #version 3.6 and no assumed_gamma: no gamma handling at all, values written raw; a
// declared colour from colors.inc and the 3.6 default camera (right 1.33, angle unset).
#version 3.6;
#include "colors.inc"
camera { location <0, 1.5, -5> look_at <0, 0.5, 0> }
light_source { <-3, 5, -4> color White }
light_source { <4, 2, -3> color rgb <0.3, 0.3, 0.5> }
background { color MidnightBlue }
plane { y, -0.5 pigment { color Gray40 } finish { ambient 0.2 } }
sphere { <-1.2, 0.5, 0>, 1 pigment { color Coral } finish { specular 0.6 roughness 0.02 } }
box { <0.3, -0.5, -0.6>, <1.9, 1, 0.8> pigment { color ForestGreen } finish { diffuse 0.9 } }
