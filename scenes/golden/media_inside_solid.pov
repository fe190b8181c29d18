// The camera inside a solid (non-hollow) object, here the half-space under a plane: POV-Ray
// computes no media on its rays, neither on those that hit something nor on those that
// miss everything below the horizon, past the disc (white or black otherwise, as above it).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -5> look_at <0, 0.5, 0> angle 60 }
light_source { <-3, 4, -5> color rgb 1 }
background { color rgb <0.3, 0.5, 0.9> }
media { absorption 0.3 emission 0.05 }
plane { y, 3 pigment { rgbt 1 } }
disc { <0, -1, 0>, y, 4 pigment { checker rgb 0.9 rgb 0.2 } }
sphere { <0, 0.5, 1>, 0.8 hollow pigment { rgbt 1 } interior { media { emission <1, 0.4, 0.1> } } }
