// inside() on the surfaces and at the clips where POV-Ray's inverse rules differ by shape:
// a plane and a quadric keep their surface inside both ways, a sphere in neither, a box,
// a torus and a cylinder flip; a disc is the half-space behind it; an inverted or
// subtracted part keeps its clips as they are.
#version 3.7;
#macro Show(Name, Obj, P)
  #debug concat(Name, " ", str(inside(Obj, P), 0, 0), "\n")
#end
#debug "BEGIN\n"
Show("plane on", plane { y, 1 }, <0, 1, 0>)
Show("plane above", plane { y, 1 }, <0, 1 + 1e-9, 0>)
Show("plane inverse on", plane { y, 1 inverse }, <0, 1, 0>)
Show("plane inverse below", plane { y, 1 inverse }, <0, 1 - 1e-9, 0>)
Show("sphere on", sphere { 0, 1 }, <1, 0, 0>)
Show("sphere inverse on", sphere { 0, 1 inverse }, <1, 0, 0>)
Show("box on", box { -1, 1 }, <1, 0, 0>)
Show("box inverse on", box { -1, 1 inverse }, <1, 0, 0>)
Show("quadric on", quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 }, <1, 0, 0>)
Show("quadric inverse on", quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 inverse }, <1, 0, 0>)
Show("torus on", torus { 2, 0.5 }, <2.5, 0, 0>)
Show("torus inverse on", torus { 2, 0.5 inverse }, <2.5, 0, 0>)
Show("cylinder on", cylinder { 0, y, 1 }, <1, 0.5, 0>)
Show("cylinder inverse on", cylinder { 0, y, 1 inverse }, <1, 0.5, 0>)
Show("disc behind", disc { 0, y, 1 }, <5, -0.1, 0>)
Show("disc on", disc { 0, y, 1 }, <0.5, 0, 0>)
Show("disc front", disc { 0, y, 1 }, <0, 0.1, 0>)
Show("disc inverse behind", disc { 0, y, 1 inverse }, <5, -0.1, 0>)
#declare Cut = difference { box { -1, 1 } sphere { 0, 0.5 clipped_by { plane { x, 0 } } } };
Show("difference in the clip, in the hole", Cut, <-0.1, 0, 0>)
Show("difference past the clip, in the hole", Cut, <0.1, 0, 0>)
Show("difference past the clip, in the box", Cut, <0.8, 0, 0>)
#declare Inv = union { sphere { 0, 1 clipped_by { plane { x, 0 } } } box { 2, 3 } inverse };
Show("inverse union past a clip", Inv, <0.5, 0, 0>)
Show("inverse union in a clipped part", Inv, <-0.5, 0, 0>)
Show("inverse union outside", Inv, <-5, 0, 0>)
Show("difference by a plane on it", difference { box { -1, 1 } plane { y, 0.5 } }, <0, 0.5, 0>)
Show("intersection with an inverse plane on it", intersection { box { -1, 1 } plane { y, 0.5 inverse } }, <0, 0.5, 0>)
Show("difference by a sphere on it", difference { box { -2, 2 } sphere { 0, 1 } }, <1, 0, 0>)
#debug "END\n"
