// Cylinders as POV-Ray holds them (the unit cylinder in its frame, from the second point
// towards the first): coincident cylinders of different lengths tie pixel for pixel as in
// POV-Ray (the speckled pencil of a union), and a difference of coaxial cylinders with
// coincident caps cuts as POV-Ray's does.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <3, 14, -20> look_at <0, 3, 0> angle 40 }
light_source { <10, 30, -20> rgb 1 }
background { rgb 0.3 }
difference {
  cylinder { <0, 0, 0>, <0, 10, 0>, 5 }
  cylinder { <0, 0, 0>, <0, 10, 0>, 3 }
  cylinder { <0, 5, -10>, <0, 5, 10>, 2 }
  pigment { rgb <1, 0.8, 0.3> }
  rotate <10, 20, 5>
}
union {
  cylinder { <0, 0, 0>, <0, 6, 0>, 1 pigment { rgb <1, 0, 0> } }
  cylinder { <0, 0, 0>, <0, 7, 0>, 1 pigment { rgb <0, 0, 1> } }
  rotate <-20, 0, 30> translate <8, 0, 0>
}
