// blob component textures: each element's texture weighted by its |field| at the hit
// (POV-Ray's Determine_Textures), components without one taking the blob's, a texture
// moved by its component's transforms and by the blob's, a loose pigment/finish on a
// component, a transparent component (shadows through the blended filter), and the
// cylinder's three elements sharing its texture, and a cut-open one seen inside.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -9> look_at <0, 0.3, 0> angle 50 }
light_source { <-5, 10, -8> color rgb 1 }
light_source { <6, 5, -4> color rgb 0.4 }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.5 scale 0.8 } }
blob {
  threshold 0.5
  sphere { <-0.7, 0, 0>, 1.1, 1 pigment { rgb <1, 0.2, 0.1> } }
  sphere { <0.7, 0, 0>, 1.1, 1 texture { pigment { rgb <0.1, 0.3, 1> } finish { specular 0.6 } } }
  sphere { <0, 0.8, 0>, 0.9, 1 }
  pigment { rgb <0.2, 0.9, 0.2> }
  translate <-2.5, 0, 1>
}
blob {
  threshold 0.4
  cylinder { <-1, 0, 0>, <1, 0, 0>, 0.5, 1
    texture { pigment { checker rgb <1, 0.8, 0.2> rgb <0.6, 0.2, 0.6> scale 0.2 } }
    rotate 20*y }
  sphere { <0, 0, 0>, 0.8, 1 scale <1, 1.6, 1> pigment { gradient y color_map { [0 rgb 1] [1 rgb <0.2, 0.6, 0.9>] } } }
  sphere { <0.2, 0.9, -0.2>, 0.5, -0.6 }
  rotate -15*z translate <0.4, 0.1, 1.6>
}
blob {
  threshold 0.5
  sphere { <0, 0, 0>, 1, 1 pigment { rgbf <0.9, 1, 0.9, 0.8> } finish { specular 0.5 } }
  sphere { <0.8, 0.2, 0>, 0.8, 1 pigment { rgb <1, 0.6, 0.1> } }
  translate <2.6, 0, 0.3>
}
// Cut open: a multi-textured blob shows its component textures from inside too (POV-Ray
// never takes a multi-textured object's interior_texture).
difference {
  blob { threshold 0.5
    sphere { <-0.5, 0, 0>, 0.9, 1 pigment { rgb <1, 0.3, 0.2> } }
    sphere { <0.5, 0, 0>, 0.9, 1 pigment { rgb <0.2, 0.4, 1> } }
    pigment { rgb 1 } interior_texture { pigment { rgb <0.2, 1, 0.2> } } }
  box { <-2, 0, -2>, <2, 2, 0> }
  rotate 30*y translate <0, -0.3, -2.6>
}
