// golden-args: --block-mean 8
// Media photons (global photons `media steps, factor`): photons refracted by a glass
// sphere store photons along the stretches of scattering media they cross (at most
// `steps` per interval, spaced `factor` times the photon spacing), and every sample of
// a viewing ray in scattering media gathers them (POV-Ray's mediaPhotonMap): the
// focused beam under the sphere glows where the direct light scattering there is in
// the sphere's black filtered shadow. The container lets photons pass (pass_through);
// it stores none on its first stretch (the photon passed a surface just before).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10
  photons { spacing 0.02 media 60, 1 } }
camera { location <0, 2.2, -6> look_at <0, 1.3, 0> angle 45 }
light_source { <0, 8, 0.5> color rgb 1.5 }
plane { y, 0 pigment { rgb 0.7 } }
sphere { <0, 2.2, 0>, 0.6
  pigment { rgbf <1, 1, 1, 0.97> } interior { ior 1.5 }
  photons { target refraction on reflection off } }
box { <-2, 0.001, -1.5>, <2, 3, 1.5> hollow
  pigment { rgbt 1 }
  interior { media { scattering { 1, rgb 0.12 } intervals 1 samples 3 } }
  photons { pass_through } }
