// isosurface seen at grazing angles: a flat wavy sheet nearly edge-on, a container face
// seen edge-on (closed), and a thin shell.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.35, -8> look_at <0, 0.3, 0> angle 40 }
light_source { <-5, 10, -7> color rgb 1 }
light_source { <6, 5, -4> color rgb 0.4 }
plane { y, -1.2 pigment { checker rgb 0.9 rgb 0.5 scale 0.8 } }
isosurface {
  function { y - 0.05*sin(6*x)*sin(5*z) }
  contained_by { box { <-1.5, -0.2, -1.5>, <1.5, 0.2, 1.5> } }
  max_gradient 1.6
  pigment { rgb <0.9, 0.5, 0.3> }
  rotate 1*x translate <-1.6, 0.3, 0.5>
}
isosurface {
  function { x*x + y*y - 0.5 }
  contained_by { box { <-1, -1, -2>, <1, 1, 2> } }
  max_gradient 2.5
  pigment { rgb <0.4, 0.8, 0.4> }
  rotate <0.3, 1, 0> translate <1.6, 0.3, 2>
}
isosurface {
  function { abs(sqrt(x*x + y*y + z*z) - 0.6) - 0.02 }
  contained_by { sphere { 0, 0.7 } }
  max_gradient 1.1
  pigment { rgb <0.5, 0.6, 0.95> }
  translate <0, -0.4, -3>
}
