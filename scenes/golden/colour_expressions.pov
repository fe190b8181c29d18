// A colour written as any vector expression (POV-Ray 3.7's Parse_Colour takes CASE_VECTOR
// and promotes the vector to five terms): the built-in vectors x, y, z, u and v, vector and
// float functions, unary '+' and '!', wherever a colour is read on its own (WoodMath's
// mathback scene writes `emission y*2`).
#version 3.7;
global_settings { assumed_gamma 1 ambient_light y + 0.5 * x }
camera { location <0, 1, -6> look_at <0, 0.3, 0> }
background { z * 0.3 }
fog { distance 40 color x * 0.2 + z * 0.3 }
light_source { <-5, 6, -5> x + y }
light_source { <5, 4, -6> color vnormalize(<1, 1, 2>) * 0.6 }
plane { y, -1 pigment { color +y * 0.6 + 0.2 } finish { ambient color sqrt(0.01) } }
sphere { <-1.6, 0, 0>, 0.8 pigment { color y * 0.8 } finish { ambient z * 0.2 } }
sphere { <0, 0, 0>, 0.8 pigment { color u + 0.3 * v } finish { ambient !0 * 0.1 } }
box { -0.7, 0.7 hollow pigment { rgbt 1 }
  interior { media { emission y * 2 density { spherical scale 0.7 } } }
  rotate 30 * y translate <1.7, 0, 0> }
