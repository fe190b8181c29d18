// Orthographic camera looking down +z: every ray's x and y direction components are exactly 0,
// and ray origins lie exactly on box faces and edges (slab tests with zero components).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction <0, 0, 1> right <4, 0, 0> up <0, 3, 0> }
light_source { <-5, 8, -20> rgb 1 }
background { rgb <0.1, 0.2, 0.1> }
box { <-1, -1, 0>, <0, 0, 1> pigment { rgb <1, 0.2, 0.2> } }
box { <0, 0, 0>, <1, 1, 1> pigment { rgb <0.2, 1, 0.2> } }
box { <0, -1, 0.5>, <1, 0, 1.5> pigment { rgb <0.2, 0.2, 1> } }
cylinder { <-1.5, 0, 2>, <-1.5, 0, 3>, 0.25 pigment { rgb <1, 1, 0.2> } }
sphere { <1.5, 1, 0>, 0.25 pigment { rgb 1 } }
torus { 0.5, 0.1 rotate <90, 0, 0> translate <-1.5, 1, 0> pigment { rgb <1, 0.5, 0> } }
