// golden-args: --block-mean 8
// Photons through a dispersing glass sphere: each photon refracted into the sphere splits
// into its wavelength bands (7), each carrying the band's hue share, so the caustic on the
// floor spreads into colours; the view through the sphere splits the same way.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10
  photons { spacing 0.01 } }
camera { location <0, 4, -4> look_at <0, 0.3, 0> angle 40 }
light_source { <2, 6, 1> color rgb 1.2 }
plane { y, 0 pigment { rgb 0.7 } }
sphere { <0, 1, 0>, 0.8
  pigment { rgbf <1, 1, 1, 0.95> } finish { phong 0.5 reflection 0.05 }
  interior { ior 1.5 dispersion 1.3 }
  photons { target refraction on reflection off } }
