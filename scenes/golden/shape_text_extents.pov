// Text placed by its extents, as shapes.inc does: Circle_Text (Text_Width, max_extent),
// a word centred by min_extent/max_extent after rotations (POV-Ray's box grows with each
// one), and letters centred on blocks as the stacker examples do.
#version 3.7;
#include "shapes.inc"
global_settings { assumed_gamma 1 }
camera { location <0, 4, -9> look_at <0, 0.4, 0> angle 50 }
light_source { <-4, 9, -6> color rgb 1 }
light_source { <5, 4, -3> color rgb 0.4 }
plane { y, -1.2 pigment { checker rgb 0.9 rgb 0.6 } }
object { Circle_Text("cyrvetic.ttf", "Around the circle", 0.5, 0.02, 0.1, 1.6, 0,
                     Align_Center, 90)
         pigment { rgb <0.9, 0.4, 0.2> } rotate -20*x translate <-2.2, 0.8, 0> }
#declare Word = text { ttf "timrom.ttf" "Centred" 0.3, 0 rotate <0, 30, 10> }
#declare C = (min_extent(Word) + max_extent(Word)) / 2;
object { Word translate -C pigment { rgb <0.2, 0.6, 0.9> } translate <2.2, 1, 0> }
#macro Block(L, X)
  #local T = text { ttf "crystal.ttf" L 0.2, 0 }
  #local M = (min_extent(T) + max_extent(T)) / 2;
  box { <-0.45, -1.2, -0.05>, <0.45, -0.3, 0.8> pigment { rgb 0.8 } translate X*x }
  object { T translate -M scale 0.9 translate <X, -0.75, -0.05> pigment { rgb <0.3, 0.8, 0.3> } }
#end
Block("P", -1.5) Block("O", -0.5) Block("V", 0.5) Block("g", 1.5)
