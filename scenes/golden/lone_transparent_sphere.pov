// A transparent sphere alone in the scene shadows its own far side: the light reaching
// the inside of the far surface passes the near surface (transmit 0.4). The render plan
// may skip shadow rays only for a lone opaque convex object.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0.5, 0> }
light_source { <-3, 5, -4> color rgb 1 }
sphere { <0, 0.5, 0>, 1 pigment { rgbt <1, 0.5, 0.2, 0.4> } finish { ambient 0.05 } }
