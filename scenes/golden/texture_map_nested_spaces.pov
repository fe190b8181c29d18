// Texture map entries are evaluated at the map pattern's point (POV-Ray nests pattern
// spaces): the outer pattern's transforms and warps, written before or after the map,
// move the entries' own patterns too; in a texture_map, a checker of textures, an
// average, maps of maps, an object transform on top, and a filtering shadow caster whose
// entries cast coloured shadows.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -8> look_at <0, 0.2, 0> angle 55 }
light_source { <-5, 9, -6> color rgb 1 }
#declare T_check = texture { pigment { checker rgb <0.9, 0.2, 0.1> rgb <0.1, 0.2, 0.9> scale 0.25 } }
#declare T_bumpy = texture { pigment { bozo color_map { [0 rgb <0.1, 0.6, 0.1>] [1 rgb <1, 1, 0.6>] } scale 0.2 }
                             normal { bumps 0.6 scale 0.1 } finish { phong 0.5 } }
plane { y, -1
  texture { checker texture { T_check } texture { pigment { gradient x color_map { [0 rgb 1] [1 rgb 0.3] } } } scale 1.5 } }
sphere { <-2.4, 0, 0>, 1
  texture { gradient y scale 0.5 turbulence 0.3 texture_map { [0.3 T_check] [0.7 T_bumpy] } } }
sphere { <0, 0, 0>, 1
  texture { spherical texture_map {
      [0.2 gradient x texture_map { [0 T_check] [1 T_bumpy] } scale 0.3 ]
      [0.6 T_bumpy] } scale 1.2 }
  rotate y * 30 }
sphere { <2.4, 0, 0>, 1
  texture { average texture_map { [1 T_check] [2 T_bumpy] } scale 2 rotate z * 20 } }
box { <-1, -1, -2.8>, <1, 0.1, -1.8>
  texture { gradient x scale 0.6 texture_map {
      [0 pigment { checker rgbf <1, 0.3, 0.3, 0.8> rgbf <0.3, 1, 0.3, 0.5> scale 0.2 }]
      [1 pigment { rgbf <0.3, 0.3, 1, 0.7> }] } }
  interior { ior 1.0 } }
