// max_trace_level 1: the camera rays are the only level, so a filtered sphere shows
// black where POV-Ray would transmit (its transmitted ray is met at level 1), and its
// edge keeps its own colour share.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 1 }
camera { location <0, 0, -6> look_at 0 }
background { rgb <0.2, 0.8, 0.3> }
light_source { <0, 5, -100> rgb 1 }
sphere { 0, 1 pigment { rgbf <1, 1, 1, 0.8> } }
sphere { <1.5, 0, 2>, 1 pigment { rgbt <1, 0.5, 0.5, 0.6> } }
