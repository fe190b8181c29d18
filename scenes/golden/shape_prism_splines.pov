// prism: each spline kind swept straight and conic, one open, one seen edge-on (its
// walls parallel to the camera rays), sub-curves with holes, a Bezier outline.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 6, -9> look_at <0, 0.4, 0.5> angle 52 }
light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 5, -2> color rgb 0.35 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.65 scale 0.8 } }
#declare Star = prism { linear_spline 0, 1, 11,
  <0.2, -1>, <0.4, -0.2>, <1, 0>, <0.4, 0.2>, <0.2, 1>, <0, 0.3>, <-0.2, 1>, <-0.4, 0.2>,
  <-1, 0>, <-0.4, -0.2>, <0.2, -1> }
object { Star pigment { rgb <0.9, 0.3, 0.3> } translate <-3, 0, 2> }
// Quadratic, conic from 0.3 to 1 (upside down, so it stands on its wide end)
prism { conic_sweep quadratic_spline 0.3, 1, 7,
  <-1, 0>, <0, -1>, <1, 0>, <0, 1>, <-1, 0>, <0, -1>, <1, 0>
  rotate 180*x translate <0, 1, 2.5> pigment { rgb <0.3, 0.5, 0.9> } }
// Cubic through eight points, with its leading and trailing control points
prism { linear_sweep cubic_spline -0.5, 0.6, 10,
  <0.5, -1>, <1, 0>, <0.6, 0.7>, <0, 1>, <-0.6, 0.7>, <-1, 0>, <-0.5, -1>, <0.5, -1>,
  <1, 0>, <0.6, 0.7>
  translate <3, 0.5, 2> pigment { rgb <0.3, 0.8, 0.4> } }
// Two sub-polygons: a square with a square hole (even-odd)
prism { linear_spline 0, 0.5, 10,
  <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>,
  <-0.5, -0.5>, <0.5, -0.5>, <0.5, 0.5>, <-0.5, 0.5>, <-0.5, -0.5>
  translate <-3, 0, -1> pigment { rgb <0.9, 0.8, 0.3> } }
// Bezier outline, open (no caps), tilted so its inside shows
prism { bezier_spline 0, 0.8, 8,
  <-1, 0>, <-1, 1.2>, <1, 1.2>, <1, 0>, <1, 0>, <1, -1.2>, <-1, -1.2>, <-1, 0>
  open scale 0.8 rotate <-35, 20, 0> translate <0, 0.7, -2.2> pigment { rgb <0.8, 0.5, 0.9> } }
// Seen edge-on: a thin linear prism whose faces contain camera rays
prism { linear_spline -0.05, 0.05, 5, <-0.9, -0.6>, <0.9, -0.6>, <0.9, 0.6>, <-0.9, 0.6>, <-0.9, -0.6>
  rotate -90*x rotate -atan2(3, 9)*180/pi*x translate <3, 0.8, -1> pigment { rgb <0.4, 0.9, 0.9> } }
