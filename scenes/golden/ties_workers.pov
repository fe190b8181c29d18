// Exact ties in depth in black boxes of worker processes: a worker keeps only its
// boxes' objects, but which of two coincident surfaces POV-Ray shows is decided by the
// whole scene's object list and slab tree (its order of testing frame objects), so each
// worker records that list as it parses. A see-through box against an opaque one (a
// shared face), coincident spheres of two colours, a light whose looks_like object ties
// with a sphere placed after it, and a union of coincident discs.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <-3, 2.2, -4> look_at <1.2, 0.5, 0.8> angle 60 }
light_source { <-10, 10, -10> color rgb 1 }
plane { y, -0.01 pigment { checker rgb 0.8 rgb 0.4 } }
box { <1, 0, 0>, <2, 1, 1> pigment { rgb <1, 1, 0.3> } }
box { <0, 0, 0>, <1, 1, 1> pigment { rgbt <0.3, 0.4, 1, 0.5> } }
sphere { <0.5, 0.5, -1.2>, 0.4 pigment { rgb <1, 0.2, 0.2> } }
sphere { <0.5, 0.5, -1.2>, 0.4 pigment { rgb <0.2, 1, 0.2> } }
light_source { <2.5, 1.5, -1.5> color rgb 0.3
  looks_like { sphere { 0, 0.3 pigment { rgb <1, 0.5, 1> } finish { emission 1 } } } }
sphere { <2.5, 1.5, -1.5>, 0.3 pigment { rgb <0, 0.5, 1> } }
union {
  disc { <3, 0.5, 1>, -z, 0.5 pigment { rgb <0.9, 0.6, 0.1> } }
  disc { <3, 0.5, 1>, -z, 0.5 pigment { rgb <0.1, 0.6, 0.9> } }
}
box { <2, 0, 0>, <3, 1, 1> pigment { rgbf <1, 0.6, 0.6, 0.7> } }
