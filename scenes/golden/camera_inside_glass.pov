// The camera starts inside a glass sphere: POV-Ray gives camera rays the interiors of the
// objects around the camera, so the first surface they meet is an exit (1.3 to 1).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 0.5, -2> look_at <0, 0.3, 0> angle 60 }
light_source { <-4, 6, -5> color rgb 1 }
plane { y, -1 pigment { checker color rgb 0.9 color rgb <0.1,0.3,0.6> scale 0.5 } }
sphere { <0, 0.5, -2>, 1 pigment { rgbf <1, 0.9, 0.9, 0.95> } interior { ior 1.3 } }
sphere { <0, 0, 1>, 0.7 pigment { rgb <1, 0.4, 0.2> } }
