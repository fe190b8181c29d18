// Dispersion where a band reflects totally: POV-Ray sums every band of the split as light
// that passed (its dispersion loop ignores each band's total internal reflection), so a
// band reflected inside is still filtered by the surface's filter colour and the finish's
// own reflection stays; without dispersion the same reflection is unfiltered and the
// finish's reflection with the same normal is left out. A ray splits where it is not yet
// one band: here the camera is inside a glass block and looks out through its faces,
// past their critical angle towards the edges. The small block inside is dispersive too.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 5 }
camera { location <0.3, 0.2, -1.2> look_at <0, 0.1, 1> angle 100 }
light_source { <-3, 8, -6> rgb 1 }
background { rgb <0.3, 0.45, 0.7> }
plane { y, -3 pigment { checker rgb <1, 0.9, 0.6> rgb <0.2, 0.3, 0.5> scale 0.7 } }
sphere { <1, 0, 5>, 1 pigment { rgb <1, 0.3, 0.2> } }
box { <-2, -1.5, -2>, <2, 1.5, 2>
  material {
    texture { pigment { rgbf <0.7, 1, 0.8, 0.9> } finish { reflection 0.1 specular 0.4 } }
    interior { ior 1.45 dispersion 1.1 dispersion_samples 3 }
  }
  rotate 10 * y
}
box { <-0.3, -0.3, -0.3>, <0.3, 0.3, 0.3>
  material {
    texture { pigment { rgbf <1, 0.8, 0.6, 0.9> } }
    interior { ior 1.3 dispersion 1.2 }
  }
  rotate <30, 40, 0> translate <-0.6, -0.4, 0.8>
}
