// golden-args: --block-mean 8 --max-rmse 0.03 --fail 0.02 --max-bad-fraction 0
// rad_def.inc's Rad_Settings macro, as OpenSCAD's export uses it (there with
// Radiosity_Normal; Radiosity_Fast here keeps the test fast): its settings come in
// through the macro, inside the radiosity block. A #version 3.6 scene: `ambient` still
// adds to the radiosity there.
#version 3.6;
#include "rad_def.inc"
global_settings { assumed_gamma 1.0 radiosity { Rad_Settings(Radiosity_Fast, off, off) } }
camera { location <2, 2, -3> look_at <0, 0.5, 0> angle 50 }
light_source { <-3, 5, -2> color rgb 1 }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } finish { ambient 0.1 } }
plane { z, 1.5 pigment { rgb <0.3, 0.5, 0.9> } finish { ambient 0.1 } }
sphere { <0, 0.6, 0>, 0.6 pigment { rgb <0.9, 0.5, 0.2> } finish { ambient 0.1 } }
cylinder { <1, 0, 0.3>, <1, 1.2, 0.3>, 0.25 pigment { rgb 0.9 } finish { ambient 0.1 } }
