// golden-args: --block-mean 8
// An area light's photons (light `photons { area_light }`): each ring's photon is shot
// from every point of the light's grid (the axes' ends and evenly between) toward the
// target, each with its share of the light, so the caustic is the blur of the grid's
// caustics. The second light's grid shoots from its centre only (no `area_light` in its
// photons block).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10
  photons { spacing 0.01 } }
camera { location <0, 4, -4> look_at <0, 0.3, 0> angle 40 }
light_source { <1, 7, 1> color rgb 1.2
  area_light <3, 0, 0>, <0, 0, 2>, 4, 3 adaptive 1
  photons { area_light } }
light_source { <-4, 6, -2> color rgb 0.4
  area_light <1, 0, 0>, <0, 1, 0>, 2, 2 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.6 } }
sphere { <0, 1, 0>, 0.8
  pigment { rgbf <0.95, 1, 0.95, 0.95> } finish { phong 0.5 reflection 0.05 }
  interior { ior 1.5 }
  photons { target refraction on reflection on } }
