// pavement: polyominoes, polyiamonds and polyhexes with each look of their corners
// (exterior, interior, form), the bare default (triangles), one as a normal and one
// choosing between textures.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 22, -13> look_at <0, 0, -2.2> angle 47 }
light_source { <-5, 20, -10> color rgb 1 }
background { rgb <0.1, 0.1, 0.2> }
#declare Grout = colour_map { [0 rgb <0.8, 0.45, 0.3>] [0.55 rgb <0.95, 0.75, 0.55>]
  [0.8 rgb <0.35, 0.3, 0.3>] [1 rgb 0.1] }
#macro Panel(S, T, P, E, I, F, X, Z)
  box { <-1.9, -0.1, -1.9>, <1.9, 0, 1.9>
    pigment { pavement number_of_sides S number_of_tiles T pattern P
      exterior E interior I form F colour_map { Grout } scale 0.45 }
    finish { ambient 0.4 diffuse 0.6 } translate <X, 0, Z> }
#end
Panel(4, 6, 5, 0, 0, 0, -6, 4) Panel(4, 5, 3, 2, 1, 2, -2, 4)
Panel(4, 4, 2, 1, 2, 1, 2, 4) Panel(4, 6, 31, 0, 1, 3, 6, 4)
Panel(3, 6, 5, 0, 0, 0, -6, 0) Panel(3, 4, 2, 2, 2, 2, -2, 0)
Panel(3, 6, 12, 1, 1, 1, 2, 0)
Panel(6, 5, 2, 0, 0, 0, -6, -4) Panel(6, 3, 2, 0, 2, 2, -2, -4)
box { <-1.9, -0.1, -1.9>, <1.9, 0, 1.9>
  pigment { pavement colour_map { Grout } scale 0.45 } translate <6, 0, 0> }
box { <-1.9, -0.1, -1.9>, <1.9, 0, 1.9>
  pigment { pavement number_of_sides 6 number_of_tiles 4 pattern 6 interior 1 form 1
    colour_map { Grout } scale 0.4 rotate y * 20 }
  translate <2, 0, -4> }
box { <-1.9, -0.1, -1.9>, <1.9, 0, 1.9> pigment { rgb 0.8 }
  normal { pavement 0.7 number_of_sides 6 number_of_tiles 2 interior 2 scale 0.5 }
  translate <6, 0, -4> }
box { <-5.9, -0.1, -1.9>, <5.9, 0, 1.9>
  texture { pavement number_of_sides 4 number_of_tiles 3 pattern 2 form 2 scale 0.7
    texture_map { [0.3 pigment { rgb <0.3, 0.5, 0.8> } finish { phong 0.6 }]
                  [0.7 pigment { granite scale 0.5 colour_map { [0 rgb 1] [1 rgb 0.4] } }] } }
  translate <0, 0, -8> }
