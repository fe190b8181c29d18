// Dispersion (interior `dispersion`, `dispersion_samples`): a ray refracted into an
// interior whose dispersion differs from the side it comes from splits into one ray per
// wavelength band, each bent by the band's index (the index times the dispersion ratio
// to the power of the band's offset from 555 nm over 350 nm) and weighted by the band's
// hue; a split ray keeps its band, so its later surfaces bend it once. Cases: a lone
// glass sphere, a prism with 12 bands, dispersion inside CSG (difference), a dispersing
// sphere inside a box of another dispersion (leaving into it takes the larger band
// count), total internal reflection per band (a diamond-like ior), dispersion at ior 1,
// and `dispersion` without `ior` (no effect in POV-Ray: the atmosphere's index and
// dispersion are taken).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 12 }
camera { location <0, 2.2, -7> look_at <0, 0.6, 0> angle 55 }
light_source { <-5, 8, -6> color rgb 1 }
background { rgb <0.1, 0.1, 0.15> }
plane { y, 0 pigment { checker rgb 1 rgb 0.05 scale 0.25 } }
plane { z, 3 pigment { gradient x color_map { [0 rgb 0.02] [0.45 rgb 0.02] [0.5 rgb 1]
                                              [0.55 rgb 0.02] } scale 0.4 } }
#declare Glass = finish { specular 0.4 roughness 0.01 reflection 0.05 }
// A lone sphere, 7 bands (the default).
sphere { <-2.6, 0.8, 0>, 0.8
  pigment { rgbf <1, 1, 1, 0.95> } finish { Glass }
  interior { ior 1.5 dispersion 1.15 } }
// A prism with 12 bands.
prism { linear_sweep linear_spline 0, 1.6, 4, <-0.6, -0.4>, <0.6, -0.4>, <0, 0.6>, <-0.6, -0.4>
  rotate <-90, 0, 0> translate <-0.9, 0.3, 0.5>
  pigment { rgbf <1, 1, 1, 1> } finish { Glass }
  interior { ior 1.6 dispersion 1.25 dispersion_samples 12 } }
// Dispersion inside CSG.
difference {
  sphere { <0.6, 0.7, 0>, 0.7 }
  cylinder { <0.6, 0.7, -1>, <0.6, 0.7, 1>, 0.3 }
  pigment { rgbf <1, 0.95, 0.9, 0.9> } finish { Glass }
  interior { ior 1.45 dispersion 1.2 } }
// A dispersing sphere inside a box of another dispersion and band count.
union {
  box { <1.5, 0.05, -0.6>, <2.7, 1.25, 0.6>
    pigment { rgbf <1, 1, 1, 0.97> } finish { Glass }
    interior { ior 1.3 dispersion 1.05 dispersion_samples 3 } }
  sphere { <2.1, 0.65, 0>, 0.45
    pigment { rgbf <1, 1, 1, 0.97> } finish { Glass }
    interior { ior 1.7 dispersion 1.3 dispersion_samples 5 } }
}
// Total internal reflection band by band (a diamond-like index).
sphere { <3.4, 1.9, 0.8>, 0.5
  pigment { rgbf <1, 1, 1, 1> } finish { Glass }
  interior { ior 2.4 dispersion 1.08 } }
// Dispersion at ior 1: only the bands bend.
sphere { <-1.2, 2.1, 0.6>, 0.5
  pigment { rgbf <1, 1, 1, 1> }
  interior { ior 1 dispersion 1.6 } }
// Dispersion without ior: POV-Ray takes the atmosphere's (no split).
sphere { <0.9, 2.1, 0.6>, 0.45
  pigment { rgbf <1, 1, 1, 0.9> }
  interior { dispersion 1.6 } }
