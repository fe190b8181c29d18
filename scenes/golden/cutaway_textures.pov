// cutaway_textures: a textured sphere cut by an untextured box shows its own pattern on
// the cut (left); the same difference without the keyword shows the default texture on
// the cut (right); an intersection whose untextured cylinder lies in one or both spheres
// of a textured union shows that sphere's texture, or both averaged (middle).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.2, -7> look_at <0, 0.6, 0> angle 52 }
light_source { <-4, 8, -6> color rgb 1 }
light_source { <5, 4, -5> color rgb 0.4 }
plane { y, -0.6 pigment { color rgb 0.8 } }
#declare Marble = texture {
  pigment { gradient x color_map { [0 rgb <1, 0.5, 0.1>] [0.5 rgb <1, 1, 0.3>] [1 rgb <1, 0.5, 0.1>] } scale 0.4 }
  finish { phong 0.5 }
}
difference {
  sphere { 0, 1 texture { Marble } }
  box { <-1.2, 0.1, -1.2>, <0, 1.2, 0> }
  cutaway_textures
  rotate y*-20 translate <-2.4, 0.4, 0>
}
intersection {
  union {
    sphere { <-0.35, 0, 0>, 0.8 pigment { color rgb <0.1, 0.4, 1> } }
    sphere { <0.35, 0, 0>, 0.8 pigment { checker color rgb <1, 0.2, 0.2> color rgb 1 scale 0.25 } }
  }
  cylinder { <0, -2, 0>, <0, 2, 0>, 0.75 }
  cutaway_textures
  rotate x*-30 translate <0, 0.5, 0>
}
difference {
  sphere { 0, 1 texture { Marble } }
  box { <-1.2, 0.1, -1.2>, <0, 1.2, 0> }
  rotate y*-20 translate <2.4, 0.4, 0>
}
