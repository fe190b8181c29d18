// The background comes before the include, while the scene is still legacy: POV-Ray
// drops its transmit then (it is not composed over black), although the scene ends as a
// 3.7 one after colors.inc.
background { rgbt <0.2, 0.4, 0.8, 0.5> }
#include "colors.inc"
camera { location <0, 1.5, -5> look_at <0, 0.5, 0> }
light_source { <-3, 5, -4> color White }
sphere { <0, 0.5, 0>, 1 pigment { rgbt <1, 0.5, 0.2, 0.4> } }
