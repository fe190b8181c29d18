// The fractal patterns: julia (several exponents, colourings), mandel with exponents above
// 2 (and its grey default map), magnet 1 and 2 in both forms, on panels facing the
// camera (the fractals live in the x-y plane); one as a normal.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at 0 angle 60 }
light_source { <-5, 10, -20> color rgb 1 }
background { rgb <0.1, 0.1, 0.2> }
#declare Panel = box { <-1.4, -1.4, 0>, <1.4, 1.4, 0.1> }
#declare Warm = colour_map { [0 rgb <0.05, 0, 0.2>] [0.3 rgb <0.9, 0.3, 0.1>]
                             [0.6 rgb <1, 0.9, 0.2>] [1 rgb 1] }
object { Panel pigment { julia <-0.745, 0.113>, 60 colour_map { Warm } scale 1.3 }
         finish { ambient 1 diffuse 0 } translate <-4.5, 3, 0> }
object { Panel pigment { julia <0.353, 0.288>, 40 exponent 3 colour_map { Warm } }
         finish { ambient 1 diffuse 0 } translate <-1.5, 3, 0> }
object { Panel pigment { julia <-0.4, 0.4>, 30 exponent 6
                         exterior 7, 6 interior 1, 1 colour_map { Warm } }
         finish { ambient 1 diffuse 0 } translate <1.5, 3, 0> }
object { Panel pigment { mandel 40 exponent 3 translate <0.2, 0, 0> }
         finish { ambient 1 diffuse 0 } translate <4.5, 3, 0> }
object { Panel pigment { mandel 30 exponent 4 colour_map { Warm } }
         finish { ambient 1 diffuse 0 } translate <-4.5, 0, 0> }
object { Panel pigment { magnet 1 mandel 50 colour_map { Warm } scale 1.8
                         translate <1.2, 0, 0> }
         finish { ambient 1 diffuse 0 } translate <-1.5, 0, 0> }
object { Panel pigment { magnet 2 mandel 50 colour_map { Warm } scale 1.5 }
         finish { ambient 1 diffuse 0 } translate <1.5, 0, 0> }
object { Panel pigment { magnet 1 julia <0.5, 0.9>, 50 exterior 2, 0.3
                         interior 3, 1 colour_map { Warm } scale 2 }
         finish { ambient 1 diffuse 0 } translate <4.5, 0, 0> }
object { Panel pigment { magnet 2 julia <1.3, -0.6> 50 colour_map { Warm } scale 2 }
         finish { ambient 1 diffuse 0 } translate <-3, -3, 0> }
object { Panel pigment { rgb <0.8, 0.8, 0.9> }
         normal { julia <-0.745, 0.113>, 30 0.6 scale 1.3 }
         translate <0, -3, 0> }
object { Panel pigment { julia <0.285, 0.01>, 50 exponent 2 }
         finish { ambient 1 diffuse 0 } translate <3, -3, 0> }
