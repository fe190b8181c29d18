// Isosurfaces where the search is stiff: a thin shell seen edge-on, a steep wavy sheet
// with a generous max_gradient, a sphere container grazed, tiny and huge scales, and a
// threshold surface seen along the container's face.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.32, -9> look_at <0, 0.3, 0> angle 45 }
light_source { <10, 20, -10> rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
isosurface { function { abs(sqrt(x*x + y*y + z*z) - 0.8) - 0.03 } max_gradient 1.1
  contained_by { sphere { 0, 0.9 } } translate <-2.6, 0.3, 0> pigment { rgb <1, 0.6, 0.2> } }
isosurface { function { y - 0.3*sin(8*x)*sin(7*z) } max_gradient 4
  contained_by { box { <-1, -0.5, -1>, <1, 0.5, 1> } } rotate <-20, 20, 0>
  translate <0, 0.3, 0> pigment { rgb <1, 0.8, 0.4> } }
isosurface { function { x*x + y*y + z*z - 0.8 } threshold -0.1 max_gradient 2.5
  contained_by { box { -1, 1 } } rotate <0.5, 0.3, 0> translate <2.6, 0.32, 1>
  pigment { rgb <0.4, 0.8, 0.4> } }
isosurface { function { x*x + y*y + z*z - 0.5 } max_gradient 2.5
  scale 1e-3 translate <0.3, 0.32, -8.99> pigment { rgb 0.7 } }
isosurface { function { max(abs(x), abs(y), abs(z)) - 0.7 } max_gradient 1.1
  scale 1e3 rotate 0.01*x translate <0, 0.3, 5e3> pigment { rgb 0.5 } }
