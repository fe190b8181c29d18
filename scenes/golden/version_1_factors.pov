// Before #version 1.5 POV-Ray reads a float or a vector's component as one factor (a
// number with its signs, an identifier, a call, a parenthesised expression): the 3.6
// distribution's piece3 and ionic5 write vectors with their components separated by spaces
// only, `<-6.6 -0.0 -2.1>`, three components there (one sum in later versions).
#version 1.0
#declare Half = 0.5
camera { location <0 2 -6> look_at <0 0.3 0> }
light_source { <-5 10 -8> color red 1 green 1 blue 1 }
sphere { <-1.2 -0.0 -0.5> 1 pigment { color red 1 green 0.4 blue 0.2 } }
box { <0.4 -1 -0.5> <1.6 (-1 + 2) Half> rotate <0 -30 0> pigment { color red 0.2 green 0.5 blue 1 } }
cylinder { <-2.5 -1 1.5> <-2.5 1.5 1.5> -Half pigment { color red Half green 1 blue Half } }
plane { <0 1 0> -1 pigment { checker color red 1 green 1 blue 1 color red 0.2 green 0.2 blue 0.2 } }
