// The facets normal: following the surface normal (cut-gem look, default size, a
// smaller size, metrics 1 and 3) and following the point (`coords`), on spheres and a
// torus under two lights, one of them reflected.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -9> look_at <0, 0.3, 0> angle 55 }
light_source { <-6, 10, -8> color rgb 1 }
light_source { <6, 4, -6> color rgb <0.5, 0.5, 0.6> }
background { rgb <0.1, 0.1, 0.2> }
plane { y, -1 pigment { checker rgb 0.3, rgb 0.6 } }
sphere { <-3, 0.2, 0>, 1.1 pigment { rgb <0.9, 0.3, 0.3> } finish { phong 0.8 }
  normal { facets } }
sphere { <0, 0.2, 0>, 1.1 pigment { rgb <0.3, 0.9, 0.3> } finish { phong 0.8 }
  normal { facets size 0.25 metric 1 } }
sphere { <3, 0.2, 0>, 1.1 pigment { rgb <0.3, 0.4, 0.9> } finish { phong 0.8 }
  normal { facets coords 0.6 scale 0.3 } }
torus { 1.0, 0.35 rotate x * -60 translate <-1.5, 0.2, -2.8>
  pigment { rgb <0.9, 0.8, 0.3> } finish { specular 0.6 reflection 0.2 }
  normal { facets size 0.05 metric 3 } }
box { <0.6, -1, -3.4>, <2.4, 0.6, -2.2> rotate y * 20
  pigment { rgb 0.8 } normal { facets coords 1 metric 2.5 scale 0.2 } }
