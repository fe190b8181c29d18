// isosurface options: open (no container surface), all_intersections and max_trace in
// a glass object (later crossings along the ray), max_trace 2 in CSG, and an inverse
// isosurface in an intersection.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 8 }
camera { location <0, 4, -9> look_at <0, 0.3, 0> angle 52 }
light_source { <-4, 9, -6> color rgb 1 }
light_source { <5, 4, -3> color rgb 0.4 }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.5 scale 0.7 } }
#declare Glass = material { texture { pigment { rgbf <0.9, 1, 0.9, 0.85> }
                                      finish { specular 0.6 reflection 0.05 } }
                            interior { ior 1.45 } }
// An open container: the sphere shows its inside where the box cuts it.
isosurface {
  function { x*x + y*y + z*z - 1.3 }
  open
  max_gradient 2.5
  pigment { rgb <0.9, 0.4, 0.3> }
  rotate <20, 30, 0> translate <-2.7, 0, 1.2>
}
// Glass with all_intersections.
isosurface {
  function { sqrt(x*x + z*z) - 0.5 - 0.15*sin(6*y) }
  contained_by { box { <-1, -0.9, -1>, <1, 0.9, 1> } }
  all_intersections
  max_gradient 1.5
  material { Glass }
  translate <0, 0, 1.6>
}
// max_trace 2 in CSG.
intersection {
  isosurface {
    function { abs(x) + abs(y) + abs(z) - 1.1 }
    max_trace 2
    max_gradient 1.8
  }
  sphere { 0, 0.95 }
  pigment { rgb <0.3, 0.7, 0.9> }
  rotate <0, 30, 20> translate <2.6, 0, 0.8>
}
// A wavy sheet whose max_gradient is just enough.
isosurface {
  function { y - 0.25*sin(9*x) }
  contained_by { box { <-1, -0.5, -0.6>, <1, 0.5, 0.6> } }
  max_gradient 2.5
  pigment { rgb <0.5, 0.9, 0.4> }
  translate <-1.6, -0.3, -2.2>
}
// Inverse, in an intersection with a box: the hollow.
intersection {
  box { <-0.8, -0.8, -0.8>, <0.8, 0.6, 0.8> }
  isosurface { function { x*x + y*y + z*z - 0.5 } max_gradient 2 inverse }
  pigment { rgb <0.9, 0.8, 0.3> }
  rotate 25*y translate <1.5, -0.1, -2.3>
}
