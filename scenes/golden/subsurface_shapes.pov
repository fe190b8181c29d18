// golden-args: --block-mean 8
// Subsurface on shapes and CSG kinds together: a merge, an intersection, a difference, a torus,
// a mesh (a surface without inside: its samples see only its own triangles), a superellipsoid,
// a see-through (filter) subsurface sphere and a clipped one (its open cut shows the inside),
// under a 3x3 area light and a parallel light.
#version 3.7;
global_settings { assumed_gamma 1.0 mm_per_unit 8 subsurface { samples 24, 6 } }
camera { location <0, 2.6, -5.2> look_at <0, 0.5, 0> angle 50 }
light_source { <-3, 6, -4> color rgb 0.9 area_light x * 1.5, z * 1.5, 3, 3 adaptive 0 }
light_source { <2, 3, 3> color rgb 0.5 parallel point_at 0 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.5 scale 0.5 } }
#declare Wax = finish { diffuse 0.8 specular 0.3 ambient 0 subsurface { translucency <2.5, 1.2, 0.6> } }
merge {
  sphere { <-2.1, 0.5, 0>, 0.5 } sphere { <-1.7, 0.7, 0.2>, 0.45 }
  pigment { rgb <0.9, 0.7, 0.5> } finish { Wax } interior { ior 1.4 }
}
intersection {
  box { <-1.1, 0, -0.4>, <-0.3, 0.9, 0.4> } sphere { <-0.7, 0.45, 0>, 0.55 }
  pigment { rgb <0.5, 0.8, 0.9> } finish { Wax } interior { ior 1.3 }
}
difference {
  box { <0, 0, -0.4>, <0.8, 0.8, 0.4> } cylinder { <0.4, 0.4, -1>, <0.4, 0.4, 1>, 0.25 }
  pigment { rgb <0.8, 0.8, 0.6> } finish { Wax } interior { ior 1.5 }
}
torus { 0.45, 0.18 rotate x * 90 translate <1.5, 0.63, 0> pigment { rgb <0.9, 0.5, 0.5> } finish { Wax } }
mesh {
  triangle { <2.2, 0, -0.3>, <2.8, 0, -0.3>, <2.5, 0.9, 0> }
  triangle { <2.2, 0, -0.3>, <2.5, 0, 0.4>, <2.5, 0.9, 0> }
  triangle { <2.8, 0, -0.3>, <2.5, 0, 0.4>, <2.5, 0.9, 0> }
  pigment { rgb <0.7, 0.9, 0.6> } finish { Wax }
}
superellipsoid { <0.4, 0.4> scale 0.35 translate <-1.2, 0.35, -1.2> pigment { rgb <0.95, 0.9, 0.8> } finish { Wax } }
sphere { <0.9, 0.35, -1.3>, 0.35 pigment { rgbf <0.6, 0.9, 0.7, 0.5> } finish { Wax } interior { ior 1.2 } }
sphere { <2.0, 0.4, -1.3>, 0.4 clipped_by { plane { <-1, 1, -1>, 0.1 translate <2.0, 0.4, -1.3> } } pigment { rgb <0.9, 0.85, 0.5> } finish { Wax } interior { ior 1.3 } }
