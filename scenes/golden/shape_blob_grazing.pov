// blob seen at grazing angles: a flat blob edge-on, a long cylinder blob nearly along
// its axis, and tangent rays over the saddle between two spheres.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.35, -8> look_at <0, 0.3, 0> angle 40 }
light_source { <-5, 10, -7> color rgb 1 }
light_source { <6, 5, -4> color rgb 0.4 }
plane { y, -1.2 pigment { checker rgb 0.9 rgb 0.5 scale 0.8 } }
blob {
  threshold 0.5
  sphere { <-0.6, 0, 0>, 1, 1 }
  sphere { <0.6, 0, 0>, 1, 1 }
  scale <1, 0.12, 1> rotate 1*x translate <-1.6, 0.35, 0>
  pigment { rgb <0.9, 0.5, 0.3> }
}
blob {
  threshold 0.6
  cylinder { <0, 0, -3>, <0, 0, 3>, 0.5, 1.2 }
  sphere { <0, 0, 0>, 0.6, 1 }
  rotate <0.5, 2, 0> translate <1.6, 0.3, 2>
  pigment { rgb <0.4, 0.8, 0.4> }
}
blob {
  threshold 0.5
  sphere { <-0.5, 0, 0>, 0.7, 1 }
  sphere { <0.5, 0, 0>, 0.7, 1 }
  translate <0, -0.6, -3>
  pigment { rgb <0.5, 0.6, 0.95> }
}
