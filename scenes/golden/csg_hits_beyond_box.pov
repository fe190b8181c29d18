// POV-Ray walks its bounding-slab tree nearest box first and stops at the first box the
// ray enters beyond the nearest hit found so far. An object whose surface reaches outside
// its box is then seen only when nothing nearer than its box's entry was found first: an
// intersection kept by a disc's half-space (its box is the disc's), a clip by a disc, an
// object bounded_by a box smaller than itself.
// Each sits in front of an object whose box is entered sooner, which hides its middle
// (opaque, see-through and in shadow rays).
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 8 }
camera { location <0, 2.5, -9> look_at <0, 0.3, 0> angle 50 }
light_source { <3, 9, -6> rgb 1 }
light_source { <-6, 4, -4> rgb 0.35 shadowless }
background { rgb <0.2, 0.25, 0.35> }
plane { y, -1.2 pigment { checker rgb 0.8 rgb <0.4, 0.5, 0.6> } }
#declare Half = intersection {
  box { <-0.9, -0.9, -0.9>, <0.9, 0.9, 0.9> }
  disc { <0, 0, 0>, z, 0.8 }
  pigment { rgb <0.9, 0.5, 0.2> }
}
// Opaque: an intersection in front of a sphere inside it.
object { Half translate <-2.6, 0.8, 0> }
sphere { <-2.6, 0.8, 0.3>, 0.5 pigment { rgb <0.2, 0.8, 0.3> } }
// See-through: the same with a glassy intersection.
intersection {
  box { <-0.9, -0.9, -0.9>, <0.9, 0.9, 0.9> }
  disc { <0, 0, 0>, z, 0.8 }
  pigment { rgbt <0.5, 0.6, 1, 0.7> }
  translate <0, 0.8, 0>
}
sphere { <0, 0.8, 0.3>, 0.5 pigment { rgb <0.9, 0.2, 0.3> } }
// A cylinder clipped by a disc: its box is the disc's.
cylinder { <0, 0, -0.9>, <0, 0, 0.9>, 0.9 clipped_by { disc { <0, 0, 0>, z, 0.8 } }
  pigment { rgb <0.3, 0.6, 0.9> } translate <2.6, 0.8, 0> }
sphere { <2.6, 0.8, 0.3>, 0.5 pigment { rgb <0.9, 0.9, 0.2> } }
// bounded_by a box smaller than the object, and a clip by a disc.
sphere { <-1.3, -0.4, -1.5>, 0.7 bounded_by { box { <-1.45, -0.55, -1.5>, <-1.15, -0.25, -1.4> } }
  pigment { rgb <0.8, 0.3, 0.8> } }
sphere { <-1.3, -0.4, -1.4>, 0.4 pigment { rgb 0.95 } }
sphere { <1.3, -0.4, -1.5>, 0.7 clipped_by { disc { <1.3, -0.4, -1.2>, z, 0.2 } }
  pigment { rgb <0.3, 0.9, 0.8> } }
sphere { <1.3, -0.4, -1.3>, 0.35 pigment { rgb <1, 0.6, 0.6> } }
