// Glass game pieces on a board under radiosity, as CAD exporters write them (FreeCAD's
// chess example: each piece a union of tori, cones, cylinders and spheres, some of them
// differences; rad_def.inc's Radiosity_Fast). Shadow rays cross many see-through
// surfaces here, and POV-Ray restarts its search at each one.
#version 3.7;
#include "rad_def.inc"
global_settings {
  assumed_gamma 1
  radiosity { Rad_Settings(Radiosity_Fast, off, off) }
}
#default { finish { ambient 0 } }
camera { location <45, -25, 40> look_at <40, 20, 4> angle 40 sky z up z right -x * 4 / 3 }
light_source { <-40, -80, 150> colour rgb 0.9 }
light_source { <140, -20, 90> colour rgb 0.5 }
sky_sphere { pigment { gradient z colour_map { [0 rgb <0.6, 0.6, 0.7>] [1 rgb <0.2, 0.2, 0.4>] } } }
polygon { 5, <0, 0>, <80, 0>, <80, 80>, <0, 80>, <0, 0>
  pigment { checker rgb 0.9 rgb 0.15 scale 10 }
  finish { diffuse 0.8 reflection 0.1 }
}
#declare Glass = material {
  texture { pigment { rgbf <0.95, 0.97, 1, 0.9> } finish { specular 0.6 roughness 0.01 reflection 0.1 } }
  interior { ior 1.5 }
}
#declare Pawn = union {
  cylinder { 0, 3 * z, 6 }
  torus { 5, 1 rotate 90 * x translate 4 * z }
  cone { 3 * z, 5, 13 * z, 2.5 }
  torus { 3, 1 rotate 90 * x translate 13 * z }
  sphere { 0, 1 scale <4.5, 4.5, 1> translate 15 * z }
  sphere { 18.5 * z, 3.5 }
}
#declare Rook = union {
  cylinder { 0, 3 * z, 6.5 }
  torus { 5.5, 1 rotate 90 * x translate 4 * z }
  cone { 3 * z, 5.5, 17 * z, 4 }
  difference {
    cylinder { 17 * z, 23 * z, 5.5 }
    cylinder { 19 * z, 24 * z, 3.5 }
    box { <-6, -1, 20>, <6, 1, 24> }
    box { <-1, -6, 20>, <1, 6, 24> }
  }
}
#declare Piece = 0;
#while (Piece < 8)
  #declare X = mod(Piece, 8) * 10 + 5;
  #declare Y = 15 + mod(Piece, 2) * 10;
  object { #if (mod(Piece, 3) = 0) Rook #else Pawn #end
    scale 0.45 translate <X, Y, 0> material { Glass } }
  #declare Piece = Piece + 1;
#end
