// parametric: a torus by its angles (u around the axis, v around the tube) in a box, a
// sphere-contained wavy ring, a transformed copy.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 5, -9> look_at <0, 0, 0> angle 45 }
light_source { <-5, 10, -8> color rgb 1 }
light_source { <6, 5, -4> color rgb 0.4 }
plane { y, -1.2 pigment { checker rgb 0.9 rgb 0.5 scale 0.8 } }
parametric {
  function { (1.2 + 0.4*cos(v))*cos(u) }
  function { 0.4*sin(v) }
  function { (1.2 + 0.4*cos(v))*sin(u) }
  <0, 0>, <2*pi, 2*pi>
  contained_by { box { <-1.7, -0.5, -1.7>, <1.7, 0.5, 1.7> } }
  max_gradient 2
  accuracy 0.01
  pigment { rgb <0.9, 0.5, 0.3> } finish { specular 0.4 }
  translate <-1.6, 0, 0.6>
}
parametric {
  function { u*cos(v) }
  function { 0.25*sin(3*v)*u }
  function { u*sin(v) }
  <0.4, 0>, <1, 2*pi>
  contained_by { sphere { 0, 1.1 } }
  max_gradient 2.5
  accuracy 0.008
  pigment { rgb <0.3, 0.7, 0.9> }
  rotate <-30, 20, 0> translate <1.8, 0.2, 0.4>
}
