// golden-args: +UA
// The same rule in a scene without #version (3.6 compositing): a reflected ray sees the
// background's colour, a camera ray its transparency.
global_settings { assumed_gamma 1.0 }
background { color rgb <0.9, 0.8, 0.6> }
camera { orthographic right -4 * x up 3 * y location <0, 0, 50> look_at <0, 0, 0> }
light_source { <2, 3, 40> color rgb 1 }
sphere { <-1, 0, 0>, 0.9 pigment { color rgb <0.2, 0.3, 0.8> } finish { ambient 0.1 diffuse 0.5 reflection 0.5 } }
sphere { <1, 0, 0>, 0.9 pigment { color rgbt <0.8, 0.3, 0.2, 0.4> } finish { reflection 0.3 phong 0.6 } }
