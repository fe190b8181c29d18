// bicubic_patch: flatness and step limits (a full subdivision, a flatness-stopped one,
// the old keyword-less form), transforms that move the control points (and so change
// the flat pieces), a grazing view, glass, and a patch in a union and a difference.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 6 }
camera { location <0, 6, -9> look_at <0, 0.3, 0.6> angle 50 }
light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 5, -2> color rgb 0.35 }
plane { y, -0.5 pigment { checker rgb 0.9 rgb 0.6 scale 0.8 } }
#declare Saddle = bicubic_patch { type 1 flatness 0 u_steps 3 v_steps 3
  <0, 0, 0>, <1, 1, 0>, <2, 1, 0>, <3, 0, 0>,
  <0, 1, 1>, <1, 2, 1>, <2, -1, 1>, <3, 1, 1>,
  <0, 1, 2>, <1, -1, 2>, <2, 2, 2>, <3, 1, 2>,
  <0, 0, 3>, <1, 1, 3>, <2, 1, 3>, <3, 0, 3> }
object { Saddle pigment { rgb <0.9, 0.4, 0.3> } scale 0.6 translate <-3, 0, 1.5> }
// Flatness stops the subdivision before 6 levels.
bicubic_patch { type 0 flatness 0.05 u_steps 6 v_steps 6
  <0, 0, 0>, <1, 1.5, 0>, <2, 1.5, 0>, <3, 0, 0>,
  <0, 0.5, 1>, <1, 2, 1>, <2, 2, 1>, <3, 0.5, 1>,
  <0, 0.5, 2>, <1, 2, 2>, <2, 2, 2>, <3, 0.5, 2>,
  <0, 0, 3>, <1, 1.5, 3>, <2, 1.5, 3>, <3, 0, 3>
  pigment { rgb <0.3, 0.6, 0.9> } scale 0.6 translate <-0.9, 0, 1.5> }
// The old form: type 1, flatness 0.1 by default, 2 and 4 steps; scaled unevenly.
bicubic_patch { 1 2 4
  <0, 0, 0>, <1, 0.5, 0>, <2, 0.5, 0>, <3, 0, 0>,
  <0, 0.3, 1>, <1, 1.5, 1>, <2, -0.5, 1>, <3, 0.3, 1>,
  <0, 0.3, 2>, <1, -0.5, 2>, <2, 1.5, 2>, <3, 0.3, 2>,
  <0, 0, 3>, <1, 0.5, 3>, <2, 0.5, 3>, <3, 0, 3>
  scale <0.7, 1.2, 0.5> rotate 30*y translate <1.4, 0, 1.2> pigment { rgb <0.4, 0.85, 0.4> } }
// Seen nearly edge-on.
object { Saddle scale <0.7, 0.05, 0.7> rotate -3*x translate <-3.2, 0.3, -2.2>
  pigment { rgb <0.9, 0.8, 0.3> } }
// Glass.
object { Saddle scale 0.6 rotate 20*y translate <-0.6, 0.2, -2>
  pigment { rgbf <0.9, 1, 0.9, 0.8> } finish { specular 0.5 } interior { ior 1.3 } }
// In a union with a sphere, and subtracted from a box (a surface: its own hits only).
union { object { Saddle scale 0.5 } sphere { <0.75, 0.5, 0.75>, 0.35 }
  pigment { rgb <0.8, 0.5, 0.9> } translate <2, 0, -2.3> }
