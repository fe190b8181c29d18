// No #version, but colors.inc saves `version` (3.7 before any #version), sets 3.5 and
// restores it: the scene ends as an explicit 3.7 scene (sRGB output, 3.7 opacity of
// filtered layers, the background's transmit composed over black), as in POV-Ray.
#include "colors.inc"
camera { location <0, 1.5, -5> look_at <0, 0.5, 0> }
light_source { <-3, 5, -4> color White }
background { rgbt <0.2, 0.4, 0.8, 0.5> }
plane { y, -0.5 pigment { checker color Gray40 color Wheat } }
sphere { <-1.1, 0.5, 0>, 1 pigment { rgbf <1, 0.5, 0.2, 0.6> } finish { phong 0.5 } }
box { <0.4, -0.5, -0.6>, <1.8, 1, 0.8> pigment { color rgb <0.5, 0.3, 0.2> } }
