// blob: cylinder components (body and hemispherical ends) along and across the axes,
// mixed with spheres, component transforms (a sphere made an ellipsoid by a non-uniform
// scale, a rotated cylinder, a matrix), and hierarchy off.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 5, -10> look_at <0, 0.4, 0> angle 48 }
light_source { <-5, 10, -8> color rgb 1 }
light_source { <6, 5, -4> color rgb 0.4 }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.5 scale 0.8 } }
blob {
  threshold 0.5
  cylinder { <-1, 0, 0>, <1, 0, 0>, 0.6, 1 }
  cylinder { <0, 0, -1>, <0, 0, 1>, 0.6, 1 }
  cylinder { <0, -0.5, 0>, <0, 1.2, 0>, 0.5, strength 1 }
  sphere { <0, 1.3, 0>, 0.7, 1 }
  pigment { rgb <0.9, 0.4, 0.3> }
  finish { specular 0.4 }
  translate <-2.6, 0, 1>
}
blob {
  threshold 0.4
  cylinder { <-0.8, 0.2, -0.3>, <0.9, 0.9, 0.4>, 0.5, 1.2 }
  sphere { <0, 0, 0>, 0.8, 1 scale <1.8, 0.6, 1> }
  sphere { <0.3, 1.1, 0>, 0.5, 1 rotate 30*z translate 0.2*x }
  cylinder { <0, 0, 0>, <0, 1, 0>, 0.4, 1 rotate <0, 0, -50> translate <0.6, -0.3, -0.4> }
  hierarchy off
  pigment { rgb <0.3, 0.7, 0.9> }
  rotate 15*y translate <0.4, 0, 1.6>
}
blob {
  threshold 0.6
  sphere { <0, 0, 0>, 1, 1 matrix <1, 0.3, 0, 0, 1, 0, 0.2, 0, 1, 0, 0, 0> }
  sphere { <0.8, 0.4, 0>, 0.8, 1 transform { scale <1, 1.5, 1> } }
  cylinder { <0, 0, 0>, <0.01, 0.01, 1.5>, 0.45, 1 }
  pigment { rgb <0.5, 0.9, 0.4> }
  scale 0.9 rotate -20*y translate <2.7, 0, 0.2>
}
