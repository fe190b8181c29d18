// Shadow rays through see-through pieces of many parts: POV-Ray restarts a shadow ray at
// each clear surface it crosses and searches again, and povwall reuses each object's
// crossings of that ray (not for shapes that search from the restart point, a mesh here,
// nor for leaves that give only their nearest crossing, a blob and a lathe here). An area
// light sends rays from one point in many directions: each is its own ray.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 8 }
camera { location <0, 5.5, -9> look_at <0, 0.6, 0> angle 48 }
light_source { <-6, 9, -4> colour rgb 0.8 }
light_source { <5, 7, -6> colour rgb 0.5 area_light 1.5 * x, 1.5 * z, 3, 3 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.35 } }
#declare Clear = texture { pigment { rgbf <0.9, 0.95, 1, 0.85> } finish { specular 0.5 roughness 0.02 } }
// A union of overlapping parts (its surfaces inside one another all count).
union {
  cylinder { 0, 0.3 * y, 0.8 }
  torus { 0.6, 0.15 translate 0.35 * y }
  cone { 0.3 * y, 0.55, 1.5 * y, 0.25 }
  sphere { 1.75 * y, 0.4 }
  texture { Clear } interior { ior 1.3 }
  translate <-2.4, 0, 0.5>
}
// A difference (one CSG object: its crossings come from every child).
difference {
  cylinder { 0, 1.6 * y, 0.7 }
  cylinder { 0.6 * y, 1.7 * y, 0.45 }
  box { <-0.8, 1.2, -0.12>, <0.8, 1.7, 0.12> }
  texture { Clear } interior { ior 1.4 }
  translate <-0.8, 0, 0.8>
}
// A merge and an intersection with a tinted filter.
merge {
  sphere { 0.7 * y, 0.6 }
  cylinder { 0, 1.4 * y, 0.3 }
  texture { pigment { rgbf <1, 0.7, 0.6, 0.8> } }
  translate <0.7, 0, 0.2>
}
intersection {
  box { -0.6, 0.6 rotate 30 * y }
  sphere { 0, 0.75 }
  texture { pigment { rgbt <0.6, 1, 0.7, 0.7> } }
  translate <2.2, 0.6, 0.9>
}
// A mesh (searched from each restart), a blob and a lathe (nearest crossing only).
mesh {
  triangle { <-0.5, 0, -0.5>, <0.5, 0, -0.5>, <0, 1.2, 0> }
  triangle { <0.5, 0, -0.5>, <0, 0, 0.6>, <0, 1.2, 0> }
  triangle { <0, 0, 0.6>, <-0.5, 0, -0.5>, <0, 1.2, 0> }
  texture { Clear } translate <-1.6, 0, -1.2>
}
blob {
  threshold 0.5
  sphere { <0, 0.5, 0>, 0.7, 1 }
  sphere { <0.4, 0.9, 0>, 0.6, 1 }
  texture { Clear } translate <0.3, 0, -1.4>
}
lathe {
  linear_spline 5, <0, 0>, <0.5, 0>, <0.3, 0.6>, <0.45, 1.1>, <0, 1.2>
  texture { Clear } translate <1.7, 0, -1>
}
