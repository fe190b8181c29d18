// golden-args: --block-mean 8
// Photons through a glass lens made by CSG (an intersection of two spheres) inside a
// union with an opaque part: the union is the target, the photons find the glass by the
// flags its children inherit; a pass_through glass pane in front lets photons by
// unbent, a collect-off box gets none.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10
  photons { spacing 0.012 jitter 0.5 expand_thresholds 0.3, 30 } }
camera { location <0, 5, -5> look_at <0, 0.2, 0> angle 45 }
light_source { <0.5, 6, -1> color rgb 1.3 }
plane { y, 0 pigment { checker rgb 0.85 rgb 0.65 scale 0.5 } }
union {
  intersection {
    sphere { <0, -1.2, 0>, 2 }
    sphere { <0, 2.2, 0>, 2 }
    pigment { rgbf <1, 0.9, 0.7, 0.95> }
    interior { ior 1.45 }
  }
  cylinder { <0, 0, 0>, <0, 0.2, 0>, 0.15 translate <0, 0.3, 0> pigment { rgb <0.2, 0.3, 0.8> } }
  split_union off
  translate <0, 1.2, 0>
  photons { target refraction on reflection off }
}
box { <-3, 0, 1.5>, <-1.8, 0.6, 2.5> pigment { rgb 0.9 } photons { collect off } }
box { <1.5, 2.5, -1.5>, <2.5, 2.55, -0.5> pigment { rgbf <0.8, 0.9, 1, 0.9> }
  photons { pass_through } }
