// Parametrics where the search is stiff: a thin tube (minor radius 0.03) seen almost
// edge-on, a steep ripple with max_gradient above its slope, a sphere-contained saddle
// grazed, a torus scaled by 1e-3 near the camera and one scaled by 1e3 far away.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.32, -9> look_at <0, 0.3, 0> angle 45 }
light_source { <10, 20, -10> rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
#declare Torus = parametric {
  function { (0.7 + 0.03*cos(v))*cos(u) }
  function { 0.03*sin(v) }
  function { (0.7 + 0.03*cos(v))*sin(u) }
  <0, 0>, <2*pi, 2*pi>
  contained_by { box { <-0.75, -0.05, -0.75>, <0.75, 0.05, 0.75> } }
  max_gradient 1.5
}
object { Torus rotate -3*x translate <-2.4, 0.3, 0> pigment { rgb <1, 0.6, 0.2> } }
parametric {
  function { u } function { 0.3*sin(8*u)*sin(7*v) } function { v }
  <-1, -1>, <1, 1>
  contained_by { box { <-1, -0.35, -1>, <1, 0.35, 1> } }
  max_gradient 4
  rotate <-20, 20, 0> translate <0, 0.3, 0> pigment { rgb <1, 0.8, 0.4> }
}
parametric {
  function { u } function { 0.5*(u*u - v*v) } function { v }
  <-1, -1>, <1, 1>
  contained_by { sphere { 0, 0.95 } }
  max_gradient 2.5
  rotate <1, 30, 0> translate <2.4, 0.32, 1> pigment { rgb <0.4, 0.8, 0.4> }
}
object { Torus scale 1e-3 rotate 60*x translate <0.3, 0.32, -8.99> pigment { rgb 0.7 } }
object { Torus scale 1e3 rotate -80*x translate <0, 0.3, 5e3> pigment { rgb 0.5 } }
