// Object flags on the children of clipped unions, which POV-Ray keeps whole: its union
// tests no_image only on image rays that are not camera rays (here: through the pane),
// no_reflection on reflected rays, and never no_shadow (per column: no_image,
// no_reflection, no_shadow on the red sphere).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.2, -8> look_at <0, 0.2, 0> angle 52 }
light_source { <-7, 7, -5> color rgb 1 }
background { rgb <0.3, 0.4, 0.5> }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.55 } finish { reflection 0.35 } }
// A see-through pane with no ior in front of the lower half: what the camera sees through
// it comes by refracted rays (image rays, not primary rays).
box { <-5, -1, -2.6>, <5, 1.0, -2.5> pigment { rgbf <1, 1, 1, 0.85> } }
#declare Red = texture { pigment { rgb <0.9, 0.15, 0.1> } }
#declare Blue = texture { pigment { rgb <0.15, 0.35, 0.9> } }
union { sphere { <-2.6, 0, 0>, 0.8 texture { Red } no_image } box { <-2.70, -1, -0.4>, <-1.50, 0.6, 0.6> texture { Blue } } clipped_by { box { <-4.6, -2, -2>, <-0.6, 0.45, 2> } } }
union { sphere { <0, 0, 0>, 0.8 texture { Red } no_reflection } box { <-0.10, -1, -0.4>, <1.10, 0.6, 0.6> texture { Blue } } clipped_by { box { <-2, -2, -2>, <2, 0.45, 2> } } }
union { sphere { <2.6, 0, 0>, 0.8 texture { Red } no_shadow } box { <2.50, -1, -0.4>, <3.70, 0.6, 0.6> texture { Blue } } clipped_by { box { <0.6, -2, -2>, <4.6, 0.45, 2> } } }
