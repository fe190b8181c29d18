// A box keeps no matrix while it is only moved and scaled: POV-Ray moves and scales its
// corners (Box::Translate, Box::Scale; a negative scale swaps them) until its first
// rotate, matrix or transform. So boxes made coincident by scaling share exact faces (a
// difference of a box and its slightly larger copy keeps the floor and walls), and the
// uv_mapping of a box mirrored on two axes and then turned is that of the unmirrored box.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> look_at <0, 0.5, 0> angle 50 }
light_source { <-4, 9, -6> color rgb 1 }
light_source { <6, 4, -3> color rgb 0.3 }
#declare R = box { <0, 0, 0>, <2, 1.2, 2> }
difference {
  object { R scale 1.001 }
  object { R }
  pigment { rgb <0.9, 0.7, 0.5> }
  translate <-3.2, 0, -1>
}
difference {
  box { <0, 0, 0>, <1, 1, 1> scale <2, 1.2, 2> translate <0, 0, 0> }
  box { <0, 0, 0>, <2, 1.2, 2> translate <0, 0.3, 0> }
  pigment { rgb <0.5, 0.8, 0.6> }
  translate <-0.6, 0, -1>
}
box { <-0.5, -0.5, -0.5>, <0.5, 0.5, 0.5>
  texture { uv_mapping pigment { checker color rgb <1, 0.2, 0.2> color rgb <0.2, 0.2, 1> scale 0.125 } }
  scale <1, -1, -1> rotate <20, 30, 0> translate <2.5, 0.8, 0> }
box { <-0.5, -0.5, -0.5>, <0.5, 0.5, 0.5>
  texture { uv_mapping pigment { gradient x color_map { [0 rgb <1, 1, 0>] [1 rgb <0, 0.6, 1>] } } }
  rotate <0, 25, 10> scale <-1, 1, 1> translate <2.5, 0.8, -2.2> }
box { <0.5, 0, 0.5>, <-0.5, 0.6, -0.5>
  texture { uv_mapping pigment { radial frequency 8 color_map { [0.5 rgb 0.2] [0.5 rgb 0.9] } } }
  scale <-1.2, 1, 1> translate <0.5, 0, -2.8> }
plane { y, 0 pigment { rgb 0.6 } }
