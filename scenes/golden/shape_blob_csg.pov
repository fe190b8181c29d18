// blob in CSG: a glass blob (all crossings along the ray, the inside test for the
// interior), a blob cut by a box and differenced by a sphere, and a clipped blob.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 8 }
camera { location <0, 4, -9> look_at <0, 0.3, 0> angle 50 }
light_source { <-4, 9, -6> color rgb 1 }
light_source { <5, 4, -3> color rgb 0.4 }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.5 scale 0.7 } }
#declare Glass = material { texture { pigment { rgbf <0.9, 1, 0.9, 0.85> }
                                      finish { specular 0.6 reflection 0.05 } }
                            interior { ior 1.45 } }
#declare B = blob {
  threshold 0.5
  sphere { <-0.6, 0, 0>, 1, 1 }
  sphere { <0.6, 0, 0>, 1, 1 }
  cylinder { <0, -0.6, 0>, <0, 0.8, 0>, 0.5, 0.8 }
}
merge { object { B } sphere { <0, 1, 0>, 0.4 } material { Glass } translate <-2.8, 0, 1> }
object { B material { Glass } rotate 30*y translate <0, 0, 2> }
intersection {
  object { B }
  box { -0.7, 0.7 rotate <20, 30, 0> }
  pigment { rgb <0.9, 0.4, 0.3> } translate <2.8, 0, 1>
}
difference {
  object { B scale 1.1 }
  sphere { <0.3, 0.4, -0.7>, 0.6 }
  pigment { rgb <0.3, 0.7, 0.9> } translate <-1.5, 0, -2>
}
object { B clipped_by { plane { z, 0.2 } } pigment { rgb <0.5, 0.9, 0.4> }
         rotate -30*y translate <1.8, 0, -2> }
