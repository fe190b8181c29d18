// Degenerate shapes as exporters write them: zero-radius cylinders and cones, zero-thickness
// boxes, degenerate triangles (warned, never hit), degenerate mesh triangles (dropped),
// coincident duplicate spheres, a zero-radius sphere. POV-Ray renders them without error.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.5, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
background { color rgb <0.4, 0.5, 0.7> }
plane { y, 0 pigment { color rgb 0.6 } }
cylinder { <-2, 0, 0>, <-2, 2, 0>, 0 pigment { color rgb <1, 0, 0> } }
cone { <0, 0, 0>, 0, <0, 2, 0>, 0 pigment { color rgb <0, 1, 0> } }
cone { <-1, 0, 0>, 0.4, <-1, 1.5, 0>, 0 pigment { color rgb <0, 1, 0> } }
box { <1.5, 0, -0.5>, <2.5, 1.5, -0.5> pigment { color rgb <0, 0, 1> } }
box { <-3, 0.5, -1>, <-2.5, 0.5, -0.5> pigment { color rgb <0, 0, 1> } }
triangle { <0, 1, -1>, <0.5, 1.5, -1>, <1, 2, -1> pigment { color rgb <1, 1, 0> } }
triangle { <0, 1, -1>, <0, 1, -1>, <1, 2, -1> pigment { color rgb <1, 1, 0> } }
smooth_triangle { <0, 1, -1>, y, <0.5, 1.5, -1>, y, <1, 2, -1>, y pigment { color rgb <1, 1, 0> } }
sphere { <0.5, 0.4, -1.5>, 0.4 pigment { color rgb <1, 0, 1> } }
sphere { <0.5, 0.4, -1.5>, 0.4 pigment { color rgb <1, 0, 1> } }
sphere { <-0.8, 0.4, -1.5>, 0 pigment { color rgb <1, 0, 1> } }
mesh {
  triangle { <2, 2, 0>, <2, 2, 0>, <3, 2, 0> }
  triangle { <2, 2, 0>, <3, 3, 0>, <4, 4, 0> }
  triangle { <1.5, 1.5, 0>, <2, 2.5, 0>, <2.5, 1.5, 0> }
  pigment { color rgb 1 }
}
union {
  cylinder { <-2.5, 1.5, -1>, <-1.5, 1.5, -1>, 0 }
  sphere { <-2, 1.5, -1>, 0.3 }
  box { <-2.4, 1.2, -1>, <-1.6, 1.8, -1> }
  pigment { color rgb <0.9, 0.6, 0.2> }
}
