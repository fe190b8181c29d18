// CSG made of planes alone has a finite surface: a twisted column of 300 hexagonal slices
// (each an intersection of eight planes with a bounded_by, as codavex/povray's
// twisted_column.inc), a gem of planes without a bounded_by, a slab cut from a difference
// of planes and clipped by planes, and an inverted plane closing a prism. Their bounds come
// from the planes (trace/convex_region.h): the surfaces must all still be met, to their
// edges, in direct view, reflection, refraction and shadow.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 6 }
camera { location <0, 3.2, -5.5> look_at <0, 0.7, 0> angle 45 }
light_source { <4, 9, -6> rgb 1 }
light_source { <-6, 5, -3> rgb 0.3 }
background { rgb <0.2, 0.25, 0.35> }
plane { y, 0 pigment { checker rgb 0.8 rgb <0.4, 0.5, 0.6> } finish { reflection 0.15 } }
#declare Hexagon = intersection {
  plane { x, 1 }
  plane { x, 1 rotate <0, 60, 0> }
  plane { x, 1 rotate <0, 120, 0> }
  plane { x, 1 rotate <0, 180, 0> }
  plane { x, 1 rotate <0, 240, 0> }
  plane { x, 1 rotate <0, 300, 0> }
  plane { y, 1 }
  plane { -y, 0 }
  bounded_by { sphere { 0, 1.5 } }
}
#declare I = 0;
union {
  #while (I < 300)
    object { Hexagon scale <0.3, 1.6 / 300, 0.3> rotate y * I * 0.6 translate y * I * 1.6 / 300 }
    #declare I = I + 1;
  #end
  pigment { rgb <0.8, 0.6, 0.4> }
  finish { specular 0.4 }
  translate <-1.2, 0, 0.3>
}
// A gem: eight slanted planes, no bounded_by, glass.
intersection {
  #declare K = 0;
  #while (K < 4)
    plane { <1, 0.8, 0>, 0.5 rotate y * (45 + 90 * K) }
    plane { <1, -1.2, 0>, 0.5 rotate y * (90 * K) }
    #declare K = K + 1;
  #end
  pigment { rgbf <0.6, 0.9, 1, 0.8> }
  finish { reflection 0.1 specular 0.6 }
  interior { ior 1.5 }
  scale 0.55
  rotate <15, 20, 0>
  translate <0.1, 0.75, -0.2>
}
// A slab between two planes (a difference), clipped by four planes to a square.
difference {
  plane { y, 0.25 }
  plane { y, 0.05 }
  clipped_by {
    plane { x, 0.5 } plane { -x, 0.5 } plane { z, 0.5 } plane { -z, 0.5 }
  }
  pigment { rgb <0.3, 0.7, 0.4> }
  rotate y * 30
  translate <0.9, 0, 1.3>
}
// A triangular prism closed by an inverted plane.
intersection {
  plane { x, 0.3 rotate y * 0 }
  plane { x, 0.3 rotate y * 120 }
  plane { x, 0.3 rotate y * 240 }
  plane { y, 0.9 }
  plane { y, 0.1 inverse }
  pigment { rgb <0.8, 0.3, 0.5> }
  translate <1.5, 0, -0.6>
}
