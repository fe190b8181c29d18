// golden-args: --block-mean 8
// Subsurface with `radiosity { subsurface on }`: radiosity sample rays evaluate the subsurface
// light of the slab they meet. The spotlight lights only the slab; the room and the ball see its
// orange light (off, radiosity rays would see the slab without diffuse: the room stays dark).
#version 3.7;
global_settings {
  assumed_gamma 1.0
  mm_per_unit 10
  subsurface { samples 30, 5 }
  radiosity { pretrace_start 0.08 pretrace_end 0.04 count 35 recursion_limit 1 nearest_count 5 error_bound 1.5 subsurface on }
}
camera { location <0.6, 1.2, -1.9> look_at <0.6, 0.5, 0> angle 60 }
light_source { <-0.85, 2.5, -1.5> color rgb 5 spotlight point_at <-0.85, 0.8, 0.1> radius 12 falloff 14 }
box { <-2, -0.001, -2>, <2, 3, 3> hollow pigment { color rgb 0.9 } finish { diffuse 0.8 ambient 0 } }
box { <-1.4, 0, -0.6>, <-0.3, 1.6, 0.8>
  pigment { color rgb <1, 0.5, 0.1> }
  finish { diffuse 0.9 ambient 0 subsurface { translucency 1.0 } }
  interior { ior 1.3 }
}
sphere { <0.5, 0.4, -0.1>, 0.4 pigment { color rgb 1 } finish { diffuse 0.8 ambient 0 } }
