// Prisms seen edge-on and at grazing angles: caps in planes that hold the camera rays,
// walls parallel to them, a cubic outline with nearly coincident control points, and a
// conic prism whose apex lies on the line of sight.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.5, -8> look_at <0, 0.5, 0> angle 50 }
light_source { <10, 20, -10> rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
// Cap plane y = 0.5 through the camera: the cap is seen exactly edge-on.
prism { linear_spline 0, 0.5, 5, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>
  translate <-2.2, 0, 0> pigment { rgb <1, 0.6, 0.2> } }
// Walls x = const parallel to the rays of the middle column.
prism { linear_spline 0.2, 1.2, 5, <-1e-6, -1>, <1e-6, -1>, <1e-6, 1>, <-1e-6, 1>, <-1e-6, -1>
  pigment { rgb 1 } }
// Cubic with control points 1e-7 apart.
prism { cubic_spline 0, 1, 10,
  <0.5, -1>, <1, 0>, <1 + 1e-7, 1e-7>, <0, 1>, <-1, 0>, <-1, 1e-7>, <0.5, -1>, <1, 0>,
  <1 + 1e-7, 1e-7>, <0, 1>
  translate <2.2, 0, 0> pigment { rgb <0.4, 0.8, 1> } }
// Conic, apex (y = 0) on the line of sight after the turn.
prism { conic_sweep linear_spline 0.01, 1, 4, <-1, -1>, <1, -1>, <0, 1>, <-1, -1>
  rotate 90*x translate <0, 0.5, 3> pigment { rgb <0.6, 1, 0.4> } }
