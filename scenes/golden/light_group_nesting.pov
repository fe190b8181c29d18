// light_group nesting, the other way round from light_group.pov: an outer group without
// the global lights holds an inner group that asks for them, and the outer group's
// setting wins (the inner box sees only its own yellow light). Also a group in a
// difference (the sphere cut out of it is outside the group), a group whose lights have
// no objects (they light nothing), a textured copy of a group, and an area light in a
// group shadowed by objects outside it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4.5, -8> look_at <0, 0.7, 0> angle 55 }
light_source { <-6, 9, -6> color rgb 0.8 }
light_source { <5, 7, -3> color rgb 0.4 spotlight point_at <0, 0, 0> radius 20 falloff 35 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.6 } }
light_group {
  light_source { <-4, 3, -4> color rgb <0.3, 0.4, 1> }
  sphere { <-3, 0.7, 0>, 0.7 pigment { rgb 1 } }
  light_group {
    light_source { <-1, 4, -3> color rgb <1, 0.9, 0.3> }
    box { <-2, 0, 1>, <-1, 1.6, 2> pigment { rgb 1 } }
    global_lights on
  }
}
difference {
  light_group {
    light_source { <3, 2, -4> color rgb <1, 0.3, 0.3> }
    box { <0, 0, -1>, <1.6, 1.2, 0.6> pigment { rgb 1 } }
  }
  sphere { <0.8, 1.2, -1>, 0.6 pigment { rgb <0.6, 1, 0.6> } }
}
light_group { light_source { <0, 3, -3> color rgb 5 } }
#declare Pair = light_group {
  light_source { <0, 2, -2> color rgb <0.9, 0.5, 1> }
  cylinder { 0, y * 0.8, 0.3 }
  global_lights on
}
object { Pair pigment { rgb <1, 0.8, 0.6> } translate <2.8, 0, 1.4> }
// An area light (no jitter) lighting a disc only; the post outside the group shadows it.
light_group {
  light_source { <1.5, 4, 4> color rgb 0.8 area_light x * 1.5, z * 1.5, 4, 4 adaptive 1 }
  disc { <1.5, 0.01, 2.5>, y, 1.3 pigment { rgb 1 } }
}
cylinder { <1.3, 0, 2.9>, <1.3, 1.5, 2.9>, 0.12 pigment { rgb <0.3, 0.3, 0.3> } }
