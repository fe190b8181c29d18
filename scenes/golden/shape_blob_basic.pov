// blob: sphere components of several radii and strengths merging, the default threshold
// and a low one, sturm, a legacy `component` blob, and a transformed copy.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -10> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 10, -8> color rgb 1 }
light_source { <6, 5, -4> color rgb 0.4 }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.5 scale 0.8 } }
// Three spheres merging (threshold 0.6).
blob {
  threshold 0.6
  sphere { <-0.75, 0, 0>, 1, 1 }
  sphere { <0.75, 0, 0>, 1, 1 }
  sphere { <0, 0.9, 0>, 0.8, strength 1.5 }
  pigment { rgb <0.9, 0.4, 0.3> }
  finish { specular 0.5 }
  translate <-2.8, 0, 1>
}
// Default threshold 1: strengths above 1 are needed; sturm.
blob {
  sphere { <0, 0, 0>, 1.2, 2 }
  sphere { <0.9, 0.5, 0>, 0.9, 3 }
  sphere { <-0.6, 0.7, 0.4>, 1.0, 1.8 }
  sturm
  pigment { rgb <0.3, 0.7, 0.9> }
  translate <0, 0, 1.5>
}
// The legacy syntax: component strength, radius, centre.
#declare Old = blob {
  threshold 0.5
  component 1, 1, <0, 0, 0>
  component 1, 1, <0, 0.8, 0>
  component 0.8, 0.7, <0.5, 1.2, 0>
  pigment { rgb <0.5, 0.9, 0.4> }
}
object { Old translate <2.8, 0, 1> }
object { Old scale <1.2, 0.7, 1> rotate <0, 40, 25> translate <1.5, 0, -2.5> }
// A weak threshold near the components' edges.
blob {
  threshold 0.05
  sphere { <0, 0, 0>, 0.8, 1 }
  sphere { <1.2, 0, 0>, 0.8, 1 }
  pigment { rgb <0.9, 0.8, 0.3> }
  translate <-1.8, -0.2, -2.8>
}
