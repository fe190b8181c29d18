// golden-args: --block-mean 8
// Subsurface in CSG: a difference of a union whose children share the CSG's interior (one
// subsurface object) and a child with its own interior (another one); float translucency; a
// layered texture with a subsurface base under a see-through stripe layer.
#version 3.7;
global_settings {
  assumed_gamma 1.0
  mm_per_unit 10
  subsurface { samples 30, 6 }
}
camera { location <0, 1.6, -4> look_at <0, 0.5, 0> angle 45 }
light_source { <-4, 6, -3> color rgb 1 }
light_source { <3, 2, 3> color rgb 0.5 }
plane { y, 0 pigment { color rgb 0.6 } }
difference {
  union {
    box { <-0.6, 0, -0.6>, <0.6, 1.0, 0.6> }
    sphere { <0, 1.0, 0>, 0.5 }
    sphere { <0.55, 0.5, -0.55>, 0.25 interior { ior 1.6 } }   // own interior: a different SSLT object
  }
  cylinder { <0, 0.5, -1>, <0, 0.5, 1>, 0.3 }
  pigment { color rgb <0.5, 0.8, 0.6> }
  finish { diffuse 0.9 ambient 0 subsurface { translucency 0.8 } }
  interior { ior 1.4 }
  rotate y*30
  translate x*-0.6
}
// layered texture: SSS base layer plus a partly transparent stripe layer (no SSS)
sphere { <1.1, 0.45, -0.2>, 0.45
  texture { pigment { color rgb <1, 0.9, 0.8> } finish { diffuse 0.7 ambient 0 subsurface { translucency <2, 1, 0.5> } } }
  texture { pigment { gradient y color_map { [0.5 rgbt <0.2,0.2,0.8,0>] [0.5 rgbt 1] } scale 0.2 } finish { diffuse 0.6 ambient 0 } }
  interior { ior 1.2 }
}
