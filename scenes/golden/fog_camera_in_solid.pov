// The camera inside a solid (not hollow) transparent sphere: every camera ray starts
// inside it, and POV-Ray then draws no fog at all.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0.3, 0> angle 45 }
light_source { <-4, 6, -5> color rgb 1 }
plane { y, -1 pigment { checker color rgb 0.9 color rgb <0.1, 0.3, 0.6> scale 0.5 } }
fog { distance 6 color rgb <0.8, 0.8, 0.9> }
sphere { <0, 1.5, -5>, 0.5 pigment { rgbt 1 } }
sphere { <0, 0, 0>, 0.8 pigment { rgb 1 } }
