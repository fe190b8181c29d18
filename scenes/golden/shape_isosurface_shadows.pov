// Transparent isosurfaces (max_trace 1) casting shadows: POV-Ray's shadow ray restarts
// at each crossing, so the far side of a shape and the closed container's faces filter
// the light too (povwall makes those restarts inside the shape).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -9> look_at <0, 0.3, 0> angle 50 }
light_source { <-5, 10, -8> color rgb 1 }
light_source { <6, 5, -4> color rgb 0.4 }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.5 scale 0.8 } }
isosurface { function { x*x + y*y + z*z - 0.8 } max_gradient 2
  pigment { rgbf <0.9, 1, 0.9, 0.8> } translate <-2.2, 0, 0.5> }
// Cut by its container: the box's faces where F < 0 are surfaces too.
isosurface { function { x*x + y*y + z*z - 1.5 } max_gradient 3
  pigment { rgbf <0.9, 0.9, 1, 0.7> } finish { specular 0.5 } translate <0.6, 0, 1> }
isosurface { function { abs(x) + abs(y) + abs(z) - 0.8 } contained_by { sphere { 0, 0.75 } }
  max_gradient 1.8 pigment { rgbt <1, 0.8, 0.5, 0.6> } rotate 30*y translate <2.7, -0.2, -1> }
