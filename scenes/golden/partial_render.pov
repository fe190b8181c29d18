// golden-args: +SR0.25 +ER0.75 +SC41 +EC120
// Partial render: rows from a quarter to three quarters of the height (fractions), columns
// 41..120 (numbers); the rest of the image stays black in both renderers.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.8, 0> angle 50 }
light_source { <-3, 6, -5> color rgb 1 }
background { color rgb <0.3, 0.5, 0.8> }
plane { y, 0 pigment { color rgb <0.8, 0.7, 0.5> } }
sphere { <0, 1, 0>, 1 pigment { color rgb <0.9, 0.2, 0.3> } finish { phong 0.6 reflection 0.2 } }
