// Faked caustics: interior { caustics } (scaled by 45 as POV-Ray stores it) and the old
// finish { caustics } (moved into the interior unscaled) brighten the shadows of glass.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -5> look_at <0, 0, 0> angle 45 }
light_source { <0, 8, -2> color rgb 1 }
plane { y, -1 pigment { rgb 0.8 } }
sphere { <-1.1, 0, 0>, 0.8 pigment { rgbf <1, 1, 1, 0.8> } interior { ior 1.5 caustics 1 } }
sphere { <1.1, 0, 0>, 0.8 pigment { rgbf <1, 0.9, 0.8, 0.8> } finish { caustics 0.5 } interior { ior 1.3 } }
