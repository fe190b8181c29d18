// The pre-3.5 camera with orthographic: it scales the right and up vectors it finds by
// the distance to the look_at point where it stands (here the default look_at, before the
// real one), and a declared camera is continued item by item. (A 3.5+ scene would keep
// the given right and up: the view would be ten times narrower.)
#version 3.0;
#declare Cam = camera { location <0, 2, -8> up <0, 1.2, 0> right <1.6, 0, 0> orthographic }
camera { Cam look_at <0, 0, 0> rotate <0, -15, 0> }
light_source { <-5, 8, -6> color rgb 1 }
plane { y, -1 pigment { checker color rgb 0.9 color rgb 0.3 } }
sphere { <0, 0.3, 0>, 1 pigment { color rgb <0.9, 0.5, 0.2> } }
box { <1.5, -1, -0.5>, <2.5, 0.5, 0.5> pigment { color rgb <0.3, 0.6, 0.9> } }
