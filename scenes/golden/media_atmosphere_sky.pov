// Rays that miss everything in atmospheric media: POV-Ray integrates out to its
// "infinite" depth (2e10), so an absorbing atmosphere turns the background black, the
// more slowly the less it absorbs (here the objects keep their colours, the sky goes).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 0.8, 0> angle 50 }
light_source { <-3, 6, -5> color rgb 1 }
background { color rgb <0.3, 0.5, 0.9> }
media { absorption <0.05, 0.1, 0.2> }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.2 } }
sphere { <0, 1, 0>, 0.9 hollow pigment { rgbf <1, 1, 1, 0.8> } interior { ior 1.2 } }
