// golden-args: --block-mean 8
// Photons from parallel lights (POV-Ray's Parallel: a parallel point light and a parallel
// spotlight): they leave a disc across the light's direction, all along it, about the
// target's bounding sphere, and keep their spacing with distance (no spread with depth).
// A glass sphere focuses the slanted light into a caustic beside its shadow; the
// spotlight's cone does not dim its parallel photons (POV-Ray measures the cone along
// the light's own direction).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10
  photons { spacing 0.01 } }
camera { location <0, 4, -4> look_at <0, 0.3, 0> angle 40 }
light_source { <-3, 6, -1> color rgb 0.9 parallel point_at <0, 0, 0> }
light_source { <4, 8, 2> color rgb <0.6, 0.5, 0.3> spotlight parallel
  point_at <0, 1, 0> radius 10 falloff 20 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.6 } }
sphere { <0, 1, 0>, 0.8
  pigment { rgbf <0.95, 1, 0.95, 0.95> } finish { phong 0.5 reflection 0.05 }
  interior { ior 1.5 }
  photons { target refraction on reflection on } }
