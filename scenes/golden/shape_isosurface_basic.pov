// isosurface: simple functions in the default box container and in a sphere, a
// threshold, a visible container (closed: where F < 0 on its surface), accuracy and
// max_gradient set, a declared function called with more parameters.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -10> look_at <0, 0.3, 0> angle 50 }
light_source { <-5, 10, -8> color rgb 1 }
light_source { <6, 5, -4> color rgb 0.4 }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.5 scale 0.8 } }
// A sphere by sqrt, cut by the default container <-1, 1>: flat faces where it passes.
isosurface {
  function { sqrt(x*x + y*y + z*z) - 1.15 }
  pigment { rgb <0.9, 0.4, 0.3> } finish { specular 0.4 }
  translate <-2.7, 0, 1>
}
// A torus in a sphere container, threshold.
isosurface {
  function { sqrt(pow(sqrt(x*x + z*z) - 0.8, 2) + y*y) - 0.3 }
  threshold 0.05
  contained_by { sphere { 0, 1.3 } }
  max_gradient 1.2
  pigment { rgb <0.3, 0.7, 0.9> }
  rotate -60*x translate <0, 0.2, 1.5>
}
// A wavy surface in a box (max_gradient above the default), accuracy coarser.
isosurface {
  function { y - 0.3*sin(4*x)*cos(3*z) }
  contained_by { box { <-1.2, -0.6, -1.2>, <1.2, 0.6, 1.2> } }
  max_gradient 2.2
  accuracy 0.005
  pigment { rgb <0.5, 0.9, 0.4> }
  translate <2.6, -0.3, 0.5>
}
// A rounded box (functions.inc's f_rounded_box, written out), scaled.
isosurface {
  function { sqrt(pow(max(abs(x) - 0.6, 0), 2) + pow(max(abs(y) - 0.3, 0), 2) +
                  pow(max(abs(z) - 0.4, 0), 2)) - 0.3 }
  contained_by { box { -1, 1 } }
  pigment { rgb <0.9, 0.8, 0.3> }
  scale 0.8 rotate <10, 30, 0> translate <-1.2, -0.2, -2.5>
}
// A user function declared first and called with other arguments.
#declare Blobby = function(x, y, z, r) { x*x + y*y + z*z - r*r + 0.2*sin(5*x)*sin(5*y) }
isosurface {
  function { Blobby(x, y, z, 0.8) }
  max_gradient 4
  pigment { rgb <0.8, 0.5, 0.9> }
  translate <1.4, -0.1, -2.3>
}
