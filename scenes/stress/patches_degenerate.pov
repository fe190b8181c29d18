// Bicubic patches with a collapsed edge (a cone-like apex where dP/du x dP/dv vanishes),
// control points 1e-7 apart, and a patch seen at a grazing angle.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.6, -7> look_at <0, 0.4, 0> angle 50 }
light_source { <10, 20, -10> rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
// Row 0 collapsed to one point.
bicubic_patch { type 1 flatness 0 u_steps 4 v_steps 4
  <0, 1, 0>, <0, 1, 0>, <0, 1, 0>, <0, 1, 0>,
  <-1, 0.6, -1>, <-0.3, 0.6, -1>, <0.3, 0.6, -1>, <1, 0.6, -1>,
  <-1, 0.3, 1>, <-0.3, 0.3, 1>, <0.3, 0.3, 1>, <1, 0.3, 1>,
  <-1, 0, 0>, <-0.3, 0, 0.5>, <0.3, 0, 0.5>, <1, 0, 0>
  translate -2*x pigment { rgb <1, 0.6, 0.2> } }
// Nearly coincident control points.
bicubic_patch { type 1 flatness 0 u_steps 3 v_steps 3
  <0, 0, 0>, <1e-7, 0, 0>, <2, 0.5, 0>, <3, 0, 0>,
  <0, 0, 1e-7>, <1, 1, 1>, <2, 1, 1>, <3, 0.5, 1>,
  <0, 0.5, 2>, <1, 1, 2>, <2, 1, 2>, <3, 0.5, 2>,
  <0, 0, 3>, <1, 0.5, 3>, <2, 0.5, 3>, <3 + 1e-7, 0, 3>
  scale 0.5 translate <0.6, 0, -0.5> pigment { rgb 1 } }
// Grazing: nearly in the plane of the camera rays.
bicubic_patch { type 1 flatness 0.01 u_steps 5 v_steps 5
  <0, 0, 0>, <1, 0.02, 0>, <2, -0.02, 0>, <3, 0, 0>,
  <0, 0.02, 1>, <1, 0, 1>, <2, 0, 1>, <3, 0.02, 1>,
  <0, -0.02, 2>, <1, 0, 2>, <2, 0, 2>, <3, -0.02, 2>,
  <0, 0, 3>, <1, 0.02, 3>, <2, -0.02, 3>, <3, 0, 3>
  translate <-1.5, 0.6, 0> pigment { rgb <0.4, 0.8, 1> } }
