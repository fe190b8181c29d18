// golden-args: --block-mean 8
// Photons from a cylinder light (parallel, as POV-Ray's cylinder lights are): shot
// along its axis from a disc about the target's bounding sphere, dimmed by their start's
// distance from the axis as POV-Ray's photon pass dims them (tightness, then a smooth
// edge from `radius` to `falloff`), none beyond `falloff`. The beam is narrower than the
// glass sphere, so the edge shows in the caustic.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10
  photons { spacing 0.008 } }
camera { location <0, 4, -4> look_at <0, 0.3, 0> angle 40 }
light_source { <0, 6, 0> color rgb 1.5 }
light_source { <-1.5, 7, 1> color rgb 1.2 cylinder point_at <-0.2, 0, 0.1>
  radius 0.35 falloff 0.7 tightness 2 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.6 } }
sphere { <0, 1, 0>, 0.8
  pigment { rgbf <0.95, 1, 0.95, 0.95> } finish { phong 0.5 reflection 0.05 }
  interior { ior 1.5 }
  photons { target refraction on reflection on } }
