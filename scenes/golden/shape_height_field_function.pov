// height_field { function W, H { ... } }: a float function (grid at x = j/(W-1), y =
// i/(H-1); function y = 0 lies at z = 1), values out of [0, 1] wrapping as POV-Ray's
// 16-bit store, and a pigment function (its grey weights).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 5, -5.5> look_at <0, 0, 0.2> angle 50 }
light_source { <-5, 10, -7> color rgb 1 }
light_source { <6, 5, -2> color rgb 0.35 }
#declare T = texture { pigment { rgb <0.85, 0.75, 0.55> } finish { specular 0.4 } }
height_field { function 30, 24 { 0.5 + 0.4 * sin(x * 9) * cos(y * 5) } texture { T }
               translate <-0.5, 0, -0.5> scale 2 translate <-1.3, 0, 1> }
height_field { function 20, 20 { y * 1.3 } smooth texture { T }
               translate <-0.5, 0, -0.5> scale 2 translate <1.3, 0, 1> }
height_field { function 25, 25 { pigment { bozo color_map { [0 rgb 0.1] [1 rgb <1, 0.6, 0.8>] } scale 0.3 } }
               texture { T } translate <-0.5, 0, -0.5> scale <2, 0.7, 2> translate <0, 0, -1.3> }
