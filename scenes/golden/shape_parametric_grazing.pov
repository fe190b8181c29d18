// parametric: a height surface y(u, v) over the uv square, seen from just above it at a
// grazing angle, and a tilted ripple sheet seen edge-on.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.35, -4> look_at <0, 0.05, 2> angle 50 }
light_source { <-3, 8, -6> color rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
parametric {
  function { u }
  function { 0.15*sin(3*u)*cos(2*v) }
  function { v }
  <-3, -2>, <3, 5>
  contained_by { box { <-3, -0.2, -2>, <3, 0.2, 5> } }
  max_gradient 1.2
  accuracy 0.003
  pigment { checker rgb <0.9, 0.8, 0.3> rgb <0.3, 0.5, 0.2> scale 0.5 }
}
parametric {
  function { u }
  function { v }
  function { 0.1*sin(6*u + 2*v) }
  <-0.8, -0.5>, <0.8, 0.5>
  contained_by { box { <-0.8, -0.5, -0.15>, <0.8, 0.5, 0.15> } }
  max_gradient 1.5
  accuracy 0.002
  pigment { rgb <0.8, 0.4, 0.8> }
  rotate <0, 80, 0> translate <1.2, 0.5, 0>
}
