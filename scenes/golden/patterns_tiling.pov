// The tiling patterns povwall has (1 to 22), each on a panel with a colour map that
// shows the tile kinds and their centre-to-edge ramps; the rhombus tiling of
// textures/patterns/tiling.pov with its caulk; one as a normal.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 22, -10> look_at <0, 0, -6> angle 68 }
light_source { <-5, 20, -10> color rgb 1 }
background { rgb <0.1, 0.1, 0.2> }
#declare Kinds = colour_map { [0 rgb <0.9, 0.3, 0.2>] [0.3 rgb <1, 0.8, 0.6>]
  [0.3 rgb <0.2, 0.5, 0.9>] [0.65 rgb <0.7, 0.9, 1>] [0.65 rgb <0.3, 0.8, 0.3>] [1 rgb 0.1] }
#macro Panel(N, X, Z)
  box { <-1.9, -0.1, -1.9>, <1.9, 0, 1.9>
    pigment { tiling N colour_map { Kinds } scale 0.5 }
    finish { ambient 0.4 diffuse 0.6 } translate <X, 0, Z> }
#end
Panel(1, -6, 4) Panel(2, -2, 4) Panel(3, 2, 4) Panel(4, 6, 4)
Panel(5, -6, 0) Panel(6, -2, 0) Panel(7, 2, 0) Panel(8, 6, 0)
Panel(9, -6, -4) Panel(10, -2, -4)
Panel(11, -6, -8) Panel(12, -2, -8) Panel(13, 2, -8) Panel(14, 6, -8)
Panel(15, -6, -12) Panel(16, -2, -12) Panel(17, 2, -12) Panel(18, 6, -12)
Panel(19, -6, -16) Panel(20, -2, -16) Panel(21, 2, -16) Panel(22, 6, -16)
box { <-1.9, -0.1, -1.9>, <1.9, 0, 1.9>
  pigment { tiling 5 colour_map { [0 rgb <0.8, 0.2, 0.2>] [0.27 rgb <0.9, 0.5, 0.3>]
    [0.33 rgb 1] [0.33 rgb <0.2, 0.6, 0.3>] [0.6 rgb <0.5, 0.8, 0.4>] [0.67 rgb 1]
    [0.67 rgb <0.2, 0.3, 0.8>] [0.94 rgb <0.5, 0.6, 1>] [1 rgb 1] } scale 0.4 rotate y * 15 }
  translate <2, 0, -4> }
box { <-1.9, -0.1, -1.9>, <1.9, 0, 1.9> pigment { rgb 0.8 }
  normal { tiling 7 0.8 scale 0.6 } translate <6, 0, -4> }
