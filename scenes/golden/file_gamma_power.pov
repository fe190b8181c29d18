// golden-args: File_Gamma=1.8
// The output file's encoding as File_Gamma asks (INI option given on the command line, as
// POV-Ray takes it): a power law of 1.8 instead of sRGB, from a working gamma of 1; the
// shades span dark to bright so every part of the curve shows.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -4> look_at <0, 0.2, 0> }
light_source { <5, 5, -5> color rgb 1 }
sphere { 0, 1 pigment { color rgb <0.8, 0.4, 0.05> } finish { phong 0.5 } }
plane { y, -1 pigment { gradient x color_map { [0 rgb 0.002] [1 rgb 1] } scale 4 translate -2*x } }
background { rgb <0.2, 0.3, 0.5> }
