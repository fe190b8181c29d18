// An image_map `once` finds no colour off its image (POV-Ray's Compute_Pigment returns
// false there): that layer filters nothing, so conserve_energy takes nothing away for its
// reflection, whatever the layers under it do; a pigment_map finds a colour when either
// of the entries it blends does.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -7> look_at <0, 0, 0> angle 55 }
light_source { <-2, 8, -5> rgb 1 }
background { rgb <0.5, 0.25, 0.6> }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.9, 0.6, 0.3>] [1 rgb <0.2, 0.3, 0.8>] } } }
// A floor of only the decal: reflective, conserving energy.
plane { y, -1
  pigment { image_map { png "images/card.png" once } rotate 90 * x translate <-0.5, 0, -0.5> scale 2 }
  finish { reflection { 0.05, 0.7 falloff 2 } conserve_energy }
}
// A decal over a glass sphere and over a clear box, a layer on top of another texture.
sphere { <-1.6, 0.2, 0.5>, 1
  texture { pigment { rgbf <0.8, 0.9, 1, 0.9> } finish { reflection 0.2 } }
  texture { pigment { image_map { png "images/card.png" once } translate <-0.5, -0.5, 0> scale 0.8 }
            finish { reflection { 0.1, 0.5 } conserve_energy } }
  interior { ior 1.3 }
}
box { <-0.8, -0.8, -0.8>, <0.8, 0.8, 0.8>
  texture { pigment { rgbt <1, 1, 1, 0.7> } }
  texture { pigment { gradient x
                      pigment_map { [0.5 image_map { png "images/card.png" once } translate -0.5 scale 0.9 ]
                                    [0.5 rgbt 1 ] } translate -0.5 scale 4 }
            finish { reflection 0.4 conserve_energy } }
  rotate <20, -30, 0> translate <1.7, 0.1, 0.3>
}
