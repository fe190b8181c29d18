// POV-Ray never tests a bicubic_patch's clipped_by (its intersection code has no clip
// test) but shrinks the patch's box by the clip's: rays that miss the clip's box miss the
// patch, and those that enter it see the whole patch, parts outside the clip included,
// unless a nearer hit stops POV-Ray's walk of its slab tree before that box.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -7> look_at <0, 0.3, 0> angle 45 }
light_source { <4, 9, -6> rgb 1 }
light_source { <-6, 5, -4> rgb 0.4 shadowless }
background { rgb <0.2, 0.25, 0.35> }
plane { y, -1 pigment { checker rgb 0.8 rgb <0.45, 0.5, 0.6> } }
#declare Patch = bicubic_patch { type 1 flatness 0.01 u_steps 4 v_steps 4
  <-1.5, 0, -1.5>, <-0.5, 0.8, -1.5>, <0.5, -0.4, -1.5>, <1.5, 0.3, -1.5>,
  <-1.5, 0.5, -0.5>, <-0.5, 1.6, -0.5>, <0.5, 0.9, -0.5>, <1.5, 0, -0.5>,
  <-1.5, -0.2, 0.5>, <-0.5, 0.7, 0.5>, <0.5, 1.8, 0.5>, <1.5, 0.6, 0.5>,
  <-1.5, 0.4, 1.5>, <-0.5, -0.1, 1.5>, <0.5, 0.6, 1.5>, <1.5, 0.2, 1.5>
}
// A clip box covering the right half: the box shrinks to it; the left half is seen only
// by rays that pass the clip's box.
object { Patch clipped_by { box { <0, -2, -2>, <2, 3, 2> } }
  pigment { rgb <0.9, 0.55, 0.2> } translate <-1.9, 0, 0> }
// Clipped by a sphere, with a small sphere in front of the clip's box.
object { Patch clipped_by { sphere { <0.5, 0.5, 0>, 0.9 } }
  pigment { rgb <0.3, 0.7, 0.9> } translate <1.9, 0, 0> }
sphere { <2.2, 1.2, -1.2>, 0.3 pigment { rgb <0.9, 0.9, 0.3> } }
// In a union and in a difference: the clip still only shrinks the box.
difference {
  object { Patch clipped_by { plane { x, 0.2 } } }
  cylinder { <0, -3, 0>, <0, 3, 0>, 0.4 }
  pigment { rgb <0.5, 0.9, 0.5> } scale 0.6 translate <0, -0.6, -1.6>
}
