// interior_texture: spheres cut open by their clips show the inside of their surface (met
// from inside: the raw normal along the ray) in the interior texture, one through a
// material; mesh triangles and a triangle show it on the side their corners' order makes
// the back; a union hands its transparent interior texture to its children.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -6> look_at <0, 0.3, 0> angle 50 }
light_source { <-4, 7, -5> color rgb 1 }
light_source { <3, 2, -6> color rgb 0.4 }
plane { y, -1 pigment { checker color rgb 0.8 color rgb 0.4 } }
sphere { <-1.6, 0.2, 0>, 1
  texture { pigment { rgb <0.9, 0.5, 0.2> } finish { phong 0.5 } }
  interior_texture { pigment { rgb <0.2, 0.4, 0.9> } }
  clipped_by { plane { <0, 1, -1>, 0.2 } }
}
sphere { <1.2, 0.2, 0>, 1
  material {
    texture { pigment { rgb <0.3, 0.8, 0.3> } }
    interior_texture { pigment { checker rgb 1, rgb <0.8, 0.1, 0.1> scale 0.25 } }
  }
  clipped_by { box { <-1, -2, -2>, <1.1, 2, 2> inverse } }
}
mesh { triangle { <-2.8, 1.4, 1>, <-1.4, 2.2, 1>, <-2.6, 2.4, 0.5> }
       triangle { <1.4, 1.4, 1>, <2.6, 2.4, 0.5>, <2.8, 1.4, 1> }
  texture { pigment { rgb <1, 1, 0.3> } }
  interior_texture { pigment { rgb <0.3, 1, 1> } } }
triangle { <-0.6, 1.6, 1>, <0.6, 1.6, 1>, <0, 2.6, 1.2>
  texture { pigment { rgb <1, 0.6, 0.8> } }
  interior_texture { pigment { rgb <0.5, 0.3, 0.1> } } }
union {
  sphere { <0, -0.4, -1.6>, 0.5 }
  sphere { <0.5, -0.4, -1.6>, 0.4 texture { pigment { rgb <1, 1, 0> } } }
  texture { pigment { rgb <0.6, 0.6, 0.6> } }
  interior_texture { pigment { rgbf <0.9, 0.2, 0.9, 0.7> } }
  clipped_by { plane { -z, 1.7 } }
}
// Its first turn is a reflex corner: POV-Ray's normal (from the first three corners)
// points away from the camera, against the loop's overall (Newell) normal.
polygon { 5, <1, 1>, <0, 0.5>, <-1, 1>, <0, -1>, <1, 1>
  texture { pigment { rgb <0.2, 0.9, 0.5> } }
  interior_texture { pigment { rgb <0.9, 0.2, 0.2> } }
  scale 0.35 translate <-0.1, 0.9, -1.5> }
