// The block patterns square, triangular and cubic (their default colours, colour and
// pigment lists, as normals and as lists of textures), the old `tiles` checker of
// textures, and the cubic warp mapping a gradient and a checker around a sphere.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 7, -9> look_at <0, 0, 0.5> angle 60 }
light_source { <-6, 12, -9> color rgb 1 }
light_source { <7, 5, -4> color rgb 0.4 }
background { rgb <0.1, 0.1, 0.2> }
plane { y, -1
  texture { tiles { texture { pigment { rgb <0.8, 0.8, 0.7> } }
                    tile2 texture { pigment { rgb <0.3, 0.4, 0.5> } finish { phong 0.4 } } }
            scale 2 rotate y * 15 } }
box { <-4.5, -1, -0.5>, <-1.7, 0.2, 2.3> pigment { square scale 0.5 } }
box { <-1.4, -1, -0.5>, <1.4, 0.2, 2.3>
  pigment { triangular pigment { rgb <0.9, 0.2, 0.2> }, pigment { rgb <0.2, 0.9, 0.2> }
                       pigment { bozo scale 0.2 } pigment { rgb <0.9, 0.9, 0.2> }
            scale 0.6 } }
box { <1.7, -1, -0.5>, <4.5, 0.2, 2.3>
  texture { square texture { pigment { rgb <0.9, 0.5, 0.1> } }
                   texture { pigment { rgb 0.9 } normal { bumps 0.6 scale 0.1 } }
                   texture { pigment { rgb <0.2, 0.4, 0.9> } finish { phong 0.8 } }
            scale 0.7 translate <0.2, 0, 0.3> } }
sphere { <-3, 1, -2.5>, 1 pigment { cubic translate <0.1, 0.2, 0> } }
sphere { <-3, 2.5, 1.2>, 0.9
  pigment { triangular rgb <0.9, 0.2, 0.2>, rgb <0.2, 0.9, 0.2> rgb 0.5 scale 0.3 } }
sphere { <0, 1, -2.5>, 1
  pigment { cubic rgb 0.9, rgb <1, 0.5, 0.5> rgb <0.5, 1, 0.5>, rgb <0.5, 0.5, 1>
            rotate y * 30 }
  normal { triangular 0.6 scale 0.15 } }
sphere { <3, 1, -2.5>, 1
  pigment { gradient y colour_map { [0 rgb <0.2, 0.2, 0.6>] [1 rgb <1, 0.9, 0.3>] }
            frequency 3 warp { cubic } translate <3, 1, -2.5> } }
sphere { <3, 2.5, 1.2>, 0.9
  pigment { checker rgb 0.1, rgb 0.9 scale 0.08 warp { cubic } rotate <20, 30, 0> } }
