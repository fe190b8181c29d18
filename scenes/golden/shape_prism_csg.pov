// prism in every kind of CSG, as glass, clipped, inverse, and with sturm: its inside
// test (even-odd, the top plane outside) and all its crossings along a ray.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 8 }
camera { location <0, 5, -8> look_at <0, 0.3, 0.5> angle 50 }
light_source { <-4, 9, -6> color rgb 1 }
light_source { <5, 4, -4> color rgb 0.4 }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.5 scale 0.7 } }
#declare Hexa = prism { linear_spline -0.8, 0.8, 7,
  <1, 0>, <0.5, 0.87>, <-0.5, 0.87>, <-1, 0>, <-0.5, -0.87>, <0.5, -0.87>, <1, 0> }
#declare Blob = prism { cubic_spline -0.7, 0.7, 8,
  <0, -1>, <1, 0>, <0, 1.1>, <-1, 0>, <0, -1>, <1, 0>, <0, 1.1>, <-1, 0> sturm }
#declare Glass = material { texture { pigment { rgbf <0.95, 1, 0.95, 0.85> }
                                      finish { specular 0.6 reflection 0.05 } }
                            interior { ior 1.4 } }
intersection { object { Hexa } sphere { 0, 0.95 }
  pigment { rgb <0.9, 0.4, 0.3> } rotate <-20, 30, 0> translate <-2.8, 0, 1.6> }
difference { object { Blob } cylinder { <0, -1, 0>, <0, 1, 0>, 0.45 } sphere { <0.6, 0.7, -0.5>, 0.5 }
  pigment { rgb <0.3, 0.7, 0.9> } translate <0, 0, 1.6> }
merge { object { Hexa scale <0.8, 1, 0.8> } sphere { <0, 0.8, 0>, 0.6 }
  material { Glass } translate <2.8, 0, 1.6> }
union { prism { conic_sweep linear_spline 0.25, 1, 5, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1> }
  sphere { <0, 1.1, 0>, 0.3 }
  clipped_by { plane { x, 0.3 } } rotate 180*x translate <-2.8, 0.6, -1.4>
  pigment { rgb <0.5, 0.9, 0.4> } }
object { Blob material { Glass } scale 0.8 translate <0, 0, -1.6> }
intersection { box { -1, 1 } object { Hexa inverse } scale <1, 0.4, 1>
  pigment { rgb <0.9, 0.8, 0.3> } rotate 20*y translate <2.8, 0, -1.6> }
