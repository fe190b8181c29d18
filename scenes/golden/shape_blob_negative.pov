// blob: negative strengths carving dents and holes (only positive components bound the
// box), a component that never reaches the threshold alone, and a blob inverted.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4.5, -9> look_at <0, 0.3, 0> angle 50 }
light_source { <-5, 10, -8> color rgb 1 }
light_source { <6, 5, -4> color rgb 0.4 }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.5 scale 0.8 } }
blob {
  threshold 0.5
  sphere { <0, 0, 0>, 1.5, 2 }
  sphere { <0.5, 0.6, -0.6>, 0.9, -2 }
  sphere { <-0.7, -0.2, -0.8>, 0.6, -1 }
  pigment { rgb <0.9, 0.4, 0.3> }
  finish { specular 0.5 }
  translate <-2.5, 0, 0.5>
}
blob {
  threshold 0.3
  cylinder { <-1.2, 0, 0>, <1.2, 0, 0>, 0.7, 1 }
  cylinder { <0, 0.5, -1>, <0, 0.5, 1>, 0.5, -1.5 }
  sphere { <0, 0.9, 0>, 0.4, 0.4 }
  pigment { rgb <0.3, 0.7, 0.9> }
  translate <1.8, 0, 1>
}
// Inverted: seen inside a box (an intersection), the hollow a blob leaves.
intersection {
  box { <-1, -0.9, -0.8>, <1, 0.7, 0.8> }
  blob {
    threshold 0.5
    sphere { <0, 0, -0.3>, 1.0, 1 }
    sphere { <0.5, 0.3, -0.5>, 0.9, 1 }
    sphere { <-0.2, 0.2, -1>, 0.5, -0.5 }
    inverse
  }
  pigment { rgb <0.6, 0.9, 0.4> }
  rotate 20*y translate <0.3, 0, -2.3>
}
