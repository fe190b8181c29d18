// Flags on nested CSG, on a declared CSG given at object { }, an inverse CSG (POV-Ray's
// inverse intersection is a merge), a clipped union whose children all have no_shadow
// (POV-Ray's union then has it) and double_illuminate on and off over a CSG tree.
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
// A merge inside a clipped union: the merge leaves its no_image sphere out.
union {
  merge { sphere { <-3.2, 0, 0>, 0.6 texture { Red } no_image }
          box { <-3.3, -1, -0.3>, <-2.4, 0.4, 0.4> texture { Blue } } }
  cylinder { <-3.6, -1, 0.8>, <-3.6, 1, 0.8>, 0.2 texture { Blue } }
  clipped_by { box { <-4.5, -2, -2>, <-2, 0.3, 2> } }
}
// A union inside an intersection: the union leaves its no_reflection sphere out of
// reflected rays.
intersection {
  union { sphere { <-1.6, 0, 0>, 0.6 texture { Red } no_reflection }
          box { <-1.7, -1, -0.3>, <-0.8, 0.4, 0.4> texture { Blue } } }
  sphere { <-1.4, -0.2, 0>, 1 texture { Blue } }
}
// Declared CSG with the flag given at object { }: a union (split, its children take
// no_shadow) and a merge (a top-level object: hidden from the camera).
#declare U = union { sphere { <0, 0, 0>, 0.6 texture { Red } }
                     box { <-0.1, -1, -0.3>, <0.8, 0.4, 0.4> texture { Blue } } }
object { U no_shadow }
#declare M = merge { sphere { <0, 0.2, 2.5>, 0.6 texture { Red } }
                     box { <-0.1, -1, 2.2>, <0.8, 0.4, 2.9> texture { Blue } } }
object { M no_image }
// An inverse intersection inside an intersection: POV-Ray's merge of the inverted
// children, which leaves the no_image sphere out of camera rays.
intersection {
  box { <1.0, -1, -0.5>, <2.2, 0.5, 0.5> texture { Blue } }
  intersection { sphere { <1.6, 0, -0.5>, 0.5 texture { Red } no_image }
                 box { <1.2, -1.2, -0.8>, <1.8, 0.2, -0.2> texture { Red } } inverse }
}
// A clipped union whose children all have no_shadow casts no shadow; the same with one
// child without it casts all its shadow.
union { sphere { <3.2, 0, 0>, 0.6 texture { Red } no_shadow }
        box { <3.1, -1, -0.3>, <4, 0.4, 0.4> texture { Blue } no_shadow }
        clipped_by { box { <2, -2, -2>, <5, 0.3, 2> } } }
union { sphere { <3.2, 0, 2.5>, 0.6 texture { Red } no_shadow }
        box { <3.1, -1, 2.2>, <4, 0.4, 2.9> texture { Blue } }
        clipped_by { box { <2, -2, 1>, <5, 0.3, 4> } } }
// Thin leaves lit from behind: double_illuminate on the union, off on the intersection
// over a leaf that has it, and on with `double_illuminate 1` on a leaf.
#declare Leaf = box { <0, 0, 0>, <0.8, 1.2, 0.02> pigment { rgb <0.9, 0.9, 0.4> } }
union { object { Leaf translate <-3.4, -0.9, 2.5> } object { Leaf translate <-2.5, -0.9, 2.5> }
        double_illuminate }
intersection { object { Leaf translate <-1.8, -0.9, 2.5> double_illuminate }
               box { <-2, -1, 2>, <-0.9, 1, 3> } double_illuminate off }
object { Leaf translate <1.4, -0.9, 2.5> double_illuminate 1 }
light_source { <0, 1.5, 6> color rgb 0.6 }
