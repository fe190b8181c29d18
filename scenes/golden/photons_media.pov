// golden-args: --block-mean 8
// Photons through media (POV-Ray's PhotonTrace::ComputeLightedTexture): a glass sphere's
// caustic inside a hollow container of absorbing, glowing media. The photons pass
// through the container's wall (pass_through), and along each stretch inside it the
// media act on them as on a viewing ray: the absorption tints the caustic, the emission
// adds to every photon's colour. The atmosphere's media leave photons alone: the thin
// haze outside the container changes the caustic only as it dims the camera's rays.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10
  photons { spacing 0.01 } }
camera { location <0, 4, -4> look_at <0, 0.3, 0> angle 40 }
light_source { <1, 7, 1> color rgb 1.2 }
media { absorption 0.02 method 3 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.6 } }
sphere { <0, 1, 0>, 0.8
  pigment { rgbf <0.95, 1, 0.95, 0.95> } finish { phong 0.5 reflection 0.05 }
  interior { ior 1.5 }
  photons { target refraction on reflection on } }
box { <-2.5, 0.001, -1.5>, <2.5, 2.2, 2.5> hollow
  pigment { rgbt 1 }
  interior { media { absorption <0.1, 0.35, 0.6> emission <0.08, 0.06, 0.02> } }
  photons { pass_through } }
