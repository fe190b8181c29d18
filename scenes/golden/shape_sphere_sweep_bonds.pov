// Sphere sweeps as molecular exporters write them (VMD, OVITO, ASE): bonds as many
// two-sphere linear sweeps of one radius between atoms drawn as spheres, in a union
// (and a merge in glass), with a global transform over all.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 6 }
camera { location <0, 1, -9> look_at <0, 0, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
light_source { <4, 2, -8> color rgb 0.3 }
background { rgb <0.1, 0.1, 0.15> }
#declare Bond = texture { pigment { rgb <0.7, 0.7, 0.75> } finish { specular 0.4 } }
#declare Atom = texture { pigment { rgb <0.9, 0.3, 0.2> } finish { specular 0.4 } }
union {
  sphere { <1.6, -1.6, 0.0>, 0.28 texture { Atom } }
  sphere { <0.9946, -1.35, 1.2533>, 0.28 texture { Atom } }
  sphere { <-0.3635, -1.1, 1.5582>, 0.28 texture { Atom } }
  sphere { <-1.4465, -0.85, 0.6838>, 0.28 texture { Atom } }
  sphere { <-1.4348, -0.6, -0.708>, 0.28 texture { Atom } }
  sphere { <-0.3373, -0.35, -1.564>, 0.28 texture { Atom } }
  sphere { <1.0155, -0.1, -1.2364>, 0.28 texture { Atom } }
  sphere { <1.5998, 0.15, 0.0269>, 0.28 texture { Atom } }
  sphere { <0.9734, 0.4, 1.2699>, 0.28 texture { Atom } }
  sphere { <-0.3897, 0.65, 1.5518>, 0.28 texture { Atom } }
  sphere { <-1.4578, 0.9, 0.6594>, 0.28 texture { Atom } }
  sphere { <-1.4227, 1.15, -0.7321>, 0.28 texture { Atom } }
  sphere { <-0.3109, 1.4, -1.5695>, 0.28 texture { Atom } }
  sphere { <1.0362, 1.65, -1.2192>, 0.28 texture { Atom } }
  sphere_sweep { linear_spline 2, <1.6, -1.6, 0.0>, 0.1, <0.9946, -1.35, 1.2533>, 0.1 texture { Bond } }
  sphere_sweep { linear_spline 2, <0.9946, -1.35, 1.2533>, 0.1, <-0.3635, -1.1, 1.5582>, 0.1 texture { Bond } }
  sphere_sweep { linear_spline 2, <-0.3635, -1.1, 1.5582>, 0.1, <-1.4465, -0.85, 0.6838>, 0.1 texture { Bond } }
  sphere_sweep { linear_spline 2, <-1.4465, -0.85, 0.6838>, 0.1, <-1.4348, -0.6, -0.708>, 0.1 texture { Bond } }
  sphere_sweep { linear_spline 2, <-1.4348, -0.6, -0.708>, 0.1, <-0.3373, -0.35, -1.564>, 0.1 texture { Bond } }
  sphere_sweep { linear_spline 2, <-0.3373, -0.35, -1.564>, 0.1, <1.0155, -0.1, -1.2364>, 0.1 texture { Bond } }
  sphere_sweep { linear_spline 2, <1.0155, -0.1, -1.2364>, 0.1, <1.5998, 0.15, 0.0269>, 0.1 texture { Bond } }
  sphere_sweep { linear_spline 2, <1.5998, 0.15, 0.0269>, 0.1, <0.9734, 0.4, 1.2699>, 0.1 texture { Bond } }
  sphere_sweep { linear_spline 2, <0.9734, 0.4, 1.2699>, 0.1, <-0.3897, 0.65, 1.5518>, 0.1 texture { Bond } }
  sphere_sweep { linear_spline 2, <-0.3897, 0.65, 1.5518>, 0.1, <-1.4578, 0.9, 0.6594>, 0.1 texture { Bond } }
  sphere_sweep { linear_spline 2, <-1.4578, 0.9, 0.6594>, 0.1, <-1.4227, 1.15, -0.7321>, 0.1 texture { Bond } }
  sphere_sweep { linear_spline 2, <-1.4227, 1.15, -0.7321>, 0.1, <-0.3109, 1.4, -1.5695>, 0.1 texture { Bond } }
  sphere_sweep { linear_spline 2, <-0.3109, 1.4, -1.5695>, 0.1, <1.0362, 1.65, -1.2192>, 0.1 texture { Bond } }
  rotate <0, 20, 10> translate <-1.3, 0, 0>
}
merge {
  sphere_sweep { linear_spline 2, <0, -1.2, 0>, 0.15, <0, 1.2, 0>, 0.15 }
  sphere_sweep { linear_spline 2, <0, 1.2, 0>, 0.15, <1, 1.6, 0.5>, 0.1 }
  sphere_sweep { linear_spline 2, <0, -1.2, 0>, 0.15, <-0.8, -1.6, -0.6>, 0.2 }
  sphere { <0, 1.2, 0>, 0.3 }
  texture { pigment { rgbf <0.8, 0.9, 1, 0.8> } finish { specular 0.6 } }
  interior { ior 1.33 }
  scale <1, 1.2, 1> rotate <0, 0, -15> translate <1.8, 0, 0>
}
