// Height fields where the walk is stiff: a constant field seen exactly edge-on and just
// above and below its plane, rays along the cell diagonals (the DDA's corner steps), a
// field of needle spikes (triangles nearly parallel to the rays), and a tiny field far
// from the origin. Function images, so the scene needs no image files.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 0.35, -3> look_at <0.5, 0.3, 0> angle 50 }
light_source { <10, 20, -10> rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
// Constant: height 0.5 everywhere; one surface at the camera's height (edge-on), two
// just below it (grazing).
height_field { function 16, 16 { 0.5 } pigment { rgb <1, 0.6, 0.6> }
               scale <1, 0.7, 1> translate <-0.2, 0, 1> }
height_field { function 16, 16 { 0.5 } pigment { rgb <1, 0.8, 0.6> }
               scale <1, 0.6, 1> translate <-0.6, 0, 0> }
height_field { function 17, 17 { 0.5 } pigment { rgb <0.6, 0.8, 1> }
               scale <1, 0.6, 1> rotate 45*y translate <0.9, 0.0001, 0.4> }
// Needles: most vertices low, some at the top.
height_field { function 48, 48 { select(sin(x * 937.1) * cos(y * 731.3) - 0.7, 0.05, 0.99) }
               pigment { rgb <0.7, 1, 0.6> } scale <1.2, 0.5, 1.2> translate <-0.1, -0.2, 0.6> }
height_field { function 20, 20 { 0.3 + 0.3 * sin(x * 7) } smooth
               pigment { rgb 0.8 } scale 1e-3 translate <0.5, 0.3495, -2.99> }
