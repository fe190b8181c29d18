// Media under #version 3.1 (method 1, intervals 10, samples 1: emission-only constant
// media integrate exactly), a merge and a union of overlapping spheres (POV-Ray's union
// loses the media inside the overlap, merge keeps it), and the camera inside a media box.
#version 3.1;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -4> look_at <0, 0.8, 0> angle 60 }
light_source { <-3, 6, -5> color rgb 1 }
background { color rgb <0.1, 0.1, 0.2> }
plane { y, 0 pigment { checker rgb 0.7 rgb 0.3 } }
merge {
  sphere { <-0.3, 0, 0>, 0.6 } sphere { <0.3, 0, 0>, 0.6 }
  hollow pigment { rgbt 1 } interior { media { emission <0.2, 0.8, 0.3> } }
  translate <-1.2, 1.2, 1> }
union {
  sphere { <-0.3, 0, 0>, 0.6 } sphere { <0.3, 0, 0>, 0.6 }
  hollow pigment { rgbt 1 } interior { media { emission <0.9, 0.3, 0.2> } }
  translate <1.2, 1.2, 1> }
box { <-6, -1, -6>, <6, 6, 6> hollow pigment { rgbt 1 }
      interior { media { emission 0.01 } } }
