// An inverse CSG, or a difference, inverts each leaf under it, but a triangle, polygon,
// bicubic_patch or smooth_triangle keeps its normal (its Invert does nothing in POV-Ray):
// which side shows the interior_texture follows the leaf's own normal.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.3, 0> angle 50 }
light_source { <-3, 6, -5> color rgb 1 }
plane { y, -1 pigment { rgb 0.7 } }
#declare Outside = texture { pigment { rgb <0.9, 0.3, 0.2> } }
#declare Inside = texture { pigment { rgb <0.2, 0.8, 0.3> } }
union {
  triangle { <-1, -1, 0>, <1, -1, 0>, <0, 1, 0> }
  texture { Outside } interior_texture { Inside }
  inverse translate <-2.2, 0, 0>
}
union {
  polygon { 5, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1> rotate y * 30 }
  sphere { <0, 0, -0.6>, 0.4 }
  texture { Outside } interior_texture { Inside }
  inverse
}
difference {
  box { <-0.8, -0.8, -0.8>, <0.8, 0.8, 0.8> }
  bicubic_patch { type 1 flatness 0 u_steps 3 v_steps 3
    <-1, -1, -1>, <-0.3, -1, -0.5>, <0.3, -1, -0.5>, <1, -1, -1>,
    <-1, -0.3, -0.5>, <-0.3, -0.3, 1>, <0.3, -0.3, 1>, <1, -0.3, -0.5>,
    <-1, 0.3, -0.5>, <-0.3, 0.3, 1>, <0.3, 0.3, 1>, <1, 0.3, -0.5>,
    <-1, 1, -1>, <-0.3, 1, -0.5>, <0.3, 1, -0.5>, <1, 1, -1> }
  smooth_triangle { <-1, -1, -1.2>, <0, 0, -1>, <1, -1, -1.2>, <0, 0.3, -1>, <0, 1, -1.2>, <0.3, 0, -1> }
  texture { Outside } interior_texture { Inside }
  rotate y * -20 translate <2.2, 0, 0>
}
