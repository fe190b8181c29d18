// parametric precompute: the same torus with precompute on x, y and z, on y and z only,
// and without, at a coarse max_gradient where the bounds matter; a uv_mapping checker
// reads the hit's (u, v).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 6, -8> look_at <0, 0, 0.3> angle 50 }
light_source { <-5, 10, -8> color rgb 1 }
light_source { <6, 5, -4> color rgb 0.4 }
background { rgb 0.3 }
#declare Torus = parametric {
  function { (0.9 + 0.35*cos(v))*cos(u) }
  function { 0.35*sin(v) }
  function { (0.9 + 0.35*cos(v))*sin(u) }
  <0, 0>, <2*pi, 2*pi>
  contained_by { box { <-1.3, -0.4, -1.3>, <1.3, 0.4, 1.3> } }
  max_gradient 1.5
  accuracy 0.005
}
parametric {
  function { (0.9 + 0.35*cos(v))*cos(u) }
  function { 0.35*sin(v) }
  function { (0.9 + 0.35*cos(v))*sin(u) }
  <0, 0>, <2*pi, 2*pi>
  contained_by { box { <-1.3, -0.4, -1.3>, <1.3, 0.4, 1.3> } }
  max_gradient 1.5
  accuracy 0.005
  precompute 14, x, y, z
  uv_mapping pigment { checker rgb <0.9, 0.3, 0.2> rgb 0.9 scale <pi/8, pi/4, 1> }
  translate <-2.1, 0, 0>
}
parametric {
  function { (0.9 + 0.35*cos(v))*cos(u) }
  function { 0.35*sin(v) }
  function { (0.9 + 0.35*cos(v))*sin(u) }
  <0, 0>, <2*pi, 2*pi>
  contained_by { box { <-1.3, -0.4, -1.3>, <1.3, 0.4, 1.3> } }
  max_gradient 1.5
  accuracy 0.005
  precompute 10 y z
  pigment { rgb <0.3, 0.8, 0.4> }
  translate <0, 0, 1.6>
}
object { Torus pigment { rgb <0.3, 0.5, 0.9> } translate <2.1, 0, 0> }
