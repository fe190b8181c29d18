// POV-Ray walks a mesh's box tree nearest box first and, for a mesh without
// inside_vector, stops at the first box that starts beyond the last hit it kept: a CSG
// that drops the nearest hit (inside a subtracted part, outside an intersected one) never
// sees the triangles behind it. With inside_vector, or `hierarchy off` in the mesh's own
// braces (no tree), every crossing counts; `hierarchy off` on a copy finds the tree built.
// A clipped mesh keeps the nearest hit its clip keeps.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 8 }
camera { location <0, 5, -12> look_at <0, 0.2, 0> angle 52 }
light_source { <4, 10, -8> rgb 1 }
light_source { <-8, 5, -3> rgb 0.35 shadowless }
background { rgb <0.2, 0.25, 0.35> }
plane { y, -1.6 pigment { checker rgb 0.75 rgb <0.35, 0.45, 0.6> } }
#declare Tetra = mesh {
  triangle { <0, 1.4, 0>, <-1.2, -0.7, -0.7>, <1.2, -0.7, -0.7> }
  triangle { <0, 1.4, 0>, <1.2, -0.7, -0.7>, <0, -0.7, 1.3> }
  triangle { <0, 1.4, 0>, <0, -0.7, 1.3>, <-1.2, -0.7, -0.7> }
  triangle { <-1.2, -0.7, -0.7>, <1.2, -0.7, -0.7>, <0, -0.7, 1.3> }
}
#declare Solid = mesh {
  triangle { <0, 1.4, 0>, <-1.2, -0.7, -0.7>, <1.2, -0.7, -0.7> }
  triangle { <0, 1.4, 0>, <1.2, -0.7, -0.7>, <0, -0.7, 1.3> }
  triangle { <0, 1.4, 0>, <0, -0.7, 1.3>, <-1.2, -0.7, -0.7> }
  triangle { <-1.2, -0.7, -0.7>, <1.2, -0.7, -0.7>, <0, -0.7, 1.3> }
  inside_vector y
}
#declare Flat = mesh {
  triangle { <0, 1.4, 0>, <-1.2, -0.7, -0.7>, <1.2, -0.7, -0.7> }
  triangle { <0, 1.4, 0>, <1.2, -0.7, -0.7>, <0, -0.7, 1.3> }
  triangle { <0, 1.4, 0>, <0, -0.7, 1.3>, <-1.2, -0.7, -0.7> }
  triangle { <-1.2, -0.7, -0.7>, <1.2, -0.7, -0.7>, <0, -0.7, 1.3> }
  hierarchy off
}
// Row at the back: a difference with a sphere cutting the near faces.
difference { object { Tetra } sphere { <-0.2, 0.1, -0.5>, 0.9 }
  pigment { rgb <1, 0.7, 0.3> } rotate 20 * y translate <-4.2, 0, 2.5> }
difference { object { Solid } sphere { <-0.2, 0.1, -0.5>, 0.9 }
  pigment { rgb <0.4, 1, 0.5> } rotate 20 * y translate <-1.4, 0, 2.5> }
difference { object { Flat } sphere { <-0.2, 0.1, -0.5>, 0.9 }
  pigment { rgb <0.5, 0.7, 1> } rotate 20 * y translate <1.4, 0, 2.5> }
difference { object { Tetra hierarchy off } sphere { <-0.2, 0.1, -0.5>, 0.9 }
  pigment { rgb <1, 0.5, 0.8> } rotate 20 * y translate <4.2, 0, 2.5> }
// Front row: an intersection with a box, a merge of glass, a clipped mesh in a union
// and a mesh under a shear.
intersection { object { Tetra scale 1.2 } box { <-0.6, -2, -0.2>, <2, 2, 2> }
  pigment { rgb <0.9, 0.9, 0.4> } rotate -30 * y translate <-3.6, 0, -1.5> }
merge { object { Tetra } sphere { <0.5, 0.3, -0.3>, 0.6 }
  pigment { rgbf <0.9, 1, 0.9, 0.8> } interior { ior 1.4 } translate <-1, 0, -1.5> }
union { object { Tetra clipped_by { plane { z, -0.2 } } } sphere { <0, -1.2, 0>, 0.3 }
  pigment { rgb <0.8, 0.5, 1> } rotate 160 * y translate <1.3, 0, -1.5> }
difference { object { Tetra matrix <1, 0, 0, 0.4, 1, 0, 0, 0, 1, 0, 0, 0> }
  cylinder { <0, -2, -0.6>, <0, 2, -0.6>, 0.7 }
  pigment { rgb <0.4, 0.9, 1> } translate <3.8, 0, -1.5> }
