// bounded_by as POV-Ray 3.7 renders undersized bounds. A CSG keeps its bound: rays (and
// shadow rays) that miss the bounding object skip the whole object, and rays through it
// see all of it. A shape's bound is removed as unnecessary, but its box still shrinks the
// shape's bounding box, which clips the shape in the bounding-slab tree and in the box
// test of shapes that have one. Children of a CSG keep their bounds (here also those of a
// union with split_union off); clipped_by { bounded_by } clips by the bound.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.3, 0> angle 55 }
light_source { <-5, 8, -6> color rgb 1 }
// A plane with a bound: its box is the bound's, so it ends there.
plane { y, -1 pigment { checker color rgb 0.85 color rgb 0.45 }
  bounded_by { box { <-4, -2, -1>, <4, 0, 6> } } }
// Intersection bound by a small sphere off its centre.
intersection { sphere { <-2.2, 0.3, 0>, 1 } box { <-3.1, -0.6, -0.9>, <-1.3, 1.1, 0.9> }
  pigment { rgb <0.9, 0.5, 0.2> }
  bounded_by { sphere { <-2.5, 0.6, -0.5>, 0.6 } } }
// A sphere whose bound (removed) still clips it through its box.
sphere { <0, 0.3, 0>, 1 pigment { rgb <0.3, 0.6, 0.9> }
  bounded_by { box { <-1, -0.2, -1>, <0.4, 1.5, 1> } } }
// A cylinder (it tests its own box) with a lower bound.
cylinder { <2.2, -1, 0>, <2.2, 1.5, 0>, 0.7 pigment { rgb <0.4, 0.8, 0.4> }
  bounded_by { box { <1.4, -1, -1>, <3, 0.5, 1> } } }
// A union keeps its bound (not split); the difference's cutter has a bound that misses
// most rays: where it is skipped the sphere stays whole.
union {
  difference { sphere { <-1, 1.9, 1.5>, 0.7 }
               cylinder { <-1, 1.9, 0>, <-1, 1.9, 3>, 0.35 bounded_by { sphere { <-1.1, 2.1, 0.8>, 0.2 } } } }
  sphere { <0.4, 1.9, 1.5>, 0.6 }
  pigment { rgb <0.9, 0.3, 0.6> }
  bounded_by { box { <-2, 1.6, 0>, <0.6, 3, 3> } } }
// split_union off: linked whole, so the children keep their bounds.
union {
  sphere { <1.8, 2, 1.5>, 0.5 bounded_by { box { <1.2, 2, 0.9>, <2.4, 2.6, 2.1> } } }
  box { <2.5, 1.5, 1.2>, <3.1, 2.5, 1.8> }
  pigment { rgb <0.9, 0.9, 0.3> }
  split_union off }
// Clipped by its bound; and a bound made of the clip.
sphere { <-2.4, -0.55, -1.8>, 0.45 pigment { rgb <0.6, 0.3, 0.9> }
  bounded_by { box { <-3, -1, -1.8>, <-1.8, 0, -1.2> } }
  clipped_by { bounded_by } }
intersection { sphere { <2.2, -0.55, -1.8>, 0.45 } sphere { <2.4, -0.55, -1.8>, 0.45 }
  pigment { rgb <0.3, 0.9, 0.9> }
  clipped_by { plane { x, 2.3 } }
  bounded_by { clipped_by } }
