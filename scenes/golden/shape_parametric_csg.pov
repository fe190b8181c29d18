// parametric in CSG: cut by a sphere (intersection: only its surface inside the sphere,
// the sphere's none, as it has no inside), joined to a box, the surface left inside a
// box (difference: the box's own faces are gone), clipped by a plane.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -9> look_at <0, 0, 0> angle 50 }
light_source { <-5, 10, -8> color rgb 1 }
light_source { <6, 5, -4> color rgb 0.4 }
plane { y, -1.3 pigment { checker rgb 0.9 rgb 0.5 scale 0.8 } }
#declare Sheet = parametric {
  function { u }
  function { 0.3*sin(2*u)*sin(2*v) }
  function { v }
  <-1.2, -1.2>, <1.2, 1.2>
  contained_by { box { <-1.2, -0.4, -1.2>, <1.2, 0.4, 1.2> } }
  max_gradient 1.2
  accuracy 0.004
}
intersection {
  object { Sheet }
  sphere { 0, 1 }
  pigment { rgb <0.9, 0.5, 0.3> }
  translate <-2.6, 0, 0>
}
union {
  object { Sheet pigment { rgb <0.3, 0.7, 0.9> } }
  box { <-0.3, -1.3, -0.3>, <0.3, 0, 0.3> pigment { rgb 0.7 } }
  rotate 30*y translate <0, 0, 1.5>
}
difference {
  box { -0.9, 0.9 }
  object { Sheet }
  pigment { rgb <0.5, 0.9, 0.4> }
  translate <2.6, 0, 0>
}
object { Sheet clipped_by { plane { x, 0.3 } } pigment { rgb <0.9, 0.8, 0.3> }
  scale 0.6 rotate -40*x translate <0, -0.7, -3> }
