// POV-Ray keeps a sphere's centre and radius through translate, rotate and a uniform
// scale, and a matrix from the first other transform on (a scale with unequal
// components, a sign included, or a matrix); its box is then the turned cube's box,
// larger than the sphere's. An intersection's box is its parts' boxes' overlap, and a
// height field in an intersection is solid below its own box: the sphere's surface
// below the field is seen as far down as the intersection's box reaches, so the
// sphere's box decides how much of it shows. In front: mirrored in x and z and turned (a
// matrix kept); behind, left: the same sphere turned by 180 degrees about y instead (no
// matrix); right: an identity matrix then turned.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <-0.143, 1.242, -5.718> angle 41 look_at <0.006, 0.18, -0.08> }
light_source { <-3, 8, -6> rgb 1 }
light_source { <5, 3, -8> rgb 0.4 shadowless }
background { rgb <0.25, 0.3, 0.4> }
#declare Field = height_field { function 40, 20 { x * y } translate <-0.5, 0, -0.5> scale <2, 1, 2> }
#declare Paint = texture {
  pigment { checker rgb <0.9, 0.6, 0.2>, rgb <0.3, 0.4, 0.8> scale 0.25 }
  finish { phong 0.4 }
}
intersection {
  union { object { Field } }
  sphere { <0.165, 0.077, -0.266>, 0.798 scale <-1, 1, -1> rotate <47.503, -53.559, -65.149> }
  texture { Paint }
}
intersection {
  union { object { Field } }
  sphere { <0.165, 0.077, -0.266>, 0.798 rotate 180 * y rotate <47.503, -53.559, -65.149> }
  texture { Paint } translate <-1.6, 0.9, 4>
}
intersection {
  object { Field }
  sphere { <0.1, 0.1, -0.2>, 0.8 matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0> rotate <30, 20, 40> }
  texture { Paint } translate <1.7, 0.9, 4>
}
