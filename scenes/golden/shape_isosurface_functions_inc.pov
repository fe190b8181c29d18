// Isosurfaces of functions.inc's geometric internal functions: f_torus, f_superellipsoid,
// f_helix2, f_spiral, f_heart (a clamped algebraic field), f_strophoid_2d revolved (a 2d
// curve with its SOR switch), f_mesh1 and f_rounded_box.
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1 }
camera { location <0, 6, -11> look_at <0, 0, 0.6> angle 52 }
light_source { <-6, 12, -9> color rgb 1 }
light_source { <7, 6, -5> color rgb 0.35 }
plane { y, -1.2 pigment { checker rgb 0.85 rgb 0.55 } }
#declare Row = 1.3;
isosurface {
  function { f_torus(x, y, z, 0.8, 0.25) }
  contained_by { box { -1.1, 1.1 } }
  pigment { rgb <0.9, 0.4, 0.3> }
  rotate -30 * x translate <-3, 0, Row>
}
isosurface {
  function { -f_superellipsoid(x, y, z, 0.3, 0.7) }
  contained_by { box { -1, 1 } }
  threshold 0 max_gradient 6
  pigment { rgb <0.3, 0.6, 0.9> }
  scale 0.8 rotate <20, 30, 0> translate <-1, 0, Row>
}
isosurface {
  function { f_helix2(x, y, z, 0, 4, 0.15, 0.45, 0, 1, 0) }
  contained_by { box { <-0.8, -1, -0.8>, <0.8, 1, 0.8> } }
  max_gradient 3
  pigment { rgb <0.4, 0.85, 0.4> }
  translate <1, 0, Row>
}
isosurface {
  function { f_spiral(x, y, z, 0.3, 0.1, 1, 0, 0, 2) }
  contained_by { box { -1, 1 } }
  max_gradient 3
  pigment { rgb <0.9, 0.8, 0.3> }
  rotate -50 * x translate <3, 0, Row>
}
isosurface {
  function { -f_heart(x, y, z, 0.25) }
  contained_by { box { -1.25, 1.25 } }
  max_gradient 30
  pigment { rgb <0.9, 0.2, 0.4> }
  rotate -90 * x scale 0.75 translate <-3, 0, -1.5>
}
isosurface {
  function { f_strophoid_2d(x, y, z, 1, 0.7, 0.1, 1.3, 1, 0.2, 0) }
  contained_by { box { -1, 1 } }
  max_gradient 10
  pigment { rgb <0.7, 0.5, 0.9> }
  translate <-1, 0, -1.5>
}
isosurface {
  function { f_mesh1(x, y, z, 0.3, 0.3, 1, 0.08, 1) - 0.06 }
  contained_by { box { <-0.9, -0.3, -0.9>, <0.9, 0.3, 0.9> } }
  max_gradient 3
  pigment { rgb <0.9, 0.6, 0.2> }
  rotate 20 * y translate <1, -0.5, -1.5>
}
isosurface {
  function { f_rounded_box(x, y, z, 0.2, 0.7, 0.4, 0.6) }
  contained_by { box { -1, 1 } }
  pigment { rgb <0.5, 0.8, 0.8> }
  rotate 35 * y translate <3, -0.5, -1.5>
}
